"""anchor_blender.py: Blender 3.4 Cycles' ambient-occlusion bake to a colour attribute, on the same
mesh and points as bench_visibility, against the same 4096-sample reference. Run headless:

  blender -b --factory-startup --python-exit-code 1 --python anchor_blender.py -- \
      EXPORT AO_CSV OUT_CSV [--samples 1,4,16] [--threads 2]

The mesh is built from the exported float vertices (the floats shadetool's BVH holds; half extent
1), smooth shaded, so Blender's shading normal at a vertex is its own angle-weighted vertex normal
(shadetool's points use angle-weighted vertex normals too; they differ only in rounding). For each
sample count N: Cycles on the CPU, N samples per bake point, adaptive sampling and denoising off
(Debian's Blender has no OpenImageDenoise: with denoising on, every colour is 0), world AO
distance 100 (beyond the mesh's diameter 2 sqrt 3: unlimited, as the reference), bake type AO to a
FLOAT_COLOR attribute on the point domain (no 8-bit rounding, linear). Cycles' AO is the same
quantity as shadetool's open fraction: cosine-weighted directions about the shading normal, the
fraction unoccluded within the distance (rays below the geometric surface count as occluded).
Baking to a point-domain attribute, Blender evaluates each corner of each triangle and averages the
corners at the vertex; the corners of a vertex get the same point, normal and (measured) the same
samples: the error is that of N samples per vertex (at N = 4 within 2% of shadetool's N = 4 row).
Time: the bake operator (bpy.ops.object.bake: Cycles' scene sync, its BVH build and the bake; the
mesh creation excluded), one run per N, against shadetool's time per vertex at equal error times
the vertex count plus shadetool's BVH build (--shadetool-build-ms): whole job against whole job.
"""
import os
import sys
import time

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from anchor_common import equal_error_cells, read_export, read_shadetool, rms, shadetool_us_per_vertex_at  # noqa: E402


def build_object(vertices, triangles):
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o, do_unlink=True)
    me = bpy.data.meshes.new("knot")
    V, T = vertices.shape[0], triangles.shape[0]
    me.vertices.add(V)
    me.vertices.foreach_set("co", vertices.astype(np.float32).ravel())
    me.loops.add(3 * T)
    me.loops.foreach_set("vertex_index", triangles.astype(np.int32).ravel())
    me.polygons.add(T)
    me.polygons.foreach_set("loop_start", np.arange(0, 3 * T, 3, dtype=np.int32))
    me.polygons.foreach_set("loop_total", np.full(T, 3, dtype=np.int32))
    me.polygons.foreach_set("use_smooth", np.ones(T, dtype=bool))
    me.update()
    ob = bpy.data.objects.new("knot", me)
    bpy.context.scene.collection.objects.link(ob)
    bpy.context.view_layer.objects.active = ob
    ob.select_set(True)
    attr = me.color_attributes.new(name="ao", type="FLOAT_COLOR", domain="POINT")
    me.color_attributes.active_color = attr
    return ob, me


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    samples = [1, 4, 16]
    threads = 2
    build_ms = 0.0
    for flag in ("--samples", "--threads", "--shadetool-build-ms"):
        if flag in argv:
            i = argv.index(flag)
            if flag == "--samples":
                samples = [int(x) for x in argv[i + 1].split(",")]
            elif flag == "--threads":
                threads = int(argv[i + 1])
            else:
                build_ms = float(argv[i + 1])
            del argv[i:i + 2]
    export, ao_csv, out_csv = argv
    vertices, triangles, ids, normals, reference = read_export(export)
    ours = read_shadetool(ao_csv)
    V = vertices.shape[0]
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.render.bake.target = "VERTEX_COLORS"
    if scene.world is None:
        scene.world = bpy.data.worlds.new("World")
    scene.world.light_settings.distance = 100.0
    t0 = time.perf_counter()
    ob, me = build_object(vertices, triangles)
    print(f"Blender {bpy.app.version_string}: {V} vertices, {triangles.shape[0]} triangles, mesh made in "
          f"{1000 * (time.perf_counter() - t0):.0f} ms; Cycles CPU, {threads} threads")
    print(f"shadetool's BVH build: {build_ms:.0f} ms, added to its time at equal error")
    print("\n| N | RMS error | mean difference | Blender bake ms | shadetool ms at equal error (AO + BVH) | Blender / shadetool |")
    print("|---|---|---|---|---|---|")
    rows = []
    buf = np.empty(4 * V, dtype=np.float32)
    for n in samples:
        scene.cycles.samples = n
        t0 = time.perf_counter()
        result = bpy.ops.object.bake(type="AO", target="VERTEX_COLORS")
        ms = 1000 * (time.perf_counter() - t0)
        if result != {"FINISHED"}:
            raise SystemExit(f"anchor_blender: bake returned {result}")
        me.color_attributes["ao"].data.foreach_get("color", buf)
        ao = buf.reshape(V, 4)[:, 0].astype(np.float64)
        if not ao.any():
            raise SystemExit("anchor_blender: every baked colour is 0 (denoising on without OpenImageDenoise?)")
        open_fraction = ao[ids.astype(np.int64)]
        e = rms(open_fraction, reference)
        ours_us, bound = shadetool_us_per_vertex_at(ours, e)
        ours_ms = ours_us * V / 1000 + build_ms if ours_us is not None else None
        ours_txt, ratio = equal_error_cells(ms, ours_ms, bound)
        if ours_ms is not None:
            ours_txt = ours_txt.replace(f"{ours_ms:.2f}", f"{ours_ms:.0f}")
        bias = float(np.mean(open_fraction - reference))
        print(f"| {n} | {e:.5f} | {bias:+.5f} | {ms:.0f} | {ours_txt} | {ratio} |")
        rows.append((n, e, bias, ms, ours_ms if ours_ms is not None else float("nan")))
        sys.stdout.flush()
    with open(out_csv, "w") as f:
        f.write("samples,rms_error,mean_difference,blender_bake_ms,shadetool_ms_equal_error\n")
        for r in rows:
            f.write(",".join(f"{x:.6g}" for x in r) + "\n")


main()
