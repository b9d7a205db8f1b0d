#!/usr/bin/env bash
# Renders 1920x1080 frames with the CLI (Phong: data/torus.obj under studio.json, data/torus_knot.ply
# under window.json, and, when the shared corpus is there, its spot.obj under studio.json), then times
# io/image_png.h's encoder on them at every level against libpng's default settings, in one process,
# rounds interleaved. Usage: bench/render/png_encode.sh [ROUNDS] (default 15); prints a Markdown table
# and the load average.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target bench_png_encode shadetool_cli >/dev/null
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$build/shadetool" render "$root/data/torus.obj" -o "$tmp/torus-studio.png" --scene "$root/data/scenes/studio.json" --size 1920,1080 -q
"$build/shadetool" render "$root/data/torus_knot.ply" -o "$tmp/knot-window.png" --scene "$root/data/scenes/window.json" --size 1920,1080 -q
frames=("$tmp/torus-studio.png" "$tmp/knot-window.png")
spot=/work/shared/corpus/c3d/spot/spot.obj
if [ -f "$spot" ]; then
  "$build/shadetool" render "$spot" -o "$tmp/spot-studio.png" --scene "$root/data/scenes/studio.json" --size 1920,1080 -q
  frames+=("$tmp/spot-studio.png")
fi
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/render/bench_png_encode" "${1:-15}" "${frames[@]}" | sed "s#$tmp/##"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
