#!/usr/bin/env bash
# The GPU node's one command (packed by tools/bundle/make_bundle.sh): points an ICD file at
# the vendor's OpenCL library, then runs, in this order, `facet devices`; renders of the
# demo scenes, each compared with the PoCL render packed in reference/ by a z-test
# (facet_film_ztest); the samples per second of the CLI's renders at 512² and 1024²; the
# bench's kernel resources (registers, private memory); the kernel unit tests that need no
# images; the bench's trace, render (quality), program-build (specialisation) and packet
# sections. Everything goes to results/ beside this
# script (or $RESULTS); the exit status is the number of failed steps.
#
#   ./run.sh [VENDOR_LIBOPENCL]   e.g. /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1
# Without an argument, the system's /etc/OpenCL/vendors is used when it names a library, else
# the first NVIDIA, AMD or Intel OpenCL library found under the usual folders. Environment:
# DEVICE (--device, default: the first GPU, else CPU), SPP (demo renders, default 256),
# TESTS (gtest filter), BENCH=0 to skip the bench, THROUGHPUT=0 to skip the samples-per-second
# renders, STEP_TIMEOUT (seconds a step may run, default 600), DEADLINE (seconds after which
# the steps left are skipped, each counted as failed; default none): a lease of fixed length
# still brings back every finished step's log.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
results=${RESULTS:-$here/results}
mkdir -p "$results"
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
vendor=${1:-}
if [ -z "$vendor" ] && ! cat /etc/OpenCL/vendors/*.icd >/dev/null 2>&1; then
    for dir in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu /usr/lib64 /usr/lib \
        /opt/rocm/lib /usr/local/cuda/lib64 /usr/local/cuda/targets/x86_64-linux/lib; do
        for lib in libnvidia-opencl.so.1 libamdocl64.so libigdrcl.so; do
            [ -e "$dir/$lib" ] && [ -z "$vendor" ] && vendor=$dir/$lib
        done
    done
    [ -n "$vendor" ] || echo "run.sh: no /etc/OpenCL/vendors and no vendor OpenCL library found" >&2
fi
if [ -n "$vendor" ]; then
    [ -e "$vendor" ] || { echo "run.sh: $vendor: no such OpenCL library" >&2; exit 1; }
    echo "run.sh: OpenCL library $vendor"
    mkdir -p "$results/vendors"
    echo "$vendor" >"$results/vendors/vendor.icd"
    export OCL_ICD_VENDORS="$results/vendors"
    # The vendor's library loads its driver (libcuda.so.1 beside libnvidia-opencl) by name.
    export LD_LIBRARY_PATH="$LD_LIBRARY_PATH:$(dirname "$vendor")"
fi
device=(${DEVICE:+--device "$DEVICE"})
failed=0
step() { # step NAME command...: runs it, output to results/NAME.log, and says how it went
    local name=$1 start=$SECONDS
    shift
    if [ -n "${DEADLINE:-}" ] && [ "$SECONDS" -ge "$DEADLINE" ]; then
        echo "SKIP  $name (past the deadline, ${DEADLINE} s)"
        failed=$((failed + 1))
        return
    fi
    if timeout "${STEP_TIMEOUT:-600}" "$@" >"$results/$name.log" 2>&1; then
        echo "ok    $name ($((SECONDS - start)) s)"
    else
        echo "FAIL  $name ($((SECONDS - start)) s): $results/$name.log"
        tail -5 "$results/$name.log" | sed 's/^/      /'
        failed=$((failed + 1))
    fi
}

step devices "$here/bin/facet" devices
cat "$results/devices.log"
for ref in "$here"/reference/*.film; do
    name=$(basename "$ref" .film)
    step "render-$name" "$here/bin/facet" render "$here/scenes/$name.json" "${device[@]}" --width 128 --height 96 \
        --spp "${SPP:-256}" --seed 2 --out "$results/$name.pfm" --film "$results/$name.film"
    step "ztest-$name" "$here/bin/facet_film_ztest" "$ref" "$results/$name.film"
    grep -h "Msamples/s\|wrote\|share" "$results/render-$name.log" | tail -2 | sed 's/^/      /'
    sed 's/^/      /' "$results/ztest-$name.log"
done
# Samples per second of the CLI's own progressive render at sizes that fill a GPU: the
# four demo scenes at SPEED_SIZES (default 512² and 1024²), SPEED_SPP samples per pixel
# (default 256) or SPEED_TIME seconds (default 30), whichever ends first; the log's last
# progress line gives the rate.
if [ "${THROUGHPUT:-1}" != 0 ]; then
    for size in ${SPEED_SIZES:-512 1024}; do
        for name in cornell_box spheres_sky material_grid glass_metal_sky; do
            step "speed-$name-$size" "$here/bin/facet" render "$here/scenes/$name.json" "${device[@]}" --width "$size" \
                --height "$size" --spp "${SPEED_SPP:-256}" --time "${SPEED_TIME:-30}" --seed 3 --out "$results/speed-$name-$size.pfm"
            for pattern in '^kernels' 'Msamples/s'; do
                tr '\r' '\n' <"$results/speed-$name-$size.log" | grep -h "$pattern" | tail -1 | sed 's/^/      /'
            done
        done
    done
    rm -f "$results"/speed-*.pfm "$results"/speed-*.png "$results"/speed-*.film
fi
bench() { # bench SECTION...: facet_bench's sections, quick
    [ "${BENCH:-1}" != 0 ] || return 0
    for section in "$@"; do
        step "bench-$section" "$here/bin/facet_bench" "${device[@]}" --quick --only "$section" \
            --json "$results/bench-$section.json"
    done
}
# Each program's registers, private memory and spills on this device (issue 29).
bench kernels
# Kernel tests that read no files (the tests' scene and asset folders are not packed).
tests=${TESTS:-'Layout.*:Microfacet.*:Dielectric.*:Models.*:Sampler.*:Lights.*:AreaLight.*:Material.*:DeviceGroup.*:FilmMerge.*:Progressive.*'}
step kernel-tests env ${DEVICE:+FACET_TEST_DEVICE="$DEVICE"} "$here/bin/facet_tests" --gtest_filter="$tests"
bench trace quality specialisation packet
echo "$failed failed; logs in $results"
exit "$failed"
