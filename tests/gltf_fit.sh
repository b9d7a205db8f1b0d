#!/usr/bin/env bash
# bake-lighting and occlusion with --fit least-squares and occlusion --error on a glTF scene
# (issue 30: "both flags work on every format"): per primitive, in world space, with the whole
# scene as occluder. Truth: the same commands on the scene's flattened world mesh (an ASCII PLY
# written by `normals`, the path that has no glTF in it: one mesh, its own BVH, its own scene
# file), compared vertex by vertex (tests/gltf/compare_flat.py). Lighting is deterministic (point
# and directional shadows: one ray each) and must agree to float rounding; occlusion's rays are
# seeded by vertex and point index, which differ between a primitive and the flattened mesh, so
# the two agree within the Monte Carlo error, and that agreement must be tighter than the fit's
# own effect (mean |fit - point|). Every glTF output passes the Khronos glTF Validator (skipped
# loudly without node/npm, as tests/gltf_cli.sh).
set -uo pipefail
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
check() {  # check NAME COMMAND...
  local name=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $name"; fi
}
py=/usr/bin/python3; [ -x "$py" ] || py=python3
cmp() { "$py" "$src/tests/gltf/compare_flat.py" "$@"; }

source "$src/tests/gltf/validator.sh"  # $validate and valid FILE...

# Three primitives (two in one mesh), every one with NORMAL, placed by rotated, scaled, translated
# nodes; a directional and a point light (KHR_lights_punctual) and the same lights as a scene file.
"$py" "$src/tests/gltf/make_fit_scene.py" "$tmp/scene.gltf" "$tmp/scene.json" || { echo "FAIL: fixture"; exit 1; }
check "fixture is valid glTF" valid "$tmp/scene.gltf"
"$bin" normals "$tmp/scene.gltf" -o "$tmp/flat.ply" --ascii -q
check "flattened: 3 primitives, 223 vertices" grep -q "element vertex 223" "$tmp/flat.ply"

# bake-lighting: the file's own lights, shadows from the whole scene; float and 8-bit colours.
for depth in hdr 8bit; do
  flag=(); [ $depth = hdr ] && flag=(--hdr)
  "$bin" bake-lighting "$tmp/scene.gltf" -o "$tmp/lit_$depth.gltf" --fit least-squares --shadows "${flag[@]}" -q
  check "bake-lighting --fit least-squares glTF ($depth): exit 0" test $? -eq 0
  check "bake-lighting --fit least-squares glTF ($depth): valid" valid "$tmp/lit_$depth.gltf"
  "$bin" bake-lighting "$tmp/flat.ply" --scene "$tmp/scene.json" -o "$tmp/flat_lit_$depth.ply" --ascii --linear \
    --fit least-squares --shadows "${flag[@]}" -q
  "$bin" bake-lighting "$tmp/flat.ply" --scene "$tmp/scene.json" -o "$tmp/flat_point_$depth.ply" --ascii --linear \
    --shadows "${flag[@]}" -q
  # Float colours: float rounding (COLOR_0 is float32). 8-bit: each solve stops within a quarter
  # step of the exact values (fit/least_squares_fit.h, accuracy), the glTF's per primitive and the
  # flattened mesh's for all at once, so a byte may differ by one step where a value lies near a
  # rounding boundary.
  tol=1e-6; [ $depth = 8bit ] && tol=0.00393
  check "bake-lighting --fit least-squares glTF ($depth) = the flattened mesh's fit" \
    cmp "$tmp/lit_$depth.gltf" "$tmp/flat_lit_$depth.ply" color $tol "$tmp/flat_point_$depth.ply"
done

# occlusion: a fixed count, and to a stated error (with and without the fit).
"$bin" occlusion "$tmp/scene.gltf" -o "$tmp/ao.gltf" --fit least-squares --samples 1024 --as color -q
check "occlusion --fit least-squares glTF: exit 0" test $? -eq 0
check "occlusion --fit least-squares glTF: valid" valid "$tmp/ao.gltf"
"$bin" occlusion "$tmp/flat.ply" -o "$tmp/flat_ao.ply" --ascii --as quality --fit least-squares --samples 1024 -q
"$bin" occlusion "$tmp/flat.ply" -o "$tmp/flat_ao_point.ply" --ascii --as quality --samples 1024 -q
check "occlusion --fit least-squares glTF = the flattened mesh's fit (1024 rays)" \
  cmp "$tmp/ao.gltf" "$tmp/flat_ao.ply" quality 0.03 "$tmp/flat_ao_point.ply"

for fit in point least-squares; do
  "$bin" occlusion "$tmp/scene.gltf" -o "$tmp/ao_e_$fit.gltf" --fit $fit --error 0.003 --samples 16384 --as color \
    --stats --json > "$tmp/ao_e_$fit.json" 2> /dev/null
  check "occlusion --error --fit $fit glTF: exit 0" test $? -eq 0
  check "occlusion --error --fit $fit glTF: valid" valid "$tmp/ao_e_$fit.gltf"
  "$bin" occlusion "$tmp/flat.ply" -o "$tmp/flat_ao_e_$fit.ply" --ascii --as quality --fit $fit --error 0.003 \
    --samples 16384 -q
done
# Both within 10 E of the flattened mesh's (the two estimates' errors are independent, each <= E
# at most points); the fit's agreement also tighter than its effect.
check "occlusion --error glTF = the flattened mesh's, within the error" \
  cmp "$tmp/ao_e_point.gltf" "$tmp/flat_ao_e_point.ply" quality 0.03
check "occlusion --error --fit least-squares glTF = the flattened mesh's fit" \
  cmp "$tmp/ao_e_least-squares.gltf" "$tmp/flat_ao_e_least-squares.ply" quality 0.03 "$tmp/flat_ao_e_point.ply"
check "occlusion --error glTF: a rays histogram per primitive in --json" "$py" -c '
import json,sys
j=json.load(open(sys.argv[1]))
files=j["files"] if "files" in j else [j]
s=json.dumps(j)
assert s.count("rays_histogram")>=3, s[:400]' "$tmp/ao_e_point.json"

echo "gltf_fit: $pass passed, $fail failed"
[ $fail -eq 0 ]
