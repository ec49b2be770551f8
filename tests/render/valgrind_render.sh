#!/usr/bin/env bash
# One small headless render on each back-end (EGL surfaceless, OSMesa) under Valgrind's memcheck:
# fails on a definite leak or an invalid read or write, an uninitialised value used, a bad free.
# The drivers' own leaks are suppressed in tests/render/valgrind.supp, which names only driver
# objects; bentray's own allocations are always reported.
#   BT=./bentray tests/render/valgrind_render.sh [egl|osmesa ...]
# The optimised binary is the one to run (a sanitizer build cannot run under Valgrind).
set -u
cd "$(dirname "$0")/../.."
BT=${BT:-./bentray}
SUPP=tests/render/valgrind.supp
# Exit code that valgrind gives when it found an error; any other nonzero code is bentray's.
VG_ERROR=97
BACKENDS=${*:-egl osmesa}
if ! command -v valgrind >/dev/null 2>&1; then
    echo "valgrind_render: valgrind is not installed (make deps installs it)"; exit 1
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# Mesa's shader disk cache makes the run depend on what earlier runs on this machine left
# (a warm cache compiles nothing) and its writer thread hands padding bytes to write(2): off,
# every run compiles the same shaders and sees the same driver code.
export MESA_SHADER_CACHE_DISABLE=true
fails=0
for backend in $BACKENDS; do
    log="$TMP/$backend.log"
    start=$(date +%s)
    valgrind --tool=memcheck --leak-check=full --errors-for-leak-kinds=definite \
        --show-leak-kinds=definite --error-exitcode=$VG_ERROR --keep-debuginfo=yes \
        --num-callers=40 --suppressions="$SUPP" \
        "$BT" render --scene assets/scenes/test.scene --size 64x48 --backend "$backend" \
        --out "$TMP/$backend.png" --force >"$log" 2>&1
    rc=$?
    took=$(( $(date +%s) - start ))
    summary=$(grep -E "ERROR SUMMARY|definitely lost:" "$log" | sed 's/^==[0-9]*== *//' | paste -sd ';' -)
    if [ "$rc" = 0 ] && grep -q "^$TMP/$backend.png$" "$log"; then
        echo "ok   valgrind render $backend (${took} s): $summary"
    else
        if [ "$rc" = "$VG_ERROR" ]; then
            echo "FAIL valgrind render $backend: memcheck errors ($summary)"
        else
            echo "FAIL valgrind render $backend: bentray exited with $rc"
        fi
        # the reports themselves, without the suppression counts and the banner
        grep -E "^==[0-9]+== " "$log" | sed -n '/Invalid\|uninitialised\|definitely lost in\|Mismatched\|free()/,/^==[0-9]*== $/p' | head -60
        grep -vE "^==[0-9]+== |^--[0-9]+-- " "$log" | tail -5
        fails=$((fails + 1))
    fi
done
echo "valgrind render tests: $fails failed"
[ "$fails" = 0 ]
