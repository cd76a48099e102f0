#!/usr/bin/env bash
# The Oclgrind tier (ctest -L oclgrind; docs/robustness.md): facet's kernels run on
# Oclgrind, an OpenCL device simulator that checks every memory access (out of bounds,
# invalid or unaligned), API errors (--check-api) and data races. A second OpenCL
# implementation also catches what PoCL tolerates and a GPU driver would not.
#   1. each demo scene, 8x8 pixels at 2 spp (and the generic program, the packet paths, on
#      4-wide nodes and on 8-wide ones, where their rays are traced in packets, with BSDFs
#      per lane, and the denoiser once), by the CLI;
#   2. the kernel unit tests that fit (KERNEL_TESTS below) in facet_tests.
# Any message in Oclgrind's log fails the tier. Oclgrind is picked alone through an ICD
# file (OCL_ICD_VENDORS), so no selector is needed. Exit 77 (skipped) without oclgrind.
# Usage: run_oclgrind.sh FACET FACET_TESTS SCENES_DIR
set -u
FACET=$1 TESTS=$2 SCENES=$3

lib=""
for l in /usr/lib/oclgrind/liboclgrind-rt-icd.so /usr/lib/*/oclgrind/liboclgrind-rt-icd.so /usr/local/lib/liboclgrind-rt-icd.so; do
    [ -e "$l" ] && lib=$l && break
done
if [ -z "$lib" ]; then
    echo "oclgrind is not installed (Debian package oclgrind): skipped"
    exit 77
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/icd"
echo "$lib" > "$work/icd/oclgrind.icd"
export OCL_ICD_VENDORS="$work/icd" OCLGRIND_CHECK_API=1 OCLGRIND_DATA_RACES=1 OCLGRIND_LOG="$work/oclgrind.log"
export FACET_CACHE_DIR="$work/cache"
# --uninitialized is left out: Oclgrind 21.10's uninitialised-value plugin stops with
# "Unsupported instruction: freeze" on render_pass (LLVM emits freeze; the plugin
# predates it), and it crashed in the BSDF test kernels.

failed=0
SCENE_LIMIT_S=240
check_log() {   # $1: what ran
    if [ -s "$work/oclgrind.log" ]; then
        echo "FAIL $1: Oclgrind reported:"
        head -c 4000 "$work/oclgrind.log"
        failed=1
    fi
    rm -f "$work/oclgrind.log"
}

run_scene() {   # $1: scene file, then extra options
    local scene=$1
    shift
    local start=$SECONDS
    # Each scene takes seconds; a runaway (garbage masks once made one run for 17 minutes
    # at 20 GB) is cut off and reported rather than eating the tier's whole time limit.
    timeout -k 10 "$SCENE_LIMIT_S" "$FACET" render "$SCENES/$scene" --width 8 --height 8 --spp 2 --out "$work/out.exr" -q "$@" >"$work/render.txt" 2>&1
    local rc=$?
    if [ $rc -ne 0 ]; then
        [ $rc -ge 124 ] && echo "FAIL $scene $*: no result within ${SCENE_LIMIT_S} s (exit status $rc)"
        echo "FAIL $scene $*: facet render failed:"
        tail -c 4000 "$work/render.txt"
        failed=1
    fi
    check_log "$scene $*"
    echo "scene $scene $* ($((SECONDS - start)) s)"
}

for s in cornell_box.json cornell_box.obj furnace_sphere.json glass_metal_sky.json material_grid.json spheres_sky.json; do
    run_scene "$s"
done
run_scene cornell_box.json --generic
# Packet paths (kernels/integrator/packet_paths.cl), forced on: Oclgrind's vectors are 1 wide,
# where facet would not pick them (host/render/packet_paths.hpp).
export FACET_PACKET_PATHS=1
echo "FACET_PACKET_PATHS=1:"
run_scene cornell_box.json
# the environment in packets: met by escaping rays and sampled per lane (a generated sky map)
run_scene cornell_box.json --env sky
# the rays traced in packets (kernels/trace/packet_trace.cl), which needs the 8-wide nodes
# facet builds for CPUs with 8-wide vectors (Oclgrind's device gets 4-wide ones): float and
# quantised boxes
export FACET_BVH_WIDTH=8
run_scene cornell_box.json
FACET_BVH_QUANTISED=1 run_scene cornell_box.json --env sky
# every model, its BSDF per lane (a copy of each lane's material): the area-lit grid of seven
# models, the spheres under the sky, and glass and metals (refraction) under it
run_scene material_grid.json
run_scene spheres_sky.json
run_scene glass_metal_sky.json
unset FACET_BVH_WIDTH FACET_PACKET_PATHS
# The AOV pass and facet's denoiser (padded planes, 8-pixel vector loads and stores)
run_scene cornell_box.json --denoise facet

# The kernel tests that take under a minute each on Oclgrind (measured on a loaded 2-core
# machine): struct layouts, dielectric and model reciprocity, environment lookups,
# microfacet G and sampling. The lights, render and statistical tests took over two
# minutes each; the demo scenes above cover the render kernel.
KERNEL_TESTS='Layout.*:Dielectric.ReciprocityWithEtaSquared:Models.Reciprocity:Environment.RotationAndConvention'
KERNEL_TESTS+=':Microfacet.GeometryMatchesReference:Microfacet.SampleMatchesEvalAndPdf:Lanes.*'
start=$SECONDS
timeout -k 10 600 "$TESTS" --gtest_filter="$KERNEL_TESTS" --gtest_output="xml:$work/tests.xml" >"$work/tests.txt" 2>&1
rc=$?
# Oclgrind 21.10's runtime aborts at process exit ("corrupted double-linked list", in
# static destruction after every test has finished; facet itself exits cleanly), so
# the verdict is the XML report's, not the exit status.
if ! grep -q '<testsuites tests="[1-9][0-9]*" failures="0" disabled="[0-9]*" errors="0"' "$work/tests.xml" 2>/dev/null; then
    echo "FAIL facet_tests on Oclgrind (exit status $rc):"
    tail -c 6000 "$work/tests.txt"
    failed=1
fi
check_log "facet_tests"
echo "facet_tests --gtest_filter=$KERNEL_TESTS ($((SECONDS - start)) s, exit status $rc)"
[ $failed -eq 0 ] && echo "Oclgrind: no invalid access, API error or data race reported"
exit $failed
