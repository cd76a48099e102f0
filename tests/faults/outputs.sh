#!/usr/bin/env bash
# Output names that cannot work are refused before the first sample (exit 1, a message
# naming the option and the file, nothing rendered), outputs never overwrite each other
# or an input, two renders on one output are refused, and a report that cannot be
# written costs no image.
source "$(dirname "${BASH_SOURCE[0]}")/common.bash"
cd "$tmp" || exit 1

# Refused before rendering: no "kernels" line (the kernel build comes after the checks).
refused() {
    local name=$1 pattern=$2
    shift 2
    if run "$name" 1 "$pattern" -- "$FACET" render "$scene" --width 16 --height 16 --spp 2 "$@"; then
        grep -q '^kernels' "$tmp/log" && bad "$name: rendered before refusing"
    fi
}

mkdir -p "$tmp/dir.exr"
refused out-is-folder "--out .*dir\.exr: is a folder" --out "$tmp/dir.exr"
refused out-ends-with-slash "folder" --out "$tmp/newdir/"
refused out-no-extension "--out .*img: .*no extension" --out "$tmp/img"
refused out-unknown-extension "--out .*a\.xyz: .*\.xyz" --out "$tmp/a.xyz"
refused out-png "--out .*a\.png: .*a\.exr" --out "$tmp/a.png"
refused out-dev-full "--out /dev/full: is not a regular file" --out /dev/full
check dev-full-still-a-device test -c /dev/full
long=$(printf 'n%.0s' $(seq 1 300))
refused out-name-too-long "--out .*more than" --out "$tmp/$long.exr"
printf 'x' >"$tmp/plainfile"
refused out-folder-is-a-file "--out .*plainfile" --out "$tmp/plainfile/a.exr"
refused out-in-proc "--out /proc/facet-fault-test\.exr: cannot write in /proc" --out /proc/facet-fault-test.exr
if [ "$(id -u)" -ne 0 ]; then
    mkdir -p "$tmp/ro" && chmod 555 "$tmp/ro"
    refused out-read-only-folder "--out .*ro/a\.exr: cannot write in .*Permission denied" --out "$tmp/ro/a.exr"
else
    skip "out-read-only-folder (root ignores folder permissions; /proc is checked instead)"
fi
refused report-unwritable "--report .*plainfile/r\.csv" --out "$tmp/ok.exr" --report "$tmp/plainfile/r.csv"

# A name of NAME_MAX bytes: its temporary would be longer; the write still works.
name254=$(printf 'm%.0s' $(seq 1 250))
if run out-name-at-name-max 0 "wrote" -- "$FACET" render "$scene" "${small[@]}" --out "$tmp/$name254.exr"; then
    check name-at-name-max-written readable_image "$tmp/$name254.exr"
fi

# Colliding outputs: refused, and the file already there is kept as it was.
"$FACET" render "$scene" "${small[@]}" --out "$tmp/good.exr" >/dev/null 2>&1
cp "$tmp/good.exr" "$tmp/good.copy"
refused report-is-out "--report .*good\.exr: is the same file as --out" --out "$tmp/good.exr" --report "$tmp/good.exr"
check report-is-out-kept-image cmp -s "$tmp/good.exr" "$tmp/good.copy"
refused report-is-png "--report .*good\.png: is the same file as the PNG beside --out" --out "$tmp/good.exr" \
    --report "$tmp/good.png"
refused report-named-json ".json summary beside --report .*is the same file as --report" --out "$tmp/x.exr" \
    --report "$tmp/r.json"
refused film-is-out "--film .*: is the same file as --out" --out "$tmp/good.exr" --film "$tmp/good.exr"
refused report-is-spelled-differently "is the same file as --out" --out "$tmp/good.exr" --report "$tmp/./sub/../good.exr"
cp "$scene" "$tmp/scene.json"
cp "$SCENES"/cornell_box.obj "$SCENES"/cornell_box.mtl "$tmp/" 2>/dev/null
if run report-overwrites-scene 1 "--report .*scene\.json: would overwrite the scene" -- "$FACET" render \
    "$tmp/scene.json" "${small[@]}" --out "$tmp/y.exr" --report "$tmp/scene.json"; then
    grep -q '^kernels' "$tmp/log" && bad "report-overwrites-scene: rendered before refusing"
fi
refused film-overwrites-reference "would overwrite --reference" --out "$tmp/z.exr" --reference "$tmp/good.exr" \
    --film "$tmp/good.exr"
check colliding-kept-image cmp -s "$tmp/good.exr" "$tmp/good.copy"
check scene-kept cmp -s "$scene" "$tmp/scene.json"

# --out with another float format: written, PNG beside it.
if run out-hdr 0 "wrote" -- "$FACET" render "$scene" "${small[@]}" --out "$tmp/h.hdr"; then
    check out-hdr-files eval 'readable_image "$tmp/h.hdr" && [ -s "$tmp/h.png" ]'
fi

# Two renders on one --out: the second is refused at its start, naming the first (its
# lock file beside the image), and the first finishes with a whole image; the lock file
# goes with it, and a third render then works.
mkdir -p "$tmp/two"
"$FACET" render "$scene" --width 24 --height 24 --spp 100000 --time 3 --snapshot 0.01 \
    --out "$tmp/two/same.exr" --report "$tmp/two/r1.csv" >"$tmp/two/log1" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    grep -q '^kernels' "$tmp/two/log1" 2>/dev/null && break
    sleep 0.1
done
run two-renders-one-out-second-refused 1 "--out .*two/same\.exr: in use by another facet \(process $pid\)" -- \
    "$FACET" render "$scene" "${small[@]}" --out "$tmp/two/same.exr" --report "$tmp/two/r2.csv"
check two-renders-one-out-second-not-rendered eval '! grep -q "^kernels" "$tmp/log"'
s1=0
wait "$pid" || s1=$?
cp "$tmp/two/log1" "$tmp/log"
check two-renders-one-out-first-succeeds [ "$s1" -eq 0 ]
check two-renders-one-out-whole-image readable_image "$tmp/two/same.exr"
check two-renders-one-out-no-temporaries no_temporaries "$tmp/two"
check two-renders-one-out-lock-removed eval '[ -z "$(find "$tmp/two" -name "*.lock")" ]'
run two-renders-one-out-then-free 0 "wrote" -- "$FACET" render "$scene" "${small[@]}" --out "$tmp/two/same.exr" \
    --report "$tmp/two/r3.csv"
# A lock file left by a killed render does not block the next one.
"$FACET" render "$scene" --width 24 --height 24 --spp 1000000 --out "$tmp/two/k.exr" >"$tmp/two/logk" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    grep -q '^kernels' "$tmp/two/logk" 2>/dev/null && break
    sleep 0.1
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null
check killed-render-left-lock-file test -e "$tmp/two/.k.exr.lock"
run killed-render-lock-not-blocking 0 "wrote" -- "$FACET" render "$scene" "${small[@]}" --out "$tmp/two/k.exr"

# The report's folder gone while rendering (replaced by a file): a warning, once per
# file, and the image and PNG are written all the same (exit 0).
mkdir -p "$tmp/rep" "$tmp/img"
"$FACET" render "$scene" --width 24 --height 24 --spp 1000000 --time 2 --out "$tmp/img/x.exr" \
    --report "$tmp/rep/r.csv" >"$tmp/rep.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    grep -q '^kernels' "$tmp/rep.log" 2>/dev/null && break
    sleep 0.1
done
mv "$tmp/rep" "$tmp/rep.gone" && : >"$tmp/rep"
status=0
wait "$pid" || status=$?
cp "$tmp/rep.log" "$tmp/log"
check report-lost-render-succeeds [ "$status" -eq 0 ]
check report-lost-image-written eval 'readable_image "$tmp/img/x.exr" && [ -s "$tmp/img/x.png" ]'
check report-lost-warned grep -q "warning: the report .*rep/r\.csv was not written" "$tmp/log"
check report-lost-warned-once eval '[ "$(grep -c "rep/r\.csv was not written" "$tmp/log")" -eq 1 ]'
check report-lost-svg-warned grep -q "warning: the report .*rep/r\.svg was not written" "$tmp/log"

check no-temporaries-left no_temporaries "$tmp" "$tmp/dir.exr"
finish
