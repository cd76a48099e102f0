#!/usr/bin/env bash
# A full disk: facet never says "wrote" for a file it could not write, keeps the good old
# file, leaves no temporary, exits non-zero, and saves the finished image and film
# elsewhere ($TMPDIR) saying where. Two ways: a small full tmpfs (needs mount, i.e.
# root: skipped with a message otherwise) and libfiu injecting ENOSPC into write()
# (fiu-run/fiu-ctrl from Debian's fiu-utils: skipped with a message when absent).
source "$(dirname "${BASH_SOURCE[0]}")/common.bash"
cd "$tmp" || exit 1
mkdir -p "$tmp/rescue" "$tmp/reports"
export TMPDIR="$tmp/rescue"

# --- a tmpfs with 8 KiB left: the checks before rendering pass, the final image does not fit.
disk="$tmp/disk"
mkdir -p "$disk"
if mount -t tmpfs -o size=1M tmpfs "$disk" 2>/dev/null; then
    cleanup_hooks+=("umount '$disk' 2>/dev/null")
    "$FACET" render "$scene" "${small[@]}" --out "$disk/x.exr" --report "$tmp/reports/r0.csv" >/dev/null 2>&1
    cp "$disk/x.exr" "$tmp/x.good"
    dd if=/dev/zero of="$disk/filler" bs=4k >/dev/null 2>&1
    truncate -s -8k "$disk/filler"
    run tmpfs-full-final-write 1 "x\.exr: .*No space left on device" -- \
        "$FACET" render "$scene" --width 64 --height 64 --spp 4 --quiet --out "$disk/x.exr" \
        --report "$tmp/reports/r1.csv"
    check tmpfs-full-no-wrote-claim eval '! grep -q "^wrote" "$tmp/log"'
    check tmpfs-full-no-temporary-named no_temporary_named
    check tmpfs-full-old-image-kept cmp -s "$disk/x.exr" "$tmp/x.good"
    check tmpfs-full-no-temporaries no_temporaries "$disk"
    rescued=$(ls "$tmp/rescue"/facet-rescue-*-x.exr 2>/dev/null | head -1)
    check tmpfs-full-image-rescued eval '[ -n "$rescued" ] && readable_image "$rescued" && grep -qF "$rescued" "$tmp/log"'
    film=$(ls "$tmp/rescue"/facet-rescue-*-x.film 2>/dev/null | head -1)
    check tmpfs-full-film-rescued eval '[ -n "$film" ] && grep -qF -- "--resume $film" "$tmp/log"'
    if [ -n "$film" ]; then
        run tmpfs-full-film-resumes 0 "wrote" -- "$FACET" render "$scene" --width 64 --height 64 --spp 6 --quiet \
            --resume "$film" --out "$tmp/resumed.exr"
    fi

    # Full before the start: refused before rendering, with the reason, old file kept.
    dd if=/dev/zero of="$disk/filler2" bs=4k >/dev/null 2>&1
    run tmpfs-full-at-start 1 "--out .*x\.exr: cannot write in .*No space left on device" -- \
        "$FACET" render "$scene" "${small[@]}" --out "$disk/x.exr" --report "$tmp/reports/r2.csv"
    check tmpfs-full-at-start-not-rendered eval '! grep -q "^kernels" "$tmp/log"'
    check tmpfs-full-at-start-old-image-kept cmp -s "$disk/x.exr" "$tmp/x.good"
    check tmpfs-full-at-start-no-temporaries no_temporaries "$disk"
    # The report on the full disk: refused before rendering, naming it, no temporary.
    run tmpfs-full-report 1 "--report .*r\.csv: cannot write in .*No space left on device" -- \
        "$FACET" render "$scene" --width 64 --height 64 --spp 4 --quiet --out "$tmp/y.exr" --report "$disk/r.csv"
    check tmpfs-full-report-no-temporaries no_temporaries "$disk"
    umount "$disk"
else
    skip "tmpfs cases: mount is not permitted here (needs root)"
fi

# --- libfiu: every write() fails with ENOSPC once the kernel is built. Messages cannot be
# checked (they are written with write() too). The reports fail (a warning: the render
# goes on); the image is written through other calls (OpenEXR's streams) and then
# succeeds, or fails with a non-zero exit and the old image kept; no temporaries.
if command -v fiu-run >/dev/null && command -v fiu-ctrl >/dev/null; then
    mkdir -p "$tmp/fiu"
    "$FACET" render "$scene" "${small[@]}" --out "$tmp/fiu/x.exr" >/dev/null 2>&1
    cp "$tmp/fiu/x.exr" "$tmp/x.fiu.good"
    fiu-run -x "$FACET" render "$scene" --width 32 --height 32 --spp 1000000 --time 4 \
        --out "$tmp/fiu/x.exr" >"$tmp/fiu/log" 2>&1 &
    pid=$!
    for _ in $(seq 1 600); do
        grep -q '^kernels' "$tmp/fiu/log" 2>/dev/null && break
        sleep 0.1
    done
    if fiu-ctrl -c 'enable name=posix/io/rw/write,failinfo=28' "$pid" 2>"$tmp/log"; then
        status=0
        wait "$pid" || status=$?
        check fiu-enospc-image-whole-or-old-kept eval '{ [ "$status" -eq 0 ] && readable_image "$tmp/fiu/x.exr"; } ||
            { [ "$status" -ne 0 ] && cmp -s "$tmp/fiu/x.exr" "$tmp/x.fiu.good"; }'
        check fiu-enospc-no-temporaries no_temporaries "$tmp/fiu"
    else
        wait "$pid"
        skip "libfiu cases: fiu-ctrl cannot reach the process: $(cat "$tmp/log")"
    fi
else
    skip "libfiu cases: fiu-run is not installed (Debian package fiu-utils)"
fi
finish
