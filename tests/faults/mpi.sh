#!/usr/bin/env bash
# MPI ranks on one image: `mpirun -n 2` (two ranks on this machine, one PoCL thread each)
# gives the image of one process rendering the same samples, as do two devices in one
# process and two ranks of two devices each (determinism up to float summation order);
# --resume and --film work on rank 0; a rank killed mid-render (kill -9) loses only the
# pass in progress: rank 0 writes the film and image of the samples every rank finished,
# names the dead rank and the missing samples, and exits non-zero; those samples rendered
# with --samples-from and merged give the image of one uninterrupted render. Ranks given
# another scene or size are refused before the first sample. A rank without an OpenCL
# platform says so and ends the job. Skipped without mpirun or a facet built
# without MPI.
source "$(dirname "${BASH_SOURCE[0]}")/common.bash"
cd "$tmp" || exit 1
export POCL_MAX_PTHREAD_COUNT=1
# Open MPI refuses root unless told (CI containers run as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
opts=(--width 24 --height 24 --seed 7 --spp 12)

rmse_below() {
    local r
    r=$("$FACET" compare "$1" "$2" 2>/dev/null | awk '$1 == "rmse" { print $2 }')
    [ -n "$r" ] && awk -v r="$r" -v l="$3" 'BEGIN { exit !(r + 0 <= l + 0) }' || { echo "    rmse $r"; return 1; }
}

if ! command -v mpirun >/dev/null; then
    skip "mpi (no mpirun: apt-get install openmpi-bin)"
    finish
    exit
fi
mpi=(timeout 240 mpirun -n 2 --oversubscribe)
run one-process 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --quiet --out "$tmp/one.exr"
run two-ranks 0 "rank     1: .*% of the samples" -- "${mpi[@]}" "$FACET" render "$scene" "${opts[@]}" \
    --out "$tmp/ranks.exr" --film "$tmp/ranks.film"
if ! grep -q "rank     1" "$tmp/log"; then
    skip "mpi (facet built without MPI: -DFACET_MPI=ON with libopenmpi-dev)"
    finish
    exit
fi
check two-ranks-equal-one-process rmse_below "$tmp/ranks.exr" "$tmp/one.exr" 1e-5
check film-of-the-whole-job grep -aq '"spp": 12,' "$tmp/ranks.film"
check one-report test -s "$tmp/ranks.csv"
run two-devices 0 "wrote" -- "$FACET" render "$scene" "${opts[@]}" --quiet --device 0,0 --out "$tmp/devices.exr"
check two-devices-equal-one-process rmse_below "$tmp/devices.exr" "$tmp/one.exr" 1e-5
run two-ranks-two-devices 0 "wrote" -- "${mpi[@]}" "$FACET" render "$scene" "${opts[@]}" --quiet --device 0,0 \
    --out "$tmp/both.exr"
check ranks-and-devices-equal-one-process rmse_below "$tmp/both.exr" "$tmp/one.exr" 1e-5
# Resumed by two ranks: samples 12..19, the image of one process rendering 20.
run one-process-20 0 "wrote" -- "$FACET" render "$scene" --width 24 --height 24 --seed 7 --spp 20 --quiet \
    --out "$tmp/one20.exr"
run ranks-resume 0 "wrote .*20 spp" -- "${mpi[@]}" "$FACET" render "$scene" --width 24 --height 24 --seed 7 --spp 20 \
    --quiet --resume "$tmp/ranks.film" --out "$tmp/resumed.exr"
check ranks-resume-equals-one-process rmse_below "$tmp/resumed.exr" "$tmp/one20.exr" 1e-5
# Ctrl-C on mpirun: rank 0 ends the pass and writes the whole job's samples, the film too.
mpirun -n 2 --oversubscribe "$FACET" render "$scene" --width 24 --height 24 --spp 1000000 --out "$tmp/int/i.exr" \
    >"$tmp/int.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    [ -s "$tmp/int/i.csv" ] && break
    sleep 0.1
done
kill -INT "$pid"
wait "$pid"
cp "$tmp/int.log" "$tmp/log"
check interrupt-writes-image readable_image "$tmp/int/i.exr"
check interrupt-writes-film eval 'test -s "$tmp/int/i.film" && grep -q "interrupted; wrote the" "$tmp/log"'

# kill -9 of rank 1 in mid-render (Open MPI then ends the job: SIGTERM, SIGKILL 1 s later).
rank_pid() { # MPIRUN_PID RANK: the pid of that rank's process
    local p
    for p in $(pgrep -P "$1"); do
        tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2" && echo "$p" && return
    done
}
mpirun -n 2 --oversubscribe "$FACET" render "$scene" --width 24 --height 24 --seed 7 --spp 1000000 \
    --out "$tmp/dead/d.exr" >"$tmp/dead.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    [ -s "$tmp/dead/d.csv" ] && break
    sleep 0.1
done
sleep 0.5
victim=$(rank_pid "$pid" 1)
[ -n "$victim" ] && kill -9 "$victim"
wait "$pid"
status=$?
cp "$tmp/dead.log" "$tmp/log"
check dead-rank-exit-non-zero test "$status" -ne 0
check dead-rank-named grep -qE "waits for MPI rank 1( in the films' reduction)?: that rank died" "$tmp/log"
check dead-rank-image-written readable_image "$tmp/dead/d.exr"
held=$(sed -n 's/.*holds samples 0-\([0-9]*\) (.*/\1/p' "$tmp/log")
held=$((${held:-0} + 1))
check dead-rank-film-records-samples eval \
    '[ "$held" -gt 1 ] && tr -d " \n" <"$tmp/dead/d.film" | grep -aq "\"samples\":\[\[0,$held\]\]"'
check dead-rank-missing-named grep -q "missing: $((1000000 - held)) spp, samples $held-999999" "$tmp/log"
# The film reads back whole, and the missing samples (here 6 of them) merged with it give
# the image of one process rendering them all.
run dead-rank-rest 0 "wrote" -- "$FACET" render "$scene" --width 24 --height 24 --seed 7 --quiet \
    --samples-from "$held" --spp 6 --out "$tmp/rest.exr" --film "$tmp/rest.film"
run dead-rank-merge 0 "merged   2 films: $((held + 6)) spp" -- "$FACET" merge "$tmp/dead/d.film" "$tmp/rest.film" \
    --out "$tmp/merged.exr"
run dead-rank-whole 0 "wrote" -- "$FACET" render "$scene" --width 24 --height 24 --seed 7 --quiet \
    --spp "$((held + 6))" --out "$tmp/whole.exr"
check dead-rank-merge-equals-whole rmse_below "$tmp/merged.exr" "$tmp/whole.exr" 1e-5

# Ranks given different scenes or sizes: refused before the first sample, naming the rank,
# and no image of two scenes is written.
mix=(--width 24 --seed 7 --spp 4 --quiet --out "$tmp/mix.exr")
run ranks-other-scene 1 "MPI rank 1 renders another scene \(identity [0-9a-f]{16}, rank 0 has [0-9a-f]{16}\)" -- \
    timeout 120 mpirun -n 1 "$FACET" render "$scene" --height 24 "${mix[@]}" : \
    -n 1 "$FACET" render "$SCENES/furnace_sphere.json" --height 24 "${mix[@]}"
run ranks-other-size 1 "MPI rank 1 renders a 24x16 image, rank 0 a 24x24 one" -- \
    timeout 120 mpirun -n 1 "$FACET" render "$scene" --height 24 "${mix[@]}" : \
    -n 1 "$FACET" render "$scene" --height 16 "${mix[@]}"
check ranks-of-other-scenes-write-nothing test ! -e "$tmp/mix.exr"

# A rank with no OpenCL platform: its message names it, and the job ends (no hang).
mkdir -p "$tmp/no-icd"
run rank-without-device 1 "MPI rank 1 of 2 on .*: .*clGetPlatformIDs" -- timeout 120 mpirun -n 1 --oversubscribe \
    "$FACET" render "$scene" "${opts[@]}" --out "$tmp/nodev.exr" : -n 1 env OCL_ICD_VENDORS="$tmp/no-icd" \
    "$FACET" render "$scene" "${opts[@]}" --out "$tmp/nodev.exr"
finish
