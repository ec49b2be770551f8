# Sourced by run_all.sh: the hostile trial's cases, each failing before its fix. No input is an
# output, a repeated or conflicting option is refused naming both, standard output closed is an
# error, no reader waits on a FIFO, and a legal long file name is written.
R=$TMP/reliability
mkdir -p "$R"
# the scene, its textures and its sky are never written over, whatever --out, --dump or --force say
sed 's|\.\./|'"$(pwd)"'/assets/|g' assets/scenes/test.scene > "$R/own.scene"
cp "$R/own.scene" "$R/own.before"
check "render: --dump is the scene" 2 "--dump .*own.scene is the scene file .*, which this render reads" -- \
    $BT render --scene "$R/own.scene" --dump "$R/own.scene" --force --out "$R/own.png"
check "render: the scene is kept" 0 "^kept$" -- sh -c "cmp -s '$R/own.scene' '$R/own.before' && echo kept"
# (a sky of its own: a failing run must not write over the project's)
cp assets/sky/grid_*.png "$R/"
sed 's|^cubemap = .*|cubemap = '"$R"'/grid|; s|\.\./|'"$(pwd)"'/assets/|g' assets/scenes/schwarzschild.scene > "$R/sky.scene"
check "render: --out is a cube face" 2 "--out .*grid_px.png is the sky's cube face" -- \
    $BT render --scene "$R/sky.scene" --out "$R/grid_px.png" --force
ln -s "$R/own.scene" "$R/link.dump"
check "render: --dump through a link to the scene" 2 "is the scene file" -- \
    $BT render --scene "$R/own.scene" --dump "$R/link.dump" --force --out "$R/own.png"
sed 's|^log = stderr|log = '"$R"'/kiosk.conf|; s|\.\./assets|'"$(pwd)"'/assets|g' kiosk/kiosk.conf > "$R/kiosk.conf"
check "kiosk: log is its configuration" 2 "kiosk.conf:[0-9]+: key 'log' in \[kiosk\]: .* is this configuration" -- \
    timeout 60 $BT kiosk --config "$R/kiosk.conf" --display headless --frames 1 --out "$R/kf"
# options given twice, or against each other
check "option given twice" 2 "option --scene given twice \('a.scene', then 'b.scene'\)" -- $BT render --scene a.scene --scene b.scene
check "--out given twice" 2 "option --out given twice" -- $BT render --scene $S --out a.png --out b.png
check "--version with an argument" 2 "unexpected argument 'extra'" -- $BT --version extra
check "animate --fps without --video" 2 "--fps sets the video's frame rate and goes with --video" -- \
    $BT animate --scene $S --frames 2 --out "$R/an" --fps 10
check "animate --set and --set-range of one key" 2 "--set model.mass=1 and --set-range model.mass" -- \
    $BT animate --scene assets/scenes/demo.scene --frames 2 --out "$R/an" --set-range model.mass=0:1 --set model.mass=1
check "animate two ranges of one key" 2 "--set-range model.mass given twice" -- \
    $BT animate --scene assets/scenes/demo.scene --frames 2 --out "$R/an" --set-range model.mass=0:1 --set-range model.mass=1:2
check "bench --kiosk with --only" 2 "--kiosk runs the kiosk's section alone" -- $BT bench --kiosk --only table1
check "bench --only nothing" 2 "--only: name at least one section" -- $BT bench --out "$R" --only ''
# standard output closed: an error, not a PNG in stderr's file
check "render --out - with standard output closed" 1 "standard output is closed" -- sh -c "$BT render --scene $S --size 16x12 --out - >&-"
check "render --dump -" 2 "--dump -: a dump is written to a file" -- $BT render --scene $S --dump - --out "$R/d.png"
# a FIFO or a directory where a shader file should be: refused at once, never waited on
mkdir -p "$R/shaders" && cp shaders_es/*.glsl "$R/shaders/" && rm "$R/shaders/common.glsl" && mkfifo "$R/shaders/common.glsl"
check "--shader-dir with a FIFO" 2 "cannot read shader .*common.glsl: not a regular file" -- \
    timeout 60 $BT render --scene $S --size 16x12 --shader-dir "$R/shaders" --out "$R/fifo.png"
# a file name of 250 bytes is legal; its temporary's name is not what decides
long=$(printf 'n%.0s' $(seq 1 246))
check "a 250-byte file name" 0 "^written$" -- sh -c "$BT render --scene $S --size 16x12 --out '$R/$long.png' --quiet >/dev/null && test -s '$R/$long.png' && echo written"
# one kiosk configuration travels: --display takes another screen than the file's, whose keys for
# its own screen are set aside with a note, not refused
mkdir -p "$R/kh"
check "kiosk --display headless over a screen's configuration" 0 "--display headless: \[display\] vsync set aside" -- \
    timeout 120 $BT kiosk --config kiosk/kiosk.conf --display headless --out "$R/kh" --frames 1
sed 's|^headless_frames = 0|headless_out = '"$R"'/kh|; s|\.\./\.\./assets|'"$(pwd)"'/assets|g; s|^path = |path = '"$(pwd)"'/tests/kiosk/|' tests/kiosk/headless.conf > "$R/headless.conf"
check "kiosk --display x11 over a headless configuration" 0 "^headless_out set aside$" -- sh -c "$BT kiosk --config '$R/headless.conf' --display x11 --check-inputs 2>&1 | sed -n 's/.*\[display\] \(.*\) (for the file.*/\1/p' | head -1"
# --set cannot turn an object into another type (it would keep none of its geometry); a direction of
# 1e-200 is a direction
check "--set an object's type" 2 "an object's type is not changed with --set" -- $BT render --scene $S --set object.red.type=triangle --out "$R/t.png"
check "a tiny camera up is a direction" 0 "^same$" -- sh -c "$BT render --scene $S --size 16x12 --set 'camera.up=0 1e-200 0' --out '$R/up_tiny.png' --quiet > /dev/null && $BT render --scene $S --size 16x12 --out '$R/up_one.png' --quiet > /dev/null && cmp -s '$R/up_tiny.png' '$R/up_one.png' && echo same"
# a flat primitive the GPU's 32-bit floats cannot intersect is refused; the largest allowed is hit
# on the GPU as on the CPU
check "a rect too large for the GPU" 2 "\[object floor\]: a rect's axis is 1e\+10 long; at most 1e\+09" -- \
    $BT render --scene $S --size 32x24 --set "object.floor.axis_u=1e10 0 0" --set "object.floor.axis_v=0 0 -1e10" --out "$R/big.png"
check "the largest rect on both engines" 0 "^same$" -- sh -c "for e in gpu cpu; do $BT render --scene $S --size 32x24 --engine \$e \
    --set 'object.floor.axis_u=1e9 0 0' --set 'object.floor.axis_v=0 0 -1e9' --out '$R/big_\$e.png' 2>&1 | grep '^rays:'; done | uniq | wc -l | sed 's/^1$/same/'"
# bench from any directory: the project's scenes are found from the program's place
mkdir -p "$R/elsewhere"
check "bench from another directory" 0 "wrote out/BENCH.md" -- sh -c "cd '$R/elsewhere' && mkdir -p out && $(cd "$(dirname "$BT")" && pwd)/$(basename "$BT") bench --out out --quick --only table1"
# docs/KIOSK.md's example tour is a script the kiosk reads (the whole file is checked before the first
# event is replayed)
awk '/^### A tour.s script/{f=1} f&&/^```$/{if(g){exit}; g=1; next} g' docs/KIOSK.md > "$R/tour.events"
sed 's|^path = visitor.events|path = '"$R"'/tour.events|; s|\.\./\.\./assets|'"$(pwd)"'/assets|g' tests/kiosk/headless.conf > "$R/tour.conf"
mkdir -p "$R/tour_out"
check "KIOSK.md's example tour" 0 "input replay: turn mass \+3" -- sh -c "timeout 3 $BT kiosk --config '$R/tour.conf' --check-inputs --out '$R/tour_out' 2>&1; true"
# a field so strong that one fixed step crosses the whole scene fails its rays with the warning, on
# the GPU as on the CPU (the GPU used to report every ray as a hit: its chords crossed the floor)
for e in gpu cpu; do
    check "a Yukawa zeta of -1e18 fails every ray ($e)" 0 "768 of 768 rays failed" -- \
        $BT render --scene assets/scenes/potential.scene --size 32x24 --engine $e --set model.zeta=-1e18 --out "$R/zeta_$e.png"
done
for p in multipass fused; do
    check "a Yukawa zeta of -1e18 fails every ray ($p)" 0 "768 of 768 rays failed" -- \
        $BT render --scene assets/scenes/potential.scene --size 32x24 --set render.pipeline=$p --set model.zeta=-1e18 --out "$R/zeta_$p.png"
done
# a kiosk font that is not a font is refused at start at its line, as a missing one is
sed 's|\.\./\.\./assets|'"$(pwd)"'/assets|g; s|path = visitor.events|path = '"$(pwd)"'/tests/kiosk/visitor.events|; s|^hud = on|hud = on\nfont = '"$(pwd)"'/README.md|' tests/kiosk/headless_hud.conf > "$R/font.conf"
mkdir -p "$R/font_out"
check "a kiosk font that is not a font" 2 "font.conf:11: \[kiosk\] font = .*README.md: not a font" -- $BT kiosk --config "$R/font.conf" --out "$R/font_out" --frames 1
# dumps of two scenes whose names share their first 31 characters are two scenes to compare
for n in x y; do
    $BT render --scene assets/scenes/test.scene --size 16x12 --set "scene.name=aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa$n" --dump "$R/long_$n.dump" --out "$R/long_$n.png" --quiet > /dev/null 2>&1
done
check "compare long scene names" 2 "scene 'a{22}~[0-9a-f]{8}' differs from the reference's 'a{22}~[0-9a-f]{8}'" -- $BT compare "$R/long_x.dump" "$R/long_y.dump"
# a scene on exact orbits whose table is too large to build ahead is refused at the kiosk's start
# (it would be built on the loop at every mass detent, for seconds)
sed 's|^\[render\]|[render]\norbit_rows = 2048|; s|\.\./sky/|'"$(pwd)"'/assets/sky/|g; s|\.\./textures/|'"$(pwd)"'/assets/textures/|g' assets/scenes/schwarzschild.scene > "$R/big_table.scene"
sed 's|^scenes = .*|scenes = '"$R"'/big_table.scene|; s|^start_scene = .*|start_scene = 0|; /^assets_root/d; s|path = visitor.events|path = '"$(pwd)"'/tests/kiosk/visitor.events|' tests/kiosk/headless.conf > "$R/big_table.conf"
mkdir -p "$R/big_table_out"
check "a kiosk scene with a table too large to build ahead" 2 "big_table.scene: render.orbit_rows = 2048 and render.orbit_columns = 128 make an orbit table of 10.1 MB.*at most 8 MB in the kiosk" -- \
    $BT kiosk --config "$R/big_table.conf" --out "$R/big_table_out" --frames 1
# animate's frames go through the same writer as render's images (io/output_file.h): a link at a
# frame is replaced and its target kept, a file-size limit or an interrupt leaves the earlier frame
# whole and no temporary, and two runs writing the same frames at once leave complete PNGs
A=$R/frames && mkdir -p "$A"
echo keep > "$R/frame_target" && ln -s "$R/frame_target" "$A/frame_0001.png"
check "animate: a link at a frame is replaced, its target kept" 0 "^keep regular$" -- sh -c "$BT animate --scene $S --frames 1 --size 8x6 --out '$A' --force --quiet > /dev/null && echo \$(cat '$R/frame_target') \$(stat -c %F '$A/frame_0001.png' | cut -d' ' -f1)"
echo 'old frame' > "$A/frame_0001.png"
check "animate: a file-size limit keeps the old frame" 0 "^old frame; 0 temporaries$" -- sh -c "(ulimit -f 1; $BT animate --scene $S --frames 1 --size 160x120 --out '$A' --force --quiet) > /dev/null 2>&1; echo \"\$(cat '$A/frame_0001.png'); \$(ls '$A' | grep -c tmp-) temporaries\""
check "animate: an interrupt leaves no temporary" 0 "^0 temporaries$" -- sh -c "timeout -s INT 1 $BT animate --scene assets/scenes/schwarzschild.scene --frames 40 --size 160x120 --out '$A' --force --quiet > /dev/null 2>&1; echo \"\$(ls '$A' | grep -c tmp-) temporaries\""
check "animate: two writers at once leave whole frames" 0 "^6 of 6 whole, both wrote$" -- sh -c "$BT animate --scene $S --frames 6 --size 64x48 --out '$A' --force --quiet > /dev/null 2>&1 & a=\$!; $BT animate --scene $S --frames 6 --size 64x48 --set camera.fov=50 --out '$A' --force --quiet > /dev/null 2>&1; b=\$?; wait \$a; a=\$?; n=0; for f in '$A'/frame_000[1-6].png; do [ \"\$(tail -c 8 \"\$f\" | od -An -tx1 | tr -d ' \\n')\" = 49454e44ae426082 ] && n=\$((n + 1)); done; [ \$a\$b = 00 ] && w='both wrote' || w=\"exits \$a \$b\"; echo \"\$n of 6 whole, \$w\""
