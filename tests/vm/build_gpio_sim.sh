#!/bin/sh
# The kernel's GPIO simulator (gpio-sim) for the virtual exhibit's kernel, built as a module of its
# own: Debian 12's amd64 kernel is configured without it (CONFIG_GPIO_SIM) and without the
# interrupt simulator it needs (CONFIG_IRQ_SIM), so both sources come from Debian's linux-source
# package and are built against the guest kernel's headers into build/vm/gpio-sim-bentray.ko.
# irq_sim.c's one call of irq_to_desc(), which a module cannot reach, becomes generic_handle_irq(),
# which runs the same handler. Needs root for apt-get (the headers and the source, about 150 MB).
# Usage: tests/vm/build_gpio_sim.sh [OUT_DIR]   (default build/vm; base.tar built first)
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/vm}
release=$(tar -tf "$out/base.tar" | sed -n 's#^\./usr/lib/modules/\([^/]*\)/$#\1#p' | head -n 1)
[ -n "$release" ] || { echo "build_gpio_sim.sh: no kernel in $out/base.tar" >&2; exit 1; }
ko=$out/gpio-sim-bentray.ko
if [ -f "$ko" ] && [ "$(cat "$ko.release" 2>/dev/null)" = "$release" ]; then
    echo "gpio-sim: $ko (up to date, $release)"
    exit 0
fi
series=$(echo "$release" | cut -d. -f1-2)
headers=/usr/src/linux-headers-$release
if [ ! -d "$headers" ] || ! ls /usr/src/linux-source-"$series".tar.xz > /dev/null 2>&1; then
    apt-get install -y --no-install-recommends "linux-headers-$release" "linux-source-$series" > "$out/gpio-sim-apt.log" 2>&1 || {
        echo "build_gpio_sim.sh: cannot install linux-headers-$release and linux-source-$series:" >&2
        tail -n 5 "$out/gpio-sim-apt.log" >&2
        exit 1
    }
fi
work=$out/gpio-sim-build
rm -rf "$work"
mkdir -p "$work"
tar -xJf "/usr/src/linux-source-$series.tar.xz" -C "$work" --strip-components=3 \
    "linux-source-$series/drivers/gpio/gpio-sim.c" "linux-source-$series/drivers/gpio/gpiolib.h"
tar -xJf "/usr/src/linux-source-$series.tar.xz" -C "$work" --strip-components=3 \
    "linux-source-$series/kernel/irq/irq_sim.c"
sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$work/irq_sim.c"
grep -q 'generic_handle_irq(irqnum);' "$work/irq_sim.c" || { echo "build_gpio_sim.sh: irq_sim.c changed upstream" >&2; exit 1; }
printf 'obj-m := gpio-sim-bentray.o\ngpio-sim-bentray-y := gpio-sim.o irq_sim.o\n' > "$work/Kbuild"
make -C "$headers" M="$(pwd)/$work" modules > "$out/gpio-sim-build.log" 2>&1 || {
    echo "build_gpio_sim.sh: the module did not build; the end of $out/gpio-sim-build.log:" >&2
    tail -n 10 "$out/gpio-sim-build.log" >&2
    exit 1
}
cp "$work/gpio-sim-bentray.ko" "$ko"
echo "$release" > "$ko.release"
rm -rf "$work"
echo "gpio-sim: $ko for $release"
