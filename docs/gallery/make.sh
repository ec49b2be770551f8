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
    echo "## Scenes"
    echo
} > "$tmp/GALLERY.md"
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
