#!/usr/bin/env python3
"""compare_flat.py GLTF FLAT.ply KIND TOL [POINT.ply]: the per-vertex values a glTF output holds
(COLOR_0 of every triangle primitive, concatenated in the order of gltf/gltf_scene.h's world mesh:
scene order, depth first, each mesh's primitives in order; every mesh of the fixture is shown by
exactly one node) against those of the flattened mesh's output (an ASCII PLY: KIND colour = its
red green blue, KIND quality = its quality property as a grey). Both are clamped to [0, 1] (glTF's
COLOR_0 range). Prints the largest and the mean absolute difference; fails above TOL.
With POINT.ply (the flattened mesh's point-sampled output), also fails unless the mean difference
glTF - flat is below a quarter of the mean difference fit - point: the tolerance is then tighter
than the effect of the fit itself, so it could not pass with the point values or another fit.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_check  # noqa: E402  (the independent glTF decoder of tests/gltf)


def gltf_values(path):
    doc, bufs = gltf_check.load(path)
    out = []
    order = []
    for n in doc["scenes"][doc.get("scene", 0)]["nodes"]:
        stack = [n]
        while stack:
            k = stack.pop(0)
            node = doc["nodes"][k]
            if "mesh" in node:
                order.append(node["mesh"])
            stack[0:0] = node.get("children", [])
    for m in order:
        for prim in doc["meshes"][m]["primitives"]:
            if prim.get("mode", 4) != 4:
                continue
            rows = gltf_check.accessor(doc, bufs, prim["attributes"]["COLOR_0"])
            out += [[min(max(x, 0.0), 1.0) for x in r[:3]] for r in rows]
    return out


def ply_values(path, kind):
    lines = open(path).read().split("\n")
    props, types, count, k = [], [], 0, 0
    while lines[k] != "end_header":
        w = lines[k].split()
        if w[:2] == ["element", "vertex"]:
            count = int(w[2])
            props = []
        elif w[:1] == ["property"] and w[1] != "list" and count and not props_done(lines, k):
            props.append(w[2])
            types.append(w[1])
        k += 1
    rows = [list(map(float, lines[k + 1 + i].split())) for i in range(count)]
    if kind == "quality":
        q = props.index("quality")
        return [[min(max(r[q], 0.0), 1.0)] * 3 for r in rows]
    idx = [props.index(c) for c in ("red", "green", "blue")]
    scale = [255.0 if types[i] in ("uchar", "uint8") else 1.0 for i in idx]  # 8-bit: linear bytes (--linear)
    return [[min(max(r[i] / s, 0.0), 1.0) for i, s in zip(idx, scale)] for r in rows]


def props_done(lines, k):
    # True once a later element (face) has started before line k.
    for j in range(k, 0, -1):
        w = lines[j].split()
        if w[:1] == ["element"]:
            return w[1] != "vertex"
    return False


def main():
    gltf, flat, kind, tol = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    a, b = gltf_values(gltf), ply_values(flat, kind)
    if len(a) != len(b):
        print("vertex counts differ: glTF %d, flattened %d" % (len(a), len(b)))
        return 1
    d = [abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb)]
    worst, mean = max(d), sum(d) / len(d)
    print("%d vertices: max |glTF - flattened| %.3g, mean %.3g (tolerance %g)" % (len(a), worst, mean, tol))
    ok = worst <= tol
    if len(sys.argv) > 5:
        p = ply_values(sys.argv[5], kind)
        effect = sum(abs(x - y) for ra, rb in zip(b, p) for x, y in zip(ra, rb)) / len(d)
        print("mean |fit - point| on the flattened mesh %.3g" % effect)
        ok = ok and mean < 0.25 * effect
    return 0 if ok else 1


sys.exit(main())
