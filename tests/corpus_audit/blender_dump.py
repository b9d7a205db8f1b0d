# blender_dump.py: run inside Blender 3.4 (blender -b --factory-startup --python blender_dump.py --
# OUT.json FILE...). Imports each FILE with Blender's own importer (OBJ: wm.obj_import, PLY:
# import_mesh.ply, glTF: import_scene.gltf) and writes, per file, what Blender shows: every polygon
# of every mesh object in world space with its corner positions, its split (custom) normals and
# its corner colours (linear floats as Blender holds them, or null). blender_compare.py compares
# them with what shadetool wrote (read by tests/corpus/read_mesh.py).
import json
import sys

import bpy
import numpy

# Blender 3.4's glTF importer uses numpy.bool, which numpy 1.24 (Debian 12) removed: the alias it meant.
if not hasattr(numpy, "bool") or "bool" in getattr(numpy, "__former_attrs__", {}):
    numpy.bool = bool

args = sys.argv[sys.argv.index("--") + 1:]
out_path, files = args[0], args[1:]
result = {}
for path in files:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    low = path.lower()
    try:
        if low.endswith(".obj"):
            bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")  # no axis change
        elif low.endswith(".ply"):
            bpy.ops.import_mesh.ply(filepath=path)
        elif low.endswith((".glb", ".gltf")):
            bpy.ops.import_scene.gltf(filepath=path)
    except Exception as e:  # Blender could not import it: say so
        result[path] = {"error": str(e)}
        continue
    # the glTF importer turns Y-up into Z-up, (x, y, z) -> (x, -z, y): back into the file's frame
    back = (lambda v: [v[0], v[2], -v[1]]) if low.endswith((".glb", ".gltf")) else (lambda v: list(v))
    polys = []
    for ob in bpy.context.scene.objects:
        if ob.type != "MESH":
            continue
        me = ob.data
        me.calc_normals_split()
        mw = ob.matrix_world
        nmat = mw.to_3x3().inverted_safe().transposed()
        col = me.color_attributes.active_color if hasattr(me, "color_attributes") else None
        for p in me.polygons:
            pos, nor, cols = [], [], []
            for li in p.loop_indices:
                lo = me.loops[li]
                pos.append(back(mw @ me.vertices[lo.vertex_index].co))
                n = nmat @ lo.normal
                nor.append(back(n.normalized()) if n.length > 0 else [0.0, 0.0, 0.0])
                if col is not None:
                    d = col.data[li] if col.domain == "CORNER" else col.data[lo.vertex_index]
                    cols.append(list(d.color)[:3])
            polys.append({"p": pos, "n": nor, "c": cols if col is not None else None})
    result[path] = {"polygons": polys}
json.dump(result, open(out_path, "w"))
