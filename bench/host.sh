#!/usr/bin/env bash
# Instructions per frame of the reference scene on this host, counted by callgrind (exact and
# repeatable, unlike wall time): draw_scene (the drawing: vertex stage, culling, shading,
# rasterising) and clear_buffers, per frame and per covered pixel.
#   bench/host.sh [FRAMES]        (default 20)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-20}
if ! command -v valgrind >/dev/null; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo=sudo
    $sudo apt-get update -qq && $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq valgrind >/dev/null
fi
cargo build --release --example torus_bench
out=target/callgrind.torus
line=$(valgrind --tool=callgrind --callgrind-out-file="$out" target/release/examples/torus_bench "$frames" 2>/dev/null)
echo "$line"
covered=$(sed -E 's/.*covered ([0-9]+) pixels.*/\1/' <<<"$line")
ir() { callgrind_annotate --inclusive=yes "$out" 2>/dev/null | awk -v f="$1" '$0 ~ f"[ (]" || $0 ~ f"$" { gsub(",", "", $1); print $1; exit }'; }
draw=$(ir "torus_bench::draw_scene")
clear=$(ir "torus_bench::clear_buffers")
awk -v d="$draw" -v c="$clear" -v n="$frames" -v px="$covered" 'BEGIN {
    printf "draw_scene:    %.3f M instructions per frame, %.1f per covered pixel\n", d / n / 1e6, d / n / px;
    printf "clear_buffers: %.3f M instructions per frame\n", c / n / 1e6;
}'
