#!/usr/bin/env bash
# `make gallery`: every committed scene as `bentray render` draws it at its own settings, and one
# animation made by `bentray animate` (the demo's black hole growing from no mass to its kiosk's
# largest), into
# docs/gallery/, with docs/GALLERY.md listing them and the commands that made them.
set -euo pipefail
cd "$(dirname "$0")/../.."
BT=./bentray
OUT=docs/gallery
md=docs/GALLERY.md
ANIMATE="bentray animate --scene assets/scenes/demo.scene --frames 48 --size 320x180 --set-range model.mass=0:1.4 --fps 12 --out FRAMES --video docs/gallery/demo_mass.gif"
CUBEMAP_SKY="bentray render --scene assets/scenes/star_sky.scene --size 1920x1080 --set sky.stars=0 --set sky.milky_way=0 --set sky.type=cubemap --set sky.cubemap=../sky/stars"
POINT_SKY="bentray render --scene assets/scenes/star_sky.scene --size 1920x1080"
BLOOM="bentray render --scene assets/scenes/demo.scene --size 960x540 --set render.bloom=0.2"
LAYERS="bentray render --scene assets/scenes/demo.scene --set observer.effects=E --set observer.gravitational_shift=G"
PIPELINE_VIEW="bentray kiosk --config docs/gallery/pipeline_view.conf --display headless --out DIR --frames 1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
{
    echo "# Gallery"
    echo
    echo "Written by \`make gallery\` (docs/gallery/make.sh): each scene of assets/scenes/ at its own size and"
    echo "settings, and one animation. Each image is \`bentray render --scene assets/scenes/NAME.scene\`."
    echo
    echo "## The demo's mass growing"
    echo
    echo "From flat space (M = 0, straight rays: the disk as it is) to M = 1.4: the far side of the disk"
    echo "lifts over the hole, its underside appears below it, and the shadow grows."
    echo
    echo "\`$ANIMATE\`"
    echo
    echo "![The demo's black hole growing from no mass](gallery/demo_mass.gif)"
    echo
    echo "## The star sky at 1920x1080"
    echo
    echo "star_sky.scene at 1920x1080, twice: first with the sky of a cube map of stars, 256x256 texels a"
    echo "face, as the scenes had it before \`[sky] stars\`, then with 30000 point stars and the Milky Way"
    echo "(docs/STARS.md). The texels blur into blobs and smear into arcs next to the shadow; the point"
    echo "stars stay points of the same size everywhere, brighter where the hole magnifies them."
    echo
    echo "\`$CUBEMAP_SKY\`"
    echo
    echo "![star_sky with the cube map of stars](gallery/star_sky_cubemap_1080p.png)"
    echo
    echo "\`$POINT_SKY\`"
    echo
    echo "![star_sky with point stars and the Milky Way](gallery/star_sky_1080p.png)"
    echo
    echo "## Bloom"
    echo
    echo "demo.scene at 960x540 with \`render.bloom = 0.2\` (docs/SCENES.md): a fifth of every pixel's light"
    echo "spread by a glare's point-spread, so the disk's hot side, brighter than white, glows into the"
    echo "shadow and the sky beside it. Compare demo.scene's own image below."
    echo
    echo "\`$BLOOM\`"
    echo
    echo "![demo with bloom](gallery/demo_bloom.png)"
    echo
    echo "## The layers of the disk's light"
    echo
    echo "demo.scene as the kiosk's effects button shows it, one layer added at a time (docs/RELATIVITY.md):"
    echo "the bending alone, the disk in its RGB colour (\`E = geometry\`); the colour of each point's black"
    echo "body shifted by its matter's motion, bluer where it comes towards the camera (\`E = doppler\`,"
    echo "\`G = off\`); its brightness too, the searchlight (\`E = searchlight\`, \`G = off\`); and gravity's"
    echo "redshift of the matter deep in the hole's field on top: demo.scene's own image, in the Scenes below."
    echo
    echo "\`$LAYERS\`"
    echo
    echo "![demo, geometry only](gallery/demo_layer_geometry.png) ![demo, Doppler colour of the motion](gallery/demo_layer_doppler.png) ![demo, with the searchlight](gallery/demo_layer_searchlight.png)"
    echo
    echo "## The kiosk's pipeline view"
    echo
    echo "The black hole's rays as the renderer leaves them (key \`v\` at the kiosk; docs/KIOSK.md, docs/PIPELINE.md):"
    echo "the image, the rays' final positions and directions, the segment of each hit, the orbit table the"
    echo "rays followed and each ray's outcome, each panel with what its colours mean below it."
    echo
    echo "\`$PIPELINE_VIEW\`"
    echo
    echo "![The kiosk's pipeline view of schwarzschild.scene](gallery/pipeline_view.png)"
    echo
    echo "## Scenes"
    echo
} > "$tmp/GALLERY.md"
mkdir "$tmp/pipeline_view"
$BT kiosk --config docs/gallery/pipeline_view.conf --display headless --out "$tmp/pipeline_view" --frames 1 \
    > /dev/null 2> "$tmp/kiosk.log" || { cat "$tmp/kiosk.log" >&2; exit 1; }
mv "$tmp/pipeline_view/frame_0001.png" "$OUT/pipeline_view.png"
$BT render --scene assets/scenes/star_sky.scene --size 1920x1080 --set sky.stars=0 --set sky.milky_way=0 \
    --set sky.type=cubemap --set sky.cubemap=../sky/stars --out "$OUT/star_sky_cubemap_1080p.png" --force --quiet > /dev/null
$BT render --scene assets/scenes/star_sky.scene --size 1920x1080 --out "$OUT/star_sky_1080p.png" --force --quiet > /dev/null
$BT render --scene assets/scenes/demo.scene --size 960x540 --set render.bloom=0.2 --out "$OUT/demo_bloom.png" --force --quiet > /dev/null
for layer in "geometry on" "doppler off" "searchlight off"; do
    set -- $layer
    $BT render --scene assets/scenes/demo.scene --set observer.effects="$1" --set observer.gravitational_shift="$2" \
        --out "$OUT/demo_layer_$1.png" --force --quiet > /dev/null
done
$BT animate --scene assets/scenes/demo.scene --frames 48 --size 320x180 --set-range model.mass=0:1.4 --fps 12 \
    --out "$tmp/frames" --video "$OUT/demo_mass.gif" --force --quiet > /dev/null
for f in assets/scenes/*.scene; do
    name=$(basename "$f" .scene)
    $BT render --scene "$f" --out "$OUT/$name.png" --force --quiet > /dev/null
    description=$(sed -n 's/^description *= *//p' "$f" | head -1)
    {
        echo "### $name"
        echo
        echo "$description"
        echo
        echo "![$name](gallery/$name.png)"
        echo
    } >> "$tmp/GALLERY.md"
done
mv "$tmp/GALLERY.md" "$md"
echo "$md"
