#!/bin/sh
# `make vm-test`: the kiosk deployed on a virtual exhibit (docs/KIOSK.md, "The virtual exhibit").
# Builds the guest's disk from the cached base system (tests/vm/build_base.sh), with this tree's
# bentray, kiosk/, assets/ and the guest's agent under /opt/bentray-src, then boots it and runs
# the checks of tests/vm/drive.py. Log: build/vm/vm-test.log; the guest's console and the kiosk's
# journal: build/vm/serial.log; the screens: build/vm/*.ppm. Needs root (debootstrap, mkfs).
set -eu
cd "$(dirname "$0")/../.."
out=build/vm
[ -x ./bentray ] || { echo "run.sh: build bentray first (make)" >&2; exit 2; }
tests/vm/build_base.sh "$out"
tests/vm/build_gpio_sim.sh "$out"
root=$out/root
rm -rf "$root" "$out/root.img" "$out"/*.ppm "$out/serial.log"
mkdir -p "$root"
tar -C "$root" -xf "$out/base.tar"
src=$root/opt/bentray-src
mkdir -p "$src/docs" "$src/tests/vm"
cp -a bentray kiosk assets "$src/"
cp docs/KIOSK.md docs/SCENES.md docs/HARDWARE.md "$src/docs/"
cp tests/vm/guest_agent.sh tests/vm/gpio_sim.sh "$out/gpio-sim-bentray.ko" "$src/tests/vm/"
cp tests/vm/bentray-vmagent.service "$root/etc/systemd/system/"
ln -sf /etc/systemd/system/bentray-vmagent.service "$root/etc/systemd/system/multi-user.target.wants/bentray-vmagent.service"
echo bentray-exhibit > "$root/etc/hostname"
echo "/dev/vda / ext4 rw,errors=remount-ro 0 1" > "$root/etc/fstab"
# the kiosk's journal survives nothing: the test reads it before the guest stops
mkdir -p "$root/etc/systemd/journald.conf.d"
printf '[Journal]\nStorage=volatile\n' > "$root/etc/systemd/journald.conf.d/volatile.conf"
mkfs.ext4 -q -F -L bentray -d "$root" "$out/root.img" 3G
rm -rf "$root"
exec python3 tests/vm/drive.py "$out"
