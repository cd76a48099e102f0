#!/usr/bin/env bash
# The film: saved with --film, on interrupt, and on failure; --resume continues it with
# new sample indices so that N/2 + N/2 samples equal one render of N (up to float
# summation); a film of another scene or settings, or a corrupt one, is refused.
source "$(dirname "${BASH_SOURCE[0]}")/common.bash"
cd "$tmp" || exit 1
opts=(--width 24 --height 24 --seed 7 --quiet)

# rmse_below IMAGE REFERENCE LIMIT
rmse_below() {
    local r
    r=$("$FACET" compare "$1" "$2" 2>/dev/null | awk '$1 == "rmse" { print $2 }')
    [ -n "$r" ] && awk -v r="$r" -v l="$3" 'BEGIN { exit !(r + 0 <= l + 0) }' || { echo "    rmse $r"; return 1; }
}

run whole-with-film 0 "film .*whole\.film" -- "$FACET" render "$scene" "${opts[@]}" --spp 8 --out "$tmp/whole.exr" \
    --film "$tmp/whole.film"
check film-written test -s "$tmp/whole.film"
run half 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 4 --out "$tmp/half.exr" --film "$tmp/half.film"
cp "$tmp/half.film" "$tmp/half.copy"
run resume-to-8 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 8 --resume "$tmp/half.film" \
    --out "$tmp/resumed.exr" --film "$tmp/resumed.film"
check resume-equals-whole rmse_below "$tmp/resumed.exr" "$tmp/whole.exr" 1e-5
check resume-differs-from-half eval '! rmse_below "$tmp/half.exr" "$tmp/whole.exr" 1e-5 >/dev/null'
check resumed-film-holds-8-spp grep -aq '"spp": 8,' "$tmp/resumed.film"
check resume-input-untouched cmp -s "$tmp/half.film" "$tmp/half.copy"
# Resuming a film in place (--film the same file) is allowed and updates it.
run resume-in-place 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --spp 8 --resume "$tmp/half.film" \
    --film "$tmp/half.film" --out "$tmp/inplace.exr"
check resume-in-place-updated eval '! cmp -s "$tmp/half.film" "$tmp/half.copy"'
check resume-in-place-equals-whole rmse_below "$tmp/inplace.exr" "$tmp/whole.exr" 1e-5
# A film that already has the samples asked for: written as is, nothing rendered.
run resume-already-done 0 "wrote .*8 spp" -- "$FACET" render "$scene" "${opts[@]}" --spp 8 \
    --resume "$tmp/whole.film" --out "$tmp/again.exr"
check resume-already-done-same rmse_below "$tmp/again.exr" "$tmp/whole.exr" 0

# Refused: other settings, another scene, a corrupt or foreign file.
run refuse-other-size 1 "half\.copy: the film was rendered with a size of 24x24, this render has 32x24" -- \
    "$FACET" render "$scene" --width 32 --height 24 --seed 7 --quiet --spp 8 --resume "$tmp/half.copy" --out "$tmp/no.exr"
run refuse-other-seed 1 "half\.copy: .*--seed 7, this render has 8" -- \
    "$FACET" render "$scene" --width 24 --height 24 --seed 8 --quiet --spp 8 --resume "$tmp/half.copy" --out "$tmp/no.exr"
run refuse-other-depth 1 "--max-depth" -- \
    "$FACET" render "$scene" "${opts[@]}" --max-depth 2 --spp 8 --resume "$tmp/half.copy" --out "$tmp/no.exr"
other=$(ls "$SCENES"/*.json | grep -v cornell_box | head -1)
run refuse-other-scene 1 "another scene" -- \
    "$FACET" render "$other" "${opts[@]}" --spp 8 --resume "$tmp/half.copy" --out "$tmp/no.exr"
head -c 300 "$tmp/half.copy" >"$tmp/cut.film"
run refuse-truncated 1 "cut\.film: .*truncated" -- \
    "$FACET" render "$scene" "${opts[@]}" --spp 8 --resume "$tmp/cut.film" --out "$tmp/no.exr"
run refuse-not-a-film 1 "whole\.exr: not a facet film" -- \
    "$FACET" render "$scene" "${opts[@]}" --spp 8 --resume "$tmp/whole.exr" --out "$tmp/no.exr"
check refused-wrote-nothing test ! -e "$tmp/no.exr"

# Interrupted: the film goes beside --out, and the message says how to continue.
"$FACET" render "$scene" "${opts[@]}" --spp 1000000 --out "$tmp/int/i.exr" >"$tmp/int.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    [ -s "$tmp/int/i.csv" ] && break
    sleep 0.1
done
kill -INT "$pid"
status=0
wait "$pid" || status=$?
cp "$tmp/int.log" "$tmp/log"
check interrupt-exit-130 [ "$status" -eq 130 ]
check interrupt-film-beside-out eval 'test -s "$tmp/int/i.film" && grep -qF -- "--resume $tmp/int/i.film" "$tmp/log"'
spp=$(grep -oE 'film \(([0-9]+) spp\)' "$tmp/log" | grep -oE '[0-9]+' | head -1)
if [ -n "$spp" ]; then
    run interrupt-resumes 0 "wrote .*\($((spp + 2)) spp" -- "$FACET" render "$scene" "${opts[@]}" --spp $((spp + 2)) \
        --resume "$tmp/int/i.film" --out "$tmp/int/i.exr"
fi

# The implicit film never replaces an older one: a second interrupted render to the same
# --out saves its film under a new name (i-2.film), says so, and the first film is kept.
cp "$tmp/int/i.film" "$tmp/int/i.keep"
"$FACET" render "$scene" "${opts[@]}" --spp 1000000 --out "$tmp/int/i.exr" --report "$tmp/int/i2.csv" \
    >"$tmp/int2.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    [ -s "$tmp/int/i2.csv" ] && break
    sleep 0.1
done
kill -INT "$pid"
wait "$pid"
cp "$tmp/int2.log" "$tmp/log"
check implicit-film-older-kept cmp -s "$tmp/int/i.film" "$tmp/int/i.keep"
check implicit-film-new-name eval 'test -s "$tmp/int/i-2.film" && grep -qF -- "--resume $tmp/int/i-2.film" "$tmp/log"'

# Two renders resuming one film in place: the second is refused at its start (the first
# holds the film's lock), so neither's samples are lost.
cp "$tmp/whole.film" "$tmp/shared.film"
"$FACET" render "$scene" --width 24 --height 24 --seed 7 --spp 1000000 --time 3 --resume "$tmp/shared.film" \
    --film "$tmp/shared.film" --out "$tmp/s1.exr" >"$tmp/s1.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    grep -q '^kernels' "$tmp/s1.log" 2>/dev/null && break
    sleep 0.1
done
run concurrent-resume-refused 1 "--film .*shared\.film: in use by another facet" -- "$FACET" render "$scene" \
    "${opts[@]}" --spp 1000 --resume "$tmp/shared.film" --film "$tmp/shared.film" --out "$tmp/s2.exr"
status=0
wait "$pid" || status=$?
check concurrent-resume-first-succeeds [ "$status" -eq 0 ]
spp=$(grep -aoE '"spp": [0-9]+' "$tmp/shared.film" | grep -oE '[0-9]+')
s1=$(grep -oE 'wrote .*\(([0-9]+) spp' "$tmp/s1.log" | grep -oE '[0-9]+ spp' | grep -oE '[0-9]+')
check concurrent-resume-film-holds-first [ -n "$spp" ] && [ "$spp" = "$s1" ]

check no-temporaries-left no_temporaries "$tmp" "$tmp/int"
finish
