#!/usr/bin/env bash
# The GPU node's one command (packed by tools/bundle/make_bundle.sh): points an ICD file at
# the vendor's OpenCL library, then runs `facet devices`, the kernel unit tests that need
# no images, the bench's trace, program-build (specialisation) and render (quality)
# sections, and renders of the demo scenes, each compared with the PoCL render packed in
# reference/ by a z-test (facet_film_ztest). Everything goes to results/ beside this
# script (or $RESULTS); the exit status is the number of failed steps.
#
#   ./run.sh [VENDOR_LIBOPENCL]   e.g. /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1
# Without an argument, the system's /etc/OpenCL/vendors is used. Environment: DEVICE
# (--device, default: the first GPU, else CPU), SPP (demo renders, default 256),
# TESTS (gtest filter), BENCH=0 to skip the bench.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
results=${RESULTS:-$here/results}
mkdir -p "$results"
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
if [ $# -ge 1 ]; then
    [ -e "$1" ] || { echo "run.sh: $1: no such OpenCL library" >&2; exit 1; }
    mkdir -p "$results/vendors"
    echo "$1" >"$results/vendors/vendor.icd"
    export OCL_ICD_VENDORS="$results/vendors"
fi
device=(${DEVICE:+--device "$DEVICE"})
failed=0
step() { # step NAME command...: runs it, output to results/NAME.log, and says how it went
    local name=$1 start=$SECONDS
    shift
    if "$@" >"$results/$name.log" 2>&1; then
        echo "ok    $name ($((SECONDS - start)) s)"
    else
        echo "FAIL  $name ($((SECONDS - start)) s): $results/$name.log"
        tail -5 "$results/$name.log" | sed 's/^/      /'
        failed=$((failed + 1))
    fi
}

step devices "$here/bin/facet" devices
cat "$results/devices.log"
# Kernel tests that read no files (the tests' scene and asset folders are not packed).
tests=${TESTS:-'Layout.*:Microfacet.*:Dielectric.*:Models.*:Sampler.*:Lights.*:AreaLight.*:Material.*:DeviceGroup.*:FilmMerge.*:Progressive.*'}
step kernel-tests env ${DEVICE:+FACET_TEST_DEVICE="$DEVICE"} "$here/bin/facet_tests" --gtest_filter="$tests"
if [ "${BENCH:-1}" != 0 ]; then
    for section in trace specialisation quality; do
        step "bench-$section" "$here/bin/facet_bench" "${device[@]}" --quick --only "$section" \
            --json "$results/bench-$section.json"
    done
fi
for ref in "$here"/reference/*.film; do
    name=$(basename "$ref" .film)
    step "render-$name" "$here/bin/facet" render "$here/scenes/$name.json" "${device[@]}" --width 128 --height 96 \
        --spp "${SPP:-256}" --seed 2 --out "$results/$name.pfm" --film "$results/$name.film"
    step "ztest-$name" "$here/bin/facet_film_ztest" "$ref" "$results/$name.film"
    grep -h "Msamples/s\|wrote\|share" "$results/render-$name.log" | tail -2 | sed 's/^/      /'
    sed 's/^/      /' "$results/ztest-$name.log"
done
echo "$failed failed; logs in $results"
exit "$failed"
