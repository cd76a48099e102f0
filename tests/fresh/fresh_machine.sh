#!/usr/bin/env bash
# The fresh-machine check (`make fresh-check`): the README's first command, `make demo`, on a
# freshly bootstrapped Debian 12, as a person who has just cloned facet runs it.
#
#   1. A minimal bookworm (`debootstrap --variant=minbase`) plus only git, make,
#      ca-certificates and sudo: what the README says a fresh machine needs before the two
#      commands. It is bootstrapped once and kept in FACET_FRESH_BASE (default
#      /var/cache/facet/fresh-bookworm): the base is the same for every run.
#   2. A copy of that base, a clone of this repository's HEAD in a normal user's home (the user
#      has sudo, as on a desktop), then `make demo` as that user, timed.
#   3. The demo's image and PNG must be there and not empty; with FRESH_DEB=1 (`make fresh-check`
#      passes it), `make package` builds the .deb in the same system, apt installs it (and the
#      dependencies it declares) on a second copy of the base, and the installed `facet` renders
#      the installed Cornell box there as the user.
#
# Needs root (chroot, mounts), debootstrap (installed when missing) and the Debian mirror of the
# host's apt sources. Downloaded packages are kept in FACET_FRESH_APT_CACHE between runs, only to
# save the download: every package is still installed by `make demo` itself.
# Exit status: 0 when the demo rendered, 1 when it did not, 2 when the check could not be set up.
set -uo pipefail

repo=$(cd "$(dirname "$0")/../.." && pwd)
base=${FACET_FRESH_BASE:-/var/cache/facet/fresh-bookworm}
apt_cache=${FACET_FRESH_APT_CACHE:-/var/cache/facet/fresh-apt}
command=${FRESH_COMMAND:-make demo}

fail_setup() { echo "fresh-check: $*" >&2; exit 2; }

[[ $(id -u) -eq 0 ]] || fail_setup "needs root (debootstrap, chroot and bind mounts); run it as root or with sudo"
git -C "$repo" rev-parse HEAD >/dev/null 2>&1 || fail_setup "$repo is not a git checkout"
if [[ -n $(git -C "$repo" status --porcelain --untracked-files=no) ]]; then
    echo "fresh-check: note: the check clones HEAD; uncommitted changes in $repo are not part of it" >&2
fi

# The Debian mirror the host's apt already reaches (deb822 sources, then the one-line form).
mirror() {
    local m
    m=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/*.sources 2>/dev/null)
    [[ -n $m ]] || m=$(awk '$1 == "deb" {print $2; exit}' /etc/apt/sources.list 2>/dev/null)
    echo "${m:-http://deb.debian.org/debian}"
}

# --- 1. the base system, bootstrapped once ---------------------------------------------------
if [[ ! -f $base/.facet-fresh-base ]]; then
    if ! command -v debootstrap >/dev/null; then
        echo "fresh-check: installing debootstrap"
        { apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q debootstrap; } >/dev/null ||
            fail_setup "could not install debootstrap"
    fi
    echo "fresh-check: bootstrapping a minimal Debian 12 into $base (once)"
    rm -rf "$base" && mkdir -p "$(dirname "$base")"
    log=$(mktemp)
    if ! debootstrap --variant=minbase bookworm "$base" "$(mirror)" >"$log" 2>&1; then
        tail -20 "$log" >&2
        fail_setup "debootstrap failed (log above)"
    fi
    # What the README asks of a fresh machine before its two commands: git and make (plus the
    # certificates git needs and sudo, which a desktop user has).
    if ! chroot "$base" /bin/bash -c 'apt-get update -q && DEBIAN_FRONTEND=noninteractive \
            apt-get install -y -q --no-install-recommends git make ca-certificates sudo && apt-get clean' \
            >"$log" 2>&1; then
        tail -20 "$log" >&2
        fail_setup "installing git, make, ca-certificates and sudo into the base failed (log above)"
    fi
    rm -f "$log"
    touch "$base/.facet-fresh-base"
fi

# --- 2. a copy of the base, a user, a clone --------------------------------------------------
work=$(mktemp -d "${TMPDIR:-/tmp}/facet-fresh.XXXXXX")
mounted=()
cleanup() {
    local m
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2>/dev/null; done
    mounted=()
    [[ -n ${FACET_FRESH_KEEP:-} ]] && { echo "fresh-check: kept $work"; return; }
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# A root of its own from the base: bind mounts of the kernel's file systems, the host's
# resolver, the package cache.
new_root() {
    local root=$1
    cp -a "$base/." "$root/" || fail_setup "could not copy the base into $root"
    local m
    for m in proc sys dev; do mount --bind "/$m" "$root/$m" && mounted+=("$root/$m") || fail_setup "mount $m"; done
    mkdir -p "$apt_cache/partial" "$root/var/cache/apt/archives"
    mount --bind "$apt_cache" "$root/var/cache/apt/archives" && mounted+=("$root/var/cache/apt/archives") ||
        fail_setup "mount the apt cache"
    cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null
    # A user as on a desktop: sudo for apt-get, which `make demo` calls when not root.
    chroot "$root" /bin/bash -c 'useradd -m -s /bin/bash user && echo "user ALL=(ALL) NOPASSWD:ALL" >/etc/sudoers.d/user' ||
        fail_setup "could not add a user"
}

root=$work/demo
mkdir -p "$root"
new_root "$root"
git clone -q "$repo" "$root/home/user/facet" || fail_setup "git clone of $repo failed"
# The sibling shared/ of the checkout (assets the tests read) is not needed for the demo.
chroot "$root" chown -R user:user /home/user/facet

echo "fresh-check: '$command' in a fresh Debian 12 (minbase + git, make, ca-certificates, sudo) as a user with sudo"
start=$(date +%s.%N)
chroot "$root" /bin/su - user -c "cd ~/facet && $command" 2>&1 | sed 's/^/  | /'
status=${PIPESTATUS[0]}
elapsed=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.0f", b - a}')
echo "fresh-check: '$command' exited $status after ${elapsed} s"
[[ $status -eq 0 ]] || exit 1

out=$root/home/user/facet/out
for f in cornell_box.exr cornell_box.png; do
    [[ -s $out/$f ]] || { echo "fresh-check: FAILED: '$command' exited 0 but did not write out/$f" >&2; exit 1; }
done
echo "fresh-check: the demo wrote out/cornell_box.exr ($(stat -c %s "$out/cornell_box.exr") bytes) and out/cornell_box.png"

# --- 3. the package, installed on a second fresh system --------------------------------------
if [[ ${FRESH_DEB:-0} == 1 ]]; then
    chroot "$root" /bin/su - user -c "cd ~/facet && make package" 2>&1 | sed 's/^/  | /'
    [[ ${PIPESTATUS[0]} -eq 0 ]] || { echo "fresh-check: FAILED: make package" >&2; exit 1; }
    deb=$(ls "$root"/home/user/facet/build-demo/facet_*.deb 2>/dev/null | head -n 1)
    [[ -n $deb ]] || { echo "fresh-check: FAILED: make package wrote no .deb" >&2; exit 1; }
    root2=$work/installed
    mkdir -p "$root2"
    new_root "$root2"
    cp "$deb" "$root2/tmp/"
    echo "fresh-check: installing $(basename "$deb") with apt on a second fresh system"
    chroot "$root2" /bin/bash -c "apt-get update -q >/dev/null && DEBIAN_FRONTEND=noninteractive \
        apt-get install -y -q /tmp/$(basename "$deb")" 2>&1 | tail -3 | sed 's/^/  | /'
    [[ ${PIPESTATUS[0]} -eq 0 ]] || { echo "fresh-check: FAILED: apt-get install of the package" >&2; exit 1; }
    chroot "$root2" /bin/su - user -c "facet --version && facet render /usr/share/facet/scenes/cornell_box.json \
        --spp 4 --width 64 --height 64 --out out/cb.exr" 2>&1 | sed 's/^/  | /'
    [[ ${PIPESTATUS[0]} -eq 0 && -s $root2/home/user/out/cb.exr ]] ||
        { echo "fresh-check: FAILED: the installed facet did not render" >&2; exit 1; }
    echo "fresh-check: the installed package rendered out/cb.exr"
fi
echo "fresh-check: passed"
