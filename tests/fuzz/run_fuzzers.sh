#!/usr/bin/env bash
# Runs every libFuzzer harness of tests/fuzz for a bounded time (docs/robustness.md):
#   tests/fuzz/run_fuzzers.sh BUILD_FUZZ_DIR [SECONDS_EACH]   (default 30)
# For each harness: first the stored regression inputs (tests/fuzz/regressions/<h>/,
# once each), then fuzzing from a fresh copy of the stored corpus
# (tests/fuzz/corpus/<h>/, plus small seeds cut from ../shared/assets when that folder
# exists) in BUILD_FUZZ_DIR/fuzz-run/<h>/corpus, so the repository is never modified.
# A finding (crash, sanitizer report, leak, timeout, out-of-memory, broken invariant)
# fails the script and leaves its input in BUILD_FUZZ_DIR/fuzz-run/<h>/ (crash-*,
# timeout-*, oom-*, leak-*): reproduce with `BUILD_FUZZ_DIR/fuzz_<h> FILE`.
# Environment: FUZZ_HARNESSES (default "scene_json obj_mtl env_map gltf ply"), FUZZ_JOBS
# (parallel harnesses, default 1), FUZZ_RSS_MB (default 2048), FUZZ_TIMEOUT (seconds
# an input may take, default 10).
set -u
build=$(cd "${1:?usage: run_fuzzers.sh BUILD_FUZZ_DIR [SECONDS_EACH]}" && pwd) || exit 1
seconds=${2:-30}
here=$(cd "$(dirname "$0")" && pwd)
assets=$(cd "$here/../../.." && pwd)/shared/assets
harnesses=${FUZZ_HARNESSES:-scene_json obj_mtl env_map gltf ply}
rss=${FUZZ_RSS_MB:-2048}
timeout=${FUZZ_TIMEOUT:-10}
# UBSan reports abort (the build uses -fno-sanitize-recover); leaks are findings.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
# Leaks inside Assimp and OpenImageIO (tests/fuzz/lsan_suppressions.txt) are theirs.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$(cd "$(dirname "$0")" && pwd)/lsan_suppressions.txt}

# Small seeds from ../shared/assets (optional): the first 150 lines of each OBJ with its
# MTL appended after the harness's separator, and 16x8 copies of the environment maps.
asset_seeds() {
    local h=$1 dir=$2 n=0
    [ -d "$assets" ] || return 0
    case $h in
    obj_mtl)
        while IFS= read -r obj; do
            n=$((n + 1))
            local mtl out="$dir/asset_$n.obj"
            mtl=$(grep -m1 '^mtllib' "$obj" | awk '{print $2}' | tr -d '\r')
            head -n 150 "$obj" | sed 's/^mtllib .*/mtllib in.mtl/' >"$out"
            if [ -n "$mtl" ] && [ -f "$(dirname "$obj")/$mtl" ]; then
                printf '\n#--mtl--\n' >>"$out"
                head -c 3000 "$(dirname "$obj")/$mtl" >>"$out"
            fi
        done < <(find "$assets" -name '*.obj' -size -20M | sort | head -n 12)
        ;;
    gltf)
        # The small glTF files of Debian's assimp-testmodels, when installed.
        find /usr/share/assimp/models/glTF2 \( -name '*.glb' -o -name '*.gltf' \) -size -64k 2>/dev/null |
            sort | head -n 24 | while IFS= read -r f; do n=$((n + 1)); cp "$f" "$dir/testmodel_$n.${f##*.}"; done
        ;;
    ply)
        # The first 200 vertices and faces' worth of each PLY of the assets is too
        # structured to cut; the stored seeds cover the formats.
        ;;
    env_map)
        local maps
        mapfile -t maps < <(find "$assets" \( -name '*.exr' -o -name '*.hdr' \) -size -40M | sort | head -n 8)
        [ ${#maps[@]} -gt 0 ] && "$build/make_env_seeds" "$dir" "${maps[@]}" >/dev/null 2>&1
        ;;
    esac
    return 0
}

run_one() {
    local h=$1 bin="$build/fuzz_$1" run="$build/fuzz-run/$1"
    [ -x "$bin" ] || { echo "fuzz $h: $bin not built"; return 1; }
    rm -rf "$run" && mkdir -p "$run/corpus"
    cp "$here/corpus/$h/"* "$run/corpus/"
    asset_seeds "$h" "$run/corpus"
    local regs=()
    [ -d "$here/regressions/$h" ] && mapfile -t regs < <(find "$here/regressions/$h" -type f | sort)
    if [ ${#regs[@]} -gt 0 ]; then
        if ! "$bin" -rss_limit_mb="$rss" -timeout="$timeout" "${regs[@]}" >"$run/regressions.log" 2>&1; then
            echo "fuzz $h: FAILED on a stored regression input (log: $run/regressions.log)"
            tail -n 30 "$run/regressions.log"
            return 1
        fi
    fi
    local status=0
    (cd "$run" && "$bin" -max_total_time="$seconds" -rss_limit_mb="$rss" -timeout="$timeout" \
        -print_final_stats=1 -artifact_prefix="$run/" corpus >"$run/fuzz.log" 2>&1) || status=$?
    local execs units
    execs=$(grep -m1 'stat::number_of_executed_units' "$run/fuzz.log" | awk '{print $2}')
    units=$(ls "$run/corpus" | wc -l)
    if [ "$status" -ne 0 ]; then
        echo "fuzz $h: FINDING (exit $status) after ${execs:-?} executions; input and log in $run"
        grep -E 'ERROR|SUMMARY|runtime error|invariant|terminate|==[0-9]+==' "$run/fuzz.log" | head -n 20
        return 1
    fi
    echo "fuzz $h: ok, ${execs:-?} executions in ${seconds}s, ${#regs[@]} regression inputs, corpus $units units"
}

failed=0
if [ "${FUZZ_JOBS:-1}" -gt 1 ]; then
    pids=()
    for h in $harnesses; do run_one "$h" & pids+=($!); done
    for p in "${pids[@]}"; do wait "$p" || failed=1; done
else
    for h in $harnesses; do run_one "$h" || failed=1; done
fi
exit $failed
