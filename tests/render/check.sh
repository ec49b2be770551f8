# The command-line tests' shared part (sourced): the repository root as working directory, BT, a
# temporary directory removed at exit, and `check NAME EXPECTED_RC PATTERN -- command...`, which
# runs the command and passes when it exits with EXPECTED_RC and its output matches PATTERN.
cd "$(dirname "$0")/../.."
BT=${BT:-./bentray}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
check() {
    local name=$1 want=$2 pattern=$3; shift 4
    "$@" >"$TMP/out" 2>&1
    local rc=$?
    if [ "$rc" != "$want" ] || ! grep -qE -- "$pattern" "$TMP/out"; then
        echo "FAIL $name: exit $rc (want $want), output:"; sed 's/^/    /' "$TMP/out" | head -8
        fails=$((fails + 1))
    else
        echo "ok   $name"
    fi
}
