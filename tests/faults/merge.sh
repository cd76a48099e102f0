#!/usr/bin/env bash
# A farm's tasks (--samples-from K) merged with `facet merge` give the image of one render
# of all the samples; two devices in one process (--device 0,0: two contexts on the one
# CI device) give it too; overlapping ranges and other settings are refused.
source "$(dirname "${BASH_SOURCE[0]}")/common.bash"
cd "$tmp" || exit 1
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-1}
opts=(--width 24 --height 24 --seed 7 --quiet)

# rmse_below IMAGE REFERENCE LIMIT
rmse_below() {
    local r
    r=$("$FACET" compare "$1" "$2" 2>/dev/null | awk '$1 == "rmse" { print $2 }')
    [ -n "$r" ] && awk -v r="$r" -v l="$3" 'BEGIN { exit !(r + 0 <= l + 0) }' || { echo "    rmse $r"; return 1; }
}

run whole 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 12 --out "$tmp/whole.exr" --film "$tmp/whole.film"
run task-a 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 5 --out "$tmp/a.exr" --film "$tmp/a.film"
run task-b 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 4 --samples-from 5 --out "$tmp/b.exr" \
    --film "$tmp/b.film"
run task-c 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 3 --samples-from 9 --out "$tmp/c.exr" \
    --film "$tmp/c.film"
check task-film-holds-its-range grep -aq '"samples": \[\s*\[\s*5,\s*9\s*\]\s*\]' <(tr -d '\n' <"$tmp/b.film")
run merge 0 "merged   3 films: 12 spp \(samples 0-11\)" -- "$FACET" merge "$tmp/c.film" "$tmp/a.film" "$tmp/b.film" \
    --out "$tmp/merged.exr" --film "$tmp/merged.film"
check merge-equals-whole rmse_below "$tmp/merged.exr" "$tmp/whole.exr" 1e-5
check merge-png-written test -s "$tmp/merged.png"
check part-differs eval '! rmse_below "$tmp/b.exr" "$tmp/whole.exr" 1e-5 >/dev/null'
# The merged film resumes like any other.
run merged-resumes 0 "wrote .*16 spp" -- "$FACET" render "$scene" "${opts[@]}" --spp 16 --resume "$tmp/merged.film" \
    --out "$tmp/resumed.exr"
run samples-from-inside-film 1 "would repeat" -- "$FACET" render "$scene" "${opts[@]}" --spp 16 --samples-from 3 \
    --resume "$tmp/merged.film" --out "$tmp/no.exr"

# Refused: overlapping ranges, other settings, a corrupt film.
run refuse-overlap 1 "a\.film and .*whole\.film both hold sample 0" -- "$FACET" merge "$tmp/a.film" "$tmp/whole.film" \
    --out "$tmp/no.exr"
run other-seed 0 "wrote" -- "$FACET" render "$scene" --width 24 --height 24 --seed 8 --quiet --spp 2 --samples-from 20 \
    --out "$tmp/s.exr" --film "$tmp/s.film"
run refuse-other-seed 1 "s\.film has seed 8, .*a\.film has 7" -- "$FACET" merge "$tmp/a.film" "$tmp/s.film" \
    --out "$tmp/no.exr"
head -c 300 "$tmp/a.film" >"$tmp/cut.film"
run refuse-truncated 1 "cut\.film: .*truncated" -- "$FACET" merge "$tmp/cut.film" "$tmp/b.film" --out "$tmp/no.exr"
check refused-wrote-nothing test ! -e "$tmp/no.exr"
# An output naming an input film, by another spelling too, or another output: refused, the film kept.
cp "$tmp/a.film" "$tmp/a.keep"
run refuse-film-is-input 1 "--film .*/\./a\.film: would overwrite the input film" -- "$FACET" merge "$tmp/a.film" \
    "$tmp/b.film" --out "$tmp/m.exr" --film "$tmp/./a.film"
ln "$tmp/b.film" "$tmp/b-link.film"
run refuse-film-is-hard-link 1 "would overwrite the input film" -- "$FACET" merge "$tmp/a.film" "$tmp/b.film" \
    --out "$tmp/m.exr" --film "$tmp/b-link.film"
run refuse-film-is-png 1 "--film .*m\.png: is the same file as the PNG beside --out" -- "$FACET" merge \
    "$tmp/a.film" "$tmp/b.film" --out "$tmp/m.exr" --film "$tmp/m.png"
check input-film-kept cmp -s "$tmp/a.film" "$tmp/a.keep"
check refused-merges-wrote-nothing test ! -e "$tmp/m.exr"

# Two devices in one process: the same image, and each device's speed in the summary.
run two-devices 0 "share    \[0\].*Msamples/s" -- "$FACET" render "$scene" --width 24 --height 24 --seed 7 --spp 12 \
    --device 0,0 --out "$tmp/two.exr"
check two-devices-equal-whole rmse_below "$tmp/two.exr" "$tmp/whole.exr" 1e-5
run device-all 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 2 --device all --out "$tmp/all.exr"
run device-list-bad 1 "no device with that index" -- "$FACET" render "$scene" "${opts[@]}" --device 0,99 \
    --out "$tmp/no2.exr"
finish
