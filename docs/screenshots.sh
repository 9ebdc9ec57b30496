#!/usr/bin/env bash
# Regenerates the pictures in docs/images: the three render modes and the showcase scene file
# from the render tool, and a screenshot of the viewer in a real window under Xvfb (needs xvfb, xdotool, imagemagick and
# libsdl2, as .ci/run installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --example render
cargo build --release --features window --example viewer
for mode in wire flat gouraud; do
    target/release/examples/render --obj models/spot.obj --mode "$mode" --size 240x240 \
        --eye -1.5,0.6,-1.7 --target 0,0.05,0 --light -1,1,-1,0.75 --light 1,0.3,-0.2,0.3 \
        --out "docs/images/render-$mode.png"
done
target/release/examples/render --scene examples/scenes/showcase.toml --size 480x300 \
    --out docs/images/render-scene.png
display=:98
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
export DISPLAY=$display
sleep 1
target/release/examples/viewer </dev/null >/dev/null 2>&1 &
viewer=$!
wid=$(timeout 30 xdotool search --sync --name "fixed3d viewer" | head -1)
sleep 2
xdotool windowfocus --sync "$wid" || true
xdotool key Tab
sleep 0.5
import -window "$wid" docs/images/viewer.png
xdotool key h
sleep 0.5
import -window "$wid" docs/images/viewer-help.png
xdotool key Escape
wait $viewer || true
echo "wrote docs/images/{render-wire,render-flat,render-gouraud,render-scene,viewer,viewer-help}.png"
