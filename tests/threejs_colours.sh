#!/usr/bin/env bash
# Baked colours as three.js shows them (issue 28, item 1 and its "done when"): the same bake written
# as glTF (COLOR_0, linear by the glTF specification) and as PLY (8-bit colours, which three.js,
# Blender and MeshLab read as sRGB) must both come out, in three.js's linear working space, as the
# linear values the lighting computed (a --hdr glTF bake: float COLOR_0). npm `three` is installed
# into the build tree on first use; skipped loudly without node/npm or a registry.
set -uo pipefail
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
dir=$(dirname "$bin")/threejs-node
if ! command -v node > /dev/null; then echo "skipped: three.js colours (no node)"; echo "0 passed, 0 failed"; exit 0; fi
if [ ! -d "$dir/node_modules/three" ] && command -v npm > /dev/null; then
  npm install --silent --no-audit --no-fund --prefix "$dir" three > "$tmp/npm.log" 2>&1 || cat "$tmp/npm.log"
fi
if [ ! -d "$dir/node_modules/three" ]; then echo "skipped: three.js colours (npm install three failed: no registry?)"; echo "0 passed, 0 failed"; exit 0; fi
cp "$src/tests/threejs/check_colours.mjs" "$dir/"
scene=$src/data/scenes/studio.json
"$bin" bake-lighting "$src/data/torus.obj" -o "$tmp/truth.glb" --scene "$scene" --hdr -q || { echo "FAIL: bake --hdr"; exit 1; }
"$bin" bake-lighting "$src/data/torus.obj" -o "$tmp/bytes.glb" --scene "$scene" -q || { echo "FAIL: bake glb"; exit 1; }
"$bin" bake-lighting "$src/data/torus.obj" -o "$tmp/bytes.ply" --scene "$scene" -q || { echo "FAIL: bake ply"; exit 1; }
if node "$dir/check_colours.mjs" "$tmp/truth.glb" "$tmp/bytes.glb" "$tmp/bytes.ply"; then
  echo "2 passed, 0 failed"
else
  echo "FAIL: three.js shows other colours than the lighting computed"
  echo "0 passed, 1 failed"; exit 1
fi
