#!/bin/sh
# Mesa's drm-shim with the compilers of the exhibit's GPUs (vc4, v3d, lima, panfrost, freedreno),
# built from Debian's own Mesa source, the version this machine's llvmpipe comes from. Nothing is
# drawn: each driver's noop shim answers the kernel's calls, and the driver compiles real shaders
# and reports their statistics (tests/gpus/shader_stats.sh). Installed under $1 (default
# build/mesa-shim): prefix/ holds the EGL, GLES and driver libraries, prefix/lib/*noop_drm_shim.so
# the shims. About 1,500 ninja steps (twenty to forty minutes on two cores); run once.
set -eu
# Debian's python3 (with its mako), not another one earlier on PATH
PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/build/mesa-shim}
mkdir -p "$out"
out=$(cd "$out" && pwd)
SUDO=; [ "$(id -u)" = 0 ] || SUDO=sudo

# built, and with this version of the patch below
stamp=$(md5sum <"$root/tests/gpus/vc4_noop_shader_bo.patch" | cut -c1-32)
if [ "$(cat "$out/prefix/.complete" 2>/dev/null)" = "$stamp" ]; then
    echo "mesa-shim: already built in $out/prefix"
    exit 0
fi

# The source: a deb-src line for the archive this machine already installs from
if ! ls "$out"/src/mesa-*/meson.build >/dev/null 2>&1; then
    if ! apt-get source --print-uris mesa >/dev/null 2>&1; then
        list=/etc/apt/sources.list.d/bentray-deb-src.sources
        for f in /etc/apt/sources.list.d/debian.sources; do
            [ -f "$f" ] || continue
            sed 's/^Types: deb$/Types: deb-src/' "$f" | $SUDO tee "$list" >/dev/null
        done
        if [ ! -f "$list" ] && [ -f /etc/apt/sources.list ]; then
            grep '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' | $SUDO tee /etc/apt/sources.list.d/bentray-deb-src.list >/dev/null
        fi
        $SUDO apt-get update -qq
    fi
    mkdir -p "$out/src"
    (cd "$out/src" && apt-get source -qq --only-source mesa)
fi
src=$(ls -d "$out"/src/mesa-*/ | head -n 1)
# vc4's noop shim lacks the ioctls of a shader BO and of a submission, without which vc4's driver
# aborts at its first shader (tests/gpus/vc4_noop_shader_bo.patch makes them; applied once)
if ! patch -d "$src" -p1 -R --dry-run -s -f <"$root/tests/gpus/vc4_noop_shader_bo.patch" >/dev/null 2>&1; then
    patch -d "$src" -p1 -s -f <"$root/tests/gpus/vc4_noop_shader_bo.patch"
fi

# What these drivers need to build (no LLVM, no window system)
packages="meson ninja-build pkg-config python3-mako bison flex libdrm-dev libexpat1-dev zlib1g-dev \
libzstd-dev libelf-dev glslang-tools python3-ply"
missing=
for p in $packages; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed' || missing="$missing $p"
done
if [ -n "$missing" ]; then
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing
fi

if [ ! -f "$out/build/build.ninja" ]; then
    meson setup "$out/build" "$src" --prefix="$out/prefix" --libdir=lib --buildtype=release \
        -Dgallium-drivers=vc4,v3d,lima,panfrost,freedreno -Dvulkan-drivers= -Dtools=drm-shim \
        -Dllvm=disabled -Dplatforms= -Degl=enabled -Dgles2=enabled -Dgles1=disabled -Dopengl=true \
        -Dglx=disabled -Dgbm=disabled -Dshared-glapi=enabled -Dvalgrind=disabled -Dlibunwind=disabled \
        -Dzstd=enabled -Dbuild-tests=false
fi
ninja -C "$out/build" -j "$(nproc)"
ninja -C "$out/build" install >/dev/null
for d in vc4 v3d lima panfrost freedreno; do
    f=$(find "$out/build" -name "lib${d}_noop_drm_shim.so" | head -n 1)
    [ -n "$f" ] || { echo "mesa-shim: lib${d}_noop_drm_shim.so was not built" >&2; exit 1; }
    cp "$f" "$out/prefix/lib/"
done
echo "$stamp" >"$out/prefix/.complete"
echo "mesa-shim: built in $out/prefix"
