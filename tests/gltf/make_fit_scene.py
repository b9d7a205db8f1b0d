#!/usr/bin/env python3
"""make_fit_scene.py OUT.gltf SCENE.json: a glTF scene of three triangle primitives, every one with
unit NORMALs (written by hand, not by shadetool), for tests/gltf_fit.sh, and the lighting scene
(lighting/read_scene.h) that lights its flattened world mesh as gltf/gltf_lights.h lights the glTF.

  mesh 0, primitive 0: a UV sphere of radius 1 (8 rings x 12 segments), analytic normals
  mesh 0, primitive 1: a 4 x 4 grid square [-1, 1]^2 at y = -1.2 facing +y (a plinth under it)
  mesh 1, primitive 0: an 8 x 8 grid ground [-4, 4]^2 at y = 0 facing +y
  node 0 places mesh 0: translation (0.4, 1.6, -0.3), rotation 30 degrees about y, uniform scale 1.3
  node 1 places mesh 1: translation (0, -0.2, 0)
  node 2: a directional light (rotation -60 degrees about x: it shines along (0, -sin 60, -cos 60))
  node 3: a point light at (2, 4, 1)
Uniform scales only, so that the world normals (cofactor times the unit object normal) keep the
same direction whether they are normalised before interpolation (the flattened mesh) or after.
"""
import json
import math
import struct
import sys


def sphere(rings=8, segments=12):
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        th = math.pi * r / rings
        for s in range(segments + 1):
            ph = 2 * math.pi * s / segments
            n = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            pos.append(n)
            nrm.append(n)
    w = segments + 1
    for r in range(rings):
        for s in range(segments):
            a, b, c, d = r * w + s, r * w + s + 1, (r + 1) * w + s, (r + 1) * w + s + 1
            if r > 0:
                idx += [a, c, b]
            if r < rings - 1:
                idx += [b, c, d]
    return pos, nrm, idx


def grid(n, half, y):
    pos, nrm, idx = [], [], []
    for k in range(n + 1):
        for i in range(n + 1):
            pos.append((-half + 2 * half * i / n, y, -half + 2 * half * k / n))
            nrm.append((0.0, 1.0, 0.0))
    for k in range(n):
        for i in range(n):
            a = k * (n + 1) + i
            b, c, d = a + 1, a + n + 1, a + n + 2
            idx += [a, c, b, b, c, d]  # counter-clockwise seen from +y
    return pos, nrm, idx


def main():
    out, scene_path = sys.argv[1], sys.argv[2]
    blob = bytearray()
    views, accessors = [], []

    def add(data, target):
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob.extend(data)
        return len(views) - 1

    def vec3(rows, minmax):
        flat = [x for r in rows for x in r]
        a = {"bufferView": add(struct.pack("<%df" % len(flat), *flat), 34962), "componentType": 5126,
             "count": len(rows), "type": "VEC3"}
        if minmax:
            f32 = [struct.unpack("<f", struct.pack("<f", x))[0] for x in flat]
            a["min"] = [min(f32[k::3]) for k in range(3)]
            a["max"] = [max(f32[k::3]) for k in range(3)]
        accessors.append(a)
        return len(accessors) - 1

    def primitive(mesh):
        pos, nrm, idx = mesh
        p = vec3(pos, True)
        n = vec3(nrm, False)
        accessors.append({"bufferView": add(struct.pack("<%dH" % len(idx), *idx), 34963), "componentType": 5123,
                          "count": len(idx), "type": "SCALAR"})
        return {"attributes": {"POSITION": p, "NORMAL": n}, "indices": len(accessors) - 1}

    half = math.radians(30) / 2
    light_half = math.radians(-60) / 2
    doc = {
        "asset": {"version": "2.0", "generator": "shadetool tests/gltf/make_fit_scene.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "color": [1, 1, 1], "intensity": 0.6},
            {"type": "point", "color": [1, 0.8, 0.6], "intensity": 8}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"mesh": 0, "translation": [0.4, 1.6, -0.3], "rotation": [0, math.sin(half), 0, math.cos(half)],
             "scale": [1.3, 1.3, 1.3]},
            {"mesh": 1, "translation": [0, -0.2, 0]},
            {"rotation": [math.sin(light_half), 0, 0, math.cos(light_half)],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"translation": [2, 4, 1], "extensions": {"KHR_lights_punctual": {"light": 1}}},
        ],
        "meshes": [{"primitives": [primitive(sphere()), primitive(grid(4, 1.0, -1.2))]},
                   {"primitives": [primitive(grid(8, 4.0, 0.0))]}],
    }
    doc["accessors"], doc["bufferViews"] = accessors, views
    bin_name = out.rsplit("/", 1)[-1].rsplit(".", 1)[0] + ".bin"
    doc["buffers"] = [{"uri": bin_name, "byteLength": len(blob)}]
    with open(out, "w") as f:
        json.dump(doc, f, indent=1)
    with open(out.rsplit("/", 1)[0] + "/" + bin_name if "/" in out else bin_name, "wb") as f:
        f.write(blob)
    # The same lights as gltf/gltf_lights.h makes of them, in world space: diffuse = specular =
    # colour x intensity, point lights 1/d^2, a node's light shining down its -Z; the default
    # material (diffuse 1, no ambient, no specular) and no global ambient.
    c, s = math.cos(math.radians(-60)), math.sin(math.radians(-60))
    scene = {"ambient": [0, 0, 0],
             "material": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [0, 0, 0]},
             "lights": [{"type": "directional", "direction": [0, s, -c], "color": [1, 1, 1], "intensity": 0.6},
                        {"type": "point", "position": [2, 4, 1], "color": [1, 0.8, 0.6], "intensity": 8,
                         "attenuation": [0, 0, 1]}]}
    with open(scene_path, "w") as f:
        json.dump(scene, f, indent=1)


main()
