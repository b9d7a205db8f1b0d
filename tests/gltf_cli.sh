#!/usr/bin/env bash
# glTF 2.0 through every subcommand (issue 19): files written by hand (tests/gltf/make_fixtures.py)
# and by a second writer (assimp export), each output checked by an independent reader
# (tests/gltf/gltf_check.py: everything not changed is kept, images byte for byte) and by the
# Khronos glTF Validator (npm gltf-validator, installed into the build tree on first use; skipped
# loudly where Node.js/npm or the registry are missing). Bad inputs: one line naming the file and
# the JSON path, exit 1, no output.
set -uo pipefail
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
check() {  # check NAME COMMAND...
  local name=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $name"; fi
}
py=/usr/bin/python3; [ -x "$py" ] || py=python3
gcheck() { "$py" "$src/tests/gltf/gltf_check.py" "$@"; }
# derive FROM OUT.gltf CODE: FROM's document as `d` and its first buffer as `b` (a bytearray), edited
# by the Python CODE, written as OUT.gltf with a .bin of its own and FROM's image files beside it.
derive() {
  "$py" - "$src/tests/gltf" "$@" <<'PYEOF'
import json, os, shutil, struct, sys
sys.path.insert(0, sys.argv[1]); import gltf_check
src_path, out, code = sys.argv[2:5]
d, buffers = gltf_check.load(src_path)
b = bytearray(buffers[0])
exec(code)
d["buffers"][0]["uri"] = os.path.basename(out)[:-5] + ".bin"
d["buffers"][0]["byteLength"] = len(b)
open(out[:-5] + ".bin", "wb").write(b)
for i in d.get("images", []):
    if "uri" in i and not i["uri"].startswith("data:"):
        shutil.copy(os.path.join(os.path.dirname(src_path), i["uri"]), os.path.dirname(out))
json.dump(d, open(out, "w"))
PYEOF
}
fx=$tmp/fx
"$py" "$src/tests/gltf/make_fixtures.py" "$fx" || { echo "FAIL: fixtures"; exit 1; }

source "$src/tests/gltf/validator.sh"  # $validate and valid FILE...
check "hand-written fixtures are valid glTF" valid "$fx/rich.gltf" "$fx/rich.glb" "$fx/embedded.gltf"

# normals: NORMAL replaced or added, everything else kept, .gltf -> .glb -> .gltf.
for in in rich.gltf rich.glb embedded.gltf; do
  for out in n.glb n.gltf; do
    rm -f "$tmp/$out"
    "$bin" normals "$fx/$in" -o "$tmp/$out" --recompute -q
    check "normals $in -> $out exit 0" test $? -eq 0
    check "normals $in -> $out keeps everything else" gcheck keep "$fx/$in" "$tmp/$out" --changed NORMAL,TANGENT
    check "normals $in -> $out valid" valid "$tmp/$out"
  done
done
# A .gltf output's buffer is a file beside it (NAME.bin, percent-encoded in the URI), never one the
# input reads; to stdout it is a data URI (checked below).
"$bin" normals "$fx/rich.gltf" -o "$tmp/sep dir.gltf" --recompute -q
check "gltf -> gltf: the buffer in 'sep dir.bin' beside it" "$py" -c '
import json,sys
j=json.load(open(sys.argv[1])); b=j["buffers"]
assert len(b)==1 and b[0]["uri"]=="sep%20dir.bin", b
import os; assert os.path.getsize(sys.argv[2])==b[0]["byteLength"]' "$tmp/sep dir.gltf" "$tmp/sep dir.bin"
check "gltf -> gltf with a .bin: valid" valid "$tmp/sep dir.gltf"
check "gltf -> gltf with a .bin: everything else kept" gcheck keep "$fx/rich.gltf" "$tmp/sep dir.gltf" --changed NORMAL,TANGENT
mkdir -p "$tmp/own"
cp "$fx/rich.gltf" "$tmp/own/a.gltf"
for f in $("$py" -c 'import json,sys; j=json.load(open(sys.argv[1])); print(" ".join(x["uri"] for x in j.get("buffers",[])+j.get("images",[]) if "uri" in x and not x["uri"].startswith("data:")))' "$fx/rich.gltf"); do cp "$fx/$f" "$tmp/own/"; done
binname=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["buffers"][0]["uri"])' "$fx/rich.gltf")
sum_before=$(md5sum < "$tmp/own/$binname")
"$bin" normals "$tmp/own/a.gltf" -o "$tmp/own/${binname%.bin}.gltf" -q 2> "$tmp/own.err"
rc=$?
check "gltf output whose .bin is the input's buffer: refused (exit 1)" test $rc -eq 1
check "... one line naming both" grep -q "would overwrite .*$binname, which the input reads" "$tmp/own.err"
check "... the input's buffer untouched, no output" test "$(md5sum < "$tmp/own/$binname")" = "$sum_before" -a ! -e "$tmp/own/${binname%.bin}.gltf"

"$bin" normals "$fx/rich.gltf" -o "$tmp/n.glb" --recompute -q
check "gltf -> glb: no data URI inside the GLB, image moved into a bufferView" "$py" -c '
import json,struct,sys
d=open(sys.argv[1],"rb").read(); n=struct.unpack_from("<I",d,12)[0]; j=json.loads(d[20:20+n])
assert all("uri" not in b for b in j["buffers"]) and len(j["buffers"])==1, j["buffers"]
assert all("bufferView" in im and "uri" not in im for im in j["images"]), j["images"]
assert d[:4]==b"glTF" and struct.unpack_from("<I",d,8)[0]==len(d) and n%4==0' "$tmp/n.glb"

# The computed normals: the cube's are its face normals (24 split vertices); the strip lies in z=0.
check "cube NORMALs are the face normals" "$py" -c '
import json,subprocess,sys
pos=json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"0","0","POSITION"]))
nor=json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"0","0","NORMAL"]))
for p,n in zip(pos,nor):
  k=max(range(3),key=lambda i:abs(p[i])) if sorted(abs(x) for x in p)[1]<0.99 else None
  assert abs(sum(x*x for x in n)-1)<1e-6, n
  assert max(abs(x) for x in n)>0.999999, n
' "$py" "$src/tests/gltf/gltf_check.py" "$tmp/n.glb"
# Strip vertices (i//2, i%2, 0): its first triangle (0,0) (0,1) (1,0) is clockwise seen from +z, and
# the strip rule keeps every other one the same way: all normals -z.
check "strip NORMALs are -z (strip unrolled with alternating order)" "$py" -c '
import json,subprocess,sys
nor=json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"1","0","NORMAL"]))
assert len(nor)==6 and all(abs(n[2]+1)<1e-6 for n in nor), nor' "$py" "$src/tests/gltf/gltf_check.py" "$tmp/n.glb"
check "morph target NORMAL deltas recomputed: zero for the pushed-out face (a translation)" "$py" -c '
import json,subprocess,sys
d=json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"0","0","targets.0.NORMAL"]))
assert len(d)==24 and max(abs(x) for r in d for x in r)<1e-6, d' "$py" "$src/tests/gltf/gltf_check.py" "$tmp/n.glb"

# --crease and --faces split vertices; every other attribute follows the split.
"$bin" normals "$fx/rich.glb" -o "$tmp/c.glb" --recompute --crease 30 -q
check "crease: kept and valid" gcheck keep "$fx/rich.glb" "$tmp/c.glb" --changed NORMAL,TANGENT
check "crease: valid" valid "$tmp/c.glb"
"$bin" normals "$fx/rich.glb" -o "$tmp/f.glb" --faces -q
check "faces: kept" gcheck keep "$fx/rich.glb" "$tmp/f.glb" --changed NORMAL,TANGENT
check "faces: valid" valid "$tmp/f.glb"

# info and repair.
"$bin" info "$fx/rich.glb" > "$tmp/info.txt" 2> /dev/null
check "info: one block per triangle primitive (4)" test "$(grep -c '^  vertices' "$tmp/info.txt")" -eq 4
check "info: names the primitive" grep -q 'rich.glb: meshes\[1\].primitives\[0\]: GLB' "$tmp/info.txt"
"$bin" repair "$fx/rich.glb" -o "$tmp/r.glb" -q
check "repair: kept" gcheck keep "$fx/rich.glb" "$tmp/r.glb" --changed NORMAL
check "repair: valid" valid "$tmp/r.glb"

"$bin" repair "$fx/rich.glb" -o "$tmp/rw.glb" --weld 1e-6 2> "$tmp/err.txt"
check "repair --weld on a primitive with texcoords/skin/targets: exit 1" test $? -eq 1
check "repair --weld: names what cannot follow" grep -q "TEXCOORD_0.*cannot follow" "$tmp/err.txt"
check "repair --weld: no output" test ! -e "$tmp/rw.glb"

# transform: a mirror with a non-uniform scale (not a similarity: TANGENT recomputed by MikkTSpace
# from the mapped normals, with a note; on the cube's flat faces its direction is still A t), and a
# mirror alone (a similarity: TANGENT mapped, w flipped, gltf/gltf_transform.h).
"$bin" transform "$fx/rich.glb" --scale -1,2,1 -o "$tmp/t.glb" 2> "$tmp/t.err"
check "transform: kept" gcheck keep "$fx/rich.glb" "$tmp/t.glb" --changed POSITION,NORMAL,TANGENT
check "transform: valid (min/max updated)" valid "$tmp/t.glb"
check "transform: a map that is not a similarity recomputes TANGENT (note)" grep -q "TANGENT recomputed (MikkTSpace) with the new normals (the map is not a similarity" "$tmp/t.err"
"$bin" transform "$fx/rich.glb" --scale -1,1,1 -o "$tmp/tm.glb" 2> "$tmp/tm.err"
check "transform: a similarity keeps the mapped TANGENT (no note)" test "$(grep -c "TANGENT recomputed" "$tmp/tm.err")" -eq 0
transform_check() {  # OUT SX SY W_FLIPPED: POSITION (x, y) scaled; TANGENT along A t (w flipped, if asked); re-wound; morph deltas mapped
  "$py" -c '
import json,subprocess,sys
sx,sy,wflip=float(sys.argv[5]),float(sys.argv[6]),sys.argv[7]=="1"
def dump(f,a): return json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",f,"0","0",a]))
pi,po=dump(sys.argv[3],"POSITION"),dump(sys.argv[4],"POSITION")
ti,to=dump(sys.argv[3],"TANGENT"),dump(sys.argv[4],"TANGENT")
ci,co=json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"0","0","corners"])),json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[4],"0","0","corners"]))
assert len(po)==len(pi)
for a,b in zip(pi,po): assert b==[sx*a[0],sy*a[1],a[2]], (a,b)
for a,b in zip(ti,to):
  m=[sx*a[0],sy*a[1],a[2]]; l=sum(x*x for x in m)**0.5
  assert all(abs(m[k]/l-b[k])<1e-6 for k in range(3)) and abs(b[3])==1 and (not wflip or b[3]==-a[3]), (a,b)
assert co==[c for t in range(0,len(ci),3) for c in (ci[t],ci[t+2],ci[t+1])], "mirror re-winds"
di,do=dump(sys.argv[3],"targets.0.POSITION"),dump(sys.argv[4],"targets.0.POSITION")
for a,b in zip(di,do): assert b==[sx*a[0],sy*a[1],a[2]], (a,b)
' "$py" "$src/tests/gltf/gltf_check.py" "$fx/rich.glb" "$@"
}
check "transform --scale -1,2,1: POSITION x negated, y doubled; TANGENT along A t; morph deltas mapped" transform_check "$tmp/t.glb" -1 2 0
check "transform --scale -1,1,1: POSITION x negated; TANGENT mapped, w flipped; morph deltas mapped" transform_check "$tmp/tm.glb" -1 1 1

# bake-lighting: the file's own lights and camera; COLOR_0 in the input's type (normalised ubyte).
"$bin" bake-lighting "$fx/rich.glb" -o "$tmp/b.glb" -q
check "bake-lighting: kept" gcheck keep "$fx/rich.glb" "$tmp/b.glb" --changed COLOR_0,NORMAL
check "bake-lighting: valid" valid "$tmp/b.glb"
check "bake-lighting: COLOR_0 stays normalised UNSIGNED_BYTE where it was, float elsewhere" "$py" -c '
import json,struct,sys
d=open(sys.argv[1],"rb").read(); n=struct.unpack_from("<I",d,12)[0]; j=json.loads(d[20:20+n])
acc=lambda m:j["accessors"][j["meshes"][m]["primitives"][0]["attributes"]["COLOR_0"]]
assert acc(0)["componentType"]==5121 and acc(0)["normalized"], acc(0)
assert acc(1)["componentType"]==5126, acc(1)' "$tmp/b.glb"
"$bin" bake-lighting "$fx/rich.glb" -o "$tmp/bh.gltf" --hdr -q
check "bake-lighting --hdr: valid (COLOR_0 clamped to [0,1])" valid "$tmp/bh.gltf"
"$bin" bake-lighting "$src/data/torus.obj" -o "$tmp/x.obj" 2> "$tmp/x.err" > /dev/null
check "bake-lighting without --scene on OBJ: the default scene (exit 0, a note)" grep -q "no --scene: the default scene" "$tmp/x.err"

# Baked glTF outputs (issue 28, 2-3). COLOR_0 is linear whatever --srgb says (with a note); from
# OBJ the output carries the normals used (checked against the torus's analytic normals) and an
# unlit material; a glTF input keeps its materials, and gains KHR_materials_unlit only with --unlit.
studio=$src/data/scenes/studio.json
"$bin" bake-lighting "$src/data/torus.obj" --scene "$studio" -o "$tmp/lin.glb" -q
"$bin" bake-lighting "$src/data/torus.obj" --scene "$studio" -o "$tmp/srgb.glb" --srgb 2> "$tmp/err.txt"
check "bake --srgb to glTF: a note says it is the default (a no-op)" grep -q -- "--srgb is the default now" "$tmp/err.txt"
"$bin" bake-lighting "$src/data/torus.obj" --scene "$studio" -o "$tmp/linear.glb" --linear -q
for f in srgb linear; do
  check "bake --$f to glTF: COLOR_0 equals the default (linear) bake's" "$py" -c '
import json,subprocess,sys
a,b=[json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",f,"0","0","COLOR_0"])) for f in sys.argv[3:5]]
assert a==b' "$py" "$src/tests/gltf/gltf_check.py" "$tmp/lin.glb" "$tmp/$f.glb"
done
"$bin" occlusion "$src/data/torus.obj" -o "$tmp/ao_obj.glb" --samples 8 -q
"$bin" bake-lighting "$src/data/torus.obj" --scene "$studio" -o "$tmp/hdr_obj.glb" --hdr -q
for f in lin ao_obj hdr_obj; do
  check "baked $f.glb from OBJ: valid" valid "$tmp/$f.glb"
  check "baked $f.glb from OBJ: NORMAL within 2 degrees of the torus's analytic normals" "$py" -c '
import json,math,subprocess,sys
d=lambda a: json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"0","0",a]))
P,N=d("POSITION"),d("NORMAL")
r=[math.hypot(p[0],p[1]) for p in P]; R=(max(r)+min(r))/2   # the ring radius (axis z)
for p,n,rr in zip(P,N,r):
  a=[p[0]-R*p[0]/rr,p[1]-R*p[1]/rr,p[2]]; l=math.sqrt(sum(x*x for x in a))
  assert sum(x*y for x,y in zip(a,n))/l>math.cos(math.radians(2)), (p,n)' "$py" "$src/tests/gltf/gltf_check.py" "$tmp/$f.glb"
  check "baked $f.glb from OBJ: an unlit material, COLOR_0 normalised ubyte (float with --hdr)" "$py" -c '
import json,struct,sys
d=open(sys.argv[1],"rb").read(); n=struct.unpack_from("<I",d,12)[0]; j=json.loads(d[20:20+n])
p=j["meshes"][0]["primitives"][0]; m=j["materials"][p["material"]]
assert "KHR_materials_unlit" in m["extensions"] and "KHR_materials_unlit" in j["extensionsUsed"], j
c=j["accessors"][p["attributes"]["COLOR_0"]]
assert (c["componentType"],c.get("normalized"))==((5126,None) if sys.argv[2]=="hdr_obj" else (5121,True)), c' "$tmp/$f.glb" "$f"
done
"$bin" bake-lighting "$fx/rich.glb" -o "$tmp/bu.glb" --unlit -q
"$bin" occlusion "$fx/rich.glb" -o "$tmp/ou.glb" --unlit --samples 4 -q
for f in bu ou; do
  check "$f: glTF input --unlit: valid" valid "$tmp/$f.glb"
  check "$f: glTF input --unlit: every triangle primitive's material unlit, the material otherwise as read" "$py" -c '
import json,struct,sys
def load(f):
  d=open(f,"rb").read(); n=struct.unpack_from("<I",d,12)[0]; return json.loads(d[20:20+n])
i,o=load(sys.argv[1]),load(sys.argv[2])
for m,mesh in enumerate(o["meshes"]):
  for k,p in enumerate(mesh["primitives"]):
    if p.get("mode",4) not in (4,5,6): continue
    mat=o["materials"][p["material"]]
    assert "KHR_materials_unlit" in mat["extensions"], (m,k,mat)
    if "material" in i["meshes"][m]["primitives"][k]:
      was=dict(i["materials"][p["material"]]); now=dict(mat); now["extensions"]=dict(now["extensions"]); del now["extensions"]["KHR_materials_unlit"]
      if not now["extensions"]: del now["extensions"]
      assert was==now, (was,now)' "$fx/rich.glb" "$tmp/$f.glb"
done

# Bad input: one line naming the file and the JSON path, exit 1, no output.
for case in "missing_bin:buffers[0].uri" "index_out_of_range:meshes[3].primitives[0].indices" \
            "accessor_overrun:accessors[0]" "wrong_component_type:meshes[0].primitives[0].attributes.POSITION" \
            "nan_position:meshes[0].primitives[0].attributes.POSITION" "recursive_nodes:nodes[" \
            "draco:KHR_draco_mesh_compression" "type_scene_name:scenes[0].name" \
            "type_texture_index:materials[0].pbrMetallicRoughness.baseColorTexture.index" \
            "type_not_object:materials[0].pbrMetallicRoughness" "type_count_string:accessors[1].count" \
            "type_extensions:extensions" "type_node_mesh:nodes[0].mesh" \
            "type_extension_value:materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform"; do
  name=${case%%:*} path=${case#*:}
  "$bin" normals "$fx/bad_$name.gltf" -o "$tmp/bad.glb" 2> "$tmp/err.txt"
  code=$?
  check "bad $name: exit 1" test $code -eq 1
  check "bad $name: one line" test "$(wc -l < "$tmp/err.txt")" -eq 1
  check "bad $name: names file and $path" grep -qF "bad_$name.gltf: " "$tmp/err.txt"
  check "bad $name: JSON path $path" grep -qF "$path" "$tmp/err.txt"
  check "bad $name: no output" test ! -e "$tmp/bad.glb"
done

# Nothing for a step to do (issue 27, 15): only POINTS/LINES primitives, or a scene without nodes:
# written unchanged with a note, exit 0 (a batch over a folder goes on); to a format that needs a
# mesh, still refused.
for f in points_lines no_nodes; do
  rm -f "$tmp/nothing.glb"
  "$bin" normals "$fx/$f.gltf" -o "$tmp/nothing.glb" 2> "$tmp/err.txt"
  check "$f: normals exit 0" test $? -eq 0
  check "$f: a note says nothing was computed" grep -q "nothing to compute, the document written unchanged" "$tmp/err.txt"
  check "$f: kept" gcheck keep "$fx/$f.gltf" "$tmp/nothing.glb"
  check "$f: valid" valid "$tmp/nothing.glb"
  "$bin" normals "$fx/$f.gltf" -o "$tmp/nothing.ply" 2> /dev/null
  check "$f: to PLY refused (exit 1), nothing written" test $? -eq 1 -a ! -e "$tmp/nothing.ply"
done
# info describes such a file, as it does a PLY point cloud (it exited 1 before): the POINTS/LINES
# primitives and their POSITION counts, counted independently from the JSON here.
"$bin" info --json "$fx/points_lines.gltf" > "$tmp/info.json" 2> /dev/null
check "points_lines: info exit 0" test $? -eq 0
check "points_lines: info counts the POINTS/LINES primitives and their vertices" "$py" -c '
import json,sys
info=json.loads(open(sys.argv[1]).read())["stats"]; d=json.load(open(sys.argv[2]))
prims=[p for m in d["meshes"] for p in m["primitives"] if p.get("mode",4) in (0,1,2,3)]
assert info["faces"]==0 and info["points_lines_primitives"]==len(prims)>0, info
assert info["points_lines_vertices"]==sum(d["accessors"][p["attributes"]["POSITION"]]["count"] for p in prims), info' "$tmp/info.json" "$fx/points_lines.gltf"
# render has no glTF path of its own: it read such a file as one Mesh and said "no vertex in the
# file", though it has vertices. It says what the file is, with the counts the JSON holds.
rm -f "$tmp/points.png"
"$bin" render "$fx/points_lines.gltf" -o "$tmp/points.png" 2> "$tmp/err.txt"
check "points_lines: render refused (exit 1), nothing written" test $? -eq 1 -a ! -e "$tmp/points.png"
check "points_lines: render says so in one line naming the file" bash -c "test \$(wc -l < '$tmp/err.txt') -eq 1 && grep -qF 'points_lines.gltf: a glTF whose primitives are points or lines only' '$tmp/err.txt'"
check "points_lines: render's counts are the JSON's" "$py" -c '
import json,re,sys
d=json.load(open(sys.argv[2])); err=open(sys.argv[1]).read()
prims=[p for m in d["meshes"] for p in m["primitives"] if p.get("mode",4) in (0,1,2,3)]
n=sum(d["accessors"][p["attributes"]["POSITION"]]["count"] for p in prims)
assert "(%d POINTS/LINES primitives, %d vertices)" % (len(prims), n) in err, err' "$tmp/err.txt" "$fx/points_lines.gltf"

# A triangle primitive without POSITION (glTF 2.0 3.7.2.1: nothing to draw; magnum's mesh.gltf,
# scene.gltf...) made the whole file refused. The other primitive is read, this one kept as it is:
# the validator's count of MESH_PRIMITIVE_NO_POSITION is the input's, and the written NORMAL of the
# read triangle is the closed-form +z of the triangle (0,0,0) (1,0,0) (0,1,0).
"$bin" normals "$fx/no_position.gltf" -o "$tmp/no_position.glb" --recompute 2> "$tmp/err.txt"
check "no_position: normals exit 0" test $? -eq 0
check "no_position: a note names the primitive" grep -qF "meshes[0].primitives[1]: no POSITION" "$tmp/err.txt"
check "no_position: the primitive without POSITION kept as it is" "$py" "$src/tests/gltf/gltf_check.py" keep "$fx/no_position.gltf" "$tmp/no_position.glb" --changed NORMAL
check "no_position: the read triangle's NORMAL is +z" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
d, b = gltf_check.load(sys.argv[1]); p = d["meshes"][0]["primitives"]
assert "POSITION" not in p[1]["attributes"], p
n = gltf_check.accessor(d, b, p[0]["attributes"]["NORMAL"])
assert all(abs(v[0]) < 1e-6 and abs(v[1]) < 1e-6 and abs(v[2] - 1) < 1e-6 for v in n), n' "$tmp/no_position.glb" "$src/tests/gltf"
if [ -n "$validate" ]; then
  $validate "$fx/no_position.gltf" > "$tmp/v_in.txt"; $validate "$tmp/no_position.glb" > "$tmp/v_out.txt"
  check "no_position: output valid, as many MESH_PRIMITIVE_NO_POSITION as the input" bash -c "grep -q ': 0 errors' '$tmp/v_out.txt' && test \$(grep -c NO_POSITION '$tmp/v_in.txt') -eq 1 -a \$(grep -c NO_POSITION '$tmp/v_out.txt') -eq 1"
fi
"$bin" normals "$fx/no_position.gltf" -o "$tmp/no_position.ply" -q
check "no_position -> PLY: the one triangle" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import read_mesh
parts = read_mesh.read(sys.argv[1]); assert sum(len(q["faces"]) for q in parts) == 1, parts' "$tmp/no_position.ply" "$src/tests/corpus"

# A glTF with an image and no mesh, written unchanged: its image moves into the buffer, and the
# writer left an empty "accessors" array behind (every output of magnum's image*.gltf failed the
# validator with EMPTY_ENTITY /accessors).
for out in image_only.glb image_only.gltf; do
  "$bin" normals "$fx/image_only.gltf" -o "$tmp/$out" -q
  check "image_only -> $out: exit 0" test $? -eq 0
  check "image_only -> $out: valid" valid "$tmp/$out"
  check "image_only -> $out: no empty top-level array" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
d, b = gltf_check.load(sys.argv[1]); assert not [k for k, v in d.items() if v == []], d.keys()
assert len(d["images"]) == 1, d' "$tmp/$out" "$src/tests/gltf"
done

# Exact bounds (issue 27, 16): a split that drops an unused vertex, and an input whose NORMAL
# min/max do not hold; every output's accessors have exact min/max (the validator computes them).
for args in "--faces" "--recompute --crease 30" ""; do
  rm -f "$tmp/bounds.glb"
  "$bin" normals "$fx/bounds.gltf" -o "$tmp/bounds.glb" $args -q
  check "bounds normals $args: exit 0" test $? -eq 0
  check "bounds normals $args: valid (no ACCESSOR_MIN/MAX_MISMATCH)" valid "$tmp/bounds.glb"
  check "bounds normals $args: TEXCOORD_0 max is (0.5, 0.5), the unused vertex's (1, 1) gone" "$py" -c '
import json,struct,sys
d=open(sys.argv[1],"rb").read(); n=struct.unpack_from("<I",d,12)[0]; j=json.loads(d[20:20+n])
p=j["meshes"][0]["primitives"][0]; a=j["accessors"][p["attributes"]["TEXCOORD_0"]]
assert a["max"]==[0.5,0.5] or sys.argv[2]=="", a' "$tmp/bounds.glb" "$args"
done

# An accessor that does not start on a multiple of its component size (corpus TestScene.gltf has
# three): copied to an aligned view, so the output is valid; its values are kept.
"$bin" normals "$fx/misaligned.gltf" -o "$tmp/aligned.glb" --recompute -q
check "misaligned accessor: output valid" valid "$tmp/aligned.glb"
check "misaligned accessor: TEXCOORD_0 kept" gcheck keep "$fx/misaligned.gltf" "$tmp/aligned.glb" --changed NORMAL

# Replaced accessors leave nothing behind (issue 28, 6): repeated normals --recompute keeps the
# accessor and bufferView counts and the size; the validator finds no more unused objects than in
# the input (one: a TEXCOORD_0 that no material uses).
"$bin" normals "$fx/rich.glb" -o "$tmp/p1.glb" --recompute --crease 30 -q
"$bin" normals "$tmp/p1.glb" -o "$tmp/p2.glb" --recompute -q
"$bin" normals "$tmp/p2.glb" -o "$tmp/p3.glb" --recompute --crease 30 -q
"$bin" transform "$tmp/p3.glb" -o "$tmp/p4.glb" --scale 2 -q
valid "$fx/rich.glb"; unused_in=$(grep -c UNUSED_OBJECT "$tmp/validator.txt")
for f in p1 p2 p3 p4; do
  check "prune $f: valid" valid "$tmp/$f.glb"
  if [ -n "$validate" ]; then
    check "prune $f: no more UNUSED_OBJECT than the input ($unused_in)" test "$(grep -c UNUSED_OBJECT "$tmp/validator.txt")" -eq "$unused_in"
  fi
  check "prune $f: kept" gcheck keep "$fx/rich.glb" "$tmp/$f.glb" --changed NORMAL,POSITION,TANGENT
done
check "prune: p1 and p3 have the same counts and size" "$py" -c '
import json,struct,sys
def head(f):
  d=open(f,"rb").read(); n=struct.unpack_from("<I",d,12)[0]; j=json.loads(d[20:20+n])
  return len(j["accessors"]),len(j["bufferViews"]),j["buffers"][0]["byteLength"]
a,b=head(sys.argv[1]),head(sys.argv[2]); assert a==b, (a,b)' "$tmp/p1.glb" "$tmp/p3.glb"

# An extension shadetool does not know prunes nothing only when it could name an index: one that
# holds no number (FB_ngon_encoding's empty object on a primitive, as Blender and assimp write it;
# an extension listed with no object, as assimp's KHR_technique_webgl files) cannot, and the
# replaced NORMAL accessor is removed as without it (the validator's UNUSED_OBJECT on
# xcorpus2's quad_skin.glb and techniqueWebGL BoxTextured.gltf outputs, not on the inputs). One
# that holds a number still keeps everything, with a note.
ngon='
d["extensionsUsed"] = d.get("extensionsUsed", []) + ["FB_ngon_encoding", "KHR_technique_webgl"]
for m in d["meshes"]:
    for p in m["primitives"]: p.setdefault("extensions", {})["FB_ngon_encoding"] = {}
'
derive "$fx/rich.gltf" "$tmp/ngon.gltf" "$ngon"
derive "$fx/rich.gltf" "$tmp/xref.gltf" "$ngon"'
d["extensionsUsed"].append("X_unknown_ref")
d["meshes"][0]["primitives"][0]["extensions"]["X_unknown_ref"] = {"accessor": 0}'
all_referenced() {  # every accessor of FILE named by a primitive, skin or animation (gltf_check's reading)
  "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
j, _ = gltf_check.load(sys.argv[1]); used = set()
for m in j["meshes"]:
    for p in m["primitives"]:
        used |= set(p["attributes"].values()) | ({p["indices"]} if "indices" in p else set())
        for t in p.get("targets", []): used |= set(t.values())
for s in j.get("skins", []): used |= {s["inverseBindMatrices"]} if "inverseBindMatrices" in s else set()
for a in j.get("animations", []):
    for s in a["samplers"]: used |= {s["input"], s["output"]}
assert used == set(range(len(j["accessors"]))), ("unreferenced", sorted(set(range(len(j["accessors"]))) - used))' "$1" "$src/tests/gltf"
}
check "number-free extensions: the input's accessors are all referenced" all_referenced "$tmp/ngon.gltf"
for out in ngon.glb ngon_out.gltf; do
  "$bin" normals "$tmp/ngon.gltf" -o "$tmp/$out" --recompute 2> "$tmp/ngon.err"
  check "number-free extensions -> $out: exit 0" test $? -eq 0
  check "number-free extensions -> $out: the replaced NORMAL removed (every accessor referenced)" all_referenced "$tmp/$out"
  check "number-free extensions -> $out: no 'may refer to them' note" bash -c "! grep -q 'may refer to them' '$tmp/ngon.err'"
  check "number-free extensions -> $out: the extensions kept" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
j, _ = gltf_check.load(sys.argv[1])
assert {"FB_ngon_encoding", "KHR_technique_webgl"} <= set(j["extensionsUsed"]), j["extensionsUsed"]
assert all(p["extensions"]["FB_ngon_encoding"] == {} for m in j["meshes"] for p in m["primitives"])' "$tmp/$out" "$src/tests/gltf"
  check "number-free extensions -> $out: valid" valid "$tmp/$out"
  if [ -n "$validate" ]; then
    valid "$tmp/ngon.gltf"; unused_in=$(grep -c UNUSED_OBJECT "$tmp/validator.txt")
    valid "$tmp/$out"
    check "number-free extensions -> $out: no more UNUSED_OBJECT than the input ($unused_in)" test "$(grep -c UNUSED_OBJECT "$tmp/validator.txt")" -le "$unused_in"
  fi
done
"$bin" normals "$tmp/xref.gltf" -o "$tmp/xref.glb" --recompute 2> "$tmp/xref.err"
check "an unknown extension holding a number: exit 0" test $? -eq 0
check "an unknown extension holding a number: nothing pruned, a note names it" grep -q "kept: extension X_unknown_ref may refer to them" "$tmp/xref.err"

# Compressed glTF (issue 28, 5): Draco and meshopt files made by the libraries' own encoders
# (tests/gltf/compressed_fixtures.h, built as gltf_compressed_fixtures beside the binary) and the
# same mesh uncompressed. Every command reads them; glTF outputs are uncompressed, valid, with a
# note; the decoded triangles (positions, normals, texture coordinates) equal the uncompressed file's.
fixtures_bin=$(dirname "$bin")/gltf_compressed_fixtures
mkdir -p "$tmp/cz"
if [ -x "$fixtures_bin" ] && "$fixtures_bin" "$tmp/cz"; then
  for c in draco meshopt; do
    ext=KHR_draco_mesh_compression; [ $c = meshopt ] && ext=EXT_meshopt_compression
    "$bin" normals "$tmp/cz/$c.glb" -o "$tmp/cz/n_$c.glb" 2> "$tmp/err.txt"
    check "$c: normals exit 0" test $? -eq 0
    check "$c: a note names the decoded $ext" grep -q "$ext) decoded (glTF output is written uncompressed)" "$tmp/err.txt"
    check "$c: decoded triangles equal the uncompressed file's" gcheck keep "$tmp/cz/plain.glb" "$tmp/cz/n_$c.glb"
    check "$c: output valid" valid "$tmp/cz/n_$c.glb"
    check "$c: output uncompressed (no extension, no fallback)" sh -c "! grep -a -q -e '$ext' -e fallback '$tmp/cz/n_$c.glb'"
    if [ -n "$validate" ]; then
      check "$c: no unused object (the compressed bytes are gone)" sh -c "! grep -q UNUSED_OBJECT.*buffer '$tmp/validator.txt'"
    fi
    "$bin" normals "$tmp/cz/$c.glb" -o "$tmp/cz/r_$c.gltf" --recompute -q
    check "$c: normals --recompute to .gltf valid" valid "$tmp/cz/r_$c.gltf"
    "$bin" transform "$tmp/cz/$c.glb" -o "$tmp/cz/t_$c.glb" --scale 2 -q
    check "$c: transform valid" valid "$tmp/cz/t_$c.glb"
    "$bin" repair "$tmp/cz/$c.glb" -o "$tmp/cz/p_$c.glb" -q
    check "$c: repair valid" valid "$tmp/cz/p_$c.glb"
    "$bin" bake-lighting "$tmp/cz/$c.glb" -o "$tmp/cz/b_$c.glb" --scene "$src/data/scenes/studio.json" -q
    check "$c: bake-lighting valid" valid "$tmp/cz/b_$c.glb"
    "$bin" occlusion "$tmp/cz/$c.glb" -o "$tmp/cz/o_$c.glb" --samples 4 -q
    check "$c: occlusion valid" valid "$tmp/cz/o_$c.glb"
    "$bin" render "$tmp/cz/$c.glb" -o "$tmp/cz/$c.png" --scene "$src/data/scenes/studio.json" --size 32,24 2> "$tmp/err.txt"
    check "$c: render exit 0" test $? -eq 0
    check "$c: render notes the decoding too (the one-mesh reader)" grep -q "$ext) decoded" "$tmp/err.txt"
    "$bin" info "$tmp/cz/$c.glb" --json > "$tmp/cz/i_$c.json" 2> /dev/null
    "$bin" info "$tmp/cz/plain.glb" --json > "$tmp/cz/i_plain.json" 2> /dev/null
    check "$c: info counts equal the uncompressed file's" "$py" -c '
import json,sys
a=json.load(open(sys.argv[1]))["stats"]; b=json.load(open(sys.argv[2]))["stats"]
assert (a["vertices"],a["faces"])==(b["vertices"],b["faces"]), (a,b)' "$tmp/cz/i_$c.json" "$tmp/cz/i_plain.json"
    if command -v assimp > /dev/null && assimp export "$tmp/cz/$c.glb" "$tmp/cz/ai_$c.obj" > /dev/null 2>&1; then
      check "$c: decoded positions equal assimp's reading of the same file" "$py" -c '
import json,subprocess,sys
ours=json.loads(subprocess.check_output([sys.argv[1],sys.argv[2],"dump",sys.argv[3],"0","0","POSITION"]))
theirs=[[float(x) for x in l.split()[1:4]] for l in open(sys.argv[4]) if l.startswith("v ")]
assert len(ours)==len(theirs), (len(ours),len(theirs))
for a,b in zip(sorted(ours),sorted(theirs)): assert max(abs(x-y) for x,y in zip(a,b))<1e-6, (a,b)' "$py" "$src/tests/gltf/gltf_check.py" "$tmp/cz/n_$c.glb" "$tmp/cz/ai_$c.obj"
    else
      echo "skipped: assimp comparison of $c.glb (assimp cannot read it)"
    fi
  done
else
  check "compressed fixtures: build target gltf_compressed_fixtures" false
fi

# A second writer: assimp (assimp-utils) exports OBJ -> glb/gltf; we read, compute, validate.
if command -v assimp > /dev/null; then
  assimp export "$src/data/torus.obj" "$tmp/torus_assimp.glb" > /dev/null 2>&1
  assimp export "$src/data/torus.obj" "$tmp/torus_assimp.gltf" > /dev/null 2>&1
  for f in torus_assimp.glb torus_assimp.gltf; do
    "$bin" normals "$tmp/$f" -o "$tmp/n_$f" --recompute -q
    check "assimp $f: normals exit 0" test $? -eq 0
    check "assimp $f: kept" gcheck keep "$tmp/$f" "$tmp/n_$f" --changed NORMAL
    check "assimp $f: valid" valid "$tmp/n_$f"
  done
  "$bin" info "$tmp/torus_assimp.glb" --json > "$tmp/ai.json"
  "$bin" info "$src/data/torus.obj" --json > "$tmp/oi.json"
  check "assimp glb: same face count as the OBJ" "$py" -c '
import json,sys
a=json.loads(open(sys.argv[1]).read()); o=json.loads(open(sys.argv[2]).read())
assert a["stats"]["faces"]==o["stats"]["faces"], (a["stats"]["faces"],o["stats"]["faces"])' "$tmp/ai.json" "$tmp/oi.json"
else
  echo "skipped: second writer (no assimp: install assimp-utils)"
fi

# A third writer: Blender's glTF exporter (default scene: a cube with TANGENT, a point light as
# KHR_lights_punctual, a camera). bake-lighting without --scene must light exactly the vertices
# whose normal faces the light (no ambient or emission in the glTF mapping).
if command -v blender > /dev/null; then
  blender -b --factory-startup --python-exit-code 1 --python-expr "
import bpy
bpy.ops.export_scene.gltf(filepath='$tmp/blender.glb', export_format='GLB', export_tangents=True, export_lights=True, export_cameras=True)
" > "$tmp/blender.log" 2>&1
  check "blender export" test -s "$tmp/blender.glb"
  "$bin" bake-lighting "$tmp/blender.glb" -o "$tmp/blender_lit.glb" -q
  check "blender: bake-lighting with the file's own light: kept" gcheck keep "$tmp/blender.glb" "$tmp/blender_lit.glb" --changed COLOR_0
  check "blender: bake-lighting valid" valid "$tmp/blender_lit.glb"
  check "blender: lit exactly where the normal faces the point light" "$py" -c '
import sys
sys.path.insert(0,sys.argv[2])
import gltf_check as g
doc,bufs=g.load(sys.argv[4])
light=[n for n in doc["nodes"] if "KHR_lights_punctual" in n.get("extensions",{})][0]["translation"]
cube=[n for n in doc["nodes"] if n.get("mesh")==0][0]
assert "matrix" not in cube and cube.get("translation",[0,0,0])==[0,0,0] and "scale" not in cube, cube
prim=doc["meshes"][0]["primitives"][0]
P,N,C=(g.accessor(doc,bufs,prim["attributes"][a]) for a in ("POSITION","NORMAL","COLOR_0"))
for p,n,c in zip(P,N,C):
  facing=sum(n[k]*(light[k]-p[k]) for k in range(3))>0
  assert (max(c[:3])>0)==facing, (p,n,c,light)' "$py" "$src/tests/gltf" "$tmp/blender.glb" "$tmp/blender_lit.glb"
  "$bin" transform "$tmp/blender.glb" --scale -1,1,1 -o "$tmp/blender_mirror.glb" -q
  check "blender: mirror keeps the rest" gcheck keep "$tmp/blender.glb" "$tmp/blender_mirror.glb" --changed POSITION,NORMAL,TANGENT
  check "blender: mirror valid" valid "$tmp/blender_mirror.glb"
else
  echo "skipped: third writer (no blender)"
fi

# Other formats in and out: OBJ -> glb (a fresh document) and glb -> OBJ (one mesh, with a note).
"$bin" normals "$src/data/torus.obj" -o "$tmp/from_obj.glb" -q
check "obj -> glb valid" valid "$tmp/from_obj.glb"
"$bin" normals "$fx/rich.glb" -o "$tmp/to.obj" 2> "$tmp/note.txt"
check "glb -> obj: a note says the primitives were placed in world space" grep -q "placed in world space" "$tmp/note.txt"

# glTF -> OBJ in world space, against assimp's OBJ exporter (it applies node matrices too): a node
# tree with T*R*S under a parent, a matrix mirror and a mesh shown by two nodes. Compared as
# multisets of triangles (unordered corners, positions rounded to 1e-5); the winding by the signed
# volume of each placed tetrahedron (a mirrored node is re-wound: glTF 2.0, 3.7.2.1).
"$py" - "$tmp/tree.glb" <<'PY'
import json, math, struct, sys
pos = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]  # a tetrahedron, outward faces
idx = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]
pos2 = [2, 0, 0, 3, 0, 0, 2, 1, 0]
bin = struct.pack("<12f", *pos) + struct.pack("<12H", *idx) + struct.pack("<9f", *pos2)
h = math.sqrt(0.5)
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 2, 3]}],
  "nodes": [{"translation": [5, 1, -2], "rotation": [0, h, 0, h], "children": [1]},
            {"scale": [2, 1, 0.5], "mesh": 0},
            {"matrix": [1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 3, 0, 1], "mesh": 0},
            {"translation": [0, 0, 7], "rotation": [0.1, 0.2, 0.3, 0.927362], "mesh": 1}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]},
             {"primitives": [{"attributes": {"POSITION": 2}}]}],
  "buffers": [{"byteLength": len(bin)}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24},
                  {"buffer": 0, "byteOffset": 72, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
                {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"},
                {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3", "min": [2, 0, 0], "max": [3, 1, 0]}]}
text = json.dumps(doc).encode()
text += b" " * (-len(text) % 4)
bin += b"\0" * (-len(bin) % 4)
out = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(bin)) + struct.pack("<I", len(text)) + b"JSON" + text
out += struct.pack("<I", len(bin)) + b"BIN\0" + bin
open(sys.argv[1], "wb").write(out)
PY
check "node tree fixture is valid glTF" valid "$tmp/tree.glb"
"$bin" normals "$tmp/tree.glb" -o "$tmp/tree.obj" -q
check "glb node tree -> obj exit 0" test $? -eq 0
objtris='
import sys
def tris(path):
    v, vn, out, vns = [], [], [], []
    for line in open(path):
        w = line.split()
        if not w: continue
        if w[0] == "v": v.append(tuple(float(x) for x in w[1:4]))
        if w[0] == "vn": vn.append(tuple(float(x) for x in w[1:4]))
        if w[0] == "f":
            c = [x.split("/") for x in w[1:]]
            out.append([v[int(x[0]) - 1] for x in c])
            vns.append([vn[int(x[2]) - 1] for x in c] if len(c[0]) > 2 and c[0][2] else None)
    return out, vns
'
if command -v assimp > /dev/null && assimp export "$tmp/tree.glb" "$tmp/tree_assimp.obj" > /dev/null 2>&1; then
  check "glb node tree -> obj: the triangles assimp export writes (world space)" "$py" -c "$objtris"'
key = lambda t: tuple(sorted(tuple(round(x, 5) + 0.0 for x in p) for p in t))
ours, _ = tris(sys.argv[1]); theirs, _ = tris(sys.argv[2])
assert len(ours) == 4 + 4 + 1, len(ours)
assert sorted(map(key, ours)) == sorted(map(key, theirs)), (sorted(map(key, ours))[:3], sorted(map(key, theirs))[:3])' \
    "$tmp/tree.obj" "$tmp/tree_assimp.obj"
else
  echo "skipped: glTF node tree against assimp export (no assimp: install assimp-utils)"
fi
check "glb node tree -> obj: both placed tetrahedra enclose positive volume (faces out, the mirror re-wound)" "$py" -c "$objtris"'
ts, _ = tris(sys.argv[1])
det = lambda a, b, c: a[0]*(b[1]*c[2]-b[2]*c[1]) - a[1]*(b[0]*c[2]-b[2]*c[0]) + a[2]*(b[0]*c[1]-b[1]*c[0])
for first in (0, 4):
    vol = sum(det(*t) for t in ts[first:first + 4]) / 6
    assert vol > 0.05, (first, vol)' "$tmp/tree.obj"

# --format glb / gltf, stdout and stdin, --output-dir.
"$bin" normals "$fx/rich.glb" -o - --format glb -q > "$tmp/stdout.glb"
check "-o - --format glb writes a GLB" test "$(head -c 4 "$tmp/stdout.glb")" = glTF
check "stdout GLB valid" valid "$tmp/stdout.glb"
"$bin" normals "$fx/rich.glb" -o - --format gltf -q > "$tmp/stdout.gltf"
check "-o - --format gltf writes JSON" "$py" -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/stdout.gltf"
mkdir -p "$tmp/od"
"$bin" normals "$fx/rich.gltf" --output-dir "$tmp/od" --format glb -q
check "--output-dir --format glb names the output .glb" test -s "$tmp/od/rich.glb"
"$bin" info - --input-format glb < "$fx/rich.glb" > "$tmp/stdin.txt" 2> /dev/null
check "stdin with --input-format glb" grep -q "GLB" "$tmp/stdin.txt"
"$bin" normals "$fx/rich.glb" -o "$tmp/j.glb" --json -q > "$tmp/j.json"
check "--json: one line, counts summed over primitives, per-primitive stats" "$py" -c '
import json,sys
rows=[json.loads(l) for l in open(sys.argv[1])]
assert len(rows)==1 and rows[0]["status"]=="ok"
st=rows[0]["stats"]
assert st["primitives"]==4 and st["faces"]==12+4+6+4, st
assert len(st["per_primitive"])==4, st' "$tmp/j.json"

# occlusion and bake-lighting --shadows of a glTF file: COLOR_0 written, the document kept, valid;
# settings (samples, lights) reported once per file, counts (rays) summed over the primitives.
"$bin" occlusion "$fx/rich.glb" -o "$tmp/ao.glb" --samples 8 --json -q > "$tmp/ao.json"
check "occlusion glb exit 0" test $? -eq 0
check "occlusion glb keeps everything else" gcheck keep "$fx/rich.glb" "$tmp/ao.glb" --changed COLOR_0
check "occlusion glb valid" valid "$tmp/ao.glb"
"$bin" bake-lighting "$fx/rich.glb" -o "$tmp/sh.glb" --shadows --json -q > "$tmp/sh.json"
check "bake-lighting --shadows glb valid" valid "$tmp/sh.glb"
check "--json over primitives: samples and lights once, rays summed" "$py" -c '
import json,sys
a=json.loads(open(sys.argv[1]).read()); b=json.loads(open(sys.argv[2]).read())
s=a["stats"]; t=b["stats"]
assert s["samples"]==8, s["samples"]
assert s["rays"]==sum(p["rays"] for p in s["per_primitive"].values()), s
assert t["lights"]==next(iter(t["per_primitive"].values()))["lights"], t
assert t["shadow_samples"]==1, t' "$tmp/ao.json" "$tmp/sh.json"

# bake-lighting --shadows of a glTF file with its own light: the whole scene casts shadows. A floor
# (3 x 3 grid, node scale 4) under a roof on another node (scale 1.5, 2 above), a directional
# KHR light straight down: the floor's centre is in the roof's shadow (0), its corners are lit.
"$py" - "$tmp/roof.glb" <<'PY'
import json, math, struct, sys
grid = [c for k in range(3) for i in range(3) for c in (i - 1.0, 0.0, k - 1.0)]
tri = []
for k in range(2):
    for i in range(2):
        a = 3 * k + i; tri += [a, a + 3, a + 1, a + 1, a + 3, a + 4]
bin = struct.pack("<27f", *grid) + struct.pack("<24H", *tri)
h = math.sqrt(0.5)
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 1.0}]}},
  "nodes": [{"scale": [4, 1, 4], "mesh": 0}, {"translation": [0, 2, 0], "scale": [1.5, 1, 1.5], "mesh": 1},
            {"rotation": [-h, 0, 0, h], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]},
             {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": len(bin)}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 108}, {"buffer": 0, "byteOffset": 108, "byteLength": 48}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 9, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                {"bufferView": 1, "componentType": 5123, "count": 24, "type": "SCALAR"}]}
text = json.dumps(doc).encode(); text += b" " * (-len(text) % 4)
out = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(bin)) + struct.pack("<I", len(text)) + b"JSON" + text
out += struct.pack("<I", len(bin)) + b"BIN\0" + bin
open(sys.argv[1], "wb").write(out)
PY
"$bin" bake-lighting "$tmp/roof.glb" -o "$tmp/roof_lit.glb" --shadows -q
check "bake-lighting --shadows of a glTF scene: exit 0" test $? -eq 0
check "... valid" valid "$tmp/roof_lit.glb"
check "... the roof on another node shadows the floor's centre, not its corners" "$py" -c '
import json,struct,sys
d=open(sys.argv[1],"rb").read(); n=struct.unpack_from("<I",d,12)[0]; j=json.loads(d[20:20+n]); b=d[20+n+8:]
a=j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"]]; v=j["bufferViews"][a["bufferView"]]
size={5126:4,5121:1,5123:2}[a["componentType"]]; comps={"VEC3":3,"VEC4":4}[a["type"]]; stride=v.get("byteStride",size*comps)
fmt={5126:"f",5121:"B",5123:"H"}[a["componentType"]]; scale={5126:1.0,5121:255.0,5123:65535.0}[a["componentType"]]
at=v.get("byteOffset",0)+a.get("byteOffset",0)
red=[struct.unpack_from("<"+fmt,b,at+i*stride)[0]/scale for i in range(a["count"])]
assert red[4]==0, red
assert all(red[i]>0.5 for i in (0,2,6,8)), red' "$tmp/roof_lit.glb"

# A glTF with tangents written to another format (the world-space mesh): PLY gets the merged mesh's
# MikkTSpace frames as tx ty tz tw (they were dropped without a note, though "TANGENT added" was
# said); a format without tangents says it drops them. Checked here: the properties exist, each
# tangent is unit, orthogonal to its vertex normal, w = +-1.
rm -f "$tmp/tan.ply" "$tmp/tan.obj"
"$bin" normals "$src/data/scene.gltf" --tangents -o "$tmp/tan.ply" --ascii 2> "$tmp/err.txt"
check "glTF --tangents to PLY: exit 0" test $? -eq 0
check "glTF --tangents to PLY: a note says they are written" grep -q "TANGENT: MikkTSpace frames of the world-space mesh written" "$tmp/err.txt"
check "glTF --tangents to PLY: tx ty tz tw unit, orthogonal to the normal, w = +-1" "$py" -c '
import sys, math
lines = open(sys.argv[1]).read().split("\n")
end = lines.index("end_header"); props = []; nv = 0
for l in lines[:end]:
    w = l.split()
    if w[:2] == ["element", "vertex"]: nv = int(w[2]); cur = True
    elif w[:1] == ["element"]: cur = False
    elif w[:1] == ["property"] and cur: props.append(w[-1])
ix = {p: i for i, p in enumerate(props)}
assert all(k in ix for k in ("tx", "ty", "tz", "tw", "nx", "ny", "nz")), props
for l in lines[end + 1:end + 1 + nv]:
    v = [float(x) for x in l.split()]
    t = [v[ix[k]] for k in ("tx", "ty", "tz")]; n = [v[ix[k]] for k in ("nx", "ny", "nz")]
    assert abs(math.sqrt(sum(x * x for x in t)) - 1) < 1e-5, t
    assert abs(sum(a * b for a, b in zip(t, n))) < 1e-4, (t, n)
    assert v[ix["tw"]] in (1.0, -1.0), v[ix["tw"]]' "$tmp/tan.ply"
"$bin" normals "$src/data/scene.gltf" --tangents -o "$tmp/tan.obj" 2> "$tmp/err.txt"
check "glTF --tangents to OBJ: a note says TANGENT is not written" grep -q "TANGENT not written: the output format cannot hold tangents" "$tmp/err.txt"

# Morph targets with TANGENT deltas on a primitive whose TANGENT cannot be recomputed (no
# TEXCOORD_0, as Khronos' AnimatedMorphCube): the base TANGENT is removed, so are the deltas (a
# target attribute without its base is MESH_PRIMITIVE_MORPH_TARGET_NO_BASE_ACCESSOR).
derive "$fx/rich.gltf" "$tmp/morph_tangent.gltf" '
p = d["meshes"][0]["primitives"][0]
del p["attributes"]["TEXCOORD_0"]
del d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]
p["targets"][0]["TANGENT"] = p["targets"][0]["NORMAL"]'
"$bin" normals --recompute "$tmp/morph_tangent.gltf" -o "$tmp/morph_tangent.glb" 2> "$tmp/err.txt"
check "morph TANGENT deltas without a recomputable TANGENT: exit 0" test $? -eq 0
check "... a note says TANGENT removed" grep -q "TANGENT removed" "$tmp/err.txt"
check "... valid (no target TANGENT left without its base)" valid "$tmp/morph_tangent.glb"
check "... no TANGENT in the primitive or its targets" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
j, _ = gltf_check.load(sys.argv[1])
p = j["meshes"][0]["primitives"][0]
assert "TANGENT" not in p["attributes"] and all("TANGENT" not in t for t in p["targets"]), p' "$tmp/morph_tangent.glb" "$src/tests/gltf"

# transform --normals drop: TANGENT goes with NORMAL, deltas included (a TANGENT without NORMAL is
# ignored by readers, glTF 2.0 3.7.2.1, and the validator warns MESH_PRIMITIVE_TANGENT_WITHOUT_NORMAL:
# what the writer added on xcorpus' cubevc.glb, TestScene.gltf and the AnimatedMorph files).
for in in rich.gltf morph_tangent.gltf; do
  [ "$in" = rich.gltf ] && f=$fx/$in || f=$tmp/$in
  "$bin" transform "$f" -o "$tmp/drop_$in.glb" --scale 2 --normals drop 2> "$tmp/err.txt"
  check "--normals drop $in: exit 0" test $? -eq 0
  check "--normals drop $in: a note says TANGENT removed with NORMAL" grep -q "TANGENT removed with NORMAL" "$tmp/err.txt"
  check "--normals drop $in: no TANGENT or NORMAL left, in the primitive or its targets" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
j, _ = gltf_check.load(sys.argv[1])
for m in j["meshes"]:
    for p in m["primitives"]:
        for a in [p["attributes"]] + p.get("targets", []):
            assert "TANGENT" not in a and "NORMAL" not in a, p' "$tmp/drop_$in.glb" "$src/tests/gltf"
  check "--normals drop $in: valid" valid "$tmp/drop_$in.glb"
  if [ -n "$validate" ]; then
    check "--normals drop $in: no MESH_PRIMITIVE_TANGENT_WITHOUT_NORMAL" bash -c "! grep -q TANGENT_WITHOUT_NORMAL '$tmp/validator.txt'"
  fi
  check "--normals drop $in: everything else kept" gcheck keep "$f" "$tmp/drop_$in.glb" --changed NORMAL,POSITION,TANGENT
done

# Normals off unit length (Khronos' BoxBadNormals: NORMAL of length 0.1) through a command that
# writes NORMAL anew: written divided by their length, as every writer does (core/unit_normals.h),
# one note; a glTF whose NORMAL is not unit fails the validator (ACCESSOR_VECTOR3_NON_UNIT).
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0.1\nf 1//1 2//1 3//1\n' > "$tmp/short_vn.obj"
"$bin" transform --translate 1,0,0 "$tmp/short_vn.obj" -o "$tmp/short_vn.glb" 2> "$tmp/err.txt"
check "short normals -> glb: valid" valid "$tmp/short_vn.glb"
check "short normals -> glb: a note gives the length" grep -q "1 normal not of unit length (0.1) written divided by their length" "$tmp/err.txt"
derive "$fx/rich.gltf" "$tmp/short_normals.gltf" '
a = d["accessors"][d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"]]
v = d["bufferViews"][a["bufferView"]]
off, stride = v.get("byteOffset", 0) + a.get("byteOffset", 0), v.get("byteStride", 12)
for i in range(a["count"]):
    x = struct.unpack_from("<3f", b, off + i * stride)
    struct.pack_into("<3f", b, off + i * stride, *(0.1 * c for c in x))'
"$bin" transform --translate 1,0,0 "$tmp/short_normals.gltf" -o "$tmp/short_normals.glb" 2> "$tmp/err.txt"
check "glTF NORMAL of length 0.1 through transform: valid" valid "$tmp/short_normals.glb"
check "... a note says so" grep -q "normals not of unit length (0.1" "$tmp/err.txt"

# A point cloud (a PLY with vertices and no face, as scanners and trimesh's PointCloud write it)
# into glTF: a POINTS primitive without indices (an index accessor of count 0 is invalid glTF).
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n' > "$tmp/points.ply"
"$bin" transform --translate 1,0,0 "$tmp/points.ply" -o "$tmp/points.glb" 2> "$tmp/err.txt"
check "point cloud -> glb: exit 0" test $? -eq 0
check "point cloud -> glb: valid" valid "$tmp/points.glb"
check "point cloud -> glb: one POINTS primitive, no indices, 3 positions moved by +1 in x" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
j, _ = gltf_check.load(sys.argv[1])
(p,) = j["meshes"][0]["primitives"]
assert p["mode"] == 0 and "indices" not in p, p
a = j["accessors"][p["attributes"]["POSITION"]]
assert a["count"] == 3 and a["min"] == [1, 0, 0] and a["max"] == [2, 1, 0], a' "$tmp/points.glb" "$src/tests/gltf"

# Known extensions that look like unknown ones (xcorpus4: draco's BoxMeta.gltf, glTF-Transform's
# EXT_structural_metadata tests, draco's one_face_123_cesium_rtc.gltf): CESIUM_RTC holds a centre,
# EXT_mesh_features feature counts, _FEATURE_ID_n suffixes, textures and property tables; neither
# names an accessor or a bufferView. EXT_structural_metadata's property tables name bufferViews no
# accessor refers to (values, arrayOffsets, stringOffsets). Before: everything kept with a "may
# refer to them" note, the replaced POSITION and NORMAL left as UNUSED_OBJECT. Now the replaced
# accessors go, and each property table view is kept with its bytes and its offset mod 8 (the
# table's components may be 8 bytes), its index remapped. Truth: the input's own property-table
# bytes, read by gltf_check.py from the file draco's tests wrote.
meta=$src/data/corpus_extra/draco_BoxMeta/BoxMeta.gltf
for out in meta.glb meta.gltf; do
  "$bin" transform --scale -1,1,1 "$meta" -o "$tmp/$out" 2> "$tmp/meta.err"
  check "EXT_structural_metadata -> $out: exit 0" test $? -eq 0
  check "EXT_structural_metadata -> $out: no 'may refer to them' note" bash -c "! grep -q 'may refer to them' '$tmp/meta.err'"
  check "EXT_structural_metadata -> $out: the replaced accessors removed (every accessor referenced)" all_referenced "$tmp/$out"
  check "EXT_structural_metadata -> $out: each property table view holds the input's bytes, at its offset mod 8" "$py" -c '
import sys; sys.path.insert(0, sys.argv[3]); import gltf_check
def views(path):
    j, bufs = gltf_check.load(path); out = []
    for t in j["extensions"]["EXT_structural_metadata"]["propertyTables"]:
        for name, prop in sorted(t["properties"].items()):
            for key in ("values", "arrayOffsets", "stringOffsets"):
                if key in prop:
                    v = j["bufferViews"][prop[key]]; o = v.get("byteOffset", 0)
                    out.append((name, key, o % 8, bytes(bufs[v["buffer"]][o:o + v["byteLength"]])))
    return out
a, b = views(sys.argv[1]), views(sys.argv[2])
assert len(a) == 5 and a == b, [(x[:3], y[:3]) for x, y in zip(a, b) if x != y]' "$meta" "$tmp/$out" "$src/tests/gltf"
  if [ -n "$validate" ]; then
    valid "$meta" > /dev/null; unused_in=$(grep -c UNUSED_OBJECT "$tmp/validator.txt")
    valid "$tmp/$out" > /dev/null
    check "EXT_structural_metadata -> $out: no more UNUSED_OBJECT than the input ($unused_in)" test "$(grep -c UNUSED_OBJECT "$tmp/validator.txt")" -le "$unused_in"
  fi
done
# Vertex attributes whose elements do not start on multiples of 4 bytes (glTF 2.0 3.6.2.4; the same
# BoxMeta.gltf packs its UNSIGNED_BYTE _FEATURE_ID_0 and UNSIGNED_SHORT _FEATURE_ID_1 tightly: the
# validator's MESH_PRIMITIVE_ACCESSOR_UNALIGNED, which every output repeated): copied with a
# byteStride of a multiple of 4, so the output is valid; every attribute's values kept (gltf_check
# reads both files).
if [ -n "$validate" ]; then
  valid "$meta" > /dev/null
  check "unaligned vertex attributes: the input has MESH_PRIMITIVE_ACCESSOR_UNALIGNED (the premise)" grep -q MESH_PRIMITIVE_ACCESSOR_UNALIGNED "$tmp/validator.txt"
fi
for out in meta_n.glb meta_n.gltf; do
  "$bin" normals "$meta" -o "$tmp/$out" 2> "$tmp/meta.err"
  check "unaligned vertex attributes -> $out: valid" valid "$tmp/$out"
  check "unaligned vertex attributes -> $out: a note names the copy" grep -q "2 vertex attribute accessors whose elements did not start on multiples of 4 bytes" "$tmp/meta.err"
  check "unaligned vertex attributes -> $out: every attribute kept" gcheck keep "$meta" "$tmp/$out"
done
check "unaligned vertex attributes -> meta.glb (transform): valid" valid "$tmp/meta.glb"

derive "$fx/rich.gltf" "$tmp/rtc.gltf" '
d["extensionsUsed"] = d.get("extensionsUsed", []) + ["CESIUM_RTC"]
d.setdefault("extensions", {})["CESIUM_RTC"] = {"center": [-123.4, 234.5, 345678.9]}'
"$bin" normals --recompute "$tmp/rtc.gltf" -o "$tmp/rtc.glb" 2> "$tmp/rtc.err"
check "CESIUM_RTC: exit 0" test $? -eq 0
check "CESIUM_RTC: the replaced NORMAL removed (every accessor referenced)" all_referenced "$tmp/rtc.glb"
check "CESIUM_RTC: no 'may refer to them' note" bash -c "! grep -q 'may refer to them' '$tmp/rtc.err'"
check "CESIUM_RTC: the centre kept" "$py" -c '
import sys; sys.path.insert(0, sys.argv[2]); import gltf_check
j, _ = gltf_check.load(sys.argv[1])
assert j["extensions"]["CESIUM_RTC"] == {"center": [-123.4, 234.5, 345678.9]}, j.get("extensions")' "$tmp/rtc.glb" "$src/tests/gltf"

echo "gltf_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
