# Command-line tests of `bentray kiosk` (sourced by run_all.sh: uses its check, BT and TMP). The
# kiosk runs headless here, driven by scripts (tests/kiosk/); test_kiosk_run.c compares its frames
# with the renderer's, and test_kiosk_x11.c its window with the headless frame.
K=tests/kiosk/headless.conf
check "kiosk help" 0 "--check-inputs" -- $BT kiosk --help
check "kiosk missing config" 2 "nosuch.conf" -- $BT kiosk --config "$TMP/nosuch.conf"
check "kiosk bad option" 2 "unknown option" -- $BT kiosk --config $K --frob
check "kiosk bad display" 2 "--display: unknown display 'vga'" -- $BT kiosk --config $K --display vga
check "kiosk bad frames" 2 "--frames: expected a whole number" -- $BT kiosk --config $K --frames -1
check "kiosk headless without out" 2 "headless_out" -- $BT kiosk --config $K
mkdir -p "$TMP/kiosk"
check "kiosk headless run" 0 "stopped after" -- $BT kiosk --config $K --out "$TMP/kiosk" --frames 8
check "kiosk frames written" 0 "^8 frames$" -- sh -c "echo \$(ls $TMP/kiosk/frame_*.png | wc -l) frames"
check "kiosk no overwrite" 2 "refusing to replace existing file .*frame_[0-9]+\.png \(use --force to overwrite it\): a frame of an earlier run" -- $BT kiosk --config $K --out "$TMP/kiosk" --frames 8
# frame times in the log: every refined frame's with --stats, none without it, and in staff mode
# (the staff_mode action, pressed by tests/kiosk/staff.events) until it is left
check "kiosk stats" 0 "frame times: schwarzschild: 1 preview at 80x45, [0-9.]+ ms each on average, [0-9.]+ ms the longest; refined 160x90 in [0-9]+ bands, [0-9.]+ s of drawing, [0-9.]+ s after the last change" -- $BT kiosk --config $K --out "$TMP/kiosk" --frames 2 --force --stats
check "kiosk no stats unasked" 0 "^0 lines$" -- sh -c "echo \$($BT kiosk --config $K --out $TMP/kiosk --frames 2 --force 2>&1 | grep -c 'frame times') lines"
mkdir -p "$TMP/staff"
sed "s|path = visitor.events|path = $PWD/tests/kiosk/staff.events|; s|\.\./\.\./assets|$PWD/assets|g" $K > "$TMP/staff/k.conf"
check "kiosk staff mode logs frame times" 0 "^1 lines$" -- sh -c "echo \$($BT kiosk --config $TMP/staff/k.conf --out $TMP/staff --frames 2 2>&1 | grep -c 'frame times: schwarzschild') lines"
# a scene with render.bloom: the kiosk draws it without the bloom and its log says so
mkdir -p "$TMP/bloom"
sed "s|^\[render\]|[render]\nbloom = 0.2|; s|\.\./|$PWD/assets/|g" assets/scenes/schwarzschild.scene > "$TMP/bloom/glow.scene"
sed "s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|; s|\.\./\.\./assets|$PWD/assets|g; s|^scenes = .*|scenes = $TMP/bloom/glow.scene|; s|^start_scene = .*|start_scene = glow|; s|^assets_root = .*|assets_root = /|" $K > "$TMP/bloom/k.conf"
check "kiosk says it draws no bloom" 0 "glow.scene: render.bloom = 0.2 is for bentray render's images; the kiosk draws its frames without it" -- \
    $BT kiosk --config "$TMP/bloom/k.conf" --out "$TMP/bloom" --frames 1
# a GPU without derivatives (VC4) draws the point stars of demo.scene in the sky stage, from the
# neighbouring rays: the kiosk shows both scenes, on VC4's packed path too, and refuses none
mkdir -p "$TMP/noderiv" "$TMP/noderiv_packed"
sed "s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|; s|\.\./\.\./assets|$PWD/assets|g; s|^scenes = .*|scenes = $PWD/assets/scenes/demo.scene, $PWD/assets/scenes/schwarzschild.scene|" $K > "$TMP/noderiv/k.conf"
check "kiosk without derivatives shows every scene" 0 "^refused 0, frames 2, packed: refused 0, frames 2$" -- \
    sh -c "r=\$(BT_FAULT=no_derivatives $BT kiosk --config '$TMP/noderiv/k.conf' --out '$TMP/noderiv' --frames 2 2>&1 | grep -c 'cannot draw'); \
    p=\$(env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE='-GL_OES_texture_float -GL_OES_texture_half_float' BT_FAULT=no_derivatives,gpu_rasterizer \
    $BT kiosk --config '$TMP/noderiv/k.conf' --out '$TMP/noderiv_packed' --frames 2 2>&1 | grep -c 'cannot draw'); \
    echo refused \$r, frames \$(ls '$TMP/noderiv' | grep -c frame_), packed: refused \$p, frames \$(ls '$TMP/noderiv_packed' | grep -c frame_)"
check "kiosk osmesa run" 0 "headless screen 160x90 \(OSMesa.*stopped after" -- sh -c "$BT kiosk --config $K --out $TMP/kiosk --frames 2 --backend osmesa --force 2>&1 | tr '\n' ' '"
# a bad script is refused before anything is shown, with FILE:LINE
mkdir -p "$TMP/badscript"
printf '0.5 turn speed +3\n0.2 frame\n' > "$TMP/badscript/bad.events"
sed "s|path = visitor.events|path = $TMP/badscript/bad.events|; s|\.\./\.\./assets|$PWD/assets|g" $K > "$TMP/badscript/k.conf"
check "kiosk bad script" 2 "bad.events:2: time 0.2 goes back" -- $BT kiosk --config "$TMP/badscript/k.conf" --out "$TMP/badscript"
# the scenes' decoded images are held to [kiosk] image_memory before any is decoded: schwarzschild's
# six grid faces and texture and a flight under the 256 x 256 star cube map (starflight as it was
# before its point stars) take 2 MB (2.1), each file once, also where a scene is listed twice
mkdir -p "$TMP/images"
sed -e 's|^type = color$|type = cubemap\ncubemap = '"$PWD"'/assets/sky/stars\ntemperature = 3000|' \
    -e '/^stars = /d; /^star_seed = /d; /^milky_way = /d; /^color = 0 0 0$/d' assets/scenes/starflight.scene > "$TMP/images/star_cubemap.scene"
sed '/^refine_frames/a image_memory = 1' $K | sed 's|\.\./\.\./assets|'"$PWD"'/assets|g; s|path = visitor.events|path = '"$PWD"'/tests/kiosk/visitor.events|;
    s|'"$PWD"'/assets/scenes/starflight.scene|'"$TMP"'/images/star_cubemap.scene|; s|^assets_root = .*|assets_root = /|' > "$TMP/images/k.conf"
check "kiosk image memory bound" 2 "k.conf:10: \[kiosk\] image_memory = 1 MB: the scenes' textures and sky faces take 2 MB decoded.*checker_grey.png, is 256x256" -- $BT kiosk --config "$TMP/images/k.conf" --out "$TMP/images"
sed 's|^scenes = \(.*\)$|scenes = \1, '"$PWD"'/assets/scenes/schwarzschild.scene|; s|^start_scene = .*|start_scene = 0|' "$TMP/images/k.conf" > "$TMP/images/twice.conf"
check "kiosk image memory counts a file once" 2 "take 2 MB decoded" -- $BT kiosk --config "$TMP/images/twice.conf" --out "$TMP/images"
# the anti-aliasing after a refinement at rest ([kiosk] refine_samples, default 4): its bands and
# time logged once the last sample is drawn, and a picture other than the one-ray frame's
mkdir -p "$TMP/aa"
printf '2.5 frame\n' > "$TMP/aa/rest.events"
sed 's|\.\./\.\./assets|'"$PWD"'/assets|g; s|path = visitor.events|path = '"$TMP"'/aa/rest.events|' $K > "$TMP/aa/k.conf"
sed '/^refine_frames/a refine_samples = 1' "$TMP/aa/k.conf" > "$TMP/aa/one.conf"
check "kiosk anti-aliasing logged" 0 "frame times: schwarzschild: anti-aliased with 4 rays a pixel in 36 bands, [0-9.]+ s of drawing, [0-9.]+ s after the refined frame" -- $BT kiosk --config "$TMP/aa/k.conf" --out "$TMP/aa" --frames 1 --stats
check "kiosk anti-aliasing off" 0 "^0 lines, frames differ$" -- sh -c "mkdir -p $TMP/aa/one && $BT kiosk --config $TMP/aa/one.conf \
    --out $TMP/aa/one --frames 1 --stats 2>&1 | grep -c 'anti-aliased' | tr '\n' ' '; echo \"lines, \$(cmp -s $TMP/aa/frame_0001.png \
    $TMP/aa/one/frame_0001.png && echo frames the same || echo frames differ)\" | sed 's/^ *//'"
# every device missing: one log line each, and the kiosk runs on its script
mkdir -p "$TMP/absent"
check "kiosk without devices" 0 "^1 1 1 1 2 frames$" -- sh -c "$BT kiosk --config tests/kiosk/absent_devices.conf --out $TMP/absent --frames 2 > $TMP/absent/log 2>&1;
    for n in speed_knob mass_knob next_button box; do printf '%s ' \$(grep -c \"input \$n\" $TMP/absent/log); done;
    echo \$(ls $TMP/absent/frame_*.png | wc -l) frames"
# the walk along exact orbits in a pass of its own (a GPU's default) and in the frame's pass
# (llvmpipe's): the kiosk's frames byte for byte the same, previews, refined bands, both knobs, a
# scene change, the effects and the pipeline view (its hit and position passes) included
mkdir -p "$TMP/walk/scenes" "$TMP/walk/separate" "$TMP/walk/inline"
ln -s "$PWD/assets/sky" "$TMP/walk/sky" && ln -s "$PWD/assets/textures" "$TMP/walk/textures"
for walk in separate inline; do
    for scene in schwarzschild blackhole_flight; do
        sed "s/^\[render\]\$/[render]\norbit_walk = $walk/" "assets/scenes/$scene.scene" > "$TMP/walk/scenes/${scene}_$walk.scene"
    done
    sed "s|^scenes = .*|scenes = $TMP/walk/scenes/schwarzschild_$walk.scene, $TMP/walk/scenes/blackhole_flight_$walk.scene|;
         s|^start_scene = .*|start_scene = 0|; /^assets_root/d; s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|;
         s|\.\./\.\./assets|$PWD/assets|g" $K > "$TMP/walk/$walk.conf"
done
mkdir -p "$TMP/walk/programs"
check "kiosk frames the same with the orbit walk separate and inline" 0 "^8 frames, 8 the same, walk pass built$" -- sh -c "
    BT_SHADER_DUMP=$TMP/walk/programs $BT kiosk --config $TMP/walk/separate.conf --out $TMP/walk/separate \
        --frames 8 >/dev/null 2>&1 &&
    $BT kiosk --config $TMP/walk/inline.conf --out $TMP/walk/inline --frames 8 >/dev/null 2>&1 &&
    n=0 && same=0 && for f in $TMP/walk/separate/frame_*.png; do n=\$((n + 1));
        cmp -s \$f $TMP/walk/inline/\$(basename \$f) && same=\$((same + 1)); done;
    ls $TMP/walk/programs | grep -q stage_orbit_walk && built='walk pass built'; echo \$n frames, \$same the same, \$built"
# a scene this GPU cannot draw is left out at start with the reason, the others are shown; where it
# can draw none, the kiosk stops once with exit 3, which the service does not restart
mkdir -p "$TMP/gpu/scenes" "$TMP/gpu/out" "$TMP/gpu/none" && ln -s "$PWD/assets/sky" "$TMP/gpu/sky" && ln -s "$PWD/assets/textures" "$TMP/gpu/textures"
sed 's/^max_path = 90$/max_path = 2100\npipeline = single/' assets/scenes/lorenz.scene > "$TMP/gpu/scenes/lorenz_single.scene"
sed "s|^scenes = .*|scenes = $TMP/gpu/scenes/lorenz_single.scene, $PWD/assets/scenes/starflight.scene|; s|^start_scene = .*|start_scene = 0|;
     /^assets_root/d; s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|; s|\.\./\.\./assets|$PWD/assets|g" $K > "$TMP/gpu/k.conf"
check "kiosk leaves out a scene this GPU cannot draw" 0 "lorenz_single.scene: this GPU \(.*\) cannot draw it: render.pipeline = single: this GPU ends a fragment-shader loop after 4096 turns \(probed\).*; the kiosk shows the other scenes \| .*the start scene .*lorenz_single.scene cannot be drawn; the kiosk starts with .*starflight.scene \| 2 frames$" -- \
    sh -c "BT_FAULT=loop_limit $BT kiosk --config $TMP/gpu/k.conf --out $TMP/gpu/out --frames 2 2>&1 | grep -v '^bentray kiosk: \(headless screen\|stopped\)' | tr '\n' '|' | sed 's/|/ | /g'; echo \$(ls $TMP/gpu/out/frame_*.png | wc -l) frames"
# a scene whose program the driver draws nothing with (VC4's, for a program it cannot hold) is left
# out when the kiosk compiles ahead, as it does on a display, with the reason; the others are shown
sed 's/^max_path = 90$/max_path = 90\npipeline = multipass/' assets/scenes/lorenz.scene > "$TMP/gpu/scenes/lorenz_multipass.scene"
sed "s|^scenes = .*|scenes = $TMP/gpu/scenes/lorenz_multipass.scene, $PWD/assets/scenes/starflight.scene|; s|^\\[kiosk\\]$|[kiosk]\ncompile_ahead = on|" \
    "$TMP/gpu/k.conf" > "$TMP/gpu/skipped.conf"
mkdir -p "$TMP/gpu/skipped"
check "kiosk leaves out a scene whose program the driver does not draw" 0 "lorenz_multipass.scene: this GPU \(.*\) cannot draw it: the GPU's driver draws nothing with the program of stage_intersect .*\(BT_FAULT=draw_skipped\); the kiosk shows the other scenes \| .*2 frames$" -- \
    sh -c "BT_FAULT=draw_skipped $BT kiosk --config $TMP/gpu/skipped.conf --out $TMP/gpu/skipped --frames 2 2>&1 | grep 'cannot' | tr '\n' '|' | sed 's/|/ | /g'; echo \$(ls $TMP/gpu/skipped/frame_*.png | wc -l) frames"
check "kiosk logs each scene's render path" 0 "starflight.scene: fp32\+mrt: RGBA32F ray state" -- \
    env BT_FAULT=loop_limit $BT kiosk --config "$TMP/gpu/k.conf" --out "$TMP/gpu/out" --frames 2 --force
check "kiosk on a GPU that can draw none of its scenes" 3 "starflight.scene: this GPU \(.*\) cannot draw it: this GPU has no renderable float format.*this GPU \(.*\) can draw none of the 2 scenes; stopped \(exit 3: the service does not start it again\)" -- \
    sh -c "NOGPU='MESA_GLES_VERSION_OVERRIDE=2.0 BT_FAULT=float_render,half_float_render,packing'; env \$NOGPU $BT kiosk --config $TMP/gpu/k.conf --out $TMP/gpu/none --frames 2 2>&1 | tr '\n' ' '; exit \$(env \$NOGPU $BT kiosk --config $TMP/gpu/k.conf --out $TMP/gpu/none --frames 2 >/dev/null 2>&1; echo \$?)"
# GLES 2 without float textures (VC4's kind), where the fragment shaders pack floats exactly: the
# packed path draws the scenes (lorenz_single's forced single pass is left out: GLES 2 runs no long loops)
mkdir -p "$TMP/gpu/packed"
check "kiosk on gles2 without float textures draws packed" 0 "starflight.scene: packed 8-bit: .* \| 2 frames$" -- \
    sh -c "env MESA_GLES_VERSION_OVERRIDE=2.0 MESA_EXTENSION_OVERRIDE='-GL_OES_texture_float -GL_OES_texture_half_float' $BT kiosk --config $TMP/gpu/k.conf --out $TMP/gpu/packed --frames 2 2>&1 | grep 'packed 8-bit' | tr '\n' '|' | sed 's/|/ | /g'; echo \$(ls $TMP/gpu/packed/frame_*.png | wc -l) frames"
# a GPU that renders into no float texture but runs long loops (OpenGL ES 3) shows every scene on
# the image-only path, the very frames of the float path; its pipeline view, which shows the rays'
# state, is refused on screen and in the log, and the kiosk goes on
mkdir -p "$TMP/gpu/image_only" "$TMP/gpu/float"
check "kiosk without float render targets shows its scenes" 0 "^2 scenes image only, 3 frames, 3 the same$" -- \
    sh -c "io=\$(BT_FAULT=float_render,half_float_render $BT kiosk --config $TMP/gpu/k.conf --out $TMP/gpu/image_only --frames 3 2>&1 | grep -c 'scene: image only: '); \
    $BT kiosk --config $TMP/gpu/k.conf --out $TMP/gpu/float --frames 3 >/dev/null 2>&1; n=0; same=0; for f in $TMP/gpu/image_only/frame_*.png; do n=\$((n + 1)); \
    cmp -s \$f $TMP/gpu/float/\$(basename \$f) && same=\$((same + 1)); done; echo \$io scenes image only, \$n frames, \$same the same"
mkdir -p "$TMP/gpu/pipeline"
check "kiosk without float render targets refuses the pipeline view" 0 "no pipeline view: it shows the rays' state, and this GPU renders into no float texture" -- \
    env BT_FAULT=float_render,half_float_render $BT kiosk --config tests/kiosk/pipeline_lorenz.conf --out "$TMP/gpu/pipeline" --frames 4
check "kiosk service: no restart when no scene can be drawn" 0 "^RestartPreventExitStatus=3$" -- grep '^RestartPreventExitStatus' kiosk/bentray-kiosk.service
# --check-inputs: the script's events, one line each, then it ends with the script
check "kiosk check inputs" 0 "input replay: turn speed \+20.*input replay: press next_scene" -- sh -c "$BT kiosk --config $K --out $TMP --check-inputs | tr '\n' ' '"
# a stray frame of an earlier run anywhere in the sequence is refused before the kiosk starts
mkdir -p "$TMP/stray" && touch "$TMP/stray/frame_0007.png"
check "kiosk stray frame" 2 "refusing to replace existing file .*stray/frame_0007.png .*a frame of an earlier run" -- $BT kiosk --config $K --out "$TMP/stray" --frames 8
# SIGTERM ends the loop at its next turn (the headless kiosk with no frame limit runs until
# stopped). The time it took is printed; the bound is 30 s, which no plausible load reaches: this
# proves the clean stop, not its speed. The signal is sent once the kiosk has logged that it runs,
# so a slow start cannot turn it into a kill.
mkdir -p "$TMP/term"
stop_check() {  # name, signal, then the signals sent before it that must change nothing
    # each check its own log, created by the kiosk: a log left by the check before would let the
    # signals go out before this kiosk has set its handlers (the shell truncates a reused file only
    # once the child runs, which a loaded machine delays)
    local name=$1 sig=$2 log=$TMP/term/$2.log; shift 2
    rm -f "$log"
    check "$name" 0 "^logged, exit 0 after [0-9.]+ s$" -- sh -c "$BT kiosk --config $K --out $TMP/term --frames 0 --force 2>$log & pid=\$!;
    t=0; while ! grep -q . $log 2>/dev/null && [ \$t -lt 300 ]; do sleep 0.1; t=\$((t+1)); done;
    for s in $*; do kill -\$s \$pid; sleep 0.2; done; kill -0 \$pid || { cat $log; exit 1; };
    start=\$(date +%s%N); kill -$sig \$pid;
    t=0; while kill -0 \$pid 2>/dev/null && [ \$t -lt 300 ]; do sleep 0.1; t=\$((t+1)); done;
    wait \$pid; rc=\$?; took=\$(( (\$(date +%s%N) - start) / 1000000 ));
    grep -q 'stopped after .* (signal)' $log && [ \$t -lt 300 ] && echo \"logged, exit \$rc after \$((took / 1000)).\$((took % 1000 / 100)) s\""
    grep -h "logged, exit" "$TMP/out" 2>/dev/null | sed "s/^/    $name: /"
}
stop_check "kiosk stops on SIGTERM" TERM
stop_check "kiosk stops on SIGHUP, ignores SIGUSR1 and SIGPIPE" HUP USR1 PIPE
# a scene change keeps the knobs' values where the new scene takes them (here the mass knob at the
# largest mass, which the start-up check below makes every black hole take): the kiosk goes on.
# The black hole has no [kiosk] section, so the [mass] knob sets its mass itself (the shipped ones
# map model.mass over a range of their own).
mkdir -p "$TMP/switch" "$TMP/start" "$TMP/shadow"
sed '/^\[kiosk\]/,$d; s|\.\./|'"$PWD"'/assets/|g' assets/scenes/schwarzschild.scene > "$TMP/bh.scene"
printf '0.2 turn mass +200\n0.5 frame\n1.0 press next_scene\n1.5 frame\n' > "$TMP/switch/switch.events"
sed "s|path = visitor.events|path = $TMP/switch/switch.events|; s|\.\./\.\./assets|$PWD/assets|g;
     s|^scenes = .*|scenes = $PWD/assets/scenes/starflight.scene, $TMP/bh.scene|;
     s|^start_scene = .*|start_scene = starflight|; s|^max = 1\$|max = 0.2|; s|^assets_root = .*|assets_root = /|" $K > "$TMP/switch/k.conf"
check "kiosk scene change past a limit" 0 "^exit 0, 2 frames$" -- sh -c "$BT kiosk --config $TMP/switch/k.conf --out $TMP/switch --frames 2 2>/dev/null; echo \"exit \$?, \$(ls $TMP/switch/frame_*.png | wc -l) frames\""
# every scene's images are decoded at start and kept: a texture cut short stops the start with the
# scene's FILE:LINE (before, only its header was read then, and the kiosk failed at the scene change)
mkdir -p "$TMP/tx/scenes" "$TMP/tx/textures" "$TMP/tx/sky" && cp assets/sky/grid_* "$TMP/tx/sky/" && cp assets/scenes/lorenz.scene "$TMP/tx/scenes/"
head -c $(( $(stat -c %s assets/textures/checker_grey.png) / 2 )) assets/textures/checker_grey.png > "$TMP/tx/textures/checker_grey.png"
sed "s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|; s|\.\./\.\./assets|$PWD/assets|g;
     s|^scenes = .*|scenes = $PWD/assets/scenes/starflight.scene, $TMP/tx/scenes/lorenz.scene|;
     s|^start_scene = .*|start_scene = starflight|; s|^assets_root = .*|assets_root = /|" $K > "$TMP/tx/k.conf"
check "kiosk texture cut short refused at start" 2 "tx/scenes/lorenz.scene:[0-9]+: texture: cannot read .*checker_grey.png: the file is truncated" -- $BT kiosk --config "$TMP/tx/k.conf" --out "$TMP/tx" --frames 2
# every scene must take the knobs' start values (reset and scene changes fall back to them)
sed "s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|; s|\.\./\.\./assets|$PWD/assets|g;
     s|^scenes = .*|scenes = $TMP/bh.scene, $PWD/assets/scenes/starflight.scene|;
     s|^start_scene = .*|start_scene = 0|; s|^start = 0.12|start = 5|; s|^max = 1\$|max = 10|; s|^assets_root = .*|assets_root = /|" $K > "$TMP/start/k.conf"
check "kiosk start values checked" 2 "start values .* do not fit .*bh.scene: .*horizon" -- $BT kiosk --config "$TMP/start/k.conf" --out "$TMP/start"
# the [mass] knob's range must leave such a black hole's shadow within 60% of the view's height,
# and the message says how far it may go (the shipped scenes bound their own range in [kiosk])
sed "s|path = visitor.events|path = $PWD/tests/kiosk/visitor.events|; s|\.\./\.\./assets|$PWD/assets|g;
     s|^scenes = .*|scenes = $TMP/bh.scene, $PWD/assets/scenes/starflight.scene|;
     s|^start_scene = .*|start_scene = 0|; s|^assets_root = .*|assets_root = /|" $K > "$TMP/shadow/k.conf"
check "kiosk mass range against the shadow" 2 "\[mass\] max = 1 would make the black hole of .*bh.scene cast a shadow 104 degrees across, over 60% of the view's height: .*mass_max at most 0.27" -- $BT kiosk --config "$TMP/shadow/k.conf" --out "$TMP/shadow"
