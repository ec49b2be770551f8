#!/usr/bin/env bash
# The target matrix (docs/HARDWARE.md): every shipped scene under every GPU an exhibit might buy, as
# this machine's llvmpipe emulates it with the GLES version, missing extensions and the fault hooks
# (docs/LIMITS.md). Each scene either draws what the default path draws (the same outcome in every
# pixel of its dump, the issue's 0.01% bound at this size; the image-only path, which reads nothing
# back, the same picture) or is refused with its message and exit code, never drawn otherwise. The
# guard that keeps the next speed-up from breaking a GPU we cannot see. Run by
# tests/render/run_all.sh; alone:
#   BT=./bentray tests/render/targets.sh
set -u
. "$(dirname "$0")/check.sh"
SIZE=32x24
ES2="MESA_GLES_VERSION_OVERRIDE=2.0"
ES3="MESA_GLES_VERSION_OVERRIDE=3.0"
# each scenario: name | environment | what every scene must do: "same" (its outcomes those of the
# default path), "same picture" (the default path's PNG, its stars drawn on the GPU as the image-only
# path draws them) or "refused RC PATTERN". gpu_rasterizer: the variants a GPU takes (a CPU
# rasteriser takes others for speed: docs/PIPELINE.md), whose rays are the same bit for bit.
scenarios=(
    "vc4 (Raspberry Pi 0-3: GLES 2, no float textures)|$ES2 MESA_EXTENSION_OVERRIDE=-GL_OES_texture_float,-GL_OES_texture_half_float BT_FAULT=gpu_rasterizer|same"
    "Mali-T720 (GLES 2, 16-bit float targets, MRT)|$ES2 MESA_EXTENSION_OVERRIDE=-GL_OES_texture_float BT_FAULT=gpu_rasterizer|same"
    "Mali-T720 without MRT|$ES2 MESA_EXTENSION_OVERRIDE=-GL_OES_texture_float,-GL_EXT_draw_buffers BT_FAULT=gpu_rasterizer|same"
    "lima (Mali-400: GLES 2, 16-bit floats, a 16-bit ALU)|$ES2 MESA_EXTENSION_OVERRIDE=-GL_OES_texture_float BT_FAULT=fp16_alu,gpu_rasterizer|refused 1 does not compute its fragment shaders in 32-bit floats"
    "a 16-bit ALU that reports highp (GLES 3)|BT_FAULT=fp16_alu|refused 1 does not compute its fragment shaders in 32-bit floats"
    "GLES 3 without float render targets|$ES3 BT_FAULT=float_render,half_float_render,gpu_rasterizer|same picture"
    "GLES 3 with 16-bit float targets only|$ES3 BT_FAULT=float_render,gpu_rasterizer|same"
    "V3D, Mali-G52, Adreno (GLES 3, 32-bit float targets)|$ES3 BT_FAULT=gpu_rasterizer|same"
)

for f in assets/scenes/*.scene; do
    sc=$(basename "$f" .scene)
    $BT render --scene "$f" --size $SIZE --force --out "$TMP/$sc.png" --dump "$TMP/$sc.dump" >/dev/null 2>&1 &&
        $BT render --scene "$f" --size $SIZE --force --set render.star_pass=gpu --out "$TMP/$sc-gpu-stars.png" \
            >/dev/null 2>&1 || { echo "FAIL $sc: the default path does not render"; fails=$((fails + 1)); continue; }
    for scenario in "${scenarios[@]}"; do
        IFS='|' read -r name environment want <<<"$scenario"
        set -- env $environment $BT render --scene "$f" --size $SIZE --force --backend egl --out "$TMP/t.png"
        case "$want" in
        "same")
            check "$sc on $name: the default path's outcomes" 0 "^outcome differs: 0 of " -- \
                sh -c "$* --dump $TMP/t.dump >$TMP/t.log 2>&1 || { cat $TMP/t.log; exit 1; }; $BT compare $TMP/t.dump $TMP/$sc.dump" ;;
        "same picture")
            check "$sc on $name: the default path's picture" 0 "^same$" -- \
                sh -c "$* >$TMP/t.log 2>&1 || { cat $TMP/t.log; exit 1; }; cmp $TMP/t.png $TMP/$sc-gpu-stars.png && echo same" ;;
        refused*)
            read -r _ rc pattern <<<"$want"
            check "$sc on $name: refused" "$rc" "$pattern" -- "$@" ;;
        esac
    done
done
echo "target matrix: $fails failed"
[ "$fails" = 0 ]
