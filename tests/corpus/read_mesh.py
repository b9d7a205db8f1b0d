"""read_mesh.py: a small reader of OBJ, PLY, OFF, STL and glTF, independent of shadetool, for the
corpus test (tests/corpus.sh). It reads what the checks need, nothing more:

  parts      a list of primitives (one for every format but glTF, one per mesh primitive there,
             named by its JSON path); each a dict with
               positions       [(x, y, z)]                  per vertex
               faces           [(i, j, k, ...)]             vertex indices (glTF strips/fans unrolled)
               vertex_normals  [(x, y, z)] or None          OBJ has none; PLY nx ny nz; glTF NORMAL
               corner_normals  [[(x, y, z) or None]] or None per face, per corner (OBJ vn)
               face_normals    [(x, y, z)] or None          STL facets, PLY face nx ny nz
               attributes      set of names: "normals", "colors", "texcoords", "quality"
Pure Python (no numpy): slow on big files but only a few MB each.
"""
import json
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "gltf"))
import gltf_check  # noqa: E402  (the glTF tests' independent accessor decoder)


def part(positions, faces, vertex_normals=None, corner_normals=None, face_normals=None, attributes=None, name=""):
    return {"name": name, "positions": positions, "faces": faces, "vertex_normals": vertex_normals,
            "corner_normals": corner_normals, "face_normals": face_normals, "attributes": set(attributes or ())}


def read_obj(path):
    V, N, T, F, FN = [], [], 0, [], []
    colors = False
    with open(path, "rb") as f:
        for raw in f:
            t = raw.split()
            if not t:
                continue
            if t[0] == b"v":
                V.append(tuple(float(x) for x in t[1:4]))
                colors = colors or len(t) >= 7
            elif t[0] == b"vn":
                N.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == b"vt":
                T += 1
            elif t[0] == b"f":
                face, normals = [], []
                for c in t[1:]:
                    s = c.split(b"/")
                    i = int(s[0])
                    face.append(i - 1 if i > 0 else len(V) + i)
                    n = int(s[2]) if len(s) > 2 and s[2] else 0
                    n = n - 1 if n > 0 else len(N) + n if n < 0 else -1
                    normals.append(N[n] if 0 <= n < len(N) else None)  # a dangling index: no normal
                F.append(tuple(face))
                FN.append(normals)
    attrs = set()
    if any(n is not None for fn in FN for n in fn):
        attrs.add("normals")
    if T:
        attrs.add("texcoords")
    if colors:
        attrs.add("colors")
    return [part(V, F, corner_normals=FN if "normals" in attrs else None, attributes=attrs)]


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def fmt_is_ascii(header):
    return b"format ascii" in header


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header")
    header = data[:end].decode("latin-1").splitlines()
    if data[:4] == b"ply\r" and data[4:5] not in (b"\n", b"\r"):  # header lines end in a lone CR (Rhino 6)
        body = data[end + len(b"end_header\r"):]
        if fmt_is_ascii(data[:end]):
            body = body.replace(b"\r", b"\n")
    else:
        body = data[data.index(b"\n", end) + 1:]
    fmt = None
    elements = []
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            elements.append((t[1], int(t[2]), []))
        elif t[0] == "property":
            if t[1] == "list":
                elements[-1][2].append((t[4], PLY_TYPES[t[2]], PLY_TYPES[t[3]]))
            else:
                elements[-1][2].append((t[2], None, PLY_TYPES[t[1]]))
    rows = {}
    if fmt == "ascii":
        tokens = body.split()
        pos = 0
        for name, count, props in elements:
            out = []
            for _ in range(count):
                row = {}
                for pname, ltype, vtype in props:
                    if ltype:
                        n = int(tokens[pos]); pos += 1
                        conv = float if vtype in "fd" else int
                        row[pname] = [conv(x) for x in tokens[pos:pos + n]]; pos += n
                    else:
                        row[pname] = float(tokens[pos]) if vtype in "fd" else int(tokens[pos]); pos += 1
                out.append(row)
            rows[name] = out
    else:
        e = "<" if fmt == "binary_little_endian" else ">"
        pos = 0
        for name, count, props in elements:
            out = []
            simple = all(l is None for _, l, _ in props)
            if simple:
                s = struct.Struct(e + "".join(v for _, _, v in props))
                names = [p for p, _, _ in props]
                for k in range(count):
                    out.append(dict(zip(names, s.unpack_from(body, pos))))
                    pos += s.size
            else:
                for _ in range(count):
                    row = {}
                    for pname, ltype, vtype in props:
                        if ltype:
                            n = struct.unpack_from(e + ltype, body, pos)[0]; pos += struct.calcsize(ltype)
                            row[pname] = list(struct.unpack_from(e + vtype * n, body, pos)); pos += struct.calcsize(vtype) * n
                        else:
                            row[pname] = struct.unpack_from(e + vtype, body, pos)[0]; pos += struct.calcsize(vtype)
                    out.append(row)
            rows[name] = out
    verts = rows.get("vertex", [])
    V = [(r["x"], r["y"], r["z"]) for r in verts]
    attrs = set()
    vn = None
    if verts and "nx" in verts[0]:
        vn = [(r["nx"], r["ny"], r["nz"]) for r in verts]
        attrs.add("normals")
    if verts and ("red" in verts[0] or "r" in verts[0]):
        attrs.add("colors")
    if verts and any(k in verts[0] for k in ("s", "u", "texture_u", "texture_s")):
        attrs.add("texcoords")
    if verts and "quality" in verts[0]:
        attrs.add("quality")
    F, fnormals = [], None
    for r in rows.get("face", []):
        F.append(tuple(r.get("vertex_indices", r.get("vertex_index", []))))
    faces = rows.get("face", [])
    if faces and "nx" in faces[0]:
        fnormals = [(r["nx"], r["ny"], r["nz"]) for r in faces]
        attrs.add("normals")
    if faces and ("red" in faces[0]):
        attrs.add("colors")
    if faces and any(k in faces[0] for k in ("texcoord", "texcoords")):
        attrs.add("texcoords")
    for r in rows.get("tristrips", []):  # -1 restarts; alternate winding
        strip = []
        for i in r.get("vertex_indices", []):
            if i < 0:
                strip = []
                continue
            strip.append(i)
            if len(strip) >= 3:
                a, b, c = strip[-3:]
                if (len(strip) - 3) % 2:
                    a, b = b, a
                if len({a, b, c}) == 3:
                    F.append((a, b, c))
    return [part(V, F, vertex_normals=vn, face_normals=fnormals, attributes=attrs)]


def read_off(path):
    lines = []
    for line in open(path, "rb"):
        t = line.split(b"#")[0].split()
        if t:
            lines.append(t)
    head = lines[0][0].decode()
    counts = lines[0][1:] if len(lines[0]) > 1 else lines[1]
    pos = 1 if len(lines[0]) > 1 else 2
    nv, nf = int(counts[0]), int(counts[1])
    V, vn, colors = [], [] if "N" in head else None, "C" in head
    for k in range(nv):
        row = [float(x) for x in lines[pos + k]]
        V.append(tuple(row[:3]))
        if vn is not None:
            vn.append(tuple(row[3:6]))
    pos += nv
    F = []
    for k in range(nf):
        t = list(lines[pos])
        pos += 1
        n = int(t[0])
        while len(t) < 1 + n:  # indices going on over the next lines (OFF is free-format; libigl-tutorial-data)
            t += lines[pos]
            pos += 1
        F.append(tuple(int(x) for x in t[1:1 + n]))
        colors = colors or len(t) > 1 + n  # a face colour after the indices
    attrs = {"normals"} if vn is not None else set()
    if colors:
        attrs.add("colors")
    return [part(V, F, vertex_normals=vn, attributes=attrs)]


def read_stl(path):
    data = open(path, "rb").read()
    V, F, FN = [], [], []
    binary = len(data) >= 84 and 84 + 50 * struct.unpack_from("<I", data, 80)[0] == len(data)
    if binary:
        n = struct.unpack_from("<I", data, 80)[0]
        for k in range(n):
            vals = struct.unpack_from("<12f", data, 84 + 50 * k)
            FN.append(vals[0:3])
            base = len(V)
            V += [vals[3:6], vals[6:9], vals[9:12]]
            F.append((base, base + 1, base + 2))
    else:
        normal = None
        corners = []
        for line in data.decode("latin-1").splitlines():
            t = line.split()
            if not t:
                continue
            if t[0] == "facet":
                normal = tuple(float(x) for x in t[2:5])
                corners = []
            elif t[0] == "vertex":
                corners.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == "endfacet":
                base = len(V)
                V += corners
                F.append(tuple(range(base, base + len(corners))))
                FN.append(normal)
    return [part(V, F, face_normals=FN, attributes={"normals"})]


def read_gltf(path):
    doc, buffers = gltf_check.load(path)
    parts = []
    for m, mesh in enumerate(doc.get("meshes", [])):
        for p, prim in enumerate(mesh.get("primitives", [])):
            name = "meshes[%d].primitives[%d]" % (m, p)
            attrs_in = prim.get("attributes", {})
            if prim.get("mode", 4) not in (4, 5, 6) or "POSITION" not in attrs_in:
                parts.append(part([], [], name=name))
                continue
            V = [tuple(r) for r in gltf_check.accessor(doc, buffers, attrs_in["POSITION"])]
            c = gltf_check.corners(doc, buffers, prim)
            F = [tuple(c[i:i + 3]) for i in range(0, len(c) - 2, 3)]
            vn = [tuple(r) for r in gltf_check.accessor(doc, buffers, attrs_in["NORMAL"])] if "NORMAL" in attrs_in else None
            attrs = set()
            if vn is not None:
                attrs.add("normals")
            if any(a.startswith("COLOR_") for a in attrs_in):
                attrs.add("colors")
            if any(a.startswith("TEXCOORD_") for a in attrs_in):
                attrs.add("texcoords")
            parts.append(part(V, F, vertex_normals=vn, attributes=attrs, name=name))
    return parts


def gltf_unreferenced(path):
    """Vertices of the POSITION accessors that no primitive's faces use (primitives sharing an
    accessor counted together), as the file holds them."""
    doc, buffers = gltf_check.load(path)
    used = {}
    for mesh in doc.get("meshes", []):
        for prim in mesh.get("primitives", []):
            a = prim.get("attributes", {}).get("POSITION")
            if a is None or prim.get("mode", 4) not in (4, 5, 6):
                continue
            used.setdefault(a, set()).update(gltf_check.corners(doc, buffers, prim))
    return sum(doc["accessors"][a]["count"] - len(u) for a, u in used.items())


def unreferenced(parts):
    """Vertices no face uses; a record of fewer than 3 vertices (`f 8 7`) is no face: the readers
    skip it with a note, so its vertices count as unused (tinyobjloader's invalid-face-definition.obj)."""
    return sum(len(p["positions"]) - len({i for f in p["faces"] if len(f) >= 3 for i in f}) for p in parts)


def read(path):
    ext = os.path.splitext(path)[1].lower()
    return {".obj": read_obj, ".ply": read_ply, ".off": read_off, ".stl": read_stl, ".gltf": read_gltf,
            ".glb": read_gltf}[ext](path)


if __name__ == "__main__":
    for p in read(sys.argv[1]):
        print(p["name"], len(p["positions"]), len(p["faces"]), sorted(p["attributes"]))
