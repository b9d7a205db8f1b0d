#!/usr/bin/env python3
"""gltf_check.py: reads glTF files independently of shadetool (its own GLB/JSON/accessor decoder)
and checks what a shadetool output must keep from its input.

  gltf_check.py keep IN OUT [--changed ATTR,...]
      every top-level part but buffers/bufferViews/accessors/images is equal as JSON (meshes
      compared without their accessor indices); images' bytes are equal; every attribute of every
      primitive not in --changed decodes to the same values (TRIANGLES/strip/fan: per corner, so
      that split vertices and new index lists compare equal).
  gltf_check.py dump FILE MESH PRIM ATTR
      prints the decoded attribute as JSON (per vertex), for shell tests.
"""
import urllib.parse
import base64
import json
import math
import os
import struct
import sys

CT = {5120: ("b", 1), 5121: ("B", 1), 5122: ("h", 2), 5123: ("H", 2), 5125: ("I", 4), 5126: ("f", 4)}
NC = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def load(path):
    data = open(path, "rb").read()
    bin_chunk = None
    if data[:4] == b"glTF":
        jlen = struct.unpack_from("<I", data, 12)[0]
        doc = json.loads(data[20:20 + jlen])
        if len(data) > 20 + jlen:
            blen = struct.unpack_from("<I", data, 20 + jlen)[0]
            bin_chunk = data[28 + jlen:28 + jlen + blen]
    else:
        doc = json.loads(data)
    buffers = []
    for b in doc.get("buffers", []):
        uri = b.get("uri")
        if uri is None:
            buffers.append(bin_chunk)
        elif uri.startswith("data:"):
            buffers.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            buffers.append(open(os.path.join(os.path.dirname(path), urllib.parse.unquote(uri)), "rb").read())
    return doc, buffers


def view_bytes(doc, buffers, v):
    bv = doc["bufferViews"][v]
    off = bv.get("byteOffset", 0)
    return buffers[bv["buffer"]][off:off + bv["byteLength"]], bv.get("byteStride", 0)


def accessor(doc, buffers, i):
    a = doc["accessors"][i]
    fmt, size = CT[a["componentType"]]
    n = NC[a["type"]]
    count = a["count"]
    out = [[0.0] * n for _ in range(count)]
    if "bufferView" in a:
        data, stride = view_bytes(doc, buffers, a["bufferView"])
        stride = stride or size * n
        off = a.get("byteOffset", 0)
        for k in range(count):
            out[k] = list(struct.unpack_from("<%d%s" % (n, fmt), data, off + k * stride))
    if "sparse" in a:
        s = a["sparse"]
        ifmt, isz = CT[s["indices"]["componentType"]]
        idata, _ = view_bytes(doc, buffers, s["indices"]["bufferView"])
        vdata, _ = view_bytes(doc, buffers, s["values"]["bufferView"])
        for k in range(s["count"]):
            j = struct.unpack_from("<" + ifmt, idata, s["indices"].get("byteOffset", 0) + k * isz)[0]
            out[j] = list(struct.unpack_from("<%d%s" % (n, fmt), vdata, s["values"].get("byteOffset", 0) + k * size * n))
    if a.get("normalized"):
        div = {"b": 127.0, "B": 255.0, "h": 32767.0, "H": 65535.0}[fmt]
        out = [[max(x / div, -1.0) for x in row] for row in out]
    return out


def corners(doc, buffers, prim):
    """Vertex index of every triangle corner (strips and fans unrolled)."""
    count = doc["accessors"][prim["attributes"]["POSITION"]]["count"]
    idx = [r[0] for r in accessor(doc, buffers, prim["indices"])] if "indices" in prim else list(range(count))
    mode = prim.get("mode", 4)
    if mode == 4:
        return [int(i) for i in idx]
    out = []
    for i in range(len(idx) - 2):
        if mode == 5:
            out += [idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]]
        else:
            out += [idx[i + 1], idx[i + 2], idx[0]]
    return [int(i) for i in out]


def image_bytes(doc, buffers, path, k):
    im = doc["images"][k]
    if "bufferView" in im:
        return view_bytes(doc, buffers, im["bufferView"])[0]
    uri = im["uri"]
    if uri.startswith("data:"):
        return base64.b64decode(uri.split(",", 1)[1])
    return open(os.path.join(os.path.dirname(path), urllib.parse.unquote(uri)), "rb").read()


def strip_refs(mesh):
    m = json.loads(json.dumps(mesh))
    for p in m.get("primitives", []):
        p["attributes"] = sorted(p["attributes"].keys())
        p.pop("indices", None)
        p.pop("mode", None)
        p["targets"] = [sorted(t.keys()) for t in p.get("targets", [])]
    return m


def resolved(doc, bufs, key):
    """doc[key] with every accessor index replaced by the accessor's values (skins' inverse bind
    matrices, animation samplers) and every bufferView index of EXT_structural_metadata's property
    tables by the view's bytes: a writer may renumber accessors and views, not change what they hold."""
    v = json.loads(json.dumps(doc.get(key)))
    if key == "skins":
        for s in v or []:
            if "inverseBindMatrices" in s:
                s["inverseBindMatrices"] = accessor(doc, bufs, s["inverseBindMatrices"])
    if key == "animations":
        for a in v or []:
            for s in a.get("samplers", []):
                for k in ("input", "output"):
                    if k in s:
                        s[k] = accessor(doc, bufs, s[k])
    if key == "extensions":  # EXT_structural_metadata's property tables name bufferViews
        for t in ((v or {}).get("EXT_structural_metadata") or {}).get("propertyTables", []):
            for prop in t.get("properties", {}).values():
                for k in ("values", "arrayOffsets", "stringOffsets"):
                    if k in prop:
                        bv = doc["bufferViews"][prop[k]]
                        o = bv.get("byteOffset", 0)
                        prop[k] = bufs[bv["buffer"]][o:o + bv["byteLength"]].hex()
    return v


def keep(inp, outp, changed):
    di, bi = load(inp)
    do, bo = load(outp)
    problems = []
    for key in set(di) | set(do):
        if key in ("buffers", "bufferViews", "accessors", "images", "meshes"):
            continue
        if resolved(di, bi, key) != resolved(do, bo, key):
            problems.append("top-level '%s' differs" % key)
    for k in range(len(di.get("images", []))):
        if image_bytes(di, bi, inp, k) != image_bytes(do, bo, outp, k):
            problems.append("images[%d] bytes differ" % k)
    if len(di.get("meshes", [])) != len(do.get("meshes", [])):
        problems.append("%d meshes, %d written" % (len(di.get("meshes", [])), len(do.get("meshes", []))))
    for m, (mi, mo) in enumerate(zip(di.get("meshes", []), do.get("meshes", []))):
        si, so = strip_refs(mi), strip_refs(mo)
        for p, (pi, po) in enumerate(zip(mi["primitives"], mo["primitives"])):
            for attr in pi["attributes"]:
                if attr in changed:
                    continue
                if attr not in po["attributes"]:
                    problems.append("meshes[%d].primitives[%d]: %s missing" % (m, p, attr))
                    continue
                if pi.get("mode", 4) not in (4, 5, 6):
                    same = accessor(di, bi, pi["attributes"][attr]) == accessor(do, bo, po["attributes"][attr])
                else:
                    ci, co = corners(di, bi, pi), corners(do, bo, po)
                    vi, vo = accessor(di, bi, pi["attributes"][attr]), accessor(do, bo, po["attributes"][attr])
                    # Per corner, as sets of triangles (a mirror re-winds them).
                    ti = sorted(tuple(sorted(tuple(vi[c]) for c in ci[t:t + 3])) for t in range(0, len(ci), 3))
                    to = sorted(tuple(sorted(tuple(vo[c]) for c in co[t:t + 3])) for t in range(0, len(co), 3))
                    same = ti == to
                if not same:
                    problems.append("meshes[%d].primitives[%d].attributes.%s values differ" % (m, p, attr))
            for attr in ("material",):
                if pi.get(attr) != po.get(attr):
                    problems.append("meshes[%d].primitives[%d].%s differs" % (m, p, attr))
        for p in si.get("primitives", []):
            p["attributes"] = [a for a in p["attributes"] if a not in changed]
            p["targets"] = [[a for a in t if a not in changed] for t in p["targets"]]
        for p in so.get("primitives", []):
            p["attributes"] = [a for a in p["attributes"] if a not in changed]
            p["targets"] = [[a for a in t if a not in changed] for t in p["targets"]]
        if si != so:
            problems.append("meshes[%d] differs beyond its accessors: %s vs %s" % (m, json.dumps(si), json.dumps(so)))
    for p in problems:
        print("%s -> %s: %s" % (inp, outp, p))
    return 1 if problems else 0


def main():
    if sys.argv[1] == "keep":
        changed = sys.argv[5].split(",") if len(sys.argv) > 5 and sys.argv[4] == "--changed" else []
        sys.exit(keep(sys.argv[2], sys.argv[3], changed))
    if sys.argv[1] == "dump":
        doc, bufs = load(sys.argv[2])
        prim = doc["meshes"][int(sys.argv[3])]["primitives"][int(sys.argv[4])]
        what = sys.argv[5]
        if what == "corners":
            print(json.dumps(corners(doc, bufs, prim)))
        elif what.startswith("targets."):
            _, t, attr = what.split(".")
            print(json.dumps(accessor(doc, bufs, prim["targets"][int(t)][attr])))
        else:
            print(json.dumps(accessor(doc, bufs, prim["attributes"][what])))


if __name__ == "__main__":
    main()
