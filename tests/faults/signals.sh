#!/usr/bin/env bash
# The render loop under signals and a closed stdout (issue 14): a second Ctrl-C while
# the files are written, SIGPIPE (`facet render ... | head -1`), SIGHUP, a failed
# snapshot, and SIGINT during a long first pass (every launch is bounded). Each case
# asserts the exit status, the files on disk, no temporaries left and the message.
# Needs FACET (the binary) and SCENES (the scenes folder).
set -u
: "${FACET:?}" "${SCENES:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene="$SCENES/cornell_box.json"
passed=0
failed=0

ok() { passed=$((passed + 1)); echo "PASS $1"; }
bad() {
    failed=$((failed + 1))
    echo "FAIL $1"
    [ -f "$tmp/log" ] && sed 's/^/    /' "$tmp/log"
}
# Waits up to $2 seconds for pattern $1 in the log; false if it never came.
wait_for() {
    local i
    for i in $(seq 1 $(($2 * 10))); do
        grep -qE -- "$1" "$tmp/log" && return 0
        kill -0 "$pid" 2>/dev/null || { grep -qE -- "$1" "$tmp/log"; return; }
        sleep 0.1
    done
    return 1
}
no_temporaries() { [ -z "$(find "$tmp" -name '.tmp-*' -print -quit)" ]; }
now() { date +%s.%N; }

# SIGHUP (the terminal closed) finishes like SIGTERM: the image so far is written, exit 130.
"$FACET" render "$scene" --width 64 --height 64 --spp 1000000 --out "$tmp/hup.exr" >"$tmp/log" 2>&1 &
pid=$!
wait_for "^pass" 120
kill -HUP "$pid"
wait "$pid"
status=$?
if [ "$status" -eq 130 ] && [ -s "$tmp/hup.exr" ] && [ -s "$tmp/hup.png" ] && grep -q '"interrupted": true' "$tmp/hup.json" \
    && grep -q "interrupted; wrote" "$tmp/log" && no_temporaries; then
    ok "sighup-finishes-like-sigterm"
else bad "sighup-finishes-like-sigterm (exit $status)"; fi

# A closed stdout: `facet render ... | head -1` renders on and writes its files, exit 0.
"$FACET" render "$scene" --width 64 --height 64 --spp 1000000 --time 1.5 --out "$tmp/pipe.exr" 2>"$tmp/log" \
    | head -n 1 >"$tmp/head"
status=${PIPESTATUS[0]}
if [ "$status" -eq 0 ] && [ -s "$tmp/pipe.exr" ] && [ -s "$tmp/pipe.png" ] && [ -s "$tmp/pipe.json" ] \
    && [ "$(wc -l <"$tmp/head")" -eq 1 ] && no_temporaries; then
    ok "closed-stdout-render-goes-on"
else bad "closed-stdout-render-goes-on (exit $status)"; fi

# Ctrl-C, then Ctrl-C again and again while the files are written: every file complete,
# the terminal told that facet is writing, exit 130.
"$FACET" render "$scene" --width 768 --height 768 --spp 1000000 --out "$tmp/twice.exr" >"$tmp/log" 2>&1 &
pid=$!
wait_for "^pass" 120
kill -INT "$pid"
while kill -INT "$pid" 2>/dev/null; do sleep 0.05; done
wait "$pid"
status=$?
if [ "$status" -eq 130 ] && grep -q "writing the .* spp finished so far" "$tmp/log" \
    && "$FACET" compare "$tmp/twice.exr" "$tmp/twice.exr" >/dev/null 2>&1 && [ -s "$tmp/twice.png" ] \
    && grep -q '"interrupted": true' "$tmp/twice.json" && [ -s "$tmp/twice.svg" ] && no_temporaries; then
    ok "second-ctrl-c-while-writing"
else bad "second-ctrl-c-while-writing (exit $status)"; fi

# A failed snapshot is a warning; the render goes on and the final image is written.
# The PNG's place is taken by a folder once the render has started, and freed again.
"$FACET" render "$scene" --width 96 --height 96 --spp 1000000 --snapshot 0.001 --out "$tmp/snap.exr" >"$tmp/log" 2>&1 &
pid=$!
wait_for "^kernels" 120
for _ in $(seq 1 100); do   # a snapshot may put its PNG there first
    rm -f "$tmp/snap.png"
    mkdir -p "$tmp/snap.png/in-the-way" 2>/dev/null && break
done
wait_for "snapshot not written" 60
got_warning=$?
rm -rf "$tmp/snap.png"
sleep 0.5
kill -INT "$pid" 2>/dev/null
wait "$pid"
status=$?
if [ "$got_warning" -eq 0 ] && [ "$status" -eq 130 ] && [ -f "$tmp/snap.png" ] && [ -s "$tmp/snap.exr" ] \
    && grep -q "rendering goes on" "$tmp/log" && no_temporaries; then
    ok "failed-snapshot-is-a-warning"
else bad "failed-snapshot-is-a-warning (exit $status)"; fi

# SIGINT during a long first pass (seconds at this size on a CPU) takes effect within
# a launch or two, not at the pass's end: nothing finished, nothing written, exit 130.
"$FACET" render "$scene" --width 2048 --height 2048 --spp 4 --out "$tmp/big.exr" >"$tmp/log" 2>&1 &
pid=$!
wait_for "^kernels" 120
sleep 0.5
t0=$(now)
kill -INT "$pid"
wait "$pid"
status=$?
took=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }')
if [ "$status" -eq 130 ] && awk -v t="$took" 'BEGIN { exit !(t < 4) }' && [ ! -e "$tmp/big.exr" ] \
    && grep -q "before the first pass finished; nothing written" "$tmp/log" && no_temporaries; then
    ok "sigint-in-first-pass-ends-soon (${took}s)"
else bad "sigint-in-first-pass-ends-soon (exit $status after ${took}s)"; fi

# --time shorter than one sample per pixel: told so after the probe launch, one pass, exit 0.
"$FACET" render "$scene" --width 1024 --height 1024 --spp 1000 --time 0.2 --out "$tmp/short.exr" >"$tmp/log" 2>&1 &
pid=$!
wait "$pid"
status=$?
spp=$(tail -n 1 "$tmp/short.csv" 2>/dev/null | cut -d, -f2)
if [ "$status" -eq 0 ] && [ "$spp" = "1" ] && grep -q "one sample per pixel takes about" "$tmp/log" \
    && [ -s "$tmp/short.exr" ] && no_temporaries; then
    ok "time-limit-below-one-pass ($spp spp)"
else bad "time-limit-below-one-pass (exit $status, $spp spp)"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
