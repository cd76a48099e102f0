#!/usr/bin/env bash
# lean_sources.sh ROOT ALLOWED...: fails when a source of host/ other than ALLOWED (paths
# under ROOT) includes an OpenImageIO header, since the lean build (FACET_OIIO=OFF: the GPU
# bundle, tools/bundle) leaves only ALLOWED out and would then fail to compile or link.
set -u
root=${1:?usage: lean_sources.sh ROOT ALLOWED...}
shift
status=0
while IFS= read -r file; do
    rel=${file#"$root"/}
    allowed=0
    for a in "$@"; do [ "$rel" = "$a" ] && allowed=1; done
    if [ "$allowed" = 0 ]; then
        echo "$rel includes OpenImageIO but the lean build compiles it: add a lean stand-in (host/image/*_lean.cpp)" \
            "and list it in FACET_OIIO_ONLY_SOURCES (CMakeLists.txt)"
        status=1
    fi
done < <(grep -rlE '#[[:space:]]*include[[:space:]]*[<"]OpenImageIO/' "$root/host" | sort)
exit "$status"
