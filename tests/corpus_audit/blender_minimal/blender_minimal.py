# blender_minimal.py: run inside Blender 3.4 (blender -b --factory-startup --python blender_minimal.py).
# Shows, on files of a few lines, the two classes of difference blender_compare.py found between what
# we wrote and what Blender shows, that are Blender's own (its importers do it to the inputs too):
#   1. zero_area_fan.gltf (20 vertices, 18 triangles cut from 2CylinderEngine.glb around one vertex;
#      NORMAL as in the file): Blender's split normals at the corners of the vertex that a zero-area
#      triangle (two vertices at one position) shares are off the file's NORMAL by up to 90 degrees;
#      zero_area_fan_removed.gltf, the same text without that triangle: every corner as in the file.
#   2. keyhole.obj / keyhole.ply (one polygon, a square with a square hole, two vertices repeated):
#      the OBJ importer keeps it (as 2 polygons), the PLY importer drops it (mesh.validate()).
# Prints one line per claim, "holds" or "NO LONGER HOLDS", and exits 1 when a claim no longer holds.
import math
import os
import sys

import bpy
import numpy

if not hasattr(numpy, "bool") or "bool" in getattr(numpy, "__former_attrs__", {}):
    numpy.bool = bool  # Blender 3.4's glTF importer uses numpy.bool (removed in numpy 1.24)

HERE = os.path.dirname(os.path.abspath(__file__))


def load(name):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    path = os.path.join(HERE, name)
    if name.endswith(".gltf"):
        bpy.ops.import_scene.gltf(filepath=path)
    elif name.endswith(".obj"):
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    else:
        bpy.ops.import_mesh.ply(filepath=path)
    return [ob.data for ob in bpy.context.scene.objects if ob.type == "MESH"]


def worst_normal_gap(name):
    """Largest angle (degrees) between Blender's split normal and the file's NORMAL, per corner.
    Blender's glTF importer keeps the glTF vertices in order (no merge by default) and swaps Y/Z
    (x, y, z) -> (x, -z, y); NORMAL is read back from the importer's own vertex order."""
    import json, base64, struct
    doc = json.load(open(os.path.join(HERE, name)))
    buf = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    acc, view = doc["accessors"][1], doc["bufferViews"][1]
    N = [struct.unpack_from("<3f", buf, view["byteOffset"] + 12 * i) for i in range(acc["count"])]
    me = load(name)[0]
    me.calc_normals_split()
    worst = 0.0
    for p in me.polygons:
        if p.area == 0.0:
            continue  # the zero-area triangle's own corners get no normal from Blender: not compared
        for li in p.loop_indices:
            lo = me.loops[li]
            n = N[lo.vertex_index]
            b = (lo.normal[0], lo.normal[2], -lo.normal[1])  # back into glTF's Y-up frame
            c = sum(x * y for x, y in zip(n, b)) / max(math.sqrt(sum(x * x for x in n)), 1e-30)  # divisor checked
            worst = max(worst, math.degrees(math.acos(max(-1.0, min(1.0, c)))))
    return worst


claims = []
w_with, w_without = worst_normal_gap("zero_area_fan.gltf"), worst_normal_gap("zero_area_fan_removed.gltf")
claims.append(("glTF custom normals in a fan with a zero-area triangle: worst %.1f deg with it, %.2f deg without"
               % (w_with, w_without), w_with > 45.0 and w_without < 1.0))
obj_polys = sum(len(me.polygons) for me in load("keyhole.obj"))
ply_polys = sum(len(me.polygons) for me in load("keyhole.ply"))
claims.append(("a polygon with a repeated vertex: OBJ importer keeps %d polygons, PLY importer %d" % (obj_polys, ply_polys),
               obj_polys > 0 and ply_polys == 0))
for text, holds in claims:
    print("blender_minimal: %s: %s" % (text, "holds" if holds else "NO LONGER HOLDS"))
sys.exit(0 if all(h for _, h in claims) else 1)
