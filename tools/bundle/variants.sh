#!/usr/bin/env bash
# The GPU node's second command (tools/bundle): the CLI's samples per second at one size
# under build and BVH variants, for docs/performance.md's GPU section: the default, the
# registers of a work-item capped by NVIDIA's -cl-nv-maxrregcount (FACET_CL_VENDOR_OPTIONS,
# host/cl/runtime.hpp), and the 8-wide BVH. Each line: scene, variant, samples per pixel,
# passes, the kernel seconds and rate, and the wall seconds and rate after the first pass.
#
#   ./variants.sh VENDOR_LIBOPENCL [SIZE [SPP]]    (defaults 1024, 512)
# Environment: SCENES (default "cornell_box material_grid"), CAPS (default "128 96 64").
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${RESULTS:-$here/results}/variants
mkdir -p "$out/vendors"
echo "${1:?usage: variants.sh VENDOR_LIBOPENCL [SIZE [SPP]]}" >"$out/vendors/vendor.icd"
export OCL_ICD_VENDORS="$out/vendors" LD_LIBRARY_PATH="$here/lib:$(dirname "$1")"
size=${2:-1024} spp=${3:-512}
one() { # one SCENE VARIANT [VAR=VALUE...]
    local scene=$1 variant=$2
    shift 2
    env "$@" timeout 120 "$here/bin/facet" render "$here/scenes/$scene.json" --width "$size" --height "$size" \
        --spp "$spp" --seed 3 --out "$out/$scene-$variant.pfm" >"$out/$scene-$variant.log" 2>&1 ||
        { echo "$scene $variant FAILED: $(tail -1 "$out/$scene-$variant.log")"; return; }
    # The report's CSV: the kernel time of all passes, and the wall time from the end of
    # the first pass to the end of the last (the passes and the host's work between them,
    # without start-up: scene load, program build, warm-up).
    awk -v s="$scene" -v v="$variant" -v px="$((size * size))" -F, '
        NR == 2 { spp1 = $2; w1 = $3 } NR > 1 { spp = $2; w = $3; r = $4; p = $1 }
        END { printf "%s %s spp %d passes %d kernel %.3f s: %.1f Msamples/s; after pass 1 %.3f s wall: %.1f Msamples/s\n",
              s, v, spp, p, r, spp * px / r * 1e-6, w - w1, (spp - spp1) * px / (w - w1) * 1e-6 }' \
        "$out/$scene-$variant.csv"
    rm -f "$out/$scene-$variant.pfm" "$out/$scene-$variant.png"
}
for scene in ${SCENES:-cornell_box material_grid}; do
    one "$scene" default
    for cap in ${CAPS:-128 96 64}; do one "$scene" "regs$cap" FACET_CL_VENDOR_OPTIONS="-cl-nv-maxrregcount=$cap"; done
    one "$scene" bvh8 FACET_BVH_WIDTH=8
done
