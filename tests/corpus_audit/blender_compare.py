#!/usr/bin/env python3
"""blender_compare.py BIN SRC CORPUS OUT [--only REGEX] [--max-bytes N] [--reuse-dump]: what Blender 3.4 shows
against what shadetool wrote, for corpus files up to N bytes (default 700 kB):

  normals  `normals` (authored normals kept) and `normals --recompute --crease 30`, each written as
           OBJ and glb (Blender 3.4's PLY importer reads no normals: io_mesh_ply "TODO import normals"), imported by Blender (blender_dump.py); per corner, the angle between
           Blender's split normal and the normal we wrote (read back by tests/corpus/read_mesh.py).
           Corners are paired by position (faces by their sorted corner positions), so Blender's
           own vertex order does not matter. A corner off by more than 1 degree is a finding.
  colours  `bake-lighting` written as PLY (8-bit sRGB bytes, the default), as OBJ (`v x y z r g b`,
           sRGB-encoded) and as glb (linear floats): Blender's linear colour per corner from each against the linear colour we
           meant (the glb's floats; the PLY's bytes decoded by the sRGB curve). A corner off by
           more than 2/255 (after the sRGB encoding of both) is a finding: the colour convention.
Skips (exit 0, says why) when Blender is not installed. Writes OUT/blender_results.tsv.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "corpus"))
sys.path.insert(0, HERE)
import read_mesh  # noqa: E402


def srgb_encode(c):
    c = min(max(c, 0.0), 1.0)
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def srgb_decode(s):
    return s / 12.92 if s <= 0.04045 else ((s + 0.055) / 1.055) ** 2.4


def ply_corner_colours(path):
    """Per face, per corner, the vertex colour bytes / 255 of a PLY we wrote, or None."""
    data = open(path, "rb").read()
    # read_mesh does not keep colour values: a small decoder of the vertex element only
    end = data.index(b"end_header")
    head = data[:end].decode("latin-1").splitlines()
    body = data[data.index(b"\n", end) + 1:]
    fmt = [l.split()[1] for l in head if l.startswith("format")][0]
    props, nv, in_vertex = [], 0, False
    for l in head:
        t = l.split()
        if t and t[0] == "element":
            in_vertex = t[1] == "vertex"
            if in_vertex:
                nv = int(t[2])
        elif t and t[0] == "property" and in_vertex:
            props.append((t[-1], t[1]))
    if "red" not in [p for p, _ in props]:
        return None
    types = {"float": "f", "float32": "f", "double": "d", "uchar": "B", "uint8": "B", "int": "i", "uint": "I",
             "short": "h", "ushort": "H", "char": "b", "int32": "i", "uint32": "I", "float64": "d"}
    import struct
    rows = []
    if fmt == "ascii":
        tok = body.split()
        for v in range(nv):
            rows.append(dict(zip([p for p, _ in props], [float(x) for x in tok[v * len(props):(v + 1) * len(props)]])))
    else:
        e = "<" if fmt == "binary_little_endian" else ">"
        s = struct.Struct(e + "".join(types[t] for _, t in props))
        for v in range(nv):
            rows.append(dict(zip([p for p, _ in props], s.unpack_from(body, v * s.size))))
    byte = dict(props)["red"] in ("uchar", "uint8")
    return [tuple(r[c] / 255.0 if byte else r[c] for c in ("red", "green", "blue")) for r in rows], byte


def gltf_colours(path):
    import gltf_check
    doc, buffers = gltf_check.load(path)
    out = {}  # by the primitive's JSON path, as read_mesh names parts
    for mi, m in enumerate(doc.get("meshes", [])):
        for k, p in enumerate(m["primitives"]):
            if p.get("mode", 4) not in (4, 5, 6):
                continue  # points and lines: read_mesh names no part for them, Blender shows no face
            if "COLOR_0" not in p["attributes"]:
                return None
            a = doc["accessors"][p["attributes"]["COLOR_0"]]
            vals = gltf_check.accessor(doc, buffers, p["attributes"]["COLOR_0"])
            del a  # gltf_check.accessor decodes normalized integers to [0, 1] itself
            out["meshes[%d].primitives[%d]" % (mi, k)] = [tuple(r[:3]) for r in vals]
    return out


def snap(p, scale, offset=0.0):
    """A position rounded to a grid of 1e-5 of the mesh's size (float32 files against doubles),
    shifted by `offset` cells."""
    return tuple(round(x / scale + offset) for x in p)


# Grids shifted by a part of a cell: a coordinate on a cell boundary of one grid (float32 against the
# double on either side of it) is inside a cell of another. Boundaries are hit often, not by chance:
# the cell is 1e-5 of the mesh's extent, so coordinates written with 5 or 6 decimals in a mesh of
# extent 1 (libigl's 3holes.off: 2,655 of 7,200 faces unpaired with one grid, 885 with two) or a
# coordinate that sets the extent (draco's triangle.obj: 0.8422 / 0.7188e-5 = 117167.5) sit on them.
# The third offset is no simple fraction.
GRID_OFFSETS = (0.0, 0.5, 0.2371)


def key(P, scale, offset=0.0):
    return tuple(sorted(snap(p, scale, offset) for p in P))


def main():
    args = sys.argv[1:]
    only = args[args.index("--only") + 1] if "--only" in args else None
    max_bytes = int(args[args.index("--max-bytes") + 1]) if "--max-bytes" in args else 700000
    pos = [a for i, a in enumerate(args) if not a.startswith("--") and (i == 0 or args[i - 1] not in ("--only", "--max-bytes"))]
    bin_, src, corpus, out = pos[:4]
    blender = shutil.which("blender") or ("/usr/bin/blender" if os.path.exists("/usr/bin/blender") else None)
    if not blender:
        print("skipped: Blender not installed (blender_compare needs /usr/bin/blender or blender on PATH)")
        return 0
    os.makedirs(out, exist_ok=True)
    files = [l.split("\t")[0] for l in open(os.path.join(corpus, "MANIFEST.tsv")).read().splitlines()[1:] if l.strip()]
    files = [f for f in files if os.path.getsize(os.path.join(corpus, f)) <= max_bytes and (not only or re.search(only, f))]
    studio = os.path.join(src, "data/scenes/studio.json")
    jobs = []  # (rel, label, our output)
    for rel in files:
        path = os.path.join(corpus, rel)
        base = os.path.join(out, rel.replace("/", "_"))
        for label, cmd in (("normals", ["normals"]), ("normals --recompute --crease 30", ["normals", "--recompute", "--crease", "30"])):
            for e in (".obj", ".glb"):  # Blender 3.4's PLY importer reads no normals ("TODO import normals")
                o = base + "." + label.replace(" ", "").replace("-", "") + e
                r = subprocess.run([bin_, cmd[0], path] + cmd[1:] + ["-q", "-o", o], capture_output=True, text=True)
                if r.returncode == 0:
                    jobs.append((rel, label + " -> " + e, o, "normals"))
        for e in (".ply", ".glb", ".obj"):
            o = base + ".bake" + e
            r = subprocess.run([bin_, "bake-lighting", path, "--scene", studio, "-q", "-o", o], capture_output=True, text=True)
            if r.returncode == 0:
                jobs.append((rel, "bake-lighting -> " + e, o, "colours"))
    dump = os.path.join(out, "blender_dump.json")
    reuse = "--reuse-dump" in args and os.path.exists(dump)  # re-compare the last Blender import (harness work)
    if os.path.exists(dump) and not reuse:
        os.remove(dump)  # a dump of an earlier run must not stand in for this one
    r = subprocess.CompletedProcess([], 0, "", "") if reuse else subprocess.run(["nice", "-n", "10", blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "blender_dump.py"),
                        "--", dump] + [j[2] for j in jobs], capture_output=True, text=True, timeout=3600, env=blender_env())
    if not os.path.exists(dump):  # Blender died before writing: say how, not a bare FileNotFoundError
        print("Blender wrote no %s (exit code %d); its last lines:\n%s" % (dump, r.returncode, "\n".join((r.stdout + r.stderr).splitlines()[-20:])))
        return 2
    seen = json.load(open(dump))
    rows = []
    known = []  # differences of a class proven to be Blender's with a minimal file: recorded, not findings
    bake_linear = {}
    for rel, label, o, what in jobs:
        b = seen.get(o)
        m = re.search(r"Extension (\S+) is not available", (b or {}).get("error", ""))
        if m and m.group(1) in required_extensions(os.path.join(corpus, rel)) and m.group(1) in required_extensions(o):
            known.append((rel, label, "import", "Blender 3.4 refuses %s, which the input lists in extensionsRequired "
                          "(kept, as glTF 2.0 3.12 asks): it refuses the input too" % m.group(1)))
            print("note: %s [%s]: %s" % (rel, label, known[-1][3]))
            continue
        if b is None or "error" in b:
            rows.append((rel, label, "import", "Blender could not import it: %s" % (b or {}).get("error", "no result")))
            continue
        parts = read_mesh.read(o)
        if o.endswith(".glb"):  # Blender places each node's instance in the world: so do we
            import audit
            parts = audit.world_parts(o, parts)
        P_all = [p for q in parts for p in q["positions"]]
        if not P_all or not any(q.get("faces") for q in parts):  # a point cloud: no corner to compare
            print("note: %s [%s]: no faces in the output (a point cloud): not compared" % (rel, label))
            continue
        lo = [min(p[i] for p in P_all) for i in range(3)]
        hi = [max(p[i] for p in P_all) for i in range(3)]
        scale = max(max(h - l for h, l in zip(hi, lo)), 1e-12) * 1e-5
        polys = [{} for _ in GRID_OFFSETS]  # coincident polygons (a face and its reverse twin) share a key: all kept
        for bp in b["polygons"]:
            for g, offset in enumerate(GRID_OFFSETS):
                polys[g].setdefault(key(bp["p"], scale, offset), []).append(bp)
        colours = None
        if what == "colours":
            colours = gltf_colours(o) if o.endswith(".glb") else None
            if o.endswith(".obj"):  # `v x y z r g b`: the sRGB-encoded values, as Blender and MeshLab read them
                obj_rows = [tuple(float(x) for x in l.split()[4:7]) for l in open(o, encoding="latin-1") if l.startswith("v ") and len(l.split()) >= 7]
                colours = {"": [tuple(srgb_decode(x) for x in c) for c in obj_rows]} if obj_rows else None
            if o.endswith(".ply"):
                pc = ply_corner_colours(o)
                colours = {"": [tuple(srgb_decode(x) for x in c) if pc[1] else c for c in pc[0]]} if pc else None
        unmatched = off = total = off_zero_fan = 0
        worst = 0.0
        for pi, q in enumerate(parts):
            # positions of the corners of this part's zero-area faces: Blender 3.4's glTF importer
            # mis-shows the custom normals of the smooth fans that hold one (blender_minimal/)
            zero_fan = {snap(q["positions"][i], scale) for face in q["faces"] if zero_area([q["positions"][i] for i in face])
                        for i in face} if what == "normals" and o.endswith(".glb") else set()
            for f, face in enumerate(q["faces"]):
                P = [q["positions"][i] for i in face]
                if what == "normals" and zero_area(P):
                    continue  # Blender gives a zero-area face's corners no normal (0, 0, 0) or its neighbours
                cands = None
                for g, offset in enumerate(GRID_OFFSETS):
                    cands = cands or polys[g].get(key(P, scale, offset))
                if not cands:
                    unmatched += 1
                    continue
                if len(cands) > 1:  # twins on one key (a face and its mirror closer than the grid): those that pair every corner
                    unpaired = [corner_pairs(P, c["p"], scale).count(None) for c in cands]
                    cands = [c for c, u in zip(cands, unpaired) if u == min(unpaired)]
                if len(cands) == 1:
                    bp = cands[0]
                elif what == "normals":
                    bp = best_twin(cands, q, f, P, scale)
                else:  # coincident twins, each with its own vertices: the one whose colours are ours
                    bp = min(cands, key=lambda c: colour_gap(c, colours.get(q.get("source", q["name"])) if colours else None, face, P, scale))
                pairs = corner_pairs(P, bp["p"], scale)
                for k, i in enumerate(face):
                    j = pairs[k]
                    if j is None:
                        continue
                    if what == "normals":
                        n = read_mesh_corner_normal(q, f, k)
                        if n is None:
                            continue
                        bn = bp["n"][j]
                        ln = math.sqrt(sum(x * x for x in n))
                        if ln == 0:
                            continue
                        c = sum(a * b_ for a, b_ in zip(n, bn)) / ln
                        ang = math.degrees(math.acos(max(-1.0, min(1.0, c))))
                        total += 1
                        worst = max(worst, ang)
                        off += ang > 1.0
                        off_zero_fan += ang > 1.0 and snap(P[k], scale) in zero_fan
                    elif colours is not None and bp["c"] is not None:
                        ours = colours[q.get("source", q["name"])][i]
                        theirs = bp["c"][j]
                        d = max(abs(srgb_encode(a) - srgb_encode(b_)) for a, b_ in zip(ours, theirs)) * 255
                        total += 1
                        worst = max(worst, d)
                        off += d > 2.0
        if not b["polygons"]:  # Blender kept no polygon: drops faces with a repeated vertex, else a finding
            repeated = sum(len(set(f)) < len(f) for q in parts for f in q["faces"])
            faces = sum(len(q["faces"]) for q in parts)
            if repeated == faces:  # Blender's PLY importer drops such a polygon (mesh.validate()), its OBJ importer splits it
                known.append((rel, label, "import", "Blender kept none of our %d faces, each with a repeated vertex: its PLY "
                              "importer drops such a polygon (blender_minimal/keyhole.ply), the input's own" % faces))
                print("note: %s [%s]: %s" % (rel, label, known[-1][3]))
                continue
            rows.append((rel, label, "import", "Blender kept none of our %d faces (%d with a repeated vertex)" % (faces, repeated)))
            continue
        if what == "colours" and (colours is None or all(bp["c"] is None for bp in b["polygons"])):
            rows.append((rel, label, "colours", "colours missing: ours %s, Blender's %s" % (
                colours is not None, any(bp["c"] is not None for bp in b["polygons"]))))
        if unmatched:  # Blender's importers drop faces with a repeated vertex and merge others: a note
            print("note: %s [%s]: %d of our faces not found among Blender's polygons (not compared)" % (rel, label, unmatched))
        if off and off == off_zero_fan:  # every one at a zero-area face's vertex, in a glb: Blender's class
            known.append((rel, label, what, "%d of %d corners differ from Blender's (worst %.2f deg), every one at a vertex of a "
                          "zero-area face: Blender 3.4's glTF custom normals in such a fan (blender_minimal/zero_area_fan.gltf)" % (off, total, worst)))
            print("note: %s" % known[-1][3])
        elif off:
            unit = "deg" if what == "normals" else "/255"
            rows.append((rel, label, what, "%d of %d corners differ from Blender's (worst %.2f %s)" % (off, total, worst, unit)))
        print("%s [%s]: %d corners compared, worst %.3g %s" % (rel, label, total, worst, "deg" if what == "normals" else "/255"), flush=True)
    with open(os.path.join(out, "blender_results.tsv"), "w") as f:
        f.write("file\tcommand\tcheck\tdetail\n")
        for r in rows:
            f.write("\t".join(r) + "\n")
            print("FAIL %s [%s] %s: %s" % r)
    with open(os.path.join(out, "blender_known.tsv"), "w") as f:  # Blender's own classes, proven by a minimal file
        f.write("file\tcommand\tcheck\tdetail\n")
        for r in known:
            f.write("\t".join(r) + "\n")
    if known:
        print("blender: %d outputs differ only where Blender 3.4 is known to (blender_known.tsv)" % len(known))
    print("blender: %d outputs, %d findings" % (len(jobs), len(rows)))
    return 1 if rows else 0


def required_extensions(path):
    """The extensionsRequired of a glTF or glb file, or [] for any other file."""
    if not path.lower().endswith((".gltf", ".glb")):
        return []
    import gltf_check
    return gltf_check.load(path)[0].get("extensionsRequired", [])


def blender_env():
    """This environment without a pyenv interpreter on PATH: Debian's Blender finds its Python
    packages (numpy) through the python3 on PATH, and a pyenv one has none (No module named 'numpy')."""
    env = dict(os.environ)
    env["PATH"] = os.pathsep.join(d for d in env.get("PATH", "").split(os.pathsep) if ".pyenv" not in d)
    for k in [k for k in env if k.startswith("PYENV")]:
        del env[k]
    return env


def best_twin(cands, q, f, P, scale):
    """Of Blender's coincident polygons, the one whose corner normals agree best with ours."""
    def agree(bp):
        pairs = corner_pairs(P, bp["p"], scale)
        s = 0.0
        for k in range(len(P)):
            n = read_mesh_corner_normal(q, f, k)
            if n is not None and pairs[k] is not None:
                s += sum(a * b for a, b in zip(n, bp["n"][pairs[k]]))
        return s
    return max(cands, key=agree)


def corner_pairs(P, B, scale):
    """For each of our corners P[k], the index of Blender's corner of polygon B at its position, or
    None. Blender's importers keep a polygon's winding but may start it at another corner (the PLY
    importer rotates faces whose third or fourth index is 0), so the pairing is the cyclic rotation
    of B nearest to P (least sum of squared distances), each pair within the snap grid. Matching
    each corner alone by its snapped position pairs the wrong corner when a face has two corners
    closer than the grid (regr01.obj: corners 0.01 apart in a mesh 1,636 wide, grid 0.016) or at
    one position (spider.obj's zero-area faces), and reported those as differences."""
    n = len(P)
    if len(B) != n:  # Blender split or merged it: pair each corner with its nearest, when on the grid
        out = []
        for p in P:
            d, j = min((sum((a - b) ** 2 for a, b in zip(p, q)), j) for j, q in enumerate(B))
            out.append(j if d <= scale * scale * 3 else None)
        return out
    best = None
    for r in range(n):
        d = sum(sum((a - b) ** 2 for a, b in zip(P[k], B[(k + r) % n])) for k in range(n))
        if best is None or d < best[0]:
            best = (d, r)
    r = best[1]
    return [(k + r) % n if sum((a - b) ** 2 for a, b in zip(P[k], B[(k + r) % n])) <= scale * scale * 3 else None
            for k in range(n)]


def zero_area(P):
    s = [0.0, 0.0, 0.0]
    for k in range(1, len(P) - 1):
        a = [P[k][i] - P[0][i] for i in range(3)]
        b = [P[k + 1][i] - P[0][i] for i in range(3)]
        c = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        s = [s[i] + c[i] for i in range(3)]
    return s == [0.0, 0.0, 0.0]


def colour_gap(bp, ours, face, P, scale):
    if ours is None or bp["c"] is None:
        return 0.0
    pairs = corner_pairs(P, bp["p"], scale)
    gap = 0.0
    for k, i in enumerate(face):
        if pairs[k] is not None:
            gap += sum(abs(a - b) for a, b in zip(ours[i], bp["c"][pairs[k]]))
    return gap


def read_mesh_corner_normal(part, f, k):
    if part["corner_normals"] is not None:
        return part["corner_normals"][f][k]
    if part["vertex_normals"] is not None:
        return part["vertex_normals"][part["faces"][f][k]]
    if part["face_normals"] is not None:
        return part["face_normals"][f]
    return None


if __name__ == "__main__":
    sys.exit(main())
