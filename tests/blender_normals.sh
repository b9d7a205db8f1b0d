#!/usr/bin/env bash
# Normals against Blender (issue 29), run only where `blender` is on PATH (Debian's blender is
# 581 MB and not a build dependency): skipped loudly otherwise.
#  1. Weighted Normal modifier (FACE_AREA, FACE_AREA_WITH_ANGLE; weight 50/75/100; keep sharp off)
#     on a bevelled box against `shadetool normals --weight ...`: every corner within 0.05 degrees
#     (Blender stores custom normals in 16 bits per component).
#  2. Blender's OBJ importer with smooth groups on a file with `s 1`, `s 2`, `s off` against
#     `shadetool normals` (smoothing groups honoured): every corner within 0.05 degrees.
set -uo pipefail
bin=$1 src=$2
if ! command -v blender > /dev/null; then
  echo "skipped: Blender comparison of weighted normals and smoothing groups (no blender on PATH; apt-get install blender)"
  exit 0
fi
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3; [ -x "$py" ] || py=python3
pass=0 fail=0
check() { local name=$1; shift; if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $name"; fi; }

# A bevelled box: a 2 x 2 x 1 box whose top edges are chamfered by 0.1 (large flat faces, thin bevels).
"$py" - "$tmp/box.obj" <<'PY'
import sys
b = 0.1
V = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0),                                  # bottom
     (-1, -1, 1 - b), (1, -1, 1 - b), (1, 1, 1 - b), (-1, 1, 1 - b),                  # side tops
     (-1 + b, -1 + b, 1), (1 - b, -1 + b, 1), (1 - b, 1 - b, 1), (-1 + b, 1 - b, 1)]  # top
F = [(0, 3, 2, 1), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7),
     (4, 5, 9, 8), (5, 6, 10, 9), (6, 7, 11, 10), (7, 4, 8, 11), (8, 9, 10, 11)]
with open(sys.argv[1], "w") as f:
    for v in V: f.write("v %r %r %r\n" % v)
    for fc in F: f.write("f " + " ".join(str(i + 1) for i in fc) + "\n")
PY

# Blender: the modifier's split normals per loop (loops follow the OBJ's face order), as JSON.
blender_weighted() {  # OBJ MODE WEIGHT OUT
  blender -b --factory-startup --python-exit-code 1 --python-expr "
import bpy, json, math, sys
V, F = [], []
for line in open('$1'):
    w = line.split()
    if not w: continue
    if w[0] == 'v': V.append(tuple(map(float, w[1:4])))
    if w[0] == 'f': F.append(tuple(int(x.split('/')[0]) - 1 for x in w[1:]))
me = bpy.data.meshes.new('m'); me.from_pydata(V, [], F); me.update()
for p in me.polygons: p.use_smooth = True
me.use_auto_smooth = True; me.auto_smooth_angle = math.pi
ob = bpy.data.objects.new('o', me); bpy.context.scene.collection.objects.link(ob)
m = ob.modifiers.new('w', 'WEIGHTED_NORMAL'); m.mode = '$2'; m.weight = $3; m.keep_sharp = False
dg = bpy.context.evaluated_depsgraph_get(); e = ob.evaluated_get(dg).to_mesh(); e.calc_normals_split()
json.dump([list(l.normal) for l in e.loops], open('$4', 'w'))
" > "$tmp/blender.log" 2>&1 || { cat "$tmp/blender.log"; return 1; }
}

# Ours: corner normals of an OBJ (vn per corner, in face order), as JSON.
corner_normals() {  # OBJ OUT
  "$py" - "$1" "$2" <<'PY'
import json, sys
vn, out = [], []
for line in open(sys.argv[1]):
    w = line.split()
    if not w: continue
    if w[0] == 'vn': vn.append(list(map(float, w[1:4])))
    if w[0] == 'f': out += [vn[int(c.split('/')[2]) - 1] for c in w[1:]]
json.dump(out, open(sys.argv[2], 'w'))
PY
}

within() {  # A.json B.json DEG
  "$py" - "$1" "$2" "$3" <<'PY'
import json, math, sys
a, b, tol = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), float(sys.argv[3])
assert len(a) == len(b), (len(a), len(b))
worst = 0
for x, y in zip(a, b):
    d = max(-1, min(1, sum(p * q for p, q in zip(x, y)) / math.sqrt(sum(p * p for p in x) * sum(q * q for q in y))))
    worst = max(worst, math.degrees(math.acos(d)))
print("worst corner: %.4f degrees" % worst)
sys.exit(0 if worst <= tol else 1)
PY
}

for mode in FACE_AREA:face-area FACE_AREA_WITH_ANGLE:face-area-angle; do
  for w in 50 75 100; do
    blender_weighted "$tmp/box.obj" "${mode%%:*}" "$w" "$tmp/b.json"
    check "blender ${mode%%:*} weight $w ran" test $? -eq 0
    "$bin" normals "$tmp/box.obj" -o "$tmp/ours.obj" --weight "${mode##*:}" --weight-strength "$w" --crease 180 -q
    corner_normals "$tmp/ours.obj" "$tmp/o.json"
    check "weighted normals ${mode##*:} $w within 0.05 degrees of Blender" within "$tmp/b.json" "$tmp/o.json" 0.05
  done
done

# Smoothing groups: Blender's OBJ importer (smooth groups) on the box with three groups.
awk 'BEGIN{n=0} /^f/{n++; if(n==1) print "s off"; if(n==2) print "s 1"; if(n==6) print "s 2"} {print}' "$tmp/box.obj" > "$tmp/groups.obj"
blender -b --factory-startup --python-exit-code 1 --python-expr "
import bpy, json
bpy.ops.import_scene.obj(filepath='$tmp/groups.obj', use_smooth_groups=True, split_mode='OFF', axis_forward='Y', axis_up='Z')
ob = [o for o in bpy.context.scene.objects if o.type == 'MESH'][0]
me = ob.data; me.calc_normals_split()
json.dump([list(l.normal) for l in me.loops], open('$tmp/bg.json', 'w'))
" > "$tmp/blender.log" 2>&1
check "blender OBJ import ran" test $? -eq 0
"$bin" normals "$tmp/groups.obj" -o "$tmp/og.obj" -q
corner_normals "$tmp/og.obj" "$tmp/og.json"
check "smoothing groups within 0.05 degrees of Blender's importer" within "$tmp/bg.json" "$tmp/og.json" 0.05

echo "blender_normals: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
