#!/bin/sh
# In the guest: a simulated GPIO chip (the kernel's gpio-sim, through configfs) whose lines carry
# the names kiosk/kiosk.conf gives its encoder and buttons, so that the shipped configuration finds
# them as on the exhibit's board. The host drives a line with `gpio_sim.sh set NAME 0|1` (the pull
# the simulator applies to an input line: an edge for libgpiod's edge events).
# Usage: gpio_sim.sh setup | set NAME VALUE | chip
set -eu
cfg=/sys/kernel/config/gpio-sim/bentray
names="KNOB_MASS_A KNOB_MASS_B BUTTON_NEXT BUTTON_EFFECTS"
case ${1:-} in
setup)
    # Debian's kernel has no gpio-sim: tests/vm/build_gpio_sim.sh builds it beside this script
    modprobe gpio-sim 2> /dev/null || {
        modprobe configfs
        insmod "$(dirname "$0")/gpio-sim-bentray.ko"
    }
    mountpoint -q /sys/kernel/config || mount -t configfs none /sys/kernel/config
    mkdir -p "$cfg/bank0"
    echo 4 > "$cfg/bank0/num_lines"
    i=0
    for n in $names; do
        mkdir -p "$cfg/bank0/line$i"
        echo "$n" > "$cfg/bank0/line$i/name"
        i=$((i + 1))
    done
    echo 1 > "$cfg/live"
    # idle levels: encoder lines high, buttons released (active low: high)
    for n in $names; do "$0" set "$n" 1; done
    "$0" chip
    ;;
chip)
    echo "gpio-sim chip: $(cat $cfg/bank0/chip_name) ($(cat $cfg/dev_name))"
    ;;
set)
    i=0
    for n in $names; do
        if [ "$n" = "$2" ]; then
            chip=$(cat "$cfg/bank0/chip_name")
            dev=$(cat "$cfg/dev_name")
            if [ "$3" = 1 ]; then pull=pull-up; else pull=pull-down; fi
            echo "$pull" > "/sys/devices/platform/$dev/$chip/sim_gpio$i/pull"
            exit 0
        fi
        i=$((i + 1))
    done
    echo "gpio_sim.sh: no line $2" >&2
    exit 2
    ;;
*)
    echo "usage: gpio_sim.sh setup | set NAME 0|1 | chip" >&2
    exit 2
    ;;
esac
