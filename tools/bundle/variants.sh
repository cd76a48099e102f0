#!/usr/bin/env bash
# The GPU node's second command (tools/bundle): the CLI's samples per second at one size
# under build and BVH variants, for docs/performance.md's GPU section: the default, the
# registers of a work-item capped by NVIDIA's -cl-nv-maxrregcount (FACET_CL_VENDOR_OPTIONS,
# host/cl/runtime.hpp), and the 8-wide BVH. Each run prints: scene, variant, samples per
# pixel, passes, the kernel seconds and rate, and the wall seconds and rate after the first
# pass. REPEATS rounds run every variant of a scene once each, the order rotated from round
# to round (a drifting clock or temperature then falls on every variant alike); the last
# table gives each variant's median kernel rate and its ratio to the default's. With
# ZTEST=1 each variant also renders the scene at the size of reference/ (128×96, 256 spp,
# seed 2) and compares it with PoCL's film (facet_film_ztest): a register cap must not
# change the image.
#
#   ./variants.sh VENDOR_LIBOPENCL [SIZE [SPP]]    (defaults 1024, 512)
# Environment: SCENES (default "cornell_box material_grid"), CAPS (default "128 96 64"),
# REPEATS (default 1), ZTEST (default 0).
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${RESULTS:-$here/results}/variants
mkdir -p "$out/vendors"
echo "${1:?usage: variants.sh VENDOR_LIBOPENCL [SIZE [SPP]]}" >"$out/vendors/vendor.icd"
export OCL_ICD_VENDORS="$out/vendors" LD_LIBRARY_PATH="$here/lib:$(dirname "$1")"
size=${2:-1024} spp=${3:-512}
rates=$out/rates.txt
: >"$rates"
# Each variant: its name and the environment it runs under.
variants=("default FACET_VARIANT=default")
for cap in ${CAPS:-128 96 64}; do variants+=("regs$cap FACET_CL_VENDOR_OPTIONS=-cl-nv-maxrregcount=$cap"); done
variants+=("bvh8 FACET_BVH_WIDTH=8")

one() { # one SCENE ROUND VARIANT VAR=VALUE
    local scene=$1 round=$2 variant=$3 setting=$4 log
    log=$out/$scene-$variant-$round
    if ! env "$setting" timeout 120 "$here/bin/facet" render "$here/scenes/$scene.json" --width "$size" \
        --height "$size" --spp "$spp" --seed 3 --out "$log.pfm" >"$log.log" 2>&1; then
        echo "$scene $variant FAILED: $(tail -1 "$log.log")"
        return
    fi
    # The report's CSV: the kernel time of all passes, and the wall time from the end of
    # the first pass to the end of the last (the passes and the host's work between them,
    # without start-up: scene load, program build, warm-up).
    awk -v s="$scene" -v v="$variant" -v px="$((size * size))" -v rates="$rates" -F, '
        NR == 2 { spp1 = $2; w1 = $3 } NR > 1 { spp = $2; w = $3; r = $4; p = $1 }
        END { k = spp * px / r * 1e-6
              printf "%s %s spp %d passes %d kernel %.3f s: %.1f Msamples/s; after pass 1 %.3f s wall: %.1f Msamples/s\n",
                     s, v, spp, p, r, k, w - w1, (spp - spp1) * px / (w - w1) * 1e-6
              printf "%s %s %.3f\n", s, v, k >> rates }' "$log.csv"
    rm -f "$log.pfm" "$log.png"
    if [ "${ZTEST:-0}" = 1 ] && [ "$round" = 1 ] && [ -e "$here/reference/$scene.film" ]; then
        env "$setting" timeout 120 "$here/bin/facet" render "$here/scenes/$scene.json" --width 128 --height 96 \
            --spp 256 --seed 2 --quiet --out "$log-z.pfm" --film "$log-z.film" >/dev/null 2>&1 &&
            "$here/bin/facet_film_ztest" "$here/reference/$scene.film" "$log-z.film" | sed "s/^/  $variant z-test: /"
        rm -f "$log-z".*
    fi
}

for scene in ${SCENES:-cornell_box material_grid}; do
    n=${#variants[@]}
    for ((round = 1; round <= ${REPEATS:-1}; ++round)); do
        for ((k = 0; k < n; ++k)); do
            read -r variant setting <<<"${variants[$(((k + round - 1) % n))]}"
            one "$scene" "$round" "$variant" "$setting"
        done
    done
done

echo
echo "median kernel Msamples/s over ${REPEATS:-1} round(s), and the ratio to the default's:"
sort -k1,1 -k2,2 -k3,3g "$rates" | awk '
    { key = $1 " " $2; v[key, ++c[key]] = $3; if (!(key in seen)) { seen[key] = 1; order[++m] = key } }
    END { for (i = 1; i <= m; ++i) { key = order[i]; n = c[key]
              med[key] = n % 2 ? v[key, (n + 1) / 2] : (v[key, n / 2] + v[key, n / 2 + 1]) / 2 }
          for (i = 1; i <= m; ++i) { key = order[i]; split(key, p, " "); base = med[p[1] " default"]
              printf "  %-16s %-10s %8.1f  %s\n", p[1], p[2], med[key], (base > 0 ? sprintf("%.3f", med[key] / base) : "—") } }'
