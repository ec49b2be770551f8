#!/bin/sh
# kiosk/install.sh staged into a temporary directory (--destdir: the system is not touched, no
# user is created, nothing reloaded), with a stand-in program (--binary): the files and their
# modes, the example configuration pointing at the installed scenes, a changed configuration kept
# on a second run (kiosk.conf.new beside it), the prefix written into the unit, --dry-run writing
# nothing, and bad options and a system install without root refused with exit 2 and the reason.
# Prints "install checks: N failed"; exit 0 when none failed.
set -u
cd "$(dirname "$0")/../.." || exit 1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
INSTALL=kiosk/install.sh
fails=0

pass() {
    echo "ok   $1"
}

failed() {   # failed NAME WHY: prints the last command's output
    echo "FAIL $1: $2"
    sed 's/^/    /' "$TMP/out" | head -12
    fails=$((fails + 1))
}

# check NAME EXPECTED_RC PATTERN command...: the exit status and a line of output matching PATTERN
check() {
    name=$1 want=$2 pattern=$3
    shift 3
    "$@" > "$TMP/out" 2>&1
    rc=$?
    if [ "$rc" != "$want" ]; then
        failed "$name" "exit $rc, want $want"
    elif ! grep -qE -- "$pattern" "$TMP/out"; then
        failed "$name" "no line matches '$pattern'"
    else
        pass "$name"
    fi
}

# ok_if NAME WHY command...: passes when the command succeeds, else fails with WHY
ok_if() {
    name=$1 why=$2
    shift 2
    if "$@"; then
        pass "$name"
    else
        : > "$TMP/out"
        failed "$name" "$why"
    fi
}

absent() {
    [ ! -e "$1" ]
}

# the mode of a file as ls -l writes it (POSIX has no stat)
mode_of() {
    # shellcheck disable=SC2012 # one named file, not a listing to parse
    ls -l "$1" | cut -c1-10
}

# is NAME PATH MODE: a regular file with this mode, as ls -l writes it
is() {
    if [ ! -f "$2" ]; then
        : > "$TMP/out"
        failed "$1" "$2 missing"
        return
    fi
    mode=$(mode_of "$2")
    if [ "$mode" != "$3" ]; then
        : > "$TMP/out"
        failed "$1" "$2 has mode $mode, want $3"
    else
        pass "$1"
    fi
}

# holds NAME FILE PATTERN: FILE has a line matching PATTERN (FILE is shown when it has not)
holds() {
    if grep -qE -- "$3" "$2" 2> /dev/null; then
        pass "$1"
    else
        [ "$2" = "$TMP/out" ] || cp "$2" "$TMP/out" 2> /dev/null || : > "$TMP/out"
        failed "$1" "$2 has no line matching '$3'"
    fi
}

# lacks NAME FILE PATTERN: FILE exists and has no line matching PATTERN
lacks() {
    if [ -f "$2" ] && ! grep -qE -- "$3" "$2"; then
        pass "$1"
    else
        [ "$2" = "$TMP/out" ] || cp "$2" "$TMP/out" 2> /dev/null || : > "$TMP/out"
        failed "$1" "$2 missing or has a line matching '$3'"
    fi
}

# A stand-in for the program, mode 0700 so that the installed mode is the installer's doing.
STUB=$TMP/bentray-stub
printf '#!/bin/sh\necho bentray stand-in\n' > "$STUB"
chmod 0700 "$STUB"

# --- options
check "help" 0 "--destdir DIR" sh "$INSTALL" --help
check "unknown option" 2 "unknown option '--frobnicate'" sh "$INSTALL" --frobnicate --destdir "$TMP/x"
check "option without value" 2 "--prefix needs a value" sh "$INSTALL" --destdir "$TMP/x" --prefix
check "relative prefix" 2 "--prefix: expected an absolute path" sh "$INSTALL" --prefix usr/local --destdir "$TMP/x"
check "prefix with blanks" 2 "--prefix: only letters" sh "$INSTALL" --prefix "/opt/my kiosk" --destdir "$TMP/x"
check "missing binary" 2 "--binary: no executable file at '$TMP/none'" sh "$INSTALL" --binary "$TMP/none" --destdir "$TMP/x"
ok_if "refused runs write nothing" "$TMP/x exists" absent "$TMP/x"

# --- a staged install
D=$TMP/root
check "install" 0 "installed the example configuration $D/etc/bentray/kiosk.conf" \
    sh "$INSTALL" --destdir "$D" --binary "$STUB"
holds "no user created with --destdir" "$TMP/out" "no user or group created"
is "binary" "$D/usr/local/bin/bentray" "-rwxr-xr-x"
ok_if "binary is --binary" "contents differ" cmp -s "$STUB" "$D/usr/local/bin/bentray"
is "unit" "$D/etc/systemd/system/bentray-kiosk.service" "-rw-r--r--"
holds "unit runs the installed binary" "$D/etc/systemd/system/bentray-kiosk.service" \
    "^ExecStart=/usr/local/bin/bentray kiosk --config /etc/bentray/kiosk.conf$"
is "udev rules" "$D/etc/udev/rules.d/99-bentray.rules" "-rw-r--r--"
ok_if "udev rules as in kiosk/" "contents differ" cmp -s kiosk/99-bentray.rules "$D/etc/udev/rules.d/99-bentray.rules"
is "guide" "$D/usr/local/share/doc/bentray/KIOSK.md" "-rw-r--r--"
is "scene format" "$D/usr/local/share/doc/bentray/SCENES.md" "-rw-r--r--"
is "boards guide" "$D/usr/local/share/doc/bentray/HARDWARE.md" "-rw-r--r--"
CONF=$D/etc/bentray/kiosk.conf
is "example configuration" "$CONF" "-rw-r--r--"
holds "configuration names installed scenes" "$CONF" "^scenes = /usr/local/share/bentray/scenes/schwarzschild.scene,"
holds "configuration's assets_root" "$CONF" "^assets_root = /usr/local/share/bentray$"
lacks "no path into the source tree" "$CONF" "\.\./assets"
# the configuration equals the example but for its paths
sed 's#\.\./assets#/usr/local/share/bentray#g' kiosk/kiosk.conf > "$TMP/expected.conf"
ok_if "configuration is the example" "differs beyond its paths" cmp -s "$TMP/expected.conf" "$CONF"
# every scene the configuration names is installed, and so is every asset with mode 0644
missing=0
grep -oE '/usr/local/share/bentray/scenes/[A-Za-z0-9_]+\.scene' "$CONF" > "$TMP/scenes"
while IFS= read -r scene; do
    [ -f "$D$scene" ] || { echo "    missing: $D$scene"; missing=$((missing + 1)); }
done < "$TMP/scenes"
ok_if "configuration names scenes" "no scene path found" [ -s "$TMP/scenes" ]
ok_if "configured scenes installed" "$missing missing" [ "$missing" = 0 ]
bad=0
(cd assets && find . -type f) > "$TMP/assets"
while IFS= read -r f; do
    g=$D/usr/local/share/bentray/${f#./}
    if [ ! -f "$g" ] || [ "$(mode_of "$g")" != "-rw-r--r--" ] || ! cmp -s "assets/${f#./}" "$g"; then
        echo "    not installed as it should be: $g"
        bad=$((bad + 1))
    fi
done < "$TMP/assets"
ok_if "assets installed, mode 0644" "$bad wrong" [ "$bad" = 0 ]
ok_if "first install: no kiosk.conf.new" "it exists" absent "$CONF.new"

# --- installing again
check "second install, configuration unchanged" 0 "kiosk.conf is this version's example" \
    sh "$INSTALL" --destdir "$D" --binary "$STUB"
ok_if "unchanged configuration: no kiosk.conf.new" "it exists" absent "$CONF.new"
echo "; changed by the exhibition staff" >> "$CONF"
cp "$CONF" "$TMP/staff.conf"
check "install over a changed configuration" 0 "kept $CONF.*kiosk.conf.new" \
    sh "$INSTALL" --destdir "$D" --binary "$STUB"
ok_if "changed configuration kept" "it was overwritten" cmp -s "$TMP/staff.conf" "$CONF"
is "kiosk.conf.new beside it" "$CONF.new" "-rw-r--r--"
ok_if "kiosk.conf.new is the example" "contents differ" cmp -s "$TMP/expected.conf" "$CONF.new"

# --- another prefix: written into the unit and the configuration
P=$TMP/opt
check "install --prefix /opt/bentray" 0 "installed" sh "$INSTALL" --prefix /opt/bentray/ --destdir "$P" --binary "$STUB"
is "binary under the prefix" "$P/opt/bentray/bin/bentray" "-rwxr-xr-x"
holds "unit follows the prefix" "$P/etc/systemd/system/bentray-kiosk.service" "^ExecStart=/opt/bentray/bin/bentray kiosk "
holds "unit's guide follows the prefix" "$P/etc/systemd/system/bentray-kiosk.service" \
    "^Documentation=file:/opt/bentray/share/doc/bentray/KIOSK.md$"
holds "configuration follows the prefix" "$P/etc/bentray/kiosk.conf" "^scenes = /opt/bentray/share/bentray/scenes/"
lacks "no /usr/local left in the unit" "$P/etc/systemd/system/bentray-kiosk.service" "/usr/local"

# --- --dry-run: prints the commands, writes nothing
check "dry run" 0 "^install -m 0755 .* $TMP/dry/usr/local/bin/bentray$" \
    sh "$INSTALL" --dry-run --destdir "$TMP/dry" --binary "$STUB"
ok_if "dry run writes nothing" "$TMP/dry exists" absent "$TMP/dry"

# --- without root: refused, unless --dry-run. Run as an unprivileged user: as root only through
# setpriv (util-linux), so that even a broken check could not install into this system.
if [ "$(id -u)" != 0 ]; then
    as_user() { "$@"; }
    unprivileged=1
elif command -v setpriv > /dev/null 2>&1 && setpriv --reuid=65534 --regid=65534 --clear-groups true 2> /dev/null; then
    as_user() { setpriv --reuid=65534 --regid=65534 --clear-groups "$@"; }
    unprivileged=1
else
    unprivileged=0
fi
if [ "$unprivileged" = 1 ]; then
    # what the installer reads, copied where that user can read it (a checkout may not be)
    T=$TMP/tree
    mkdir -p "$T/docs"
    cp -R kiosk assets "$T/"
    cp docs/KIOSK.md docs/SCENES.md docs/HARDWARE.md "$T/docs/"
    chmod -R a+rX "$TMP"
    chmod 0755 "$STUB"
    check "system install without root" 2 "needs root: run it with sudo" \
        as_user sh "$T/kiosk/install.sh" --binary "$STUB"
    check "empty --destdir is no destdir" 2 "--destdir needs a directory, got ''" \
        as_user sh "$T/kiosk/install.sh" --destdir "" --binary "$STUB"
    check "system dry run without root" 0 "^useradd --system --no-create-home .*--shell /usr/sbin/nologin" \
        as_user sh "$T/kiosk/install.sh" --dry-run --binary "$STUB"
    holds "dry run reloads udev" "$TMP/out" "^udevadm control --reload$|udevadm not found"
    holds "dry run installs the unit" "$TMP/out" "^install -m 0644 .* /etc/systemd/system/bentray-kiosk.service$"
else
    echo "skip system install without root: running as root without setpriv"
fi

echo "install checks: $fails failed"
[ "$fails" = 0 ]
