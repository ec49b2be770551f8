#!/bin/sh
# make shader-stats: every shader program bentray builds for the shipped scenes and the kiosk,
# compiled by the real compilers of the exhibit's GPUs (Mesa's drivers over their noop drm-shim,
# tests/gpus/build_mesa_shim.sh), with their instruction counts, threads, spills and compile times,
# written to docs/bench/shader_stats.md (which docs/BENCH.md includes when `make bench` writes it).
#
#   tests/gpus/shader_stats.sh [--kiosk] [OUT.md]
#
# --kiosk: only the programs the kiosk builds (43 of about 100; the whole run compiles each program
# seven times, the largest taking half a minute each for V3D's compiler).
#
# 1. The programs: bentray writes every program it builds (BT_SHADER_DUMP) while it renders each
#    shipped scene with each pipeline (auto, multipass, fused, and multipass with one target a pass)
#    on this machine's llvmpipe, and while
#    the shipped kiosk configuration compiles ahead every variant of its scenes. Copies are dropped.
# 2. Each GPU's compiler: compile_stats links and draws each program once under the driver's shim.
# 3. tests/gpus/shader_stats.py reads the drivers' statistics and writes the tables.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
scope=all
if [ "${1:-}" = --kiosk ]; then
    scope=kiosk
    shift
fi
out_md=${1:-$root/docs/bench/shader_stats.md}
PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH
shim=$root/build/mesa-shim/prefix
work=$root/build/shader-stats
bentray=$root/bentray
stats=$root/build/tests/gpus/compile_stats

"$root/tests/gpus/build_mesa_shim.sh" "$root/build/mesa-shim"
rm -rf "$work"
mkdir -p "$work/dump" "$work/programs" "$work/logs"

# The programs are built on this machine's llvmpipe, a CPU rasteriser, whose single passes take
# variants of their own (the walk along exact orbits inline, the chord cull from copies); every GPU
# takes the others (docs/PIPELINE.md). BT_FAULT=gpu_rasterizer makes llvmpipe build what a GPU
# builds, and the one-pass walk is built as a pipeline of its own ("single-inline") for comparison.
# The scenes are copies with their paths made absolute, which the kiosk's assets_root holds.
export BT_FAULT=gpu_rasterizer
mkdir -p "$work/scenes"
for scene in "$root"/assets/scenes/*.scene; do
    sed -e "s|= \.\./|= $root/assets/|" "$scene" >"$work/scenes/$(basename "$scene")"
done

# 1. every program, by scene and pipeline, then the kiosk's compile-ahead
for scene in "$work"/scenes/*.scene; do
    name=$(basename "$scene" .scene)
    # the multipass scheme also with one target a pass (render.mrt = off): the variants a GPU with
    # one draw buffer builds (VC4, Mali-400, Mali-T720); and on the packed path, the variants a GPU
    # without float textures builds (VC4)
    for pipeline in auto multipass fused multipass-1target packed single-inline; do
        d="$work/dump/$name@$pipeline"
        mkdir -p "$d"
        set -- --set render.pipeline=$pipeline
        [ $pipeline = multipass-1target ] && set -- --set render.pipeline=multipass --set render.mrt=off
        [ $pipeline = packed ] && set -- --set render.precision=packed
        if [ $pipeline = single-inline ]; then
            grep -q '^method = orbit_table' "$scene" || continue
            set -- --set render.pipeline=auto --set render.orbit_walk=inline
        fi
        # a pipeline the scene cannot take is refused (exit 1): nothing is built, nothing counted
        BT_SHADER_DUMP=$d "$bentray" render --scene "$scene" --size 32x24 --out "$work/frame.png" --force \
            "$@" >"$work/logs/render-$name-$pipeline.log" 2>&1 || true
    done
done
# the kiosk's scenes are the copies above, so its assets_root is where they lie
sed -e "s|^assets_root = .*|assets_root = $work/scenes|" -e "s|\.\./assets/scenes|$work/scenes|g" \
    -e "s|\.\./assets|$root/assets|g" -e 's|^compile_ahead = .*|compile_ahead = on|' \
    "$root/kiosk/kiosk.conf" >"$work/kiosk.conf"
mkdir -p "$work/dump/kiosk@kiosk" "$work/kiosk-out"
BT_SHADER_DUMP="$work/dump/kiosk@kiosk" "$bentray" kiosk --config "$work/kiosk.conf" --display headless \
    --out "$work/kiosk-out" --frames 1 >"$work/logs/kiosk.log" 2>&1 ||
    { echo "shader-stats: the kiosk failed (build/shader-stats/logs/kiosk.log)" >&2; exit 1; }

# one copy of each program (the probes' programs left out), named by where it was first seen;
# uses.txt: program, then each scene@pipeline that builds it
: >"$work/uses.txt"
for d in "$work"/dump/*; do
    label=$(basename "$d")
    for frag in "$d"/*.frag; do
        [ -e "$frag" ] || continue
        base=${frag%.frag}
        stage=$(basename "$base" | sed 's/^[0-9]*-[0-9]*-//')
        [ "$stage" = probe_fragment ] && continue
        key=$(cat "$base.vert" "$frag" | md5sum | cut -c1-10)
        if [ ! -e "$work/programs/$key.frag" ]; then
            cp "$base.vert" "$work/programs/$key.vert"
            cp "$frag" "$work/programs/$key.frag"
            echo "$key $stage" >>"$work/programs.txt"
        fi
        echo "$key $label" >>"$work/uses.txt"
    done
done
n=$(wc -l <"$work/programs.txt")
echo "shader-stats: $n distinct programs"

# 2. each GPU's compiler: name|shim|driver|environment
gpus="vc4|vc4|vc4|VC4_DEBUG=shaderdb
v3d|v3d|v3d|V3D_DEBUG=shaderdb
lima|lima|lima|LIMA_DEBUG=shaderdb
panfrost-g52|panfrost|panfrost|BIFROST_MESA_DEBUG=shaderdb PAN_GPU_ID=7212
panfrost-t720|panfrost|panfrost|MIDGARD_MESA_DEBUG=shaderdb PAN_GPU_ID=720
freedreno-a306|freedreno|msm|FD_MESA_DEBUG=shaderdb FD_GPU_ID=307
freedreno-a530|freedreno|msm|FD_MESA_DEBUG=shaderdb FD_GPU_ID=530"
if [ $scope = kiosk ]; then
    grep ' kiosk@kiosk$' "$work/uses.txt" | cut -d' ' -f1 | sort -u >"$work/compiled.txt"
else
    cut -d' ' -f1 "$work/programs.txt" >"$work/compiled.txt"
fi
echo "$gpus" >"$work/gpus.txt"
while IFS='|' read -r gpu lib driver envs; do
    echo "shader-stats: $gpu, $(wc -l <"$work/compiled.txt") programs"
    mkdir -p "$work/logs/$gpu"
    # what the driver offers (compile_stats with no program)
    env $envs LD_PRELOAD="$shim/lib/lib${lib}_noop_drm_shim.so" MESA_LOADER_DRIVER_OVERRIDE=$driver \
        LD_LIBRARY_PATH="$shim/lib" LIBGL_DRIVERS_PATH="$shim/lib/dri" EGL_PLATFORM=surfaceless \
        timeout 120 "$stats" >"$work/logs/$gpu.caps" 2>&1 || true
    # one process a program (one that crashes the driver ends only its own), as many at once as
    # there are cores; compile_stats measures the CPU time of its own process
    export gpu lib driver envs shim stats work
    xargs -P "$(nproc)" -I KEY sh -c 'env $envs LD_PRELOAD="$shim/lib/lib${lib}_noop_drm_shim.so" \
        MESA_LOADER_DRIVER_OVERRIDE=$driver LD_LIBRARY_PATH="$shim/lib" LIBGL_DRIVERS_PATH="$shim/lib/dri" \
        EGL_PLATFORM=surfaceless MESA_SHADER_CACHE_DISABLE=true \
        timeout 120 "$stats" "$work/programs/KEY" >"$work/logs/$gpu/KEY.log" 2>&1 ||
        echo "== ended $work/programs/KEY status $?" >>"$work/logs/$gpu/KEY.log"' <"$work/compiled.txt"
    for key in $(cat "$work/compiled.txt"); do
        cat "$work/logs/$gpu/$key.log"
    done >"$work/logs/$gpu.log"
    # the driver asked for, never a software fallback
    if ! grep -q '^== renderer ' "$work/logs/$gpu.log" || grep -Eqi '^== renderer .*(llvmpipe|softpipe|swrast)' "$work/logs/$gpu.log"; then
        echo "shader-stats: $gpu: no context of that driver ($work/logs/$gpu.log)" >&2
        exit 1
    fi
done <"$work/gpus.txt"

# 3. the tables
/usr/bin/python3 "$root/tests/gpus/shader_stats.py" "$work" "$scope" "$out_md"
echo "shader-stats: wrote $out_md"
