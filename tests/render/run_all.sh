#!/usr/bin/env bash
# Command-line tests of the bentray binary: exit codes, error messages, the render paths that
# need a different GL environment (GLES 2.0, missing extensions), both back-ends.
set -u
. "$(dirname "$0")/check.sh"
S=assets/scenes/test.scene
check "help" 0 "usage: bentray" -- $BT --help
check "render help" 0 "--scene FILE" -- $BT render --help
check "no command" 2 "usage" -- $BT
check "unknown command" 2 "unknown command" -- $BT frobnicate
check "unknown option" 2 "unknown option" -- $BT render --scene $S --frob
# every command reads its options from one table through one parser (src/cli/options.c): the same
# words for an unknown option, a missing value and a stray argument, whatever the command
check "option guessed" 2 "^bentray render: unknown option '--scnee' \\(did you mean --scene\\?\\)" -- $BT render --scnee $S
check "kiosk option guessed" 2 "^bentray kiosk: unknown option '--confg' \\(did you mean --config\\?\\)" -- $BT kiosk --confg x
for cmd in "render --scene $S --out" "kiosk --config" "bench --out" "trace --scene" "error --scene" \
           "animate --scene $S --frames"; do
    set -- $cmd
    check "$1: value missing at the end" 2 "^bentray $1: option ${@: -1} needs a value" -- $BT $cmd
done
check "value that is an option" 2 "^bentray render: option --out needs a value \\(FILE\\), not the option '--force'" -- \
    $BT render --scene $S --out --force
check "stray argument" 2 "^bentray render: unexpected argument 'extra.png'" -- $BT render --scene $S extra.png
# read with getopt_long: a value joined with '=' or beginning with '-', unique abbreviations (named
# in full where they are echoed), and the refusals; "--" and a single dash stay unknown options
check "value joined with =" 2 "^bentray trace: --pixel: 5000 1 is outside" -- $BT trace --scene=$S --pixel=5000 1
check "value beginning with -" 2 "^bentray render: --rtol: expected a relative tolerance from 1e-14 to 0.01, got '-1'" -- \
    $BT render --scene $S --engine cpu --rtol -1 --out "$TMP/neg.png"
check "abbreviations" 0 "on (egl|osmesa).*, 2 samples a pixel" -- $BT render --sc $S --si 8x6 --sa 2 --ou "$TMP/abbrev.png"
check "abbreviations echoed in full" 0 "^frame 1/1 .*: bentray render --scene $S --size 16x12 --out " -- \
    $BT animate --sc $S --fr 1 --si 16x12 --ou "$TMP/anim_abbrev"
check "ambiguous abbreviation" 2 "^bentray render: option '--s' is ambiguous \(--scene, --shader-dir, --size, --samples, --set\); give more of its name" -- \
    $BT render --s $S
check "abbreviation missing its value" 2 "^bentray render: option --out needs a value \(FILE\)$" -- $BT render --scene $S --ou
check "flag given a value" 2 "^bentray render: option --force takes no value, got '--force=yes'" -- $BT render --scene $S --force=yes
check "double dash" 2 "^bentray compare: unknown option '--'" -- $BT compare -- a.dump b.dump
check "single dash" 2 "^bentray render: unknown option '-scene' \(did you mean --scene\?\)" -- $BT render -scene $S
check "info stray argument" 2 "^bentray info: unexpected argument 'egl'" -- $BT info egl
check "bad size" 2 "\-\-size" -- $BT render --scene $S --size 10by10
check "bad backend" 2 "\-\-backend" -- $BT render --scene $S --backend vulkan
check "bad precision" 2 "\-\-precision" -- $BT render --scene $S --precision fp8
check "missing scene" 2 "nosuch.scene" -- $BT render --scene "$TMP/nosuch.scene"
check "bad --set key" 2 "\-\-set model.mas=1" -- $BT render --scene $S --set model.mas=1
check "bad --set value" 2 "expected" -- $BT render --scene assets/scenes/schwarzschild.scene --set model.mass=-1
check "pixel outside" 2 "outside" -- $BT trace --scene $S --pixel 5000 1
# a control character in a quoted value is shown as \xNN, never sent raw to the terminal
printf '[render]\nwidth = 1\033[31mred\n' > "$TMP/ctrl.scene"
check "control characters escaped" 2 'got "1\\x1b\[31mred"' -- $BT render --scene "$TMP/ctrl.scene" --out "$TMP/x.png"
check "no raw escape character" 0 "^0$" -- sh -c "$BT render --scene $TMP/ctrl.scene --out $TMP/x.png 2>&1 | tr -dc '\033' | wc -c"
# every bad scene fixture: exit 2 and a message that names the file
for f in tests/scenes_bad/*.scene; do
    check "bad scene $(basename "$f")" 2 "$(basename "$f")(:[0-9]+)?: error: " -- $BT render --scene "$f" --out "$TMP/x.png"
done
# both back-ends render; the output is not replaced without --force
check "render egl" 0 "hit an object" -- $BT render --scene $S --size 32x24 --backend egl --out "$TMP/a.png"
check "no overwrite" 2 "--out: refusing to replace" -- $BT render --scene $S --size 32x24 --out "$TMP/a.png"
check "render osmesa" 0 "on osmesa" -- $BT render --scene $S --size 32x24 --backend osmesa --out "$TMP/b.png"
check "samples egl" 0 "4 samples a pixel" -- $BT render --scene $S --size 32x24 --backend egl --samples 4 --out "$TMP/aa_egl.png"
check "samples osmesa" 0 "5 samples a pixel" -- $BT render --scene $S --size 32x24 --backend osmesa --samples=5 --out "$TMP/aa_osmesa.png"
check "samples cpu" 0 "CPU reference .* 2 samples a pixel" -- $BT render --scene $S --size 32x24 --engine cpu --samples 2 --out "$TMP/aa_cpu.png"
check "samples zero" 2 "^bentray render: --samples: expected rays per pixel from 1 to 256, got '0'" -- $BT render --scene $S --samples 0
check "samples not a number" 2 "^bentray error: --samples: expected rays per pixel" -- $BT error --scene $S --samples four
check "samples key range" 2 "key 'samples' in \\[render\\]: expected an integer from 1 to 256" -- $BT render --scene $S --set render.samples=257
check "trace refuses samples" 2 "trace: --samples: trace follows one ray" -- $BT trace --scene $S --pixel 1 1 --samples 4
check "progress gpu" 0 "^gpu: 240/240 rows \\(100%\\), [0-9.]+ s, about 0 s left$" -- $BT render --scene $S --progress --out "$TMP/p1.png"
check "progress samples" 0 "^gpu: sample 2/2, 24/24 rows \\(100%\\)" -- $BT render --scene $S --size 32x24 --samples 2 --progress --out "$TMP/p2.png"
check "progress dump centres" 0 "^gpu: pixel centres, 24/24 rows \\(33%\\)" -- $BT render --scene $S --size 32x24 --samples 2 --progress --dump "$TMP/p3.dump" --out "$TMP/p3.png"
check "progress cpu" 0 "^cpu reference: 24/24 rows \\(100%\\)" -- $BT render --scene $S --size 32x24 --engine cpu --progress --out "$TMP/p4.png"
check "progress in a log has no carriage return" 0 "^0$" -- sh -c "$BT render --scene $S --progress --out $TMP/p5.png 2>&1 >/dev/null | tr -cd '\\r' | wc -c"
check "progress and quiet" 2 "--progress and --quiet contradict" -- $BT render --scene $S --progress --quiet --out "$TMP/p6.png"
check "quiet has no progress" 0 "^1$" -- sh -c "$BT render --scene $S --samples 3 --out $TMP/p7.png --quiet 2>&1 | wc -l"
# make install: the program, a man page groff reads without a warning, a completion bash loads
check "install" 0 "^bin man completion$" -- sh -c "make --no-print-directory install DESTDIR=$TMP/inst PREFIX=/usr > /dev/null && test -x $TMP/inst/usr/bin/bentray && test -f $TMP/inst/usr/share/man/man1/bentray.1 && test -f $TMP/inst/usr/share/bash-completion/completions/bentray && echo bin man completion"
check "man page" 0 "^0 warnings, [0-9]+ lines$" -- sh -c "w=\$(groff -man -Tutf8 -ww -z docs/bentray.1 2>&1 | wc -l); l=\$(groff -man -Tutf8 docs/bentray.1 2>/dev/null | wc -l); echo \"\$w warnings, \$l lines\""
check "man page lists every command" 0 "^8 of 8$" -- sh -c "n=0; for c in render animate trace error compare info bench kiosk; do grep -q \"^.B \$c\$\" docs/bentray.1 && n=\$((n + 1)); done; echo \"\$n of 8\""
check "completion" 0 "^render,--set --set-range,egl osmesa auto$" -- bash -c "source shell/bentray.bash; COMP_WORDS=(bentray re); COMP_CWORD=1; _bentray; a=\${COMPREPLY[*]}; COMP_WORDS=(bentray animate --se); COMP_CWORD=2; _bentray; b=\${COMPREPLY[*]}; COMP_WORDS=(bentray render --backend ''); COMP_CWORD=3; _bentray; c=\${COMPREPLY[*]}; echo \"\$a,\$b,\$c\""
# animate: every frame is `bentray render` of the settings it prints, byte for byte
check "animate frames equal their render commands" 0 "^3 of 3 identical$" -- sh -c "$BT animate --scene assets/scenes/schwarzschild.scene --frames 3 --size 40x30 --samples 2 --set-range model.mass=0:0.2 --set-range 'camera.fov=50:35' --orbit 90 --out $TMP/anim > $TMP/anim.txt && n=0 && while read -r line; do cmd=\${line#*: }; out=\${cmd##* --out }; cmd=\${cmd% --out *}; eval \"$BT render \${cmd#bentray render } --force --quiet --out $TMP/again.png\" > /dev/null && cmp -s $TMP/again.png \"\$out\" && n=\$((n + 1)); done < $TMP/anim.txt && echo \"\$n of 3 identical\""
check "animate cpu" 0 "^frame 2/2 .*--engine cpu" -- $BT animate --scene $S --engine cpu --frames 2 --size 16x12 --set-range camera.fov=40:60 --out "$TMP/anim_cpu"
check "animate refuses old frames" 2 "refusing to replace" -- $BT animate --scene assets/scenes/schwarzschild.scene --frames 3 --size 40x30 --out "$TMP/anim"
check "animate frames" 2 "^bentray animate: --frames: expected 1 to 10000, got '0'" -- $BT animate --scene $S --frames 0 --out "$TMP/a0"
check "animate frames required" 2 "--frames N is required" -- $BT animate --scene $S --out "$TMP/a0"
check "animate range syntax" 2 "--set-range: expected KEY=FROM:TO" -- $BT animate --scene $S --frames 2 --set-range camera.fov=40 --out "$TMP/a0"
check "animate range key" 2 "--set-range camera.zoom=1:2: no such key" -- $BT animate --scene $S --frames 2 --set-range camera.zoom=1:2 --out "$TMP/a0"
check "animate range choice" 2 "only a number, vector or colour key" -- $BT animate --scene $S --frames 2 --set-range render.method=rk4:euler --out "$TMP/a0"
check "animate range components" 2 "FROM and TO must be the same number" -- $BT animate --scene $S --frames 2 --set-range "camera.position=0 0 5:1 1" --out "$TMP/a0"
check "animate frame out of range" 2 "^bentray animate: frame 3: --set camera.fov=180: error: key 'fov'" -- $BT animate --scene $S --frames 3 --set-range camera.fov=60:180 --out "$TMP/a0"
check "animate orbit and camera range" 2 "--orbit and --set-range camera.position: the orbit moves the camera" -- $BT animate --scene $S --frames 2 --orbit 90 --set-range "camera.position=0 0 5:0 0 6" --out "$TMP/a0"
check "animate orbit" 2 "--orbit: expected degrees" -- $BT animate --scene $S --frames 2 --orbit left --out "$TMP/a0"
# a fly-over: the orbit about an axis of its own turns camera.up with the camera (upside down halfway)
check "animate orbit axis" 0 "frame 3/4 .* --set 'camera.up=0 -1 [0-9.e-]+' --out" -- $BT animate --scene assets/scenes/demo.scene --frames 4 --size 32x18 --orbit 360 --orbit-axis "1 0 0" --out "$TMP/fly"
check "animate orbit axis without orbit" 2 "--orbit-axis gives the axis of --orbit DEGREES" -- $BT animate --scene $S --frames 2 --orbit-axis "1 0 0" --out "$TMP/a0"
check "animate out is a file" 2 "--out $TMP/p1.png: not a directory" -- $BT animate --scene $S --frames 2 --out "$TMP/p1.png"
check "animate video extension" 2 "--video $TMP/v.avi: give the file the extension .webm, .mp4 or .gif" -- $BT animate --scene $S --frames 2 --out "$TMP/a0" --video "$TMP/v.avi"
# without ffmpeg the frames are made, and the command that makes the video from them is printed
check "animate video without ffmpeg" 1 "ffmpeg is not installed \(Debian: apt-get install ffmpeg\); the frames are in .*/a0n, and this makes the video from them:" -- env PATH=/nonexistent $BT animate --scene $S --frames 2 --size 16x12 --out "$TMP/a0n" --video "$TMP/v.gif"
check "animate video without ffmpeg: the frames" 0 "^2 frames$" -- sh -c "echo \$(ls '$TMP/a0n' | grep -c '^frame_.*png\$') frames"
if command -v ffmpeg > /dev/null; then
    check "animate video" 0 "^video: $TMP/v.gif \(4 frames at 12 per second\)" -- $BT animate --scene $S --frames 4 --size 32x24 --orbit 360 --fps 12 --out "$TMP/a4" --video "$TMP/v.gif"
    # only this run's frames, though an earlier run left more; the caller's input is left alone; a '%'
    # in the directory's name
    mkdir -p "$TMP/a%d"
    $BT animate --scene $S --frames 7 --size 16x12 --out "$TMP/a%d" --quiet > /dev/null
    check "animate video: this run's frames only" 0 "^frames 2, lines 3$" -- sh -c "printf 'a\nb\nc\n' | { $BT animate --scene $S --frames 2 --size 16x12 --out '$TMP/a%d' --force --quiet --video '$TMP/two.webm' > /dev/null; echo frames \$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 '$TMP/two.webm'), lines \$(wc -l); }"
else
    echo "skip animate video: ffmpeg is not installed"
fi
# a ray that hit an object in segment 14 of 60 (steps of 0.5 throughout): its polyline ends there,
# the end not repeated; with lorenz's far steps the same ray hits it in fewer segments, and its
# polyline ends in the segment of its depth (depth 6.09: segments 0 to 6, 8 points)
check "trace polyline ends where the ray ends" 0 "^15 points, 0 repeated$" -- sh -c "$BT trace --scene assets/scenes/lorenz.scene --size 32x24 --pixel 16 16 --set render.far_step=0 > $TMP/t.json && echo \"\$(grep -c '^    \[' $TMP/t.json) points, \$(grep '^    \[' $TMP/t.json | uniq -d | wc -l) repeated\""
check "trace polyline ends where the ray ends (far steps)" 0 "^8 points, 0 repeated, depth 6$" -- sh -c "$BT trace --scene assets/scenes/lorenz.scene --size 32x24 --pixel 16 16 > $TMP/t.json && echo \"\$(grep -c '^    \[' $TMP/t.json) points, \$(grep '^    \[' $TMP/t.json | uniq -d | wc -l) repeated, depth \$(sed -n 's/^  \"depth\": \([0-9]*\)\..*/\1/p' $TMP/t.json)\""
# on exact orbits the GPU's polyline follows the orbit from the table to where the ray ended: every
# point of the CPU reference's curve lies within 2e-3 of it (its 64 samples' own sag), and both end
# at the same point (a hit, the sky's sphere, the horizon)
for ray in "neutron_star 160 120" "neutron_star 40 40" "schwarzschild 170 100" "schwarzschild 160 120"; do
    read -r sc px py <<< "$ray"
    check "trace on exact orbits follows the orbit ($ray)" 0 "gap ([0-9.]+e-0[4-9]|0\.00[01][0-9]*|0), ends [0-9.]+e-(0[5-9]|[1-9][0-9])$" -- sh -c \
        "$BT trace --scene assets/scenes/$sc.scene --pixel $px $py > $TMP/orbit_gpu.json && $BT trace --scene assets/scenes/$sc.scene --pixel $px $py --engine cpu > $TMP/orbit_cpu.json && awk -f tests/render/polyline_gap.awk $TMP/orbit_cpu.json $TMP/orbit_gpu.json"
done
check "trace doppler ahead" 0 "\"doppler\": 1\.99" -- $BT trace --scene assets/scenes/starflight.scene --size 32x24 --pixel 16 12
# the accretion disk's frequency ratio g at the hit: above 1 where the matter comes towards the
# camera (left), below 1 where it goes away, the same on both engines to float roundings
for side in "150 140 approaching 1" "330 140 receding 0"; do
    set -- $side
    check "trace accretion g, $3 side" 0 "^agree $4\$" -- sh -c "$BT trace --scene assets/scenes/demo.scene --pixel $1 $2 \
        --engine gpu | sed -n 's/^  \"g\": \(.*\),\$/\1/p' > $TMP/g_gpu && $BT trace --scene assets/scenes/demo.scene \
        --pixel $1 $2 --engine cpu | sed -n 's/^  \"g\": \(.*\),\$/\1/p' > $TMP/g_cpu && \
        awk -v a=\$(cat $TMP/g_gpu) -v b=\$(cat $TMP/g_cpu) 'BEGIN { d = a / b - 1; if (d < 0) d = -d;
        print (d <= 1e-5 ? \"agree\" : \"differ \" a \" \" b), (b > 1) }'"
done
# without gravity's shift (observer.gravitational_shift = off, the kiosk's layer before it) the
# disk's g is its motion's alone: the same on both engines, and higher than with gravity's redshift
check "trace accretion g without gravity's shift" 0 "^agree higher\$" -- sh -c "$BT trace --scene assets/scenes/demo.scene \
    --pixel 200 150 --set observer.gravitational_shift=off | sed -n 's/^  \"g\": \(.*\),\$/\1/p' > $TMP/g_off && \
    $BT trace --scene assets/scenes/demo.scene --pixel 200 150 --set observer.gravitational_shift=off --engine cpu \
    | sed -n 's/^  \"g\": \(.*\),\$/\1/p' > $TMP/g_off_cpu && $BT trace --scene assets/scenes/demo.scene --pixel 200 150 \
    | sed -n 's/^  \"g\": \(.*\),\$/\1/p' > $TMP/g_on && awk -v a=\$(cat $TMP/g_off) -v b=\$(cat $TMP/g_off_cpu) \
    -v c=\$(cat $TMP/g_on) 'BEGIN { d = a / b - 1; if (d < 0) d = -d; print (d <= 1e-5 ? \"agree\" : \"differ \" a \" \" b),
    (a > 1.01 * c ? \"higher\" : \"not higher \" a \" \" c) }'"
check "gravitational_shift is on or off" 2 "observer.gravitational_shift" -- $BT render --scene assets/scenes/demo.scene --set observer.gravitational_shift=maybe --out "$TMP/gs.png"
check "trace doppler behind" 0 "\"doppler\": 0\.50" -- $BT trace --scene assets/scenes/starflight.scene --size 32x24 --pixel 16 12 --set "camera.look_at=0 0 1"
check "trace colour" 0 "\"color\": \[[0-9]+, [0-9]+, [0-9]+\]," -- $BT trace --scene $S --size 32x24 --pixel 16 12 --engine cpu
check "trace json" 0 "\"outcome\": \"(object|sky)\"" -- $BT trace --scene $S --size 32x24 --pixel 16 12
check "trace of a ray with more chords than segments" 0 "\"outcome\": \"sky\"" -- $BT trace --scene assets/scenes/demo.scene --size 32x24 --pixel 3 3
check "info" 0 "RGBA32F +works" -- $BT info
# each context has its own pass quad: OSMesa probed after EGL works as well as alone
check "info both back-ends work" 0 "^2$" -- sh -c "$BT info | grep -cE '^render path: +fp32\+mrt'"
# exact orbits: single pass on both back-ends, the multipass scheme on request, refusals where they
# do not apply, integration where the GPU lacks 32-bit float textures
B=assets/scenes/schwarzschild.scene
check "orbit table egl" 0 " 1 pass \(single pass: OpenGL ES 3.2 runs" -- $BT render --scene $B --size 32x24 --backend egl --out "$TMP/o1.png"
check "orbit table osmesa" 0 "on osmesa.*\(single pass: " -- $BT render --scene $B --size 32x24 --backend osmesa --out "$TMP/o2.png"
# the walk along exact orbits in a pass of its own (a GPU's default; llvmpipe's is inline): the same
# rays bit for bit on both back-ends, also where no occlusion query says that no ray goes on
for walk_case in "egl" "osmesa" "egl BT_FAULT=occlusion_query"; do
    set -- $walk_case
    check "orbit walk separate is inline ($walk_case)" 0 "^same [4-9] passes$" -- sh -c "env ${2:-} $BT render --scene $B --size 64x48 \
        --backend $1 --set render.orbit_walk=separate --force --out $TMP/ow_s.png --dump $TMP/ow_s.dump > $TMP/ow_s.txt 2>&1 && \
        $BT render --scene $B --size 64x48 --backend $1 --set render.orbit_walk=inline --force --out $TMP/ow_i.png \
        --dump $TMP/ow_i.dump >/dev/null 2>&1 && cmp $TMP/ow_s.png $TMP/ow_i.png && cmp $TMP/ow_s.dump $TMP/ow_i.dump && \
        echo same \$(grep -o '[0-9]* passes' $TMP/ow_s.txt)"
done
# a CPU rasteriser taken for a GPU (BT_FAULT=gpu_rasterizer): the single passes' variants for a
# GPU's register file (the walk in a pass of its own, the integrated pass's chord cull read from its
# uniforms) draw the same rays bit for bit
for sc in lorenz cube_approach schwarzschild; do
    check "gpu variants draw the cpu's rays ($sc)" 0 "^same$" -- sh -c "env BT_FAULT=gpu_rasterizer $BT render \
        --scene assets/scenes/$sc.scene --size 48x36 --force --out $TMP/gv_g.png --dump $TMP/gv_g.dump >/dev/null 2>&1 && \
        $BT render --scene assets/scenes/$sc.scene --size 48x36 --force --out $TMP/gv_c.png --dump $TMP/gv_c.dump \
        >/dev/null 2>&1 && cmp $TMP/gv_g.png $TMP/gv_c.png && cmp $TMP/gv_g.dump $TMP/gv_c.dump && echo same"
done
check "info --shader frame for a gpu compiles" 0 "^compiled, 1 cull from uniforms$" -- sh -c "env BT_FAULT=gpu_rasterizer $BT info \
    --shader frame --scene assets/scenes/lorenz.scene > '$TMP/gpu_frame.frag' && glslangValidator -S frag '$TMP/gpu_frame.frag' > '$TMP/glslang_gf.log' && \
    echo compiled, \$(grep -c '^#define CHORD_CULL_UNIFORMS 1' '$TMP/gpu_frame.frag') cull from uniforms || cat '$TMP/glslang_gf.log'"
check "info takes llvmpipe for a gpu under BT_FAULT=gpu_rasterizer" 0 "^orbit walk: +a pass of its own" -- env BT_FAULT=gpu_rasterizer $BT info --backend egl
check "info says where the orbit walk runs" 0 "^orbit walk: +in the frame's pass \\(a CPU rasteriser" -- $BT info --backend egl
check "info --shader orbit_walk compiles" 0 "^compiled$" -- sh -c "$BT info --shader orbit_walk --scene $B \
    --set render.orbit_walk=separate --no-mrt > '$TMP/walk.frag' && grep -q 'void main' '$TMP/walk.frag' && \
    glslangValidator -S frag '$TMP/walk.frag' > '$TMP/glslang_walk.log' && echo compiled || cat '$TMP/glslang_walk.log'"
check "orbit table multipass" 0 "\(multipass: render.pipeline = multipass\)" -- $BT render --scene $B --size 32x24 --set render.pipeline=multipass --out "$TMP/o3.png"
check "orbit table, other model" 2 "orbit_table follows the exact orbits of Schwarzschild space" -- $BT render --scene assets/scenes/lorenz.scene --set render.method=orbit_table --out "$TMP/o4.png"
# integrated rays: the single pass where the GPU runs long loops, the multipass scheme on a GLES2
# device unless forced, and always for trace, which reads every segment back
L=assets/scenes/lorenz.scene
check "integrated single pass egl" 0 " 1 pass \(single pass: OpenGL ES 3.2 runs" -- $BT render --scene $L --size 32x24 --backend egl --out "$TMP/o5.png"
check "integrated single pass osmesa" 0 "on osmesa.* 1 pass \(single pass: " -- $BT render --scene $L --size 32x24 --backend osmesa --out "$TMP/o9.png"
# GLES2: no long loops; with EXT_draw_buffers one fused pass a segment, without it the paper's scheme
check "gles2 fused" 0 "\(fused segment: OpenGL ES 2.0 need not run long fragment-shader loops \(GLSL ES 1.00, appendix A\); [0-9]+ draw buffers: one pass a segment\)" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --precision fp16 --scene $L --size 32x24 --backend egl --out "$TMP/o10.png"
check "gles2 multipass without draw buffers" 0 "\(multipass: OpenGL ES 2.0 need not run long fragment-shader loops .*; not fused: (MRT does not work here|GL_MAX_DRAW_BUFFERS is 1)" -- env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE=-GL_EXT_draw_buffers $BT render --precision fp16 --scene $L --size 32x24 --backend egl --out "$TMP/o12.png"
check "fused forced" 0 "[0-9]+ passes \(fused segment: render.pipeline = fused\)" -- $BT render --scene $L --size 32x24 --backend egl --set render.pipeline=fused --out "$TMP/o15.png"
check "fused forced osmesa" 0 "[0-9]+ passes \(fused segment: render.pipeline = fused\)" -- $BT render --scene $L --size 32x24 --backend osmesa --set render.pipeline=fused --out "$TMP/o16.png"
check "fused forced on exact orbits" 2 "render.pipeline = fused: render.method = orbit_table runs its own orbit stage; use render.pipeline = multipass or auto" -- $BT render --scene $B --size 32x24 --backend egl --set render.pipeline=fused --out "$TMP/o13.png"
check "fused forced without draw buffers" 2 "render.pipeline = fused: (MRT does not work here|GL_MAX_DRAW_BUFFERS is 1)" -- env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE=-GL_EXT_draw_buffers $BT render --precision fp16 --scene $L --size 32x24 --backend egl --set render.pipeline=fused --out "$TMP/o14.png"
check "gles2 single forced" 0 "2 passes \(single pass: render.pipeline = single\)" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --precision fp16 --scene $L --size 32x24 --backend egl --set render.pipeline=single --out "$TMP/o11.png"
check "trace runs multipass" 0 "trace runs the multipass scheme" -- $BT trace --scene $L --size 32x24 --pixel 16 12 --set render.pipeline=single
check "orbit table, adaptive" 2 "step_control must be fixed" -- $BT render --scene $B --set render.step_control=doubling --out "$TMP/o6.png"
check "orbit table, fp16 forced" 0 "fp16\+mrt: .*exact orbits in the single pass, their table sampled as RGBA32F" -- $BT render --scene $B --size 32x24 --precision fp16 --out "$TMP/o7.png"
check "orbit table, fp16 forced on gles2" 2 "orbit_table needs 32-bit float textures" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --scene $B --size 32x24 --backend egl --precision fp16 --out "$TMP/o7b.png"
check "orbit table on gles2" 0 "packed 8-bit: only 16-bit floats render here, which would change rays' outcomes from pass to pass" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --scene $B --size 32x24 --backend egl --out "$TMP/o8.png"
# a GLES 2.0 device: no sized float formats, only half floats; fp32 forced is a clear error
check "gles2 info" 0 "render path: +packed 8-bit: only 16-bit floats render here" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT info --backend egl
check "gles2 info pipeline" 0 "pipeline: +multipass \(the packed path writes one float a fragment\)$" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT info --backend egl
check "gles2 info pipeline without draw buffers" 0 "pipeline: +multipass \(the packed path writes one float a fragment\)$" -- env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE=-GL_EXT_draw_buffers $BT info --backend egl
check "gles2 info pipeline, floats not packed" 0 "pipeline: +one fused pass a segment \(4 draw buffers\) where the scene's objects fit one pass, else multipass; the single pass only when forced \(OpenGL ES 2.0 need not" -- env MESA_GLES_VERSION_OVERRIDE=2.0 BT_FAULT=packing $BT info --backend egl
check "gles2 info pipeline without draw buffers, floats not packed" 0 "pipeline: +multipass; the single pass only when forced \(OpenGL ES 2.0 need not" -- env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE=-GL_EXT_draw_buffers BT_FAULT=packing $BT info --backend egl
check "info pipeline" 0 "pipeline: +single pass where .*OpenGL ES 3.2 runs" -- $BT info --backend egl
# the multipass early stop: occlusion queries proved by the probe; without them every segment runs
# (lorenz: 180 segments of 5 passes and 3 at the end; its rays all end before the budget)
check "info occlusion query" 0 "occlusion query: works: the multipass scheme stops" -- $BT info --backend egl
check "info occlusion query osmesa" 0 "occlusion query: works: the multipass scheme stops" -- $BT info --backend osmesa
check "gles2 without occlusion query" 0 "occlusion query: no: the multipass scheme runs every segment \(neither OpenGL ES 3 nor GL_EXT_occlusion_query_boolean\)" -- env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE=-GL_EXT_occlusion_query_boolean $BT info --backend egl
check "gles2 every segment without query" 0 " 903 passes \(multipass" -- env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE=-GL_EXT_occlusion_query_boolean $BT render --precision fp16 --scene $L --size 16x12 --backend egl --set render.pipeline=multipass --out "$TMP/q1.png"
check "gles2 stops early with query" 0 " [1-8][0-9]{2} passes \(multipass" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --precision fp16 --scene $L --size 16x12 --backend egl --set render.pipeline=multipass --out "$TMP/q2.png"
check "gles2 render" 0 "fp16.*reduced accuracy" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --precision fp16 --scene $S --size 32x24 --backend egl --out "$TMP/c.png"
check "gles2 render takes the packed path" 0 "packed 8-bit: only 16-bit floats render here" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --scene $S --size 16x12 --backend egl --out "$TMP/c2.png"
check "gles2 fp32 forced" 2 "fp32.*RGBA/FLOAT" -- env MESA_GLES_VERSION_OVERRIDE=2.0 $BT render --scene $S --size 32x24 --backend egl --precision fp32 --out "$TMP/d.png"
# EXT_color_buffer_float removed (Mesa 22.3 warns it "cannot be disabled", yet RGBA32F then
# fails the probe's read-back): auto must fall back to 16-bit floats, proved, not assumed
check "fp32 targets missing" 0 "fp16(\+mrt)?: RGBA16F.*reduced accuracy" -- env MESA_EXTENSION_OVERRIDE="-GL_EXT_color_buffer_float" $BT render --scene $S --size 32x24 --backend egl --out "$TMP/f.png"
# a broken shader directory: clear message naming the file and line, exit 1
mkdir -p "$TMP/shaders" && cp shaders_es/*.glsl "$TMP/shaders/" && echo "this is not glsl" >> "$TMP/shaders/stage_integrate.glsl"
check "broken shader" 1 "stage_integrate.glsl:[0-9]+" -- $BT render --scene $S --size 32x24 --shader-dir "$TMP/shaders" --out "$TMP/g.png"
# a shader directory that is not there is the user's mistake: exit 2, naming the file it looked for
check "missing shader directory" 2 "cannot read shader $TMP/no-shaders/[a-z_]+\.glsl" -- $BT render --scene $S --size 32x24 --shader-dir "$TMP/no-shaders" --out "$TMP/g.png"
# one stage's shader missing: the probe passes, the frame stops at that stage, the same exit 2
mkdir -p "$TMP/some-shaders" && cp shaders_es/*.glsl "$TMP/some-shaders/" && rm "$TMP/some-shaders/stage_frame.glsl"
check "missing stage shader" 2 "cannot read shader $TMP/some-shaders/stage_frame\.glsl" -- $BT render --scene $S --size 32x24 --shader-dir "$TMP/some-shaders" --out "$TMP/g.png"
# outputs: checked before any work, never anything but a regular file replaced, a link replaced
# itself and never followed, the old file kept whole when the new one cannot be written
W="$TMP/outputs" && mkdir -p "$W"
check "out and dump the same" 2 "--out and --dump name the same file" -- $BT render --scene $S --size 8x6 --out "$W/x.png" --dump "$W/./x.png" --force
check "out directory missing" 2 "--out: cannot write .*nodir/x.png: directory .*nodir: No such file" -- $BT render --scene $S --size 8x6 --out "$W/nodir/x.png"
mkfifo "$W/fifo"
check "dump onto a FIFO" 2 "--dump: .*fifo is a FIFO: bentray replaces only regular files" -- $BT render --scene $S --size 8x6 --out "$W/f.png" --dump "$W/fifo" --force
mkdir -p "$W/dir.png"
check "out onto a directory" 2 "--out: .*dir.png is a directory: bentray replaces only regular files" -- $BT render --scene $S --size 8x6 --out "$W/dir.png" --force
echo keep > "$W/target" && ln -s "$W/target" "$W/link" && ln -s "$W/none" "$W/dangling.png"
check "dump link replaced, target kept" 0 "^keep$" -- sh -c "$BT render --scene $S --size 8x6 --out $W/l.png --dump $W/link --force >/dev/null && test ! -L $W/link && cat $W/target"
check "dangling link refused before work" 2 "--out: refusing to replace existing file .*dangling" -- $BT render --scene $S --size 8x6 --out "$W/dangling.png"
# the image: PNG (8 or 16 bits), PFM, or a PNG on standard output (a pipe, not a terminal); other
# extensions are refused before any work
check "out to standard output" 0 "^same$" -- sh -c "$BT render --scene $S --size 16x12 --out - --quiet > $W/pipe.png && $BT render --scene $S --size 16x12 --out $W/file.png --quiet > /dev/null && cmp $W/pipe.png $W/file.png && echo same"
# the PNG's compression: fast by default, small on request (the same pixels: test_png_io.c)
check "compression small is smaller" 0 "^smaller$" -- sh -c "$BT render --scene $S --size 160x120 --out $W/fast.png --quiet > /dev/null && $BT render --scene $S --size 160x120 --compression small --out $W/small.png --quiet > /dev/null && [ \$(stat -c %s $W/small.png) -lt \$(stat -c %s $W/fast.png) ] && echo smaller"
check "compression of another name refused" 2 "--compression: expected fast or small, got 'best'" -- $BT render --scene $S --size 8x6 --compression best --out "$W/best.png"
check "compression of a PFM refused" 2 "--compression small: --out .*x.pfm is a PFM, which is not compressed" -- $BT render --scene $S --size 8x6 --compression small --out "$W/x.pfm"
check "out to a terminal refused" 2 "--out -: standard output is a terminal" -- script -qec "$BT render --scene $S --size 8x6 --out -" /dev/null
check "out with another extension refused" 2 "--out .*x.jpg: bentray writes PNG \\(.png, 8 or 16 bits a channel: --depth\\) and PFM" -- $BT render --scene $S --size 8x6 --out "$W/x.jpg"
check "out 16-bit png" 0 "^ *16 +6$" -- sh -c "$BT render --scene $S --size 16x12 --depth 16 --out $W/d16.png --quiet > /dev/null && od -An -tu1 -j24 -N2 $W/d16.png"
check "out pfm" 0 "^PF 16 12 -1.0 2318 bytes$" -- sh -c "$BT render --scene $S --size 16x12 --out $W/f.pfm --quiet > /dev/null && echo \$(head -3 $W/f.pfm) \$(wc -c < $W/f.pfm) bytes"
check "out pfm from the cpu" 0 "^2318$" -- sh -c "$BT render --scene $S --size 16x12 --engine cpu --out $W/fc.pfm --quiet > /dev/null && wc -c < $W/fc.pfm"
check "depth value" 2 "^bentray render: --depth: expected 8 or 16 bits a channel, got '12'" -- $BT render --scene $S --depth 12 --out "$W/d.png"
check "depth of a pfm" 2 "--depth 16 is for PNG" -- $BT render --scene $S --depth 16 --out "$W/d.pfm"
check "transparent sky" 2 "key 'sky_alpha' in \\[render\\]: expected a number from 0 to 1" -- $BT render --scene $S --set render.sky_alpha=1.5 --out "$W/t.png"
check "out with upper-case extension" 0 "X.PNG" -- $BT render --scene $S --size 8x6 --out "$W/X.PNG"
# an option's value may be joined to it with '=', and --version names the build
check "option=value" 0 "eq.png" -- $BT render --scene=$S --size=8x6 --set=render.segments=2 --out="$W/eq.png"
check "version" 0 "^bentray ([0-9a-f]|unknown)" -- $BT --version
echo "old data" > "$W/old.dump"
check "file-size limit keeps the old dump" 0 "^old data; 0 temporaries$" -- sh -c "(ulimit -f 8; $BT render --scene $S --size 64x48 --out $W/o.png --dump $W/old.dump --force) >/dev/null 2>&1; echo \"\$(cat $W/old.dump); \$(ls $W | grep -c tmp-) temporaries\""
sed 's/^name = .*/name = ..\/esc"aped/' $S > assets/scenes/.escape_test.scene
ABS_BT="$(cd "$(dirname "$BT")" && pwd)/$(basename "$BT")"
check "default name stays here" 0 "^_\._esc_aped.png$" -- sh -c "cd $W && $ABS_BT render --scene $PWD/assets/scenes/.escape_test.scene --size 8x6 --quiet && test -f $W/_._esc_aped.png && test ! -e $TMP/esc*"
rm -f assets/scenes/.escape_test.scene
# inputs: a FIFO (or any non-regular file) is refused at once, never waited on
check "scene is a FIFO" 2 "cannot read the scene file: it is a FIFO" -- timeout 60 $BT render --scene "$W/fifo" --out "$W/q.png"
check "compare dump is a FIFO" 2 "cannot read the dump: it is a FIFO" -- timeout 60 $BT compare "$W/fifo" "$W/fifo"
check "kiosk config is a FIFO" 2 "cannot read the kiosk configuration: it is a FIFO" -- timeout 60 $BT kiosk --config "$W/fifo" --display headless --frames 1 --out "$W/kf"
check "scene is a directory" 2 "cannot read the scene file: it is a directory" -- $BT render --scene "$W" --out "$W/q.png"
# trace's JSON escapes the scene's text: a name with quotes and a backslash injects no key
sed 's/^name = .*/name = a"b\\c", "x": 1/' $S > "$W/quote.scene" && sed -i "s#\.\./#$PWD/assets/#" "$W/quote.scene"
printf '%s\n' '  "scene": "a\"b\\c\", \"x\": 1",' > "$W/quote.want"
check "trace escapes strings" 0 "^1$" -- sh -c "$BT trace --scene $W/quote.scene --size 8x6 --pixel 4 3 | grep -cxF -f $W/quote.want"
# a texture whose header reads but whose data is cut off: bad input (exit 2) at the key that named it
mkdir -p "$W/tx/scenes" "$W/tx/textures" "$W/tx/sky" && cp assets/sky/grid_* "$W/tx/sky/" && cp $S "$W/tx/scenes/"
head -c $(( $(stat -c %s assets/textures/checker_grey.png) / 2 )) assets/textures/checker_grey.png > "$W/tx/textures/checker_grey.png"
check "truncated texture" 2 "tx/scenes/test.scene:59: texture: cannot read .*checker_grey.png: the file is truncated" -- $BT render --scene "$W/tx/scenes/test.scene" --size 8x6 --out "$W/tx/o.png"
# the CPU reference keeps that status (it was always 1 there)
check "truncated texture, cpu engine" 2 "^bentray render: cannot read .*checker_grey.png: the file is truncated" -- $BT render --scene "$W/tx/scenes/test.scene" --size 8x6 --engine cpu --out "$W/tx/c.png"
# settings that give no meaningful image say so, also under --quiet
check "unfinished rays warned" 0 "warning: [0-9]+ of 192 rays \([0-9]+%\) were still travelling" -- $BT render --scene assets/scenes/lorenz.scene --size 16x12 --set render.max_path=2 --out "$W/s0.png" --quiet
# a fixed step's budget is given one way in a file; an override replaces the file's other way
printf '[render]\nsegments = 60\nmax_path = 90\n' > "$W/budget.scene"
check "budget given twice refused" 2 "budget.scene: error: render.segments = 60 and render.max_path = 90 both set the budget of fixed steps" -- $BT render --scene "$W/budget.scene" --size 16x12 --out "$W/s3.png"
check "budget override replaces" 0 "note: [0-9]+ rays were still travelling at the end of their budget \\(a path of 2 in 4 segments\\); they show render.unfinished_color \\(raise render.segments\\)" -- $BT render --scene assets/scenes/lorenz.scene --size 16x12 --set render.segments=4 --out "$W/s5.png"
check "unfinished rays noted" 0 "note: [0-9]+ rays were still travelling at the end of their budget \\(a path of 2 in 4 segments\\); they show render.unfinished_color \\(raise render.max_path\\)" -- $BT render --scene assets/scenes/lorenz.scene --size 16x12 --set render.max_path=2 --out "$W/s4.png"
check "shadow filling the view warned" 0 "warning: 192 of 192 rays \(100%\) fell into the horizon: the black hole's shadow fills most of the view" -- $BT render --scene assets/scenes/schwarzschild.scene --size 16x12 --set model.mass=1 --out "$W/s6.png" --quiet
# (at 160x120: starflight's point stars, each pixel the flux of the stars within it, leave a 16x12
# image's pixels lit even behind the motion)
check "dark behind the motion warned" 0 "warning: 9[0-9]% of the image is black: the camera looks 180 degrees away from its motion at 0.90 c, where observer.effects = searchlight" -- $BT render --scene assets/scenes/starflight.scene --size 160x120 --set observer.velocity="0 0 0.9" --out "$W/s7.png" --quiet
check "no dark warning without the effects" 0 "^warnings 0$" -- sh -c "n=\$($BT render --scene assets/scenes/starflight.scene --size 160x120 --set observer.velocity='0 0 0.9' --set observer.effects=geometry --out '$W/s8.png' --quiet 2>&1 >/dev/null | grep -c warning); echo warnings \$n"
check "all rays failed warned" 0 "warning: 192 of 192 rays failed" -- $BT render --scene assets/scenes/lorenz.scene --size 16x12 --set model.strength=1e8 --out "$W/s1.png" --quiet
check "segment too long warned" 0 "warning: one segment .* is longer than the bounding sphere" -- $BT render --scene assets/scenes/schwarzschild.scene --size 16x12 --set render.method=rk4 --set render.step=1e6 --out "$W/s2.png" --quiet
# the CPU reference: same outputs as the GPU engine; on the flat test scene both give the same outcomes
check "render cpu" 0 "CPU reference" -- $BT render --scene $S --size 32x24 --engine cpu --out "$TMP/cpu.png" --dump "$TMP/cpu.dump"
check "render gpu dump" 0 "hit an object" -- $BT render --scene $S --size 32x24 --out "$TMP/gpu.png" --dump "$TMP/gpu.dump"
check "compare flat" 0 "outcome differs: 0 of 768" -- $BT compare "$TMP/gpu.dump" "$TMP/cpu.dump"
check "compare json" 0 "\"differ\": 0," -- $BT compare --json "$TMP/gpu.dump" "$TMP/cpu.dump"
check "compare other size" 2 "small.dump: size 16x12 differs from the reference's 32x24" -- sh -c "$BT render --scene $S --size 16x12 --out $TMP/small.png --dump $TMP/small.dump >/dev/null 2>&1; $BT compare $TMP/small.dump $TMP/cpu.dump"
check "compare other scene" 2 "scene" -- sh -c "$BT render --scene assets/scenes/lorenz.scene --size 32x24 --engine cpu --out $TMP/l.png --dump $TMP/l.dump >/dev/null 2>&1; $BT compare $TMP/l.dump $TMP/cpu.dump"
# a well-formed dump of the largest size, with too little memory for its records: a failure of
# the machine, exit 1, not bad input (the records are a sparse file: no disk is used)
{ printf 'BTDUMP\000\000\002\000\000\000\000\010\000\000\000\020\000\000\064\000\000\000'; head -c 32 /dev/zero
  printf '\000\000\000\000\000\000\000\000'; head -c 32 /dev/zero; } > "$TMP/big.dump"
truncate -s $((96 + 2048 * 4096 * 52)) "$TMP/big.dump"
if [ -z "${ASAN_OPTIONS:-}" ]; then
    check "compare out of memory" 1 "out of memory reading .*big.dump \(8388608 records\)" -- sh -c "ulimit -v 300000; $BT compare $TMP/big.dump $TMP/big.dump"
else
    echo "skip compare out of memory: AddressSanitizer reserves more address space than the limit allows"
fi
rm -f "$TMP/big.dump"
check "compare damaged header" 2 "unsupported dump \(version 2, 8192x8192.*at most 8388608 pixels" -- $BT compare tests/fuzz/seeds/dump/oom-header-8192x8192.dump "$TMP/cpu.dump"
check "compare not a dump" 2 "not a bentray dump" -- $BT compare "$TMP/cpu.png" "$TMP/cpu.dump"
check "error table" 0 "time: gpu .*cpu dopri5" -- $BT error --scene assets/scenes/schwarzschild.scene --size 24x18
check "trace cpu" 0 "\"engine\": \"cpu dopri5" -- $BT trace --scene $S --size 32x24 --pixel 16 12 --engine cpu
# the time a user waits, beside the rendering's own
check "render time line" 0 "^time: [0-9.]+ s rendering( \([0-9.]+ s of it compiling shaders, [^)]*\))?, [0-9.]+ s since bentray started$" -- $BT render --scene $S --size 32x24 --out "$TMP/time.png"
# a first run's compile is said (Mesa's shader cache off: 0.65 s of schwarzschild's 0.87 s here)
check "render time line says the compile" 0 "^time: [0-9.]+ s rendering \([0-9.]+ s of it compiling shaders, " -- env MESA_SHADER_CACHE_DISABLE=true $BT render --scene assets/scenes/schwarzschild.scene --size 32x24 --out "$TMP/time.png" --force
# the CPU trace's colour is the pixel's as the CPU image writes it (it was always black)
check "trace cpu colour is the pixel's" 0 "^\[173, 173, 173\] \[173, 173, 173\]$" -- sh -c "for e in cpu gpu; do $BT trace \
    --scene assets/scenes/schwarzschild.scene --pixel 100 200 --engine \$e | sed -n 's/.*\"color\": \(.*\),/\1/p'; done | tr '\n' ' ' | sed 's/ \$//'"
check "cpu with gpu option" 2 "--precision applies to the GPU engine" -- $BT render --scene $S --engine cpu --precision fp16 --out "$TMP/h.png"
check "rtol without cpu" 2 "--rtol applies to the CPU engine" -- $BT render --scene $S --rtol 1e-8 --out "$TMP/h.png"
check "bad rtol" 2 "--rtol: expected" -- $BT render --scene $S --engine cpu --rtol 0 --out "$TMP/h.png"
check "bad engine" 2 "--engine: expected gpu or cpu" -- $BT render --scene $S --engine quantum --out "$TMP/h.png"
# every scene meets its own [quality] at its own settings and size (the error is deterministic on
# one Mesa; the bounds leave a margin over what docs/BENCH.md measured); a missed bound is exit 3
for f in assets/scenes/*.scene; do
    check "quality $(basename "$f")" 0 ": met$" -- $BT error --scene "$f" --check
done
# lorenz's far steps (render.far_step) hold its [quality] at the knobs' far end too, as the scene says
check "quality lorenz at the knobs' far end" 0 ": met$" -- $BT error --scene assets/scenes/lorenz.scene --check \
    --set model.rho=50 --set model.strength=0.01
check "quality missed" 3 "MISSED" -- $BT error --scene assets/scenes/schwarzschild.scene --check --set render.method=euler
sed -e '/^\[quality\]/,$d' -e "s#\.\./#$PWD/assets/#" assets/scenes/test.scene > "$TMP/unstated.scene"
check "quality not stated" 2 "states no \[quality\]" -- $BT error --scene "$TMP/unstated.scene" --check
# relativity: the observer's speed and the effects are checked
check "observer too fast" 2 "observer.velocity has speed 1.2 c" -- $BT render --scene $S --set observer.velocity="0 0 1.2" --out "$TMP/r.png"
check "effects without black body" 2 "nothing in the scene is one" -- $BT render --scene $S --set observer.effects=doppler --out "$TMP/r.png"
# point stars (docs/STARS.md): drawn on both back-ends, the same rays and colours; bad keys named
check "stars egl" 0 "the stars of the sky [0-9.]+ s on the CPU" -- $BT render --scene assets/scenes/star_sky.scene --size 96x54 --backend egl --out "$TMP/st_egl.png" --dump "$TMP/st_egl.dump" --force
check "stars osmesa" 0 "the stars of the sky [0-9.]+ s on the CPU" -- $BT render --scene assets/scenes/star_sky.scene --size 96x54 --backend osmesa --out "$TMP/st_osm.png" --dump "$TMP/st_osm.dump" --force
check "stars backends agree" 0 "image: (identical|PSNR ([6-9][0-9]|[1-9][0-9][0-9])[0-9.]* dB)" -- $BT compare "$TMP/st_egl.dump" "$TMP/st_osm.dump"
check "stars negative" 2 "key 'stars' in \\[sky\\]: expected an integer from 0 to 1000000" -- $BT render --scene $S --set sky.stars=-1 --out "$TMP/st.png"
check "star size zero" 2 "key 'star_size' in \\[sky\\]: expected a number from 0.3 to 8" -- $BT render --scene $S --set sky.star_size=0 --out "$TMP/st.png"
check "galactic center along pole" 2 "galactic_center lies along galactic_pole" -- $BT render --scene $S --set "sky.galactic_pole=0 1 0" --set "sky.galactic_center=0 -2 0" --out "$TMP/st.png"
# the GPU's star pass (docs/STARS.md, "Stars on the GPU"): its sky colour, with derivatives, compiles as
# GLSL ES 1.00 under glslang too, the extension declared
check "info --shader GPU stars compiles" 0 "^compiled$" -- sh -c "$BT info --shader orbit_frame --scene assets/scenes/star_sky.scene \
    --set render.star_pass=gpu --no-mrt > '$TMP/stars.frag' && sed -n 2p '$TMP/stars.frag' | grep -q '^#extension GL_OES_standard_derivatives : enable$' \
    && grep -q 'define GPU_STARS 1' '$TMP/stars.frag' && glslangValidator -S frag '$TMP/stars.frag' > '$TMP/glslang.log' && echo compiled || cat '$TMP/glslang.log'"
# a render shown in bands (--progress) is the render in one run, the GPU's stars too (their
# footprints come from 2x2 groups of pixels, which no band edge splits), at an odd size as well
check "GPU stars the same in bands" 0 "^same$" -- sh -c "$BT render --scene assets/scenes/star_sky.scene --set render.star_pass=gpu --size 65x37 --quiet --out '$TMP/sb1.png' > /dev/null && \
    $BT render --scene assets/scenes/star_sky.scene --set render.star_pass=gpu --size 65x37 --progress --out '$TMP/sb2.png' > /dev/null 2>&1 && cmp -s '$TMP/sb1.png' '$TMP/sb2.png' && echo same"
# without derivatives (VC4) the sky stage draws them, the footprints from the neighbouring rays: the
# packed path (VC4's: GLES 2, no float textures) the same picture as a float one
check "GPU stars without derivatives, from the neighbouring rays" 0 "^same$" -- sh -c "env BT_FAULT=no_derivatives $BT render \
    --scene assets/scenes/star_sky.scene --set render.star_pass=gpu --size 64x48 --quiet --out '$TMP/nd1.png' > /dev/null && \
    env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE='-GL_OES_texture_float -GL_OES_texture_half_float' \
    BT_FAULT=no_derivatives,gpu_rasterizer $BT render --scene assets/scenes/star_sky.scene --set render.star_pass=gpu --size 64x48 \
    --quiet --out '$TMP/nd2.png' > /dev/null && cmp -s '$TMP/nd1.png' '$TMP/nd2.png' && echo same"
# the image's gain and tone curve (results/tone.h) with the stars the CPU's pass adds: the frame read as
# floats, the curve applied after the stars on the CPU, as the reference engine applies it
check "tone curve with CPU stars" 0 "outcome differs: 0 of 3072.*PSNR (4[5-9]|[5-9][0-9])\\.[0-9]+ dB" -- sh -c "$BT render --scene assets/scenes/star_sky.scene --set render.tone_curve=filmic --set render.gain=2 --size 64x48 --dump '$TMP/tc_gpu.dump' --quiet --out '$TMP/tc_gpu.png' > /dev/null && \
    $BT render --scene assets/scenes/star_sky.scene --set render.tone_curve=filmic --set render.gain=2 --engine cpu --size 64x48 --dump '$TMP/tc_cpu.dump' --quiet --out '$TMP/tc_cpu.png' > /dev/null && $BT compare '$TMP/tc_gpu.dump' '$TMP/tc_cpu.dump' | tr '\\n' ' '"
check "tone curve with GPU stars" 0 "star_sky: 32x24" -- $BT render --scene assets/scenes/star_sky.scene --set render.tone_curve=filmic --set render.gain=2 --set render.star_pass=gpu --size 32x24 --out "$TMP/tc.png"
check "gain zero refused" 2 "key 'gain' in \\[render\\]" -- $BT render --scene $S --set render.gain=0 --out "$TMP/tc.png"
# bloom (results/bloom.h): both back-ends the same image, the CPU engine's within a few levels, the
# float image without it (the light as traced), the render line timing it; out-of-range values refused
D=assets/scenes/demo.scene
check "bloom both back-ends" 0 "outcome differs: 0 of 2304.*image: (identical|PSNR (4[5-9]|[5-9][0-9])\\.[0-9]+ dB)" -- sh -c "$BT render --scene $D --size 64x36 --samples 1 --set render.gain=8 --set render.bloom=0.3 --backend egl --dump '$TMP/bl_egl.dump' --quiet --out '$TMP/bl_egl.png' > /dev/null && \
    $BT render --scene $D --size 64x36 --samples 1 --set render.gain=8 --set render.bloom=0.3 --backend osmesa --dump '$TMP/bl_osm.dump' --quiet --out '$TMP/bl_osm.png' > /dev/null && $BT compare '$TMP/bl_egl.dump' '$TMP/bl_osm.dump' | tr '\\n' ' '"
check "bloom timed" 0 "the bloom [0-9.]+ s on the CPU" -- $BT render --scene $D --size 64x36 --samples 1 --set render.bloom=0.3 --out "$TMP/bl.png"
check "bloom against the reference" 0 "PSNR (4[5-9]|[5-9][0-9])\\.[0-9]+ dB" -- sh -c "$BT render --scene $D --size 64x36 --samples 1 --set render.gain=8 --set render.bloom=0.3 --dump '$TMP/bl_gpu.dump' --quiet --out '$TMP/bl_g.png' > /dev/null && \
    $BT render --scene $D --size 64x36 --samples 1 --set render.gain=8 --set render.bloom=0.3 --engine cpu --dump '$TMP/bl_cpu.dump' --quiet --out '$TMP/bl_c.png' > /dev/null && $BT compare '$TMP/bl_gpu.dump' '$TMP/bl_cpu.dump'"
check "bloom keeps float images as traced" 0 "^same$" -- sh -c "$BT render --scene $D --size 32x18 --samples 1 --set render.bloom=0.5 --quiet --out '$TMP/bl1.pfm' > /dev/null && \
    $BT render --scene $D --size 32x18 --samples 1 --quiet --out '$TMP/bl0.pfm' > /dev/null && cmp -s '$TMP/bl0.pfm' '$TMP/bl1.pfm' && echo same"
check "bloom changes the 8-bit image" 0 "^differ$" -- sh -c "$BT render --scene $D --size 64x36 --samples 1 --set render.gain=8 --quiet --out '$TMP/bl_none.png' > /dev/null && \
    { cmp -s '$TMP/bl_egl.png' '$TMP/bl_none.png' && echo same || echo differ; }"
check "bloom above 1 refused" 2 "key 'bloom' in \\[render\\]: expected a number from 0 to 1" -- $BT render --scene $S --set render.bloom=1.5 --out "$TMP/bl.png"
check "bloom radius zero refused" 2 "key 'bloom_radius' in \\[render\\]" -- $BT render --scene $S --set render.bloom_radius=0 --out "$TMP/bl.png"
# the real sky (docs/STARS.md, "The real sky"): both back-ends draw the same stars; a malformed
# catalogue line is refused at its FILE:LINE, a catalogue beside generated stars, colours without a
# catalogue and the catalogue as the output are refused
check "real sky egl" 0 "the stars of the sky [0-9.]+ s on the CPU" -- $BT render --scene assets/scenes/orion.scene --size 96x54 --backend egl --out "$TMP/or_egl.png" --dump "$TMP/or_egl.dump" --force
check "real sky osmesa" 0 "the stars of the sky [0-9.]+ s on the CPU" -- $BT render --scene assets/scenes/orion.scene --size 96x54 --backend osmesa --out "$TMP/or_osm.png" --dump "$TMP/or_osm.dump" --force
check "real sky backends agree" 0 "image: (identical|PSNR ([6-9][0-9]|[1-9][0-9][0-9])[0-9.]* dB)" -- $BT compare "$TMP/or_egl.dump" "$TMP/or_osm.dump"
printf '# Dec RA Mag\n 7.4 5.9 0.5 "Betelgeuse" 2061\n 95 5 1\n' > "$TMP/bad.bsc"
check "catalogue bad line" 2 "key 'catalogue' in \\[sky\\]: $TMP/bad.bsc:3: declination 95 is outside -90..90 degrees" -- $BT render --scene $S --set sky.catalogue="$TMP/bad.bsc" --out "$TMP/st.png"
check "catalogue and stars" 2 "the sky takes its stars from one of them" -- $BT render --scene assets/scenes/star_sky.scene --set sky.catalogue=/usr/share/xplanet/stars/BSC --out "$TMP/st.png"
check "catalogue colours alone" 2 "catalogue_colours colours the stars of \\[sky\\] catalogue, which is not given" -- $BT render --scene $S --set sky.catalogue_colours=/usr/share/marble/data/stars/stars.dat --out "$TMP/st.png"
check "catalogue colours not Marble's" 2 "not a star file of Marble's" -- $BT render --scene $S --set sky.catalogue=/usr/share/xplanet/stars/BSC --set sky.catalogue_colours=/usr/share/xplanet/stars/BSC --out "$TMP/st.png"
cp /usr/share/xplanet/stars/BSC "$TMP/catalogue.png"
check "catalogue is no output" 2 "is the sky's star catalogue" -- $BT render --scene $S --set sky.catalogue="$TMP/catalogue.png" --out "$TMP/catalogue.png" --force
check "catalogue kept" 0 "^same$" -- sh -c "cmp '$TMP/catalogue.png' /usr/share/xplanet/stars/BSC && echo same"
check "starflight egl" 0 "76800 sky" -- $BT render --scene assets/scenes/starflight.scene --backend egl --out "$TMP/sf_egl.png"
check "starflight osmesa" 0 "76800 sky" -- $BT render --scene assets/scenes/starflight.scene --backend osmesa --out "$TMP/sf_osm.png"
check "starflight backends agree" 0 "outcome differs: 0 of" -- sh -c "$BT render --scene assets/scenes/starflight.scene --size 64x48 --backend egl --out $TMP/a1.png --dump $TMP/a1.dump >/dev/null && $BT render --scene assets/scenes/starflight.scene --size 64x48 --backend osmesa --out $TMP/a2.png --dump $TMP/a2.dump >/dev/null && $BT compare $TMP/a1.dump $TMP/a2.dump"
# info --shader: the stage's fragment shader as the GL compiles it for the scene, which glslang's
# GLSL ES 1.00 front end (stricter than Mesa's: no line continuation) compiles too; without MRT, as
# no draw-buffers extension is known to glslang
for case in "frame lorenz" "orbit_frame schwarzschild" "orbit_crossings demo" "integrate lorenz" "intersect three_ships" "orbit neutron_star" \
            "terminate potential" "sky demo" "setup refraction"; do
    set -- $case
    check "info --shader $1 ($2) compiles" 0 "^compiled$" -- sh -c "$BT info --shader $1 --scene assets/scenes/$2.scene \
        --set render.pipeline=\$( [ $1 = frame ] || [ $1 = orbit_frame ] || [ $1 = orbit_crossings ] && echo auto || echo multipass) --no-mrt \
        > '$TMP/stage.frag' && head -1 '$TMP/stage.frag' | grep -q '^#version 100$' && grep -q 'void main' '$TMP/stage.frag' \
        && glslangValidator -S frag '$TMP/stage.frag' > '$TMP/glslang.log' && echo compiled || cat '$TMP/glslang.log'"
done
# BT_SHADER_DUMP=DIR: every program a render builds, whole, as the GL compiles it: the single pass's
# fragment shader is the one info --shader prints, the dumped programs compile and draw on this
# machine's GL through compile_stats (the tool make shader-stats runs under the exhibit GPUs'
# compilers), and a dump that cannot be written is said, the frame rendered all the same
mkdir -p "$TMP/shader_dump"
check "BT_SHADER_DUMP writes every program" 0 "^stage_orbit_frame$" -- sh -c "BT_SHADER_DUMP='$TMP/shader_dump' $BT render \
    --scene assets/scenes/schwarzschild.scene --size 16x12 --out '$TMP/dumped.png' >/dev/null && \
    ls '$TMP/shader_dump' | sed -n 's/^[0-9]*-[0-9]*-\(stage_.*\)\.frag$/\1/p'"
mkdir -p "$TMP/info_dump"
check "BT_SHADER_DUMP's program is info --shader's" 0 "^same$" -- sh -c "BT_SHADER_DUMP='$TMP/info_dump' $BT info \\
    --shader orbit_frame --scene assets/scenes/schwarzschild.scene > '$TMP/orbit_frame.frag' && \\
    cmp '$TMP/orbit_frame.frag' '$TMP'/info_dump/*-stage_orbit_frame.frag && echo same"
check "dumped programs compile and draw" 0 "^results: [1-9][0-9]* ok, 0 other$" -- sh -c "${COMPILE_STATS:-build/tests/gpus/compile_stats} \
    \$(ls '$TMP'/shader_dump/*.frag | sed 's/\.frag$//') 2>&1 | awk '/^== result /{ if (\$4 == \"ok\") ok++; else other++ }
    END { printf \"results: %d ok, %d other\\n\", ok, other }'"
# every program of the packed path as a GPU builds it (the intersection stage's hit found and shaded
# in passes of their own) keeps to GLSL ES 1.00 under glslang: exact orbits with Doppler colour, an
# accretion disk and textures (demo), moving objects and clocks (clocks)
mkdir -p "$TMP/packed_dump"
check "the packed path's programs on a GPU compile under glslang" 0 "^glslang: [1-9][0-9]* compiled, 0 failed, [1-9][0-9]* of the hit passes$" -- sh -c "\
    for sc in demo clocks; do env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE='-GL_OES_texture_float -GL_OES_texture_half_float' \
    BT_FAULT=gpu_rasterizer BT_SHADER_DUMP='$TMP/packed_dump' $BT render --scene assets/scenes/\$sc.scene --size 8x6 --backend egl \
    --out '$TMP/packed_dump.png' --force >/dev/null 2>&1 || exit 1; done; ok=0; bad=0; for f in '$TMP'/packed_dump/*.frag; do \
    case \$f in *probe_fragment*) continue;; esac; if glslangValidator -S frag \$f >/dev/null 2>&1; then ok=\$((ok + 1)); \
    else bad=\$((bad + 1)); echo \$f; fi; done; echo glslang: \$ok compiled, \$bad failed, \$(grep -l '^#define HIT_' '$TMP'/packed_dump/*.frag | wc -l) of the hit passes"
check "BT_SHADER_DUMP into a missing directory" 0 "BT_SHADER_DUMP: cannot write $TMP/no_such_dir/.*-stage_orbit_frame.frag: No such file" -- \
    env BT_SHADER_DUMP="$TMP/no_such_dir" $BT render --scene assets/scenes/schwarzschild.scene --size 16x12 --out "$TMP/undumped.png"
check "info --shader unknown stage" 2 "no stage 'integrator' \(stages: fill, frame, integrate, intersect, orbit, orbit_crossings, orbit_frame," -- \
    $BT info --shader integrator --scene $S
check "info --shader a stage not run" 1 "runs no program of stage_integrate.glsl \(single pass" -- \
    $BT info --shader integrate --scene assets/scenes/lorenz.scene
check "info --shader without scene" 2 "needs --scene FILE" -- $BT info --shader frame
check "info scene without shader" 2 "go with --shader STAGE" -- $BT info --scene $S
# bench: the tiny configuration proves the command and its report work; it times nothing that matters
# (pipelines: a header, four rows each of the six integrated cases (multipass, fused, single, packed),
# three of the five on exact orbits, which have no fused pass)
mkdir -p "$TMP/bench"
check "bench quick" 0 "wrote .*BENCH.md" -- $BT bench --out "$TMP/bench" --quick
check "bench sections" 0 "^15 sections, table1 21 rows, pipelines 40 rows, figure5 3 rows, limit 3 rows, pareto 4 rows, relativity 5 rows, kiosk 2 rows, antialias 3 rows, light 7 rows, stars 3 rows, wait 7 rows$" -- sh -c "
    printf '%s sections, table1 %s rows, pipelines %s rows, figure5 %s rows, limit %s rows, pareto %s rows, relativity %s rows, kiosk %s rows, antialias %s rows, light %s rows, stars %s rows, wait %s rows\n' \
      \$(grep -c '^## ' $TMP/bench/BENCH.md) \$(wc -l < $TMP/bench/bench/table1.csv) \$(wc -l < $TMP/bench/bench/pipelines.csv) \
      \$(wc -l < $TMP/bench/bench/figure5.csv) \$(wc -l < $TMP/bench/bench/limit.csv) \
      \$(wc -l < $TMP/bench/bench/pareto.csv) \$(wc -l < $TMP/bench/bench/relativity.csv) \
      \$(wc -l < $TMP/bench/bench/kiosk.csv) \$(wc -l < $TMP/bench/bench/antialias.csv) \$(wc -l < $TMP/bench/bench/light.csv) \$(wc -l < $TMP/bench/bench/stars.csv) \
      \$(wc -l < $TMP/bench/bench/wait.csv)"
# the disk's target: demo's view with one ray a pixel, timed warm, met or missed said
check "bench disk target" 0 "^Target: demo.scene's view \(the disk around the hole\) at [0-9]+x[0-9]+, one ray a pixel, .* in at most 30 ms: \*\*(met|missed)\*\* \([0-9]+ ms\)\.$" -- \
    grep "^Target: demo.scene's view" "$TMP/bench/BENCH.md"
check "bench accretion cost" 0 "^The accretion disk's light \(each point's orbit and temperature, docs/RELATIVITY.md\) costs [-+][0-9.]+ ms of that: [0-9.]+ ms with the disk's matter at rest at one temperature\.$" -- \
    grep "^The accretion disk's light" "$TMP/bench/BENCH.md"
check "bench light costs" 0 "^\| \+ bloom 0\.15 \(\`render\.bloom\`\), with the stars on the CPU \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \|$" -- grep -A12 "^## The image's light" "$TMP/bench/BENCH.md"
check "bench tone cost" 0 "^The image's filmic curve and gain \(\`render.tone_curve\`, \`render.gain\`: docs/SCENES.md\) cost [-+][0-9.]+ ms of that: [0-9.]+ ms with each channel clipped at white\.$" -- \
    grep "^The image's filmic curve" "$TMP/bench/BENCH.md"
# the time a user waits: fresh render processes timed against the warm frame and their own frame
# (read from their summaries), the three targets said
check "bench wait targets" 0 "^Targets for the fresh render: .* \*\*(met|MISSED)\*\*; .* its own frame \([0-9.]+ s\): \*\*(met|MISSED)\*\*; .* \*\*(met|MISSED)\*\*" -- \
    grep '^Targets for the fresh render' "$TMP/bench/BENCH.md"
# the section of make shader-stats: copied from DIR/bench/shader_stats.md where it is there, else a
# line that says how to make it
check "bench without shader statistics" 0 "^Not measured in this run: \`make shader-stats\` writes this section" -- \
    grep -A2 '^## On the GPUs of an exhibit' "$TMP/bench/BENCH.md"
printf '## On the GPUs of an exhibit\n\nthe compilers said so\n' > "$TMP/bench/bench/shader_stats.md"
check "bench includes the shader statistics" 0 "^the compilers said so$" -- sh -c "$BT bench --out $TMP/bench --quick --force --only table1 >/dev/null 2>&1 && grep -A2 '^## On the GPUs of an exhibit' $TMP/bench/BENCH.md"
check "bench kiosk to stdout" 0 "^\| schwarzschild.scene( \| [0-9.]+){6} \| [0-9]+ \| (met|MISSED) \| (met|MISSED) \| [0-9.]+ (met|MISSED) \| [0-9.]+ (met|MISSED) \| [0-9.]+ \|$" -- $BT bench --kiosk --quick
# the shipped configuration is found from the program's own place, whatever the working directory
check "bench kiosk elsewhere" 0 "--config $(pwd)/kiosk/kiosk.conf" -- sh -c "cd '$TMP' && $(cd "$(dirname "$BT")" && pwd)/$(basename "$BT") bench --kiosk --quick"
check "bench kiosk config missing" 2 "^bentray bench: kiosk: $TMP/none.conf" -- $BT bench --kiosk --quick --config "$TMP/none.conf"
# ... and nothing of a report on standard output: a report is written whole or not at all
check "bench kiosk failed writes no report" 0 "^0 bytes$" -- sh -c "$BT bench --kiosk --quick --config '$TMP/none.conf' 2>/dev/null | wc -c | sed 's/\$/ bytes/'"
check "bench no overwrite" 2 "exists; pass --force" -- $BT bench --out "$TMP/bench" --quick
# the report is written whole or not at all: an interrupt keeps the earlier one byte for byte, a
# replaced report keeps its mode, and a link at a data file is replaced, its target untouched
chmod 600 "$TMP/bench/BENCH.md"
cp "$TMP/bench/BENCH.md" "$TMP/bench_before.md"
check "bench interrupted keeps the report" 0 "^same$" -- sh -c "timeout -s INT 2 $BT bench --out '$TMP/bench' --quick --force >/dev/null 2>&1; cmp -s '$TMP/bench/BENCH.md' '$TMP/bench_before.md' && echo same"
echo kept > "$TMP/bench_target"
ln -sf "$TMP/bench_target" "$TMP/bench/bench/kiosk.csv"
check "bench replaces a link, keeps the mode" 0 "^kept 600 regular$" -- sh -c "$BT bench --out '$TMP/bench' --quick --force --only kiosk >/dev/null 2>&1; echo \$(cat '$TMP/bench_target') \$(stat -c %a '$TMP/bench/BENCH.md') \$(stat -c %F '$TMP/bench/bench/kiosk.csv' | cut -d' ' -f1)"
check "bench bad section" 2 "--only: unknown section 'speed'" -- $BT bench --out "$TMP/bench" --only speed
check "bench without out" 2 "--out DIR is required" -- $BT bench --quick
check "bench bad runs" 2 "--runs: expected an integer from 1 to 63" -- $BT bench --out "$TMP/bench" --runs 0
# a section that fails ends the bench with its error's status: a data file the system refuses is 2
mkdir -p "$TMP/bench_refused/bench/table1.csv"
check "bench section's status" 2 "^bentray bench: table1: cannot write .*bench_refused/bench/table1.csv" -- $BT bench --out "$TMP/bench_refused" --quick --only table1
# docs/SCENES.md's example scene, as a teacher copies it next to the shipped assets, renders with every
# ray finished on both back-ends
mkdir -p "$TMP/example/scenes" && ln -s "$(pwd)/assets/sky" "$TMP/example/sky" && ln -s "$(pwd)/assets/textures" "$TMP/example/textures"
awk '/^## Example/{f=1} f&&/^```ini/{g=1;next} g&&/^```/{exit} g' docs/SCENES.md > "$TMP/example/scenes/ring.scene"
for b in egl osmesa; do
    check "SCENES.md's example ($b)" 0 "^rays: [1-9][0-9]* hit an object, [0-9]+ sky, [0-9]+ captured, 0 unfinished, 0 failed$" -- \
        $BT render --scene "$TMP/example/scenes/ring.scene" --size 64x48 --backend $b --out "$TMP/example/ring_$b.png"
done
. tests/render/kiosk.sh
. tests/render/reliability.sh
check "kiosk install" 0 "^install checks: 0 failed$" -- sh -c "sh tests/render/install_check.sh | grep -v '^ok '"
# the limits before allocation and the GL fault paths (BT_FAULT), in a script of their own
BT=$BT tests/render/limits.sh || fails=$((fails + 1))
# every shipped scene under every GPU an exhibit might buy: the default path's rays, or a refusal
BT=$BT tests/render/targets.sh || fails=$((fails + 1))
echo "command-line tests: $fails failed"
[ "$fails" = 0 ]
