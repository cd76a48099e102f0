#!/usr/bin/env bash
# Offline lint of every kernel program with clang's OpenCL front end and warnings as
# errors (PoCL accepts no -W flags, so this is where kernel warnings are caught).
# Usage: lint_kernels.sh KERNELS_DIR
set -u
dir=${1:?kernels folder}
cc=$(command -v clang || command -v clang-14) || { echo "clang not found: install Debian's clang"; exit 1; }
status=0
count=0
while IFS= read -r f; do
    count=$((count + 1))
    if ! "$cc" -x cl -cl-std=CL1.2 -Xclang -finclude-default-header -fsyntax-only -I "$dir/.." \
        -Wall -Wextra -Wdouble-promotion -Wshadow -Werror "$f"; then
        echo "FAIL $f"
        status=1
    fi
done < <(grep -rl --include='*.cl' '__kernel' "$dir" | sort)
echo "linted $count kernel programs"
exit $status
