#!/usr/bin/env bash
# Checks that every tracked C++ and OpenCL C source (*.cpp *.hpp *.h *.cl) is formatted as
# the root .clang-format says, in dry-run mode: nothing is rewritten. `make format` applies it.
# Usage: format_check.sh [REPO_ROOT]   (default: the folder above this script)
# Environment: CLANG_FORMAT (default clang-format-14, else clang-format).
# Exits 77 (ctest: skipped) when no clang-format 14 is installed: other major versions
# format differently, so their verdict would not be the one the style was measured with.
set -u
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root" || exit 1
cf=${CLANG_FORMAT:-$(command -v clang-format-14 || command -v clang-format)}
if [ -z "$cf" ]; then
    echo "clang-format not found: install Debian's clang-format (make deps)"
    exit 77
fi
major=$("$cf" --version | sed -n 's/.*version \([0-9]*\).*/\1/p')
if [ "$major" != 14 ]; then
    echo "$cf is version $major; the check uses clang-format 14 (Debian 12): skipped"
    exit 77
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cl')
else   # an unpacked archive: the same files, found on disk
    mapfile -t files < <(find host kernels tests bench -type f \
        \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cl' \) | sort)
fi
bad=0
lines=0
for f in "${files[@]}"; do
    if ! "$cf" --dry-run --Werror "$f" >/dev/null 2>&1; then
        n=$("$cf" "$f" | diff "$f" - | grep -c '^[<>]')
        echo "not formatted: $f ($n diff lines)"
        bad=$((bad + 1))
        lines=$((lines + n))
    fi
done
if [ "$bad" -gt 0 ]; then
    echo "$bad of ${#files[@]} files need formatting ($lines diff lines); run: make format"
    echo "first differences:"
    "$cf" --dry-run "${files[@]}" 2>&1 | head -n 20
    exit 1
fi
echo "${#files[@]} files formatted as .clang-format says"
