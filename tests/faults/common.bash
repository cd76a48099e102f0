# Shared by the fault-injection scripts in tests/faults/ (sourced, not a test itself).
# Each script needs FACET (the binary) and SCENES (the scenes folder), works in its own
# mktemp -d folder, prints PASS/FAIL/SKIP lines and "N passed, M failed", and exits
# non-zero when any check failed.
set -u
: "${FACET:?set FACET to the facet binary}" "${SCENES:?set SCENES to the scenes folder}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/facet-faults.XXXXXX")
passed=0
failed=0
cleanup_hooks=()
cleanup() {
    local h
    for h in "${cleanup_hooks[@]+"${cleanup_hooks[@]}"}"; do eval "$h"; done
    rm -rf "$tmp"
}
trap cleanup EXIT

ok() { passed=$((passed + 1)); echo "PASS $1"; }
bad() { failed=$((failed + 1)); echo "FAIL $1"; [ -f "$tmp/log" ] && sed 's/^/    /' "$tmp/log"; }
skip() { echo "SKIP $1"; }
check() { local name=$1; shift; if "$@"; then ok "$name"; else bad "$name"; fi; }

# run NAME STATUS PATTERN -- command...: the exit status, and PATTERN (ERE) in stdout+stderr.
run() {
    local name=$1 status=$2 pattern=$3
    shift 4
    "$@" >"$tmp/log" 2>&1
    local got=$?
    if [ "$got" -ne "$status" ]; then bad "$name (exit $got, wanted $status)"; return 1; fi
    if ! grep -qE -- "$pattern" "$tmp/log"; then bad "$name (output lacks /$pattern/)"; return 1; fi
    ok "$name"
}

# Temporaries (hidden files with "tmp" in the name) left in the folders given.
no_temporaries() {
    local left
    left=$(find "$@" -maxdepth 1 -name '.*tmp*' 2>/dev/null)
    [ -z "$left" ] || { echo "    left behind: $left"; return 1; }
}

# A complete image: facet reads it whole.
readable_image() { "$FACET" compare "$1" "$1" >/dev/null 2>&1; }

# The log does not name an internal temporary file.
no_temporary_named() { ! grep -qE '\.tmp-[0-9]+-' "$tmp/log"; }

small=(--width 16 --height 16 --spp 2 --quiet)
scene="$SCENES/cornell_box.json"

finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
