#!/usr/bin/env bash
# Command-line tests of the limits that stand before allocations (docs/LIMITS.md) and of the GL
# fault paths, driven by the BT_FAULT test hook: a refusal names the limit and where (FILE:LINE
# of the scene, or the option), a GL fault falls back to the next render path or exits 1 with a
# message that names the format and the path. Run by tests/render/run_all.sh; alone:
#   BT=./bentray tests/render/limits.sh
set -u
. "$(dirname "$0")/check.sh"
S=assets/scenes/test.scene
ASSETS=$PWD/assets

# Big-endian 32-bit integer, as bytes.
be32() {
    local v=$1
    printf "\\x$(printf %02x $(((v >> 24) & 255)))\\x$(printf %02x $(((v >> 16) & 255)))"
    printf "\\x$(printf %02x $(((v >> 8) & 255)))\\x$(printf %02x $((v & 255)))"
}
le32() {
    local v=$1
    printf "\\x$(printf %02x $((v & 255)))\\x$(printf %02x $(((v >> 8) & 255)))"
    printf "\\x$(printf %02x $(((v >> 16) & 255)))\\x$(printf %02x $(((v >> 24) & 255)))"
}
# The first 33 bytes of a PNG that declares WIDTH x HEIGHT (RGBA, 8 bits): all the loader reads.
png_header() {   # FILE WIDTH HEIGHT
    { printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR'; be32 "$2"; be32 "$3"
      printf '\x08\x06\x00\x00\x00\x00\x00\x00\x00'; } > "$1"
}
# A dump header (docs/DUMP.md) of WIDTH x HEIGHT without records.
dump_header() {   # FILE WIDTH HEIGHT
    { printf 'BTDUMP\x00\x00'; le32 2; le32 "$2"; le32 "$3"; le32 52; head -c 76 /dev/zero; } > "$1"
}
# The test scene with its assets found from $TMP, the texture and the sky replaced as asked.
scene_with() {   # FILE TEXTURE SKY_PREFIX
    sed -e "s#\.\./textures/checker_grey.png#$2#" -e "s#\.\./sky/grid#$3#" -e "s#\.\./#$ASSETS/#" $S > "$1"
}

# ---- textures and sky faces: the size their PNG headers declare, refused at the scene's line
png_header "$TMP/huge.png" 100000 100000
scene_with "$TMP/huge_texture.scene" "$TMP/huge.png" "$ASSETS/sky/grid"
check "texture over SCENE_MAX_TEXTURE_SIZE" 2 "huge_texture.scene:[0-9]+: error: .*100000x100000 pixels; at most 8192 pixels a side" -- \
    $BT render --scene "$TMP/huge_texture.scene" --out "$TMP/a.png"
for f in px nx py ny pz nz; do
    png_header "$TMP/mixed_$f.png" 64 64
    png_header "$TMP/vast_$f.png" 16384 16384
done
png_header "$TMP/mixed_pz.png" 32 32
scene_with "$TMP/mixed_sky.scene" "$ASSETS/textures/checker_grey.png" "$TMP/mixed"
check "cube faces of two sizes" 2 "mixed_sky.scene:[0-9]+: error: .*mixed_pz.png\" is 32x32 pixels, face px 64x64; every face must have the same size" -- \
    $BT render --scene "$TMP/mixed_sky.scene" --out "$TMP/a.png"
scene_with "$TMP/vast_sky.scene" "$ASSETS/textures/checker_grey.png" "$TMP/vast"
check "cube face over SCENE_MAX_TEXTURE_SIZE" 2 "vast_sky.scene:[0-9]+: error: .*16384x16384 pixels; at most 8192" -- \
    $BT render --scene "$TMP/vast_sky.scene" --engine cpu --out "$TMP/a.png"

# ---- the image: each side and the pixel count, from the file, --set and --size. Each command also
# carries a later mistake, so that a build without the limit stops there at once instead of
# rendering gigabytes (and fails the test on the message).
printf '[render]\nwidth = 8192\n\nheight = 4096\nsegments = -1\n' > "$TMP/big.scene"
check "scene over SCENE_MAX_PIXELS" 2 "big.scene:4: error: key 'height' in \[render\]: the image would be 8192x4096 = 33554432 pixels; at most 8388608" -- \
    $BT render --scene "$TMP/big.scene" --out "$TMP/a.png"
check "--set over SCENE_MAX_PIXELS" 2 "^--set render.height=8192: error: .*at most 8388608 pixels" -- \
    $BT render --scene $S --set render.width=8192 --set render.height=8192 --set render.segments=-1 --out "$TMP/a.png"
check "--size over SCENE_MAX_PIXELS" 2 "--size: expected WxH with 1 <= W, H <= 8192 and W x H <= 8388608 pixels, got '8192x8192'" -- \
    $BT render --scene $S --size 8192x8192 --set render.segments=-1 --out "$TMP/a.png"
check "--size side over SCENE_MAX_SIZE" 2 "--size: .*got '100000x1'" -- $BT render --scene $S --size 100000x1 --out "$TMP/a.png"
check "--size huge number" 2 "--size: .*got '99999999999999999999x99999999999999999999'" -- \
    $BT trace --scene $S --size 99999999999999999999x99999999999999999999 --pixel 0 0
check "bench --size over SCENE_MAX_PIXELS" 2 "bench: --size: .*8388608 pixels" -- $BT bench --out "$TMP" --size 4096x4096 --runs 0

# ---- numbers: finite, in range, and within what the GPU's 32-bit floats hold
sed 's/^position = 0 1.5 9$/position = 0 1.5 2e18/' $S | sed "s#\.\./#$ASSETS/#" > "$TMP/far.scene"
check "number over SCENE_MAX_ABS_VALUE" 2 "far.scene:8: error: key 'position' in \[camera\]: .*larger in magnitude than 1e18" -- \
    $BT render --scene "$TMP/far.scene" --out "$TMP/a.png"
check "--set number over SCENE_MAX_ABS_VALUE" 2 "^--set render.bound_radius=1e300: error: .*1e18" -- \
    $BT render --scene $S --set render.bound_radius=1e300 --out "$TMP/a.png"
check "--set nan" 2 "^--set camera.fov=nan: error: .*not a finite number" -- $BT render --scene $S --set camera.fov=nan --out "$TMP/a.png"
check "--set -inf" 2 "^--set render.step=-inf: error: .*not a finite number" -- $BT render --scene $S --set render.step=-inf --out "$TMP/a.png"
check "--threads over CPU_MAX_THREADS" 2 "--threads: expected 0 \(one per core\) to 256, got '100000'" -- \
    $BT render --scene $S --engine cpu --threads 100000 --out "$TMP/a.png"
check "--rtol nan" 2 "--rtol: expected a relative tolerance from 1e-14 to 0.01, got 'nan'" -- \
    $BT render --scene $S --engine cpu --rtol nan --out "$TMP/a.png"
check "--pixel negative" 2 "--pixel" -- $BT trace --scene $S --pixel -1 5

# ---- files read whole: the scene file and dumps
{ echo "[scene]"; head -c 1048577 /dev/zero | tr '\0' ';'; echo; } > "$TMP/long.scene"
check "scene file over SCENE_MAX_FILE_BYTES" 2 "long.scene: error: .*larger than 1048576 bytes" -- \
    $BT render --scene "$TMP/long.scene" --out "$TMP/a.png"
dump_header "$TMP/square.dump" 4096 4096
dump_header "$TMP/short.dump" 100 100
check "dump over DUMP_MAX_PIXELS" 2 "unsupported dump \(version 2, 4096x4096.*at most 8388608 pixels" -- \
    $BT compare "$TMP/square.dump" "$TMP/short.dump"
check "dump records missing" 2 "short.dump is truncated: 0 of 10000 records" -- $BT compare "$TMP/short.dump" "$TMP/short.dump"

# ---- GL faults (BT_FAULT, src/gl/caps.h): fall back where the scene allows it, else exit 1
for b in egl osmesa; do
    check "fbo incomplete falls back ($b)" 0 "fp16\+mrt: RGBA16F ray state.*\(fell back from fp32\+mrt: RGBA32F framebuffer incomplete\) on $b" -- \
        env BT_FAULT=fbo_incomplete $BT render --scene $S --size 32x24 --backend $b --out "$TMP/f_$b.png"
    check "fbo incomplete, fp32 forced ($b)" 1 "render path fp32\+mrt: a ray-state framebuffer \(2 x RGBA32F colour, 16-bit depth, 32x24\) is incomplete: GL_FRAMEBUFFER_UNSUPPORTED" -- \
        env BT_FAULT=fbo_incomplete $BT render --scene $S --size 32x24 --backend $b --precision fp32 --out "$TMP/g_$b.png"
done
check "fbo incomplete, no path left" 1 "render path fp32\+mrt: .*incomplete: GL_FRAMEBUFFER_UNSUPPORTED \(0x8cdd\); try --precision fp16 or --no-mrt" -- \
    env BT_FAULT=fbo_incomplete,half_fbo_incomplete $BT render --scene $S --size 32x24 --out "$TMP/h.png"
check "fbo incomplete, fp16 forced" 1 "render path fp16\+mrt: a ray-state framebuffer \(2 x RGBA16F colour.*try --no-mrt" -- \
    env BT_FAULT=half_fbo_incomplete $BT render --scene $S --size 32x24 --precision fp16 --out "$TMP/i.png"
check "mrt fbo incomplete falls back" 0 "fp32: RGBA32F ray state, x and v written in separate passes \(fell back from fp32\+mrt: RGBA32F framebuffer incomplete\)" -- \
    env BT_FAULT=mrt_fbo_incomplete $BT render --scene $S --size 32x24 --out "$TMP/m.png"
check "mrt fbo incomplete, mrt forced" 1 "render path fp32\+mrt: a ray-state framebuffer \(2 x RGBA32F colour.*GL_FRAMEBUFFER_UNSUPPORTED" -- \
    env BT_FAULT=mrt_fbo_incomplete $BT render --scene $S --size 32x24 --set render.mrt=on --out "$TMP/n.png"
check "fbo fault in info" 0 "render path: +fp16\+mrt: .*fell back from fp32\+mrt" -- env BT_FAULT=fbo_incomplete $BT info --backend osmesa
check "float format does not render" 0 "fp16\+mrt: RGBA16F ray state" -- \
    env BT_FAULT=float_render $BT render --scene $S --size 32x24 --out "$TMP/j.png"
check "float fault in info" 0 "RGBA32F +no: not a render target \(BT_FAULT=float_render\)" -- env BT_FAULT=float_render $BT info --backend egl
check "no float format renders nor packs (gles2)" 1 "no renderable float format for the ray state.*or long fragment-shader loops \(OpenGL ES 3\) for the image alone, or floats packed into RGBA8 texels exactly \(.*BT_FAULT=packing" -- \
    env MESA_GLES_VERSION_OVERRIDE=2.0 BT_FAULT=float_render,half_float_render,packing $BT render --scene $S --size 32x24 --backend egl --out "$TMP/k.png"
# GLES 2 without float textures (VC4's kind): the packed path, the multipass scheme on 32-bit floats
# packed into RGBA8 texels (the orbit table too), draws the very picture, rays and outcomes of the
# fp32 multipass scheme one target a pass
PACKED="env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE='-GL_OES_texture_float -GL_OES_texture_half_float'"
for sc in test lorenz schwarzschild; do
    check "packed path draws the fp32 multipass picture ($sc)" 0 "^same$" -- sh -c "$PACKED $BT render --scene assets/scenes/$sc.scene \
        --size 40x30 --force --out $TMP/pk_p.png --dump $TMP/pk_p.dump 2>$TMP/pk_p.log && $BT render \
        --scene assets/scenes/$sc.scene --size 40x30 --set render.pipeline=multipass --no-mrt --force \
        --out $TMP/pk_f.png --dump $TMP/pk_f.dump 2>$TMP/pk_f.log && grep -q 'packed 8-bit: ' $TMP/pk_p.log && \
        cmp $TMP/pk_p.png $TMP/pk_f.png && $BT compare $TMP/pk_p.dump $TMP/pk_f.dump | grep -q 'outcome differs: 0 of' && \
        $BT compare $TMP/pk_p.dump $TMP/pk_f.dump | grep -qE 'hit point +[0-9]+ +0 +0 +0 ' && echo same"
done
# on a GPU (not a CPU rasteriser) the packed path shades each batch's hit in a pass of its own
# (render.hit_shading = auto takes separate there: VC4 cannot hold the one pass on exact orbits); the
# same picture, rays and outcomes, in more passes
check "packed path on a GPU: the hit shaded apart, the same picture (schwarzschild)" 0 "^same$" -- sh -c "$PACKED BT_FAULT=gpu_rasterizer \
    $BT render --scene assets/scenes/schwarzschild.scene --size 40x30 --force --out $TMP/hs_p.png --dump $TMP/hs_p.dump 2>$TMP/hs_p.log && \
    $PACKED $BT render --scene assets/scenes/schwarzschild.scene --size 40x30 --force --out $TMP/hs_i.png --dump $TMP/hs_i.dump \
    2>$TMP/hs_i.log && cmp $TMP/hs_p.png $TMP/hs_i.png && cmp $TMP/hs_p.dump $TMP/hs_i.dump && \
    [ \$(sed -n 's/.* \([0-9]*\) passes .*/\\1/p' $TMP/hs_p.log) -gt \$(sed -n 's/.* \([0-9]*\) passes .*/\\1/p' $TMP/hs_i.log) ] && echo same"
check "info: hit shading apart on a GPU without MRT" 0 "^hit shading: +a pass of its own .*auto takes separate" -- \
    env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE="-GL_OES_texture_float -GL_OES_texture_half_float" \
    BT_FAULT=gpu_rasterizer $BT info --backend egl
# a driver that skips every draw with a program it cannot hold (VC4's, without a GL error): each new
# program is drawn once into a texel cleared to two colours, and a scene whose program drew nothing
# is refused with its stage; in passes of their own the stage's programs draw
check "a program the driver does not draw is refused" 1 "the GPU's driver draws nothing with the program of stage_intersect \(.*render.hit_shading = separate draws this stage in smaller passes \(BT_FAULT=draw_skipped\)" -- \
    env BT_FAULT=draw_skipped $BT render --scene assets/scenes/schwarzschild.scene --size 16x12 --set render.pipeline=multipass \
    --out "$TMP/ds_r.png"
check "a program the driver does not draw is refused (osmesa)" 1 "the GPU's driver draws nothing with the program of stage_intersect" -- \
    env BT_FAULT=draw_skipped $BT render --scene assets/scenes/lorenz.scene --size 16x12 --set render.pipeline=multipass \
    --backend osmesa --out "$TMP/ds_o.png"
check "the stage in passes of their own draws where the one pass is skipped" 0 "^same$" -- sh -c "env BT_FAULT=draw_skipped \
    $BT render --scene assets/scenes/schwarzschild.scene --size 40x30 --set render.pipeline=multipass --no-mrt \
    --set render.hit_shading=separate --force --out $TMP/ds_s.png 2>/dev/null && $BT render --scene assets/scenes/schwarzschild.scene \
    --size 40x30 --set render.pipeline=multipass --no-mrt --force --out $TMP/ds_i.png 2>/dev/null && cmp $TMP/ds_s.png $TMP/ds_i.png && echo same"
# a choice for a pipeline the frame does not run is said on the render line, not ignored
check "a choice for a pipeline not run is said" 0 "\(single pass: .*; render.hit_shading is for the multipass scheme's intersection stage, which this frame does not run; render.orbit_walk is for the single pass on exact orbits, which this frame does not run\)" -- \
    $BT render --scene assets/scenes/lorenz.scene --size 16x12 --set render.hit_shading=separate --set render.orbit_walk=inline \
    --out "$TMP/hs_u.png"
check "hit shading apart refused on a 16-bit ray state" 2 "render.hit_shading = separate: the hit found would be kept between passes in 16-bit floats \(render path fp16" -- \
    $BT render --scene $S --size 16x12 --precision fp16 --set render.pipeline=multipass --set render.hit_shading=separate \
    --out "$TMP/hs_r.png"
check "precision packed on a GPU with float targets" 0 "^lorenz: 16x12, .* packed 8-bit: render.precision = packed, .*multipass: the packed path writes one float a fragment" -- \
    $BT render --scene assets/scenes/lorenz.scene --size 16x12 --precision packed --out "$TMP/pk_q.png"
check "precision packed refused where floats do not pack" 2 "--precision packed: floats do not pack into RGBA8 texels exactly here \(.*BT_FAULT=packing" -- \
    env BT_FAULT=packing $BT render --scene assets/scenes/lorenz.scene --size 16x12 --precision packed --out "$TMP/pk_r.png"
check "precision packed takes no single pass" 2 "render.pipeline = single: the packed path .* runs the multipass scheme" -- \
    $BT render --scene assets/scenes/lorenz.scene --size 16x12 --precision packed --set render.pipeline=single --out "$TMP/pk_s.png"
# no float format renders, but the GPU runs long loops: the image-only path, the single pass's image
# and outcome codes in 8-bit targets, the very picture and summary of the float path; what needs
# the rest of the ray state is refused before any pass, with what needs it
NOFLOAT="env BT_FAULT=float_render,half_float_render"
# (demo's stars: the image-only path draws them on the GPU, render.star_pass = auto, so the float path
# is run with the GPU's star pass too)
for sc in schwarzschild lorenz demo; do
    check "image only draws the float path's picture ($sc)" 0 "^same$" -- sh -c "$NOFLOAT $BT render --scene assets/scenes/$sc.scene \
        --size 48x36 --force --out $TMP/io_n.png 2>$TMP/io_n.log && $BT render --scene assets/scenes/$sc.scene --size 48x36 --set render.star_pass=gpu \
        --force --out $TMP/io_f.png 2>$TMP/io_f.log && grep -qE 'image only: .* [0-9]+ pass(es)? \\(single pass' $TMP/io_n.log && \
        cmp $TMP/io_n.png $TMP/io_f.png && [ \"\$(grep '^rays:' $TMP/io_n.log)\" = \"\$(grep '^rays:' $TMP/io_f.log)\" ] && echo same"
done
check "image only in info" 0 "render path: +image only: no float format renders here" -- $NOFLOAT $BT info --backend egl
# info's ladder: every path with yes or why not, the pipelines and exact orbits as they follow
check "info lists the paths" 0 "^  fp32\+mrt +yes \(RGBA32F\) \|.*   fp16 +yes \(RGBA16F; reduced accuracy\) \|   image only +not taken: a float format renders \|   packed 8-bit +not taken: a 32-bit float format renders \(packing floats into RGBA8 texels: exact, 256 floats" -- \
    sh -c "$BT info --backend egl | grep '^  [a-z]' | tr '\n' '|' | sed 's/|/ | /g'"
# the packing probed where it is needed: an ES 2 GPU without float textures (VC4's kind)
check "info: packing exact on gles2 without float textures" 0 "^  packed 8-bit +yes \(each 32-bit float of the ray state in an RGBA8 texel: 256 floats" -- \
    env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE="-GL_OES_texture_float -GL_OES_texture_half_float" $BT info --backend egl
check "info: packing refused by its fault" 0 "^  packed 8-bit +no: .* packed as .*\(BT_FAULT=packing\)" -- \
    env BT_FAULT=packing $BT info --backend egl
check "info lists the paths, none renders" 0 "^  fp32\+mrt +no: no 32-bit float format renders \|.*   image only +yes \(the image and the rays' outcomes in 8-bit targets.*pipeline: +single pass only.*exact orbits: +yes: .* sampled as RGBA32F" -- \
    sh -c "$NOFLOAT $BT info --backend egl | grep '^  [a-z]\|^pipeline\|^exact' | tr '\n' '|' | sed 's/|/ | /g'"
check "info: exact orbits on a 16-bit ray state in the single pass" 0 "^exact orbits: +yes: .* sampled as RGBA32F, in the single pass" -- \
    env BT_FAULT=float_render $BT info --backend egl
check "info: exact orbits on gles2 packed, not on its 16-bit ray state" 0 "^exact orbits: +yes: render.method = orbit_table's table sampled as RGBA8 \(packed floats\)" -- \
    env MESA_GLES_VERSION_OVERRIDE=2.0 $BT info --backend egl
check "image only refuses a dump" 1 "render path image only: reading the rays' state back \(--dump" -- \
    $NOFLOAT $BT render --scene $S --size 32x24 --out "$TMP/io1.png" --dump "$TMP/io1.dump"
check "image only refuses a float image" 1 "render path image only: writing a float image" -- \
    $NOFLOAT $BT render --scene $S --size 32x24 --out "$TMP/io2.pfm"
check "image only refuses the stars' exit directions" 1 "render path image only: drawing the stars of the sky.*; render.star_pass = gpu \(or auto\) draws them" -- \
    $NOFLOAT $BT render --scene assets/scenes/star_sky.scene --set render.star_pass=cpu --size 32x24 --out "$TMP/io3.png"
# render.star_pass = auto (the default) draws them on the GPU there: the picture of the GPU's pass on the float path
check "image only draws the stars on the GPU" 0 "^same$" -- sh -c "$NOFLOAT $BT render --scene assets/scenes/star_sky.scene \
    --size 48x36 --quiet --out $TMP/io_s1.png > /dev/null && $BT render --scene assets/scenes/star_sky.scene --set render.star_pass=gpu \
    --size 48x36 --quiet --out $TMP/io_s2.png > /dev/null && cmp $TMP/io_s1.png $TMP/io_s2.png && echo same"
check "image only refuses bloom" 1 "render path image only: render.bloom \(the frame's colour read back as floats\) needs float render targets" -- \
    $NOFLOAT $BT render --scene assets/scenes/demo.scene --set render.bloom=0.2 --size 32x24 --out "$TMP/io4.png"
check "image only refuses trace" 1 "render path image only: reading the rays after every segment" -- \
    $NOFLOAT $BT trace --scene $S --size 32x24 --pixel 3 3
check "image only refuses the multipass scheme" 1 "render path image only .*cannot run in the single pass \(render.pipeline = multipass\)" -- \
    $NOFLOAT $BT render --scene $S --size 32x24 --set render.pipeline=multipass --out "$TMP/io4.png"
check "image only without mrt has no summary" 2 "render path image only: each ray's outcome .*render.mrt = off" -- \
    $NOFLOAT $BT render --scene $S --size 32x24 --no-mrt --out "$TMP/io5.png"
for f in io1.png io1.dump io2.pfm io3.png io4.png io5.png; do
    check "image only refusal wrote nothing ($f)" 0 "^absent$" -- sh -c "test -e '$TMP/$f' && echo exists || echo absent"
done
# a GPU whose fragment shaders compute in 16-bit floats draws no picture rather than a wrong one:
# the probe finds it out by arithmetic, whatever precision the GPU reports
for fault in no_highp fp16_alu; do
    check "fragment arithmetic in fp16 refused ($fault)" 1 "does not compute its fragment shaders in 32-bit floats: \(1 \+ 2\^-12\)\^2 - 1 came out as .*; bentray's rays need them, so it draws nothing rather than a wrong picture" -- \
        env BT_FAULT=$fault $BT render --scene assets/scenes/potential.scene --size 32x24 --out "$TMP/fp16_$fault.png"
done
check "fp16 arithmetic in info" 0 "^arithmetic: +no 32-bit floats: \(1 \+ 2\^-12\)\^2 - 1 came out as 0.0000 x 2\^-10" -- env BT_FAULT=no_highp $BT info --backend egl
check "fp32 arithmetic in info" 0 "^arithmetic: +32-bit floats \(probed\)" -- $BT info --backend osmesa
# a loop the GPU ends early (llvmpipe: after 65535 turns) would leave rays short of their budget: the
# probe counts the turns one really runs, and a single pass that would need more is not taken
for b in egl osmesa; do
    check "loop turns probed ($b)" 0 "^loop turns: +([0-9]+: a fragment-shader loop ends there|at least 200000) \(probed\)" -- $BT info --backend $b
done
check "loop limit in info" 0 "^loop turns: +4096: a fragment-shader loop ends there" -- env BT_FAULT=loop_limit $BT info --backend egl
check "a ray longer than the GPU's loops is not drawn in one pass" 0 "\(fused segment: this GPU ends a fragment-shader loop after 4096 turns \(probed\), and one ray may take 5000 segments" -- \
    env BT_FAULT=loop_limit $BT render --scene assets/scenes/potential.scene --size 16x12 --set render.segments=5000 --set render.max_path=0 --out "$TMP/loops.png"
check "a ray within the GPU's loops is" 0 "\(single pass: " -- \
    env BT_FAULT=loop_limit $BT render --scene assets/scenes/potential.scene --size 16x12 --set render.segments=4096 --set render.max_path=0 --out "$TMP/loops4096.png"
check "exact orbits longer than the GPU's loops" 0 "this GPU ends a fragment-shader loop after 4096 turns \(probed\), and one ray may take 3000 chords" -- \
    env BT_FAULT=loop_limit $BT render --scene assets/scenes/schwarzschild.scene --size 16x12 --set render.max_chords=3000 --out "$TMP/loops_orbit.png"
# the scene's own choice of the single pass does not override the GPU's loop limit: refused, not cut short
check "single pass asked for, longer than the GPU's loops" 2 "^bentray render: render.pipeline = single: this GPU ends a fragment-shader loop after 4096 turns \(probed\), and one ray may take 5000 segments; use render.pipeline = auto or multipass" -- \
    env BT_FAULT=loop_limit $BT render --scene assets/scenes/potential.scene --size 16x12 --set render.segments=5000 --set render.max_path=0 --set render.pipeline=single --out "$TMP/loops_single.png"
check "single pass asked for, within the GPU's loops" 0 "\(single pass: render.pipeline = single\)" -- \
    env BT_FAULT=loop_limit $BT render --scene assets/scenes/potential.scene --size 16x12 --set render.segments=4096 --set render.max_path=0 --set render.pipeline=single --out "$TMP/loops_single4096.png"
echo "limit and fault tests: $fails failed"
[ "$fails" = 0 ]
