#!/usr/bin/env bash
# Re-render the golden images of the render tests (64x48, EGL). Run on purpose only, after
# looking at what changed; commit the new images with the reason.
set -euo pipefail
cd "$(dirname "$0")/../.."
for s in test lorenz potential refraction schwarzschild neutron_star demo rossler starflight blackhole_flight cube_approach three_ships clocks star_sky; do
    ./bentray render --scene "assets/scenes/$s.scene" --size 64x48 --backend egl --force --quiet \
        --out "tests/golden/$s.png"
done
