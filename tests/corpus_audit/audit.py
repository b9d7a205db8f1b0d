#!/usr/bin/env python3
"""audit.py BIN SRC CORPUS OUT [--only SUBSTR] [--quick]: every subcommand, with its main options,
over every file of the real-file corpus (meshes other programs wrote, CORPUS/MANIFEST.tsv), into
every output format the input makes sense in, each output checked with tools other than shadetool:

  exit      status 0 (or a usage refusal we expect, e.g. colours into STL)
  validator glTF outputs: the Khronos glTF Validator (npm gltf-validator: $GLTF_VALIDATOR_NODE_PATH,
            else installed beside BIN as tests/gltf_cli.sh does; skipped loudly without node/npm)
            reports 0 errors
  assimp    `assimp info -raw` reads the output and counts the faces our own reader counts
  normals   every written normal (vertex, face, OBJ vn, glTF NORMAL) finite, non-zero and of unit
            length within 1e-3
  kept      `normals` without --recompute keeps authored normals: per corner within 1e-3 rad
  winding   per face, the output face's area vector against the input face's, mapped the way the
            command maps space (glTF to another format: each primitive instance by its node's world
            matrix; transform: by A^-T): no face reversed where the command must keep the winding
            (every command but repair, where tests/corpus.sh checks authored orientation)
  counts    faces as many as the input's (glTF instances flattened), unless stderr names faces
  unreferenced  no more vertices that no face uses than the input had (non-glTF outputs)
  attrs     every attribute of the input (normals, colours, texcoords, quality; PLY: every extra
            vertex/face property and element) in the output or named on stderr
Writes OUT/results.tsv (file, command, check, detail) and prints a summary per check. assimp's own
refusals of a known class (assimp_own_refusal: no faces, a binary PLY body starting with 0x0a; or
an output of an input assimp cannot read either) go to OUT/known.tsv instead, not findings.
Independent readers: tests/corpus/read_mesh.py (pure Python), assimp, gltf-validator.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "corpus"))
import read_mesh  # noqa: E402
import gltf_check  # noqa: E402  (imported by read_mesh)

NOTE_WORDS = {"normals": ("normal",), "colors": ("colo",), "texcoords": ("texcoord", "texture", "uv"),
              "quality": ("quality",)}
MESH_FORMATS = (".obj", ".ply", ".off", ".stl", ".glb", ".gltf")


# ---------------------------------------------------------------- small vector algebra
# sub, cross, dot, Newell's area vector, the shading normal at a corner and the normals a file
# holds: tests/corpus/check.py's (one copy for both harnesses)
from check import sub, cross, dot, area_vector, corner_normal, obj_vn_lines  # noqa: E402,F401
from check import written_normals as part_written_normals  # noqa: E402


def norm(a):
    return math.sqrt(dot(a, a))


def mat_mul(a, b):  # 4x4 row-major lists of lists
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def apply_point(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3))


def inverse_transpose3(m):
    a = [[m[i][j] for j in range(3)] for i in range(3)]
    c = [[a[(i + 1) % 3][(j + 1) % 3] * a[(i + 2) % 3][(j + 2) % 3] - a[(i + 1) % 3][(j + 2) % 3] * a[(i + 2) % 3][(j + 1) % 3]
          for j in range(3)] for i in range(3)]  # cofactor matrix
    det = sum(a[0][j] * c[0][j] for j in range(3))
    return [[c[i][j] / det for j in range(3)] for i in range(3)] if det != 0 else None, det


def apply3(m, v):
    return tuple(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2] for i in range(3))


def node_matrix(node):
    if "matrix" in node:
        m = node["matrix"]  # column-major
        return [[m[j * 4 + i] for j in range(4)] for i in range(4)]
    t = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    s = node.get("scale", [1, 1, 1])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


IDENTITY = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def gltf_instances(path):
    """[(mesh index, world matrix)] in depth-first scene order (the default scene, else scene 0,
    else every root); a node with EXT_mesh_gpu_instancing once per instance; a mesh no node shows
    once at identity (as gltf_scene.h places them)."""
    doc, buffers = gltf_check.load(path)
    nodes = doc.get("nodes", [])
    scenes = doc.get("scenes", [])
    if scenes:
        roots = scenes[doc.get("scene", 0)].get("nodes", [])
    else:
        children = {c for n in nodes for c in n.get("children", [])}
        roots = [i for i in range(len(nodes)) if i not in children]
    out = []
    shown = set()

    def walk(i, parent, seen=()):
        if i in seen:  # a node graph with a cycle (invalid glTF; assimp's RecursiveNodes): no instance
            raise ValueError("nodes[%d] is its own ancestor" % i)
        seen = seen + (i,)
        m = mat_mul(parent, node_matrix(nodes[i]))
        if "mesh" in nodes[i]:
            shown.add(nodes[i]["mesh"])
            for w in gpu_instance_matrices(doc, buffers, nodes[i], m):
                if det3(w) != 0:  # a singular matrix (scale 0) hides the instance: nothing placed
                    out.append((nodes[i]["mesh"], w))
        for c in nodes[i].get("children", []):
            walk(c, m, seen)
    for r in roots:
        walk(r, IDENTITY)
    # a mesh no node of the scene shows: written once in its object space (gltf_scene.h)
    out += [(k, IDENTITY) for k in range(len(doc.get("meshes", []))) if k not in shown]
    return out


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def gpu_instance_matrices(doc, buffers, node, world):
    """The world matrices a node shows its mesh at: [world], or with EXT_mesh_gpu_instancing one per
    instance, world * T_i R_i S_i (the extension's TRANSLATION, ROTATION, SCALE accessors read as a
    node's T R S; an attribute absent: identity). Decoded by gltf_check.accessor (normalized
    integer rotations to [-1, 1]), independently of the library."""
    ext = node.get("extensions", {}).get("EXT_mesh_gpu_instancing")
    if not ext or not ext.get("attributes"):
        return [world]
    cols = {k: gltf_check.accessor(doc, buffers, a) for k, a in ext["attributes"].items()
            if k in ("TRANSLATION", "ROTATION", "SCALE")}
    n = max(len(v) for v in cols.values()) if cols else 0
    out = []
    for i in range(n):
        trs = {}
        for k, key in (("TRANSLATION", "translation"), ("ROTATION", "rotation"), ("SCALE", "scale")):
            if k in cols:
                trs[key] = list(cols[k][i])
        out.append(mat_mul(world, node_matrix(trs)))
    return out


def world_parts(path, parts):
    """The glTF input as a non-glTF writer flattens it: each primitive instance in world space."""
    by_mesh = {}
    for p in parts:
        m = int(re.match(r"meshes\[(\d+)\]", p["name"]).group(1))
        by_mesh.setdefault(m, []).append(p)
    out = []
    for mesh, mat in gltf_instances(path):
        it, det = inverse_transpose3(mat)
        for p in by_mesh.get(mesh, []):
            P = [apply_point(mat, v) for v in p["positions"]]
            N = None
            if p["vertex_normals"] is not None and it is not None:
                N = [apply3(it, n) for n in p["vertex_normals"]]
                N = [tuple(x / norm(n) for x in n) if norm(n) > 0 else n for n in N]
            # glTF: a node whose matrix mirrors (det < 0) shows its triangles clockwise-front
            # (glTF 2.0, 3.7.2.1): in world space the front face is the reversed triangle
            F = [tuple(reversed(f)) for f in p["faces"]] if det < 0 else p["faces"]
            out.append(dict(p, positions=P, faces=F, vertex_normals=N, name="", source=p["name"]))
    return out


# ---------------------------------------------------------------- readers of what we wrote
def ply_schema(path):
    """{element: [property names]} of a PLY header."""
    with open(path, "rb") as f:
        data = f.read(65536)
    head = data[:data.find(b"end_header")].decode("latin-1").splitlines()
    out, cur = {}, None
    for line in head:
        t = line.split()
        if t and t[0] == "element":
            cur = t[1]
            out[cur] = []
        elif t and t[0] == "property" and cur:
            out[cur].append(t[-1])
    return out


def written_normals(parts, path):
    """Every part's vertex and face normals, then an OBJ's raw vn lines (check.py's rules)."""
    return [n for p in parts for n in part_written_normals(p, [])] + obj_vn_lines(path)


def assimp_faces(path):
    try:
        p = subprocess.run(["assimp", "info", path, "-raw"], capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return None, "timeout"
    m = re.search(r"^Faces:\s+(\d+)", p.stdout, re.M)
    if p.returncode != 0 or not m:
        return None, (p.stdout + p.stderr).strip().splitlines()[-1:] if (p.stdout + p.stderr).strip() else "no output"
    return int(m.group(1)), None


def assimp_own_refusal(path, nf_poly):
    """Why assimp's refusal of an output is assimp's own, or None. Two classes seen in every corpus,
    each reproduced on an input assimp ships (findings.md): a mesh without faces ("contains no
    faces"; point clouds, transform of points), and a binary PLY whose body starts with byte 0x0a
    (assimp skips it as a newline after end_header and misreads the rest: its own
    cube_binary_starts_with_nl.ply fails so; our bodies start with the first vertex's x, and any
    float whose low byte is 0x0a, e.g. 0.08 or 1.25052, starts with it)."""
    if nf_poly == 0:
        return "no faces"
    if path.lower().endswith(".ply"):
        with open(path, "rb") as f:
            head = f.read(1 << 16)
        at = head.find(b"end_header\n")
        if at > 0 and b"format binary" in head[:at] and head[at + 11:at + 12] == b"\n":
            return "binary PLY body starting with byte 0x0a"
    return None


# ---------------------------------------------------------------- the runs
def formats_for(ext):
    same = ".glb" if ext == ".gltf" else ext
    return [same] + [e for e in (".glb", ".ply", ".obj") if e != same]


def runs_for(src, ext, quick):
    """(name, args, out_ext, kind, linear map A or None). kind: mesh (winding kept), repair,
    colour (winding kept, colours added), image, text."""
    studio = os.path.join(src, "data/scenes/studio.json")
    window = os.path.join(src, "data/scenes/window.json")
    fm = formats_for(ext)
    same = fm[0]
    colour_same = ".ply" if same in (".stl", ".off") else same
    mirror = [[-1, 0, 0], [0, 1, 0], [0, 0, 1]]
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    rot_z = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    mirror_rot = [[sum(rot_z[i][k] * mirror[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    R = [("info", ["info"], None, "text", None), ("info --json", ["info", "--json"], None, "text", None)]
    for e in (fm if not quick else fm[:2]):  # --quick: the input's own format and glb
        R.append(("normals", ["normals"], e, "mesh", None))
        R.append(("normals --recompute --crease 30", ["normals", "--recompute", "--crease", "30"], e, "mesh", None))
        R.append(("transform mirror", ["transform", "--scale", "-1,1,1", "--rotate", "30,0,0,1"], e, "mesh", mirror_rot))
    R.append(("normals --recompute", ["normals", "--recompute"], same, "mesh", None))
    R.append(("normals --recompute --weight face-area", ["normals", "--recompute", "--weight", "face-area"], same, "mesh", None))
    if ext == ".obj":
        R.append(("normals --smoothing-groups ignore", ["normals", "--recompute", "--smoothing-groups", "ignore"], same, "mesh", None))
    R.append(("normals --faces", ["normals", "--recompute", "--faces"], ".ply", "mesh", None))
    for e in (".glb", ".ply"):
        R.append(("normals --tangents", ["normals", "--recompute", "--tangents"], e, "mesh", None))
    R.append(("repair", ["repair"], same, "repair", None))
    R.append(("repair", ["repair"], ".glb" if same != ".glb" else ".ply", "repair", None))
    R.append(("transform", ["transform", "--rotate", "30,1,1,0", "--translate", "1,2,3"], same, "mesh",
              rotation_matrix(30, (1, 1, 0))))
    for e in ([colour_same] + [x for x in (".glb", ".ply") if x != colour_same]):
        R.append(("bake-lighting", ["bake-lighting", "--scene", studio], e, "colour", None))
    R.append(("bake-lighting --hdr", ["bake-lighting", "--scene", studio, "--hdr"], ".ply", "colour", None))
    R.append(("bake-lighting --per face", ["bake-lighting", "--scene", studio, "--per", "face"], ".ply", "colour", None))
    R.append(("bake-lighting window (point lights)", ["bake-lighting", "--scene", window], ".glb", "colour", None))
    R.append(("bake-lighting --fit least-squares", ["bake-lighting", "--scene", window, "--fit", "least-squares"], ".ply", "colour", None))
    for sh in ("flat", "gouraud", "phong"):
        R.append(("render " + sh, ["render", "--shading", sh, "--size", "64", "48"], ".png", "image", None))
    R.append(("occlusion", ["occlusion", "--samples", "8"], colour_same, "colour", None))
    R.append(("occlusion", ["occlusion", "--samples", "8"], ".glb" if colour_same != ".glb" else ".ply", "colour", None))
    return R


def rotation_matrix(deg, axis):
    l = norm(axis)
    x, y, z = (a / l for a in axis)
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
            [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
            [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]


class Audit:
    def __init__(self, bin_, src, corpus, out, validator):
        self.bin, self.src, self.corpus, self.out, self.validator = bin_, src, corpus, out, validator
        self.rows = []
        self.known = []  # (file, command, check, detail) of other programs' own refusals
        self.assimp_input = {}  # input path -> assimp cannot read it
        self.big_bytes = int(os.environ.get("AUDIT_BIG_BYTES", "1500000"))  # larger inputs: --quick
        self.runs = 0

    def assimp_refuses_input(self, path):
        """True when assimp cannot read the input itself (glTF with quantized SHORT positions, a
        file without meshes...): its refusal of an output then says nothing about our writer.
        Read once per input."""
        if path not in self.assimp_input:
            self.assimp_input[path] = assimp_faces(path)[0] is None
        return self.assimp_input[path]

    def known_row(self, rel, cmd, check, detail):
        """A refusal by another program that is that program's own (a known class): listed in
        OUT/known.tsv, not a finding."""
        self.known.append((rel, cmd, check, detail))
        print("KNOWN %s [%s] %s: %s" % (rel, cmd, check, detail), flush=True)

    def finding(self, rel, cmd, check, detail):
        self.rows.append((rel, cmd, check, detail))
        print("FAIL %s [%s] %s: %s" % (rel, cmd, check, detail), flush=True)

    def run_file(self, rel, quick):
        path = os.path.join(self.corpus, rel)
        ext = os.path.splitext(rel)[1].lower()
        try:
            inp = read_mesh.read(path)
        except Exception as e:
            print("note: %s: read_mesh cannot read it (%s): exit status checked only" % (rel, e))
            inp = None
        gltf_in = ext in (".gltf", ".glb")
        try:
            inp_world = world_parts(path, inp) if (inp is not None and gltf_in) else None
        except (ValueError, LookupError, TypeError) as e:  # a cycle, a node/mesh index out of range, a bad type
            print("note: %s: cannot place its instances (%r): exit status checked only" % (rel, e))
            inp, inp_world = None, None
        in_schema = ply_schema(path) if ext == ".ply" else None
        work = os.path.join(self.out, "work")
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        glbs = []
        big = os.path.getsize(path) > self.big_bytes
        for k, (name, args, oext, kind, A) in enumerate(runs_for(self.src, ext, quick or big)):
            self.runs += 1
            label = "%s -> %s" % (name, oext) if oext else name
            out = os.path.join(work, "r%02d%s" % (k, oext)) if oext else None
            cmd = [self.bin, args[0], path] + args[1:] + (["-o", out] if out else [])  # input first: --size takes 2 values
            try:
                p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
                code, err = p.returncode, p.stderr
            except subprocess.TimeoutExpired:
                code, err = "timeout", ""
            if code != 0:
                self.finding(rel, label, "exit", "exit %s: %s" % (code, " | ".join(err.strip().splitlines()[-2:])))
                continue
            if kind == "text" or out is None:
                continue
            if not os.path.exists(out):
                self.finding(rel, label, "exit", "exit 0, no output")
                continue
            if kind == "image":
                continue
            if oext in (".glb", ".gltf"):
                glbs.append((out, label))
            try:
                outp = read_mesh.read(out)
            except Exception as e:
                self.finding(rel, label, "reread", "read_mesh cannot read our output: %r" % e)
                continue
            if oext in (".glb", ".gltf"):
                points_attributes(out, outp)
            self.check_mesh(rel, label, name, args, kind, A, path, inp, inp_world, in_schema, out, oext, outp, err)
        if glbs and self.validator:
            self.validate(rel, glbs)

    def validate(self, rel, glbs):
        env = dict(os.environ, NODE_PATH=self.validator)
        p = subprocess.run(["node", os.path.join(self.src, "tests/gltf/validate.js")] + [g for g, _ in glbs],
                           capture_output=True, text=True, env=env)
        label_of = dict(glbs)
        cur = None
        codes = {}  # (file, code) -> [count, first message]
        for line in p.stdout.splitlines():
            m = re.match(r"^(\S+): (\d+) errors", line)
            if m:
                cur = m.group(1) if int(m.group(2)) else None
                continue
            m = re.match(r"^\s*error (\S+): (.*)$", line)
            if cur and m:
                c = codes.setdefault((cur, m.group(1)), [0, m.group(2)])
                c[0] += 1
            elif cur and "validator failed" in line:
                codes.setdefault((cur, "FAILED"), [1, line.strip()])
        for (f, code), (count, first) in codes.items():
            self.finding(rel, label_of.get(f, f), "validator", "%d x %s (first: %s)" % (count, code, first))

    def check_mesh(self, rel, label, name, args, kind, A, path, inp, inp_world, in_schema, out, oext, outp, err):
        # normals: finite, non-zero, unit
        bad = nonunit = 0
        worst = 0.0
        for n in written_normals(outp, out):
            if n is None or not all(math.isfinite(x) for x in n) or norm(n) == 0:
                bad += 1
            elif abs(norm(n) - 1) > 1e-3:
                nonunit += 1
                worst = max(worst, abs(norm(n) - 1))
        if bad:
            self.finding(rel, label, "normals", "%d written normals zero or not finite" % bad)
        if nonunit:
            self.finding(rel, label, "unit", "%d written normals off unit length by > 1e-3 (worst %.3g)" % (nonunit, worst))
        # assimp: reads it, same face count as our reader
        # (assimp triangulates OFF polygons and counts a glTF mesh once however many nodes show it:
        # compare triangles, and for glTF only that it reads)
        nf_ours = sum(max(len(f) - 2, 0) for q in outp for f in q["faces"])
        nf_poly = sum(len(q["faces"]) for q in outp)
        nf_assimp, why = assimp_faces(out)
        if nf_assimp is None:
            own = assimp_own_refusal(out, nf_poly)
            if not own and self.assimp_refuses_input(path):
                own = "it cannot read the input either"
            if own:
                self.known_row(rel, label, "assimp", "assimp cannot read it (%s: assimp's own): %s" % (own, why))
            else:
                self.finding(rel, label, "assimp", "assimp cannot read it: %s" % (why,))
        elif nf_assimp not in (nf_ours, nf_poly) and oext not in (".stl", ".glb", ".gltf"):
            self.finding(rel, label, "assimp", "assimp counts %d faces, read_mesh %d triangles" % (nf_assimp, nf_ours))
        if inp is None:
            return
        ext_in = os.path.splitext(path)[1].lower()
        gltf_in, gltf_out = ext_in in (".gltf", ".glb"), oext in (".gltf", ".glb")
        # pair input parts with output parts
        if gltf_in and gltf_out:
            by_name = {q["name"]: q for q in outp}
            pairs = [(p, by_name.get(p["name"]), False) for p in inp]
        elif gltf_in:  # instances flattened in the writer's order: pair faces by their corners' positions
            pairs = [(merge(inp_world), merge(outp), True)]
        else:
            pairs = [(merge(inp), merge(outp), False)]
        # no command adds vertices no face uses (a writer that copies what it need not)
        if not gltf_out:
            un_in = read_mesh.gltf_unreferenced(path) if gltf_in else read_mesh.unreferenced(inp)
            un_out = read_mesh.unreferenced(outp)
            if un_out > un_in and not named(err, ("unreferenced", "no face uses")):
                self.finding(rel, label, "unreferenced", "%d vertices no face uses in the output, %d in the input"
                             % (un_out, un_in))
        for pin, q, by_position in pairs:
            where = (pin["name"] + ": ") if pin.get("name") else ""
            if q is None:
                if not named(err, (pin["name"],)):
                    self.finding(rel, label, "counts", "%s missing from the output, no note" % pin["name"])
                continue
            if len(q["faces"]) != len(pin["faces"]):
                tri_in = sum(max(len(f) - 2, 0) for f in pin["faces"])
                if gltf_out and len(q["faces"]) == tri_in:
                    continue  # glTF holds triangles: polygons triangulated, not paired face by face
                if not named(err, ("face",)):
                    self.finding(rel, label, "counts", "%sfaces %d -> %d, no note" % (where, len(pin["faces"]), len(q["faces"])))
                continue
            for attr in sorted(pin["attributes"] - q["attributes"]):
                if not named(err, NOTE_WORDS[attr]):
                    self.finding(rel, label, "attrs", "%s%s dropped, no note names them" % (where, attr))
            if kind == "repair":
                continue
            # winding, per face
            M = None
            if A is not None:
                M, det = inverse_transpose3(A)
            face_map = pair_faces(pin, q, A) if by_position else [(f, f, None) for f in range(len(pin["faces"]))]
            flipped = total = 0
            first = None
            # a sliver whose area is below float resolution at the mesh's size (|area vector| <
            # 1e-8 size^2: trumpet.obj has one) turns over when its corners are rounded to float:
            # its orientation is noise, not judged
            allp = q["positions"] or [(0.0, 0.0, 0.0)]
            size = max(max(abs(p[i]) for p in allp) for i in range(3))
            tiny = 1e-8 * size * size
            for fi, f, cmap in face_map:
                a_in = area_vector(pin["positions"], pin["faces"][fi])
                a_out = area_vector(q["positions"], q["faces"][f])
                if M is not None:
                    a_in = apply3(M, a_in)
                ni, no = norm(a_in), norm(a_out)
                if not (ni > tiny and no > tiny and math.isfinite(ni) and math.isfinite(no)):
                    continue
                total += 1
                if dot(a_in, a_out) / (ni * no) < -0.5:
                    flipped += 1
                    first = f if first is None else first
            if flipped:
                self.finding(rel, label, "winding", "%s%d of %d faces reversed against the input (first: face %d)"
                             % (where, flipped, total, first))
            # face normals (STL facets, PLY face nx ny nz): kept as face normals, or as every
            # corner's normal, or named in a note
            if pin["face_normals"] is not None and q["face_normals"] is None and "--recompute" not in args:
                lost = 0
                for fi, f, cmap in face_map:
                    a = pin["face_normals"][fi]
                    if a is None or norm(a) == 0:
                        continue
                    if A is not None:
                        a = apply3(inverse_transpose3(A)[0], a)
                    for k in range(len(q["faces"][f])):
                        b = corner_normal(q, f, k)
                        if b is None or norm(b) == 0 or dot(a, b) / (norm(a) * norm(b)) < 1 - 1e-6:
                            lost += 1
                            break
                if lost and not named(err, ("facet", "face normal")):
                    self.finding(rel, label, "attrs", "%sauthored face normals of %d faces not in the output, no note names them"
                                 % (where, lost))
            # kept normals (authored vertex or corner normals; face normals above)
            if name == "normals" and (pin["vertex_normals"] is not None or pin["corner_normals"] is not None) \
                    and "normals" in q["attributes"]:
                worst, moved = 0.0, 0
                for fi, f, cmap in face_map:
                    corners_at = [tuple(pin["positions"][i]) for i in pin["faces"][fi]]
                    if len(set(corners_at)) < len(corners_at):
                        # a face with two corners at one position: several such faces share their
                        # position key (2CylinderEngine.glb), so the pairing by position is a guess
                        continue
                    for k in range(len(q["faces"][f])):
                        ki = k if cmap is None else cmap[k]
                        if ki is None:
                            continue
                        a, b = corner_normal(pin, fi, ki), corner_normal(q, f, k)
                        if a is None or b is None or norm(a) == 0 or norm(b) == 0:
                            continue
                        ang = math.acos(max(-1.0, min(1.0, dot(a, b) / (norm(a) * norm(b)))))
                        if ang > 1e-3:
                            moved += 1
                            worst = max(worst, ang)
                if moved:
                    self.finding(rel, label, "kept", "%s%d corners' authored normals changed (worst %.1f deg), no --recompute"
                                 % (where, moved, math.degrees(worst)))
        # PLY extra properties and elements (PLY in, PLY out)
        if in_schema is not None and oext == ".ply":
            out_schema = ply_schema(out)
            for el, props in in_schema.items():
                if el not in out_schema:
                    if el not in ("face", "tristrips") and not named(err, (el,)):
                        self.finding(rel, label, "attrs", "PLY element %s dropped, no note names it" % el)
                    continue
                for pr in props:
                    if pr not in out_schema[el] and not named(err, (pr,) + PROPERTY_WORDS.get(pr, ())) \
                            and not alias_kept(pr, out_schema[el]):
                        self.finding(rel, label, "attrs", "PLY property %s.%s dropped, no note names it" % (el, pr))


def pair_faces(pin, q, A):
    """[(input face, output face, output corner -> input corner)] for faces whose corner positions
    (the input's mapped by A) agree on a grid of 1e-5 of the mesh's size; of coincident input
    faces (a face and its reversed twin), the one whose winding agrees with the output face."""
    P_in = pin["positions"] if A is None else [apply3(A, p) for p in pin["positions"]]
    allp = q["positions"] or [(0.0, 0.0, 0.0)]
    size = max(max(p[i] for p in allp) - min(p[i] for p in allp) for i in range(3))
    scale = max(size, 1e-12) * 1e-5

    def snap(p):
        return tuple(round(x / scale) for x in p)
    index = {}
    for fi, face in enumerate(pin["faces"]):
        index.setdefault(tuple(sorted(snap(P_in[i]) for i in face)), []).append(fi)
    out = []
    for fo, face in enumerate(q["faces"]):
        cands = index.get(tuple(sorted(snap(q["positions"][i]) for i in face)))
        if not cands:
            continue
        a_out = area_vector(q["positions"], face)
        fi = max(cands, key=lambda c: dot(area_vector(P_in, pin["faces"][c]), a_out) * (1 if A is None or inverse_transpose3(A)[1] > 0 else -1))
        keys_in = [snap(P_in[i]) for i in pin["faces"][fi]]
        cmap = [keys_in.index(snap(q["positions"][i])) if snap(q["positions"][i]) in keys_in else None for i in face]
        out.append((fi, fo, cmap))
    return out


PROPERTY_WORDS = {"red": NOTE_WORDS["colors"], "green": NOTE_WORDS["colors"], "blue": NOTE_WORDS["colors"],
                  "alpha": ("alpha",), "nx": NOTE_WORDS["normals"], "ny": NOTE_WORDS["normals"],
                  "nz": NOTE_WORDS["normals"]}

ALIASES = [{"s", "u", "texture_u", "texture_s"}, {"t", "v", "texture_v", "texture_t"},
           {"red", "r", "diffuse_red"}, {"green", "g", "diffuse_green"}, {"blue", "b", "diffuse_blue"},
           {"vertex_indices", "vertex_index"}]


def alias_kept(pr, props):
    for a in ALIASES:
        if pr in a and a & set(props):
            return True
    return False


def named(err, words):
    low = err.lower()
    return any(w.lower() in low for w in words)


def points_attributes(path, parts):
    """read_mesh reads a glTF POINTS primitive (mode 0, a point cloud) as an empty part with no
    attributes: name the attributes its JSON gives it (NORMAL, COLOR_n, TEXCOORD_n), so that a point
    cloud's normals and colours written as glb are not reported as dropped (points.ply, pond.0.ply)."""
    doc, _ = gltf_check.load(path)
    for q in parts:
        m = re.match(r"meshes\[(\d+)\]\.primitives\[(\d+)\]$", q["name"])
        if not m or q["faces"]:
            continue
        prim = doc["meshes"][int(m.group(1))]["primitives"][int(m.group(2))]
        if prim.get("mode", 4) != 0:
            continue
        a = prim.get("attributes", {})
        q["attributes"] |= ({"normals"} if "NORMAL" in a else set()) | \
            ({"colors"} if any(k.startswith("COLOR_") for k in a) else set()) | \
            ({"texcoords"} if any(k.startswith("TEXCOORD_") for k in a) else set())


def merge(parts):
    """One part: positions and faces concatenated (index offsets), attributes intersected."""
    if len(parts) == 1:
        return parts[0]
    P, F, attrs = [], [], None
    vn, cn = [], []
    has_vn = all(p["vertex_normals"] is not None for p in parts)
    for p in parts:
        base = len(P)
        P += p["positions"]
        F += [tuple(i + base for i in f) for f in p["faces"]]
        if has_vn:
            vn += p["vertex_normals"]
        attrs = set(p["attributes"]) if attrs is None else attrs & p["attributes"]
    return read_mesh.part(P, F, vertex_normals=vn if has_vn else None, attributes=attrs or set())


def find_validator(bin_, src, out):
    """The node_modules holding the Khronos glTF Validator: $GLTF_VALIDATOR_NODE_PATH, else the one
    beside BIN (BIN's directory/gltf-validator-node/node_modules), installed there on first use by
    tests/gltf/validator.sh, the install tests/gltf_cli.sh uses (one home for it). None, said
    loudly on stderr and in the summary, when neither works (no node, no npm registry)."""
    env = os.environ.get("GLTF_VALIDATOR_NODE_PATH")
    if env:
        if os.path.isdir(os.path.join(env, "gltf-validator")):
            return env
        sys.stderr.write("audit: GLTF_VALIDATOR_NODE_PATH=%s has no gltf-validator\n" % env)
    bin_dir = os.path.dirname(os.path.abspath(bin_))
    tmp = os.path.join(out, "validator-install")
    os.makedirs(tmp, exist_ok=True)
    script = 'bin="$1"; src="$2"; tmp="$3"; source "$src/tests/gltf/validator.sh" >&2; echo "NODE_PATH=${validate:+$NODE_PATH}"'
    p = subprocess.run(["bash", "-c", script, "-", os.path.abspath(bin_), os.path.abspath(src), tmp],
                       capture_output=True, text=True)
    m = re.search(r"^NODE_PATH=(\S+)$", p.stdout, re.M)
    if m and os.path.isdir(os.path.join(m.group(1), "gltf-validator")):
        return m.group(1)
    sys.stderr.write("audit: WARNING: every glTF Validator check SKIPPED: no gltf-validator in %s/gltf-validator-node "
                     "and tests/gltf/validator.sh could not install it (%s)\n"
                     % (bin_dir, (p.stderr.strip() or "no reason given").splitlines()[-1]))
    return None


def main():
    args = sys.argv[1:]
    quick = "--quick" in args
    only = None
    if "--only" in args:
        only = args[args.index("--only") + 1]
    bin_, src, corpus, out = [a for a in args if not a.startswith("--") and a != only][:4]
    os.makedirs(out, exist_ok=True)
    validator = find_validator(bin_, src, out)
    files = [l.split("\t")[0] for l in open(os.path.join(corpus, "MANIFEST.tsv")).read().splitlines()[1:] if l.strip()]
    if only:
        files = [f for f in files if re.search(only, f)]
    a = Audit(bin_, src, corpus, out, validator)
    t0 = time.time()
    for rel in files:
        t = time.time()
        a.run_file(rel, quick)
        print("done %s (%.0f s)" % (rel, time.time() - t), flush=True)
    with open(os.path.join(out, "results.tsv"), "w") as f:
        f.write("file\tcommand\tcheck\tdetail\n")
        for r in a.rows:
            f.write("\t".join(r) + "\n")
    with open(os.path.join(out, "known.tsv"), "w") as f:
        f.write("file\tcommand\tcheck\tdetail\n")
        for r in a.known:
            f.write("\t".join(r) + "\n")
    by_check = {}
    for r in a.rows:
        by_check[r[2]] = by_check.get(r[2], 0) + 1
    print("audit: %d files, %d runs, %d findings %s, %d known (known.tsv), %.0f s%s" % (len(files), a.runs, len(a.rows), by_check,
                                                                            len(a.known), time.time() - t0,
                                                                            "" if validator else "; glTF Validator checks SKIPPED"))
    return 1 if a.rows else 0


if __name__ == "__main__":
    sys.exit(main())
