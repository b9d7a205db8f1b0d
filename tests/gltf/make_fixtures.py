#!/usr/bin/env python3
"""make_fixtures.py OUTDIR: glTF 2.0 test files written by hand (not by shadetool's writer).

rich.gltf (+ rich.bin, checker.png) and rich.glb hold, on purpose, what a writer must keep:
  mesh 0: a cube of 24 vertices, UNSIGNED_BYTE indices, NORMAL, TEXCOORD_0, TANGENT,
          COLOR_0 (normalised UNSIGNED_BYTE VEC4), JOINTS_0/WEIGHTS_0 (a skin), one morph target
          (POSITION and NORMAL deltas), material with a PNG texture, extras
  mesh 1: a TRIANGLE_STRIP of 6 vertices (no NORMAL), UNSIGNED_SHORT indices, interleaved POSITION+TEXCOORD_0
          (byteStride 20), plus a LINES primitive that must pass through untouched
  mesh 2: a TRIANGLE_FAN whose POSITION is a sparse accessor (base + 2 substituted vertices)
  mesh 3: KHR_mesh_quantization: normalised SHORT positions, a node scale undoing it
  nodes with TRS and a matrix, a camera, KHR_lights_punctual (directional + point), an
  animation, extensionsUsed, asset extras.
bad_*.gltf: one defect each (the name says which), for the bad-input test.
"""
import base64
import json
import math
import os
import struct
import sys
import zlib


def png_bytes():
    # A 2x2 RGB PNG written by hand (zlib-compressed scanlines), so its bytes are known exactly.
    raw = b"".join(b"\x00" + bytes(row) for row in ([255, 0, 0, 0, 255, 0], [0, 0, 255, 255, 255, 255]))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.views = []
        self.accessors = []

    def view(self, data, stride=None, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        v = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            v["byteStride"] = stride
        if target:
            v["target"] = target
        self.bin += data
        self.views.append(v)
        return len(self.views) - 1

    def accessor(self, view, ctype, count, type_, offset=0, normalized=False, minmax=None, sparse=None):
        a = {"componentType": ctype, "count": count, "type": type_}
        if view is not None:
            a["bufferView"] = view
        if offset:
            a["byteOffset"] = offset
        if normalized:
            a["normalized"] = True
        if minmax:
            a["min"], a["max"] = minmax
        if sparse:
            a["sparse"] = sparse
        self.accessors.append(a)
        return len(self.accessors) - 1

    def floats(self, rows, type_, minmax=False, target=34962):
        flat = [x for r in rows for x in r]
        v = self.view(struct.pack("<%df" % len(flat), *flat), target=target)
        mm = None
        if minmax:
            n = len(rows[0])
            mm = ([min(r[k] for r in rows) for k in range(n)], [max(r[k] for r in rows) for k in range(n)])
        return self.accessor(v, 5126, len(rows), type_, minmax=mm)


def cube():
    # 24 vertices (4 per face, face-planar), 12 triangles, counter-clockwise seen from outside.
    faces = [((1, 0, 0), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1)), ((0, 1, 0), (0, 0, 1)),
             ((0, -1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 0)), ((0, 0, -1), (0, 1, 0))]
    pos, nor, uv, tan, idx = [], [], [], [], []
    for n, u in faces:
        v = (n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0])
        base = len(pos)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            pos.append(tuple(n[k] + su * u[k] + sv * v[k] for k in range(3)))
            nor.append(n)
            uv.append(((su + 1) / 2, (sv + 1) / 2))
            tan.append((u[0], u[1], u[2], 1.0))
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nor, uv, tan, idx


def build(png):
    b = Builder()
    pos, nor, uv, tan, idx = cube()
    a_pos = b.floats(pos, "VEC3", minmax=True)
    a_nor = b.floats(nor, "VEC3")
    a_uv = b.floats(uv, "VEC2")
    a_tan = b.floats(tan, "VEC4")
    colors = bytes(c for i in range(24) for c in (i * 10, 255 - i * 10, 128, 255))
    a_col = b.accessor(b.view(colors, target=34962), 5121, 24, "VEC4", normalized=True)
    a_joint = b.accessor(b.view(bytes([0, 1, 0, 0] * 24), target=34962), 5121, 24, "VEC4")
    a_weight = b.floats([(0.75, 0.25, 0, 0)] * 24, "VEC4")
    a_idx = b.accessor(b.view(bytes(idx), target=34963), 5121, len(idx), "SCALAR")
    # Morph target: the +z face pushed out by 0.5 (its NORMAL deltas stay zero: a translation).
    dpos = [(0, 0, 0.5) if p[2] > 0.99 else (0, 0, 0) for p in pos]
    a_dpos = b.floats(dpos, "VEC3", minmax=True)
    a_dnor = b.floats([(0, 0, 0)] * 24, "VEC3")
    ibm = b.floats([(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)] * 2, "MAT4", target=None)

    # Strip, interleaved: x y z u v (20 bytes).
    strip = [(i // 2, i % 2, 0, i / 5, i % 2) for i in range(6)]
    inter = b.view(b"".join(struct.pack("<5f", *r) for r in strip), stride=20, target=34962)
    a_spos = b.accessor(inter, 5126, 6, "VEC3", minmax=([0, 0, 0], [2, 1, 0]))
    a_suv = b.accessor(inter, 5126, 6, "VEC2", offset=12)
    a_sidx = b.accessor(b.view(struct.pack("<6H", 0, 1, 2, 3, 4, 5), target=34963), 5123, 6, "SCALAR")
    a_lidx = b.accessor(b.view(struct.pack("<4H", 0, 1, 1, 2), target=34963), 5123, 4, "SCALAR")

    # Fan with a sparse POSITION: base is a flat hexagon, vertices 1 and 4 lifted by substitution.
    hexagon = [(0, 0, 0)] + [(math.cos(k * math.pi / 3), math.sin(k * math.pi / 3), 0) for k in range(6)] + [(1, 0, 0)]
    base_view = b.view(b"".join(struct.pack("<3f", *p) for p in hexagon), target=34962)
    sp_idx = b.view(struct.pack("<2I", 1, 4))
    lifted = [hexagon[1][:2] + (0.25,), hexagon[4][:2] + (0.25,)]
    sp_val = b.view(b"".join(struct.pack("<3f", *p) for p in lifted))
    a_fan = b.accessor(base_view, 5126, 8, "VEC3", minmax=([-1, -math.sin(math.pi / 3), 0], [1, math.sin(math.pi / 3), 0.25]),
                       sparse={"count": 2, "indices": {"bufferView": sp_idx, "componentType": 5125},
                               "values": {"bufferView": sp_val}})

    # Quantized: normalised SHORT VEC3 (8-byte stride for alignment), a tetrahedron.
    tet = [(0, 0, 0), (32767, 0, 0), (0, 32767, 0), (0, 0, 32767)]
    q_view = b.view(b"".join(struct.pack("<3hxx", *p) for p in tet), stride=8, target=34962)
    a_q = b.accessor(q_view, 5122, 4, "VEC3", normalized=True, minmax=([0, 0, 0], [32767, 32767, 32767]))
    a_qidx = b.accessor(b.view(struct.pack("<12H", 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3), target=34963), 5123, 12, "SCALAR")

    # Animation: node 2 translation, two keys.
    a_time = b.floats([(0,), (1,)], "SCALAR", minmax=True, target=None)
    a_tr = b.floats([(0, 0, 0), (0, 1, 0)], "VEC3", target=None)

    png_view = None
    doc = {
        "asset": {"version": "2.0", "generator": "shadetool tests/gltf/make_fixtures.py", "extras": {"keep": "me"}},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_mesh_quantization", "KHR_materials_emissive_strength"],
        "extensionsRequired": ["KHR_mesh_quantization"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "color": [1, 1, 1], "intensity": 2},
            {"type": "point", "color": [1, 0.5, 0.25], "intensity": 10, "range": 100}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3, 4, 5, 6, 7]}],
        "nodes": [
            {"name": "cube", "mesh": 0, "skin": 0, "translation": [0, 0, 0], "extras": {"id": 7}},
            {"name": "strip", "mesh": 1, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1]},
            {"name": "fan", "mesh": 2, "rotation": [0, 0, 0.7071068, 0.7071068]},
            {"name": "quantized", "mesh": 3, "scale": [2, 2, 2]},
            {"name": "camera", "camera": 0, "translation": [0, 0, 10]},
            {"name": "sun", "rotation": [-0.3826834, 0, 0, 0.9238795],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "lamp", "translation": [0, 4, 0], "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"name": "joint", "children": [8]},
            {"name": "joint child"},
        ],
        "skins": [{"joints": [7, 8], "inverseBindMatrices": ibm}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
        "meshes": [
            {"name": "cube", "weights": [0.0], "extras": {"targetNames": ["push"]}, "primitives": [{
                "attributes": {"POSITION": a_pos, "NORMAL": a_nor, "TEXCOORD_0": a_uv, "TANGENT": a_tan, "COLOR_0": a_col,
                               "JOINTS_0": a_joint, "WEIGHTS_0": a_weight},
                "indices": a_idx, "material": 0, "targets": [{"POSITION": a_dpos, "NORMAL": a_dnor}]}]},
            {"name": "strip", "primitives": [
                {"attributes": {"POSITION": a_spos, "TEXCOORD_0": a_suv}, "indices": a_sidx, "mode": 5},
                {"attributes": {"POSITION": a_spos}, "indices": a_lidx, "mode": 1}]},
            {"name": "fan", "primitives": [{"attributes": {"POSITION": a_fan}, "mode": 6}]},
            {"name": "quantized", "primitives": [{"attributes": {"POSITION": a_q}, "indices": a_qidx}]},
        ],
        "materials": [{"name": "checker", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                                  "baseColorFactor": [0.8, 0.7, 0.6, 1]},
                       "emissiveFactor": [0.1, 0, 0],
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],
        "images": [{"uri": "checker.png"}],
        "animations": [{"channels": [{"sampler": 0, "target": {"node": 2, "path": "translation"}}],
                        "samplers": [{"input": a_time, "output": a_tr}]}],
        "accessors": b.accessors,
        "bufferViews": b.views,
    }
    return doc, b


def write_gltf(path, doc, binary_data):
    doc = json.loads(json.dumps(doc))
    doc["buffers"] = [{"uri": os.path.basename(path)[:-5] + ".bin", "byteLength": len(binary_data)}]
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
    with open(path[:-5] + ".bin", "wb") as f:
        f.write(binary_data)


def write_glb(path, doc, binary_data, png):
    doc = json.loads(json.dumps(doc))
    data = bytearray(binary_data)
    while len(data) % 4:
        data.append(0)
    doc["bufferViews"].append({"buffer": 0, "byteOffset": len(data), "byteLength": len(png)})
    doc["images"] = [{"bufferView": len(doc["bufferViews"]) - 1, "mimeType": "image/png"}]
    data += png
    while len(data) % 4:
        data.append(0)
    doc["buffers"] = [{"byteLength": len(data)}]
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(data))
    out += struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + bytes(data)
    with open(path, "wb") as f:
        f.write(out)


def small_fixtures(out):
    """Files with nothing for a step to do, and bounds a writer must keep exact (issue 27, 15-16)."""
    def embedded(b, doc, name):
        doc["buffers"] = [{"uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(b.bin)).decode(),
                           "byteLength": len(b.bin)}]
        doc["bufferViews"], doc["accessors"] = b.views, b.accessors
        with open(os.path.join(out, name), "w") as f:
            json.dump(doc, f)
    # Only POINTS and LINES primitives.
    b = Builder()
    p = b.floats([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], "VEC3", minmax=True)
    embedded(b, {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                 "meshes": [{"primitives": [{"attributes": {"POSITION": p}, "mode": 0},
                                            {"attributes": {"POSITION": p}, "mode": 1}]}]}, "points_lines.gltf")
    # A scene without nodes (and no mesh).
    with open(os.path.join(out, "no_nodes.gltf"), "w") as f:
        json.dump({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"name": "empty"}]}, f)
    # Two triangles and a vertex no face uses, whose TEXCOORD_0 (1, 1) is the only one at the
    # maximum: min/max as the input states them are exact for the input, not for an output that
    # drops that vertex. NORMAL with a min/max that does not hold.
    b = Builder()
    p = b.floats([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (5, 5, 5)], "VEC3", minmax=True)
    t = b.floats([(0, 0), (0.5, 0), (0, 0.5), (0.5, 0.5), (1, 1)], "VEC2", minmax=True)
    n = b.floats([(0, 0, 1)] * 5, "VEC3")
    b.accessors[n]["min"], b.accessors[n]["max"] = [0, 0, 0.5], [0, 0, 1.5]
    i = b.accessor(b.view(struct.pack("<6H", 0, 1, 2, 2, 1, 3), target=34963), 5123, 6, "SCALAR")
    embedded(b, {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                 "meshes": [{"primitives": [{"attributes": {"POSITION": p, "TEXCOORD_0": t, "NORMAL": n},
                                             "indices": i}]}]}, "bounds.gltf")
    # A triangle primitive without POSITION beside one with it (magnum-plugins' GltfImporter test
    # files have such; glTF 2.0 3.7.2.1: valid, nothing to draw; the validator warns
    # MESH_PRIMITIVE_NO_POSITION): the other primitive is read, this one is left as it is.
    b = Builder()
    p = b.floats([(0, 0, 0), (1, 0, 0), (0, 1, 0)], "VEC3", minmax=True)
    n = b.floats([(0, 0, 1)] * 3, "VEC3")
    embedded(b, {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                 "meshes": [{"primitives": [{"attributes": {"POSITION": p}}, {"attributes": {"NORMAL": n}}]}]},
             "no_position.gltf")
    # An image and no mesh (magnum-plugins' image.gltf): written unchanged, the image moved into
    # the buffer; no accessor, so no "accessors" array (an empty one is the validator's EMPTY_ENTITY).
    with open(os.path.join(out, "image_only.gltf"), "w") as f:
        json.dump({"asset": {"version": "2.0"},
                   "images": [{"uri": "data:image/png;base64," + base64.b64encode(png_bytes()).decode()}]}, f)


def misaligned_fixture(out):
    """TEXCOORD_0 floats starting 2 bytes into their view (as some exporters write them; the
    validator's ACCESSOR_TOTAL_OFFSET_ALIGNMENT): a writer must not pass that on."""
    b = Builder()
    p = b.floats([(0, 0, 0), (1, 0, 0), (0, 1, 0)], "VEC3", minmax=True)
    uv = b.view(b"\0\0" + struct.pack("<6f", 0, 0, 1, 0, 0, 1))
    t = b.accessor(uv, 5126, 3, "VEC2", offset=2)
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": p, "TEXCOORD_0": t}}]}],
           "buffers": [{"uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(b.bin)).decode(),
                        "byteLength": len(b.bin)}], "bufferViews": b.views, "accessors": b.accessors}
    with open(os.path.join(out, "misaligned.gltf"), "w") as f:
        json.dump(doc, f)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    png = png_bytes()
    with open(os.path.join(out, "checker.png"), "wb") as f:
        f.write(png)
    doc, b = build(png)
    write_gltf(os.path.join(out, "rich.gltf"), doc, bytes(b.bin))
    write_glb(os.path.join(out, "rich.glb"), doc, bytes(b.bin), png)

    # Embedded: the same document with the buffer and the image as data URIs.
    emb = json.loads(json.dumps(doc))
    emb["buffers"] = [{"uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(b.bin)).decode(),
                       "byteLength": len(b.bin)}]
    emb["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png).decode()}]
    with open(os.path.join(out, "embedded.gltf"), "w") as f:
        json.dump(emb, f)

    def bad(name, change):
        d = json.loads(json.dumps(doc))
        change(d)
        write_gltf(os.path.join(out, "bad_" + name + ".gltf"), d, bytes(b.bin))

    def missing_bin(d):
        pass
    bad("missing_bin", missing_bin)
    os.remove(os.path.join(out, "bad_missing_bin.bin"))
    bad("index_out_of_range", lambda d: d["accessors"][16].update(count=3))  # the tetrahedron: index 3 of 3 vertices
    bad("accessor_overrun", lambda d: d["accessors"][0].update(count=2400))
    bad("wrong_component_type", lambda d: d["accessors"][0].update(componentType=5125))
    bad("recursive_nodes", lambda d: d["nodes"][8].update(children=[7]))
    # A Draco extension whose bufferView holds no Draco data (the cube's positions): does not decode.
    bad("draco", lambda d: d["meshes"][0]["primitives"][0].setdefault("extensions", {}).update(
        KHR_draco_mesh_compression={"bufferView": 0, "attributes": {"POSITION": 0}}))
    small_fixtures(out)
    misaligned_fixture(out)

    # Schema type errors, as in assimp's test/models/glTF2/wrongTypes (written here anew): the
    # Khronos validator rejects each; so must we, naming the JSON path.
    bad("type_scene_name", lambda d: d["scenes"][0].update(name=42))
    bad("type_texture_index", lambda d: d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"].update(index=-1))
    bad("type_not_object", lambda d: d["materials"][0].update(pbrMetallicRoughness=["not an object"]))
    bad("type_count_string", lambda d: d["accessors"][1].update(count="24"))
    bad("type_extensions", lambda d: d.update(extensions=["KHR_lights_punctual"]))
    bad("type_node_mesh", lambda d: d["nodes"][0].update(mesh=99))
    # An extension's value that is not an object (extension.schema.json; assimp's badExtension.gltf).
    bad("type_extension_value", lambda d: d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"].update(
        extensions={"KHR_texture_transform": "Not an object"}))

    # NaN in POSITION: a copy of the binary with vertex 0's x replaced.
    nan_bin = bytearray(b.bin)
    off = doc["bufferViews"][doc["accessors"][0]["bufferView"]]["byteOffset"]
    nan_bin[off:off + 4] = struct.pack("<f", float("nan"))
    write_gltf(os.path.join(out, "bad_nan_position.gltf"), doc, bytes(nan_bin))


if __name__ == "__main__":
    main()
