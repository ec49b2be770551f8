#!/bin/sh
# The virtual exhibit's base system: Debian 12 (bookworm) from Debian's archive by debootstrap,
# with the packages of tests/vm/packages.txt, packed as build/vm/base.tar. Rebuilt only when the
# package list or this script changes (their checksum is kept beside the archive). Needs root
# (debootstrap), about 1 GB of disk and a few minutes of downloading the first time.
# Usage: tests/vm/build_base.sh [OUT_DIR]   (default build/vm)
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/vm}
mirror=${BT_VM_MIRROR:-http://deb.debian.org/debian}
mkdir -p "$out"
stamp=$(cat tests/vm/packages.txt tests/vm/build_base.sh | sha256sum | cut -c1-16)
if [ -f "$out/base.tar" ] && [ "$(cat "$out/base.stamp" 2>/dev/null)" = "$stamp" ]; then
    echo "base system: $out/base.tar (up to date)"
    exit 0
fi
[ "$(id -u)" = 0 ] || { echo "build_base.sh: debootstrap needs root" >&2; exit 2; }
command -v debootstrap > /dev/null || { echo "build_base.sh: debootstrap is missing: make deps-vm" >&2; exit 2; }
root=$out/base-root
rm -rf "$root" "$out/base.tar" "$out/base.stamp"
packages=$(grep -v '^#' tests/vm/packages.txt | grep -v '^$' | paste -sd, -)
start=$(date +%s)
debootstrap --variant=minbase --include="$packages" bookworm "$root" "$mirror" > "$out/debootstrap.log" 2>&1 || {
    echo "build_base.sh: debootstrap failed; the end of $out/debootstrap.log:" >&2
    tail -n 20 "$out/debootstrap.log" >&2
    exit 1
}
# gdb through apt, which resolves what debootstrap cannot (packages.txt)
chroot "$root" apt-get install -y --no-install-recommends gdb >> "$out/debootstrap.log" 2>&1 || {
    echo "build_base.sh: installing gdb in the guest failed; the end of $out/debootstrap.log:" >&2
    tail -n 20 "$out/debootstrap.log" >&2
    exit 1
}
chroot "$root" apt-get clean
# the kernel and initrd the host boots directly (qemu -kernel), and no root password: the guest
# is driven through its serial console's log and QMP, never logged into
cp "$root"/boot/vmlinuz-* "$out/vmlinuz"
cp "$root"/boot/initrd.img-* "$out/initrd.img"
rm -rf "$root/var/cache/apt/archives/"*.deb
tar -C "$root" -cf "$out/base.tar" .
rm -rf "$root"
echo "$stamp" > "$out/base.stamp"
echo "base system: $out/base.tar, built in $(( $(date +%s) - start )) s"
