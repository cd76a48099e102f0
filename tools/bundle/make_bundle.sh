#!/usr/bin/env bash
# Builds the lean facet (no OpenImageIO, no MPI: CMake FACET_OIIO=OFF FACET_MPI=OFF) and
# packs it into one folder for a GPU node that has only a vendor OpenCL driver:
#   bin/      facet, facet_tests, facet_bench, facet_film_ztest
#   lib/      the shared libraries they need beyond the C library, and the OpenCL ICD loader
#   scenes/   the demo scenes
#   reference/ PoCL renders of the demo scenes (films), for run.sh's z-test
#   run.sh    everything the node should run, in one go (tools/bundle/run.sh)
#   variants.sh  samples per second under register caps and BVH widths (tools/bundle/variants.sh)
# Usage: tools/bundle/make_bundle.sh OUT_DIR [BUILD_DIR]   (on a machine with the toolchain
# and PoCL; OUT_DIR must stay under 60 MB). Environment: REFERENCE_SPP (default 256);
# BUNDLE_EMBREE=1 links the bench's CPU reference tracer, Embree, as the full build does
# (44 MB of shared libraries with TBB: the bundle then goes over 60 MB; without it the
# bench's trace section says the Embree figures are missing, and measures facet only).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:?usage: make_bundle.sh OUT_DIR [BUILD_DIR]}
build=${2:-$root/build-bundle}
spp=${REFERENCE_SPP:-256}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
embree=(-DCMAKE_DISABLE_FIND_PACKAGE_embree=ON)
[ "${BUNDLE_EMBREE:-0}" = 1 ] && embree=(-DCMAKE_DISABLE_FIND_PACKAGE_embree=OFF)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFACET_OIIO=OFF -DFACET_MPI=OFF "${embree[@]}" \
    "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target facet facet_tests facet_bench facet_film_ztest

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/scenes" "$out/reference"
bins=("$build/facet" "$build/tests/facet_tests" "$build/facet_bench" "$build/facet_film_ztest")
cp "${bins[@]}" "$out/bin/"
strip "$out"/bin/* 2>/dev/null || true
# Shared libraries: all that ldd names, but the C library's own (every node has those,
# and mixing another glibc's loader breaks), plus the ICD loader that dispatches to the
# vendor's OpenCL library.
skip='^(libc|libm|libdl|libpthread|librt|ld-linux-x86-64|linux-vdso|libresolv)\.so'
for b in "${bins[@]}"; do ldd "$b"; done | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }' | sort -u |
    while read -r name path; do
        [[ $name =~ $skip ]] || cp -L "$path" "$out/lib/$name"
    done
loader=$(ldconfig -p | awk '/libOpenCL\.so\.1 / && !found { print $NF; found = 1 }')
[ -n "$loader" ] || { echo "make_bundle: no libOpenCL.so.1 (apt-get install ocl-icd-libopencl1)" >&2; exit 1; }
cp -L "$loader" "$out/lib/libOpenCL.so.1"
strip --strip-unneeded "$out"/lib/* 2>/dev/null || true
cp "$root"/scenes/*.json "$root"/scenes/*.obj "$root"/scenes/*.mtl "$out/scenes/" 2>/dev/null || true
cp "$root/tools/bundle/run.sh" "$root/tools/bundle/variants.sh" "$out/"
chmod +x "$out/run.sh" "$out/variants.sh"

# PoCL references: every demo scene at the size run.sh renders, seed 1 (run.sh uses seed 2).
for s in "$out"/scenes/*.json; do
    name=$(basename "$s" .json)
    POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-$(nproc)} "$out/bin/facet" render "$s" --width 128 --height 96 \
        --spp "$spp" --seed 1 --quiet --out "$out/reference/$name.pfm" --film "$out/reference/$name.film" \
        --report "$out/reference/$name.csv"
    rm -f "$out/reference/$name.json" "$out/reference/$name.svg"
done
size=$(du -sm "$out" | cut -f1)
echo "make_bundle: $out holds $size MB; the largest files:"
du -k "$out"/bin/* "$out"/lib/* | sort -rn | head -8 | awk '{ printf "  %6.1f MB  %s\n", $1 / 1024, $2 }'

[ "$size" -lt 60 ] || { echo "make_bundle: the bundle is $size MB, over 60" >&2; exit 1; }
