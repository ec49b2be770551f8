#!/bin/sh
# Installs the bentray exhibition kiosk: the binary, its scenes and textures, the systemd unit,
# the udev rules and an example configuration, and creates the system user the service runs as.
# The staff's configuration (/etc/bentray/kiosk.conf) is never overwritten. docs/KIOSK.md is the
# guide; `kiosk/install.sh --help` lists the options.
#
# Exit status: 0 installed (or, with --dry-run, shown), 1 a step failed, 2 a bad option or a
# system install without root.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
top=$(dirname "$here")

prefix=/usr/local
destdir=
destdir_given=0
binary=$top/bentray
dry_run=0

usage() {
    cat <<EOF
usage: kiosk/install.sh [--prefix DIR] [--destdir DIR] [--binary FILE] [--dry-run] [--help]

Installs the bentray kiosk (run it as root, from a built source tree):
  PREFIX/bin/bentray                          the program
  PREFIX/share/bentray/                       scenes, textures and sky maps
  PREFIX/share/doc/bentray/KIOSK.md           the staff guide
  PREFIX/share/doc/bentray/SCENES.md          the scene format
  PREFIX/share/doc/bentray/HARDWARE.md        which boards draw which scenes
  /etc/systemd/system/bentray-kiosk.service   the service
  /etc/udev/rules.d/99-bentray.rules          access to the knobs and GPIO chips
  /etc/bentray/kiosk.conf                     the example configuration, only where there is none
                                              yet; otherwise it goes to kiosk.conf.new beside it
It also creates the system user bentray and the groups the service needs, and reloads udev and
systemd. It does not enable or start the service.

options:
  --prefix DIR    where the program and its data go (default /usr/local); an absolute path
  --destdir DIR   put every file under DIR instead of / (packaging, tests): creates no user
                  or group and reloads nothing; needs no root
  --binary FILE   the program to install (default: bentray at the top of the source tree,
                  built by make)
  --dry-run       print what would be done, change nothing; needs no root
  --help          this text
EOF
}

usage_error() {
    printf 'install.sh: %s\n' "$1" >&2
    printf "run 'kiosk/install.sh --help' for the options\n" >&2
    exit 2
}

fail() {
    printf 'install.sh: %s\n' "$1" >&2
    exit 1
}

say() {
    printf '%s\n' "$1"
}

while [ $# -gt 0 ]; do
    case $1 in
    --help | -h)
        usage
        exit 0
        ;;
    --dry-run)
        dry_run=1
        ;;
    --prefix | --destdir | --binary)
        [ $# -ge 2 ] || usage_error "$1 needs a value"
        case $1 in
        --prefix) prefix=$2 ;;
        --destdir) destdir=$2 destdir_given=1 ;;
        --binary) binary=$2 ;;
        esac
        shift
        ;;
    --prefix=*) prefix=${1#--prefix=} ;;
    --destdir=*) destdir=${1#--destdir=} destdir_given=1 ;;
    --binary=*) binary=${1#--binary=} ;;
    *)
        usage_error "unknown option '$1'"
        ;;
    esac
    shift
done

# The prefix is written into the unit and the configuration: an absolute path of plain
# characters, so that it needs no quoting in either.
case $prefix in
/*) ;;
*) usage_error "--prefix: expected an absolute path, got '$prefix'" ;;
esac
case $prefix in
*[!A-Za-z0-9._/+-]*)
    usage_error "--prefix: only letters, digits and . _ / + - are allowed, got '$prefix'"
    ;;
esac
prefix=${prefix%/}
[ -n "$prefix" ] || usage_error "--prefix: / is not a prefix; use /usr or /usr/local"
# an empty --destdir (a variable that was not set) must not turn into an install into the system
if [ "$destdir_given" = 1 ]; then
    case $destdir in
    '' | --*) usage_error "--destdir needs a directory, got '$destdir'" ;;
    esac
fi
if [ ! -f "$binary" ] || [ ! -x "$binary" ]; then
    usage_error "--binary: no executable file at '$binary' (build it with make, or name it with \
--binary FILE)"
fi

if [ -z "$destdir" ] && [ "$dry_run" = 0 ] && [ "$(id -u)" != 0 ]; then
    usage_error "installing into the system needs root: run it with sudo, or pass --destdir DIR to \
stage the files elsewhere, or --dry-run to see what it would do"
fi

share=$prefix/share/bentray
doc=$prefix/share/doc/bentray
unit_dir=/etc/systemd/system
rules_dir=/etc/udev/rules.d
conf_dir=/etc/bentray
service_user=bentray
# The groups of SupplementaryGroups= in the unit: systemd refuses to start a unit that names a
# group the system does not have.
service_groups='video render input gpio plugdev'

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One argument as a shell would need it written, for --dry-run's listing.
quote() {
    case $1 in
    '' | *[!A-Za-z0-9_./:=,+@%-]*) printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")" ;;
    *) printf '%s' "$1" ;;
    esac
}

# Runs a command, or with --dry-run prints it.
run() {
    if [ "$dry_run" = 1 ]; then
        sep=
        for arg in "$@"; do
            printf '%s' "$sep"
            quote "$arg"
            sep=' '
        done
        printf '\n'
        return 0
    fi
    "$@"
}

makedir() {
    run install -d -m 0755 "$destdir$1"
}

# The unit and the configuration name the install's paths; the source tree's are for /usr/local
# and, in the configuration, for the tree itself (../assets).
sed -e "s#/usr/local/bin/bentray#$prefix/bin/bentray#g" \
    -e "s#/usr/local/share/doc/bentray#$doc#g" \
    "$here/bentray-kiosk.service" > "$work/bentray-kiosk.service"
sed -e "s#\.\./assets/#$share/#g" -e "s#\.\./assets#$share#g" \
    "$here/kiosk.conf" > "$work/kiosk.conf"
if grep -q '\.\./assets' "$work/kiosk.conf"; then
    fail "kiosk/kiosk.conf: a path into ../assets was left unchanged"
fi
# the configuration reader's limit on a line
if ! awk 'length($0) > 197 { found = 1 } END { exit found }' "$work/kiosk.conf"; then
    usage_error "--prefix: '$prefix' makes lines of kiosk.conf longer than 197 characters; choose \
a shorter prefix"
fi

if [ "$dry_run" = 1 ]; then
    say "# --dry-run: nothing is changed; these are the commands it would run"
    did='would install'
else
    did=installed
fi

# --- the system user and its groups (the system's own business, not a staging directory's)
if [ -n "$destdir" ]; then
    say "--destdir: no user or group created (where the files finally go, user $service_user and \
the groups $service_groups must exist)"
else
    for group in $service_groups; do
        if ! getent group "$group" > /dev/null; then
            say "group $group does not exist here"
            run groupadd --system "$group"
        fi
    done
    if getent passwd "$service_user" > /dev/null; then
        say "user $service_user exists"
    elif getent group "$service_user" > /dev/null; then
        run useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin \
            --gid "$service_user" "$service_user"
    else
        run useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin \
            --user-group "$service_user"
    fi
    # membership too, so that `sudo -u bentray bentray kiosk --check-inputs` sees the same devices
    # as the service (which gets the groups from SupplementaryGroups= either way)
    member_of=
    for group in $service_groups; do
        if getent group "$group" > /dev/null || [ "$dry_run" = 1 ]; then
            member_of=${member_of:+$member_of,}$group
        fi
    done
    [ -z "$member_of" ] || run usermod --append --groups "$member_of" "$service_user"
fi

# --- the program, its data, the guide
makedir "$prefix/bin"
run install -m 0755 "$binary" "$destdir$prefix/bin/bentray"
makedir "$share"
# the asset tree as it is: scenes name their textures and sky maps as ../textures, ../sky
(cd "$top/assets" && find . -type d | sort) | while IFS= read -r dir; do
    [ "$dir" = . ] || makedir "$share/${dir#./}"
done
(cd "$top/assets" && find . -type f | sort) | while IFS= read -r file; do
    run install -m 0644 "$top/assets/${file#./}" "$destdir$share/${file#./}"
done
makedir "$doc"
run install -m 0644 "$top/docs/KIOSK.md" "$destdir$doc/KIOSK.md"
# the scene format, which the guide sends staff to for scenes of their own
run install -m 0644 "$top/docs/SCENES.md" "$destdir$doc/SCENES.md"
# which boards draw which scenes, which the guide's troubleshooting sends staff to
run install -m 0644 "$top/docs/HARDWARE.md" "$destdir$doc/HARDWARE.md"
say "$did $destdir$prefix/bin/bentray and its scenes in $destdir$share"

# --- the service and the device rules: ours, replaced on every install (local changes go into a
# drop-in and into a rules file of their own, as the files say)
makedir "$unit_dir"
run install -m 0644 "$work/bentray-kiosk.service" "$destdir$unit_dir/bentray-kiosk.service"
makedir "$rules_dir"
run install -m 0644 "$here/99-bentray.rules" "$destdir$rules_dir/99-bentray.rules"
say "$did $destdir$unit_dir/bentray-kiosk.service and $destdir$rules_dir/99-bentray.rules"

# --- the configuration: the staff's once it exists
makedir "$conf_dir"
conf=$destdir$conf_dir/kiosk.conf
if [ ! -e "$conf" ]; then
    run install -m 0644 "$work/kiosk.conf" "$conf"
    say "$did the example configuration $conf: edit it for this exhibit's knobs and buttons"
elif cmp -s "$work/kiosk.conf" "$conf"; then
    say "$conf is this version's example, unchanged"
else
    run install -m 0644 "$work/kiosk.conf" "$conf.new"
    say "kept $conf, which was changed here; this version's example: $conf.new ($did; \
compare: diff $conf $conf.new)"
fi

# --- let the running system see the new files
if [ -z "$destdir" ]; then
    if command -v udevadm > /dev/null 2>&1; then
        run udevadm control --reload
        # devices plugged in already get the new modes and groups now
        run udevadm trigger --action=change --subsystem-match=usb --subsystem-match=hidraw \
            --subsystem-match=gpio
    else
        say "udevadm not found: the udev rules take effect once udev runs"
    fi
    if [ -d /run/systemd/system ]; then
        run systemctl daemon-reload
    else
        say "systemd is not running here: the unit is read when it next starts"
    fi
    say "next: edit $conf_dir/kiosk.conf, check the inputs (docs/KIOSK.md), then: \
systemctl enable --now bentray-kiosk (or, when it runs already: systemctl restart bentray-kiosk)"
else
    say "--destdir: udev and systemd not reloaded"
fi
