"""anchor_open3d.py EXPORT AO_CSV OUT_CSV [--runs R]: ambient occlusion with Open3D's
RaycastingScene (python3-open3d 0.16.1) on the same mesh and points as bench_visibility, the way a
numpy user would write it, against the same 4096-sample reference.

Run under the Embree mask shim (embree_mask_shim.c; without it Debian's Open3D misses every ray):
  LD_PRELOAD=embree_mask_shim.so /usr/bin/python3 anchor_open3d.py ...
The scene is built from the exported float vertices (the very floats shadetool's BVH holds). For
N = 4..1024 and each point: N independent cosine-weighted directions (numpy's PCG64, seed 1;
Malley: uniform disc point lifted to the hemisphere) in the point's tangent frame, origins on the
point, tnear = 1e-4 (a fixed epsilon, about 1e-4 of the mesh's half extent 1), tfar = inf,
RaycastingScene.test_occlusions on all threads. Open fraction = misses / N. Time: the median over R
runs of ray generation (numpy) + test_occlusions, both reported. Equal error: shadetool's time per
vertex at Open3D's RMS error, interpolated in ao.csv (anchor_common.py).
"""
import sys
import time

import numpy as np
import open3d as o3d

from anchor_common import equal_error_cells, read_export, read_shadetool, rms, shadetool_us_per_vertex_at


def tangent_frames(n):
    """t, b with (t, b, n) orthonormal (Duff et al. 2017, as sample_sequence.h)."""
    sign = np.copysign(1.0, n[:, 2])
    a = -1.0 / (sign + n[:, 2])
    c = n[:, 0] * n[:, 1] * a
    t = np.stack([1 + sign * n[:, 0] ** 2 * a, sign * c, -sign * n[:, 0]], axis=1)
    b = np.stack([c, sign + n[:, 1] ** 2 * a, -n[:, 1]], axis=1)
    return t, b


def make_rays(points, normals, t, b, n_samples, rng):
    K = points.shape[0]
    r = np.sqrt(rng.random((K, n_samples)))
    phi = 2 * np.pi * rng.random((K, n_samples))
    x, y = r * np.cos(phi), r * np.sin(phi)
    z = np.sqrt(np.maximum(0.0, 1 - x * x - y * y))
    d = x[..., None] * t[:, None, :] + y[..., None] * b[:, None, :] + z[..., None] * normals[:, None, :]
    rays = np.empty((K, n_samples, 6), np.float32)
    rays[..., :3] = points[:, None, :]
    rays[..., 3:] = d
    return rays


def main():
    args = sys.argv[1:]
    runs = 3
    if "--runs" in args:
        i = args.index("--runs")
        runs = int(args[i + 1])
        del args[i:i + 2]
    export, ao_csv, out_csv = args
    vertices, triangles, ids, normals, reference = read_export(export)
    ours = read_shadetool(ao_csv)
    points = vertices[ids.astype(np.int64)].astype(np.float64)
    t, b = tangent_frames(normals)
    scene = o3d.t.geometry.RaycastingScene()
    t0 = time.perf_counter()
    scene.add_triangles(o3d.core.Tensor(vertices), o3d.core.Tensor(triangles))
    # The BVH is built lazily on the first query: one ray, timed as the build.
    scene.test_occlusions(o3d.core.Tensor(np.array([[0, 0, 0, 1, 0, 0]], np.float32)))
    build_ms = 1000 * (time.perf_counter() - t0)
    # The shim's check: rays aimed head-on at two of the points (from 3 units out along the normal,
    # outside the mesh's box |local| <= 1) must hit.
    aim = np.concatenate([points[:2] + 3 * normals[:2], -normals[:2]], axis=1).astype(np.float32)
    through_vertex = int(scene.test_occlusions(o3d.core.Tensor(aim)).numpy().sum())
    print(f"Open3D {o3d.__version__}: {vertices.shape[0]} vertices, {triangles.shape[0]} triangles, "
          f"BVH build {build_ms:.0f} ms; rays through a vertex that hit: {through_vertex} of 2"
          + ("" if through_vertex else " (every ray misses: run under LD_PRELOAD=embree_mask_shim.so)"))
    if through_vertex != 2:
        sys.exit(1)
    K = points.shape[0]
    rows = []
    print("\n| N | RMS error | numpy rays ms | test_occlusions ms | total ms | us / vertex | shadetool us / vertex at equal error | Open3D / shadetool |")
    print("|---|---|---|---|---|---|---|---|")
    for n_samples in [4, 8, 16, 32, 64, 128, 256, 512, 1024]:
        gen, trace = [], []
        for _ in range(runs):
            rng = np.random.default_rng(1)
            t0 = time.perf_counter()
            rays = make_rays(points, normals, t, b, n_samples, rng)
            t1 = time.perf_counter()
            hit = scene.test_occlusions(o3d.core.Tensor(rays), tnear=1e-4).numpy()
            t2 = time.perf_counter()
            gen.append(1000 * (t1 - t0))
            trace.append(1000 * (t2 - t1))
            del rays
        open_fraction = 1.0 - hit.reshape(K, n_samples).mean(axis=1)
        e = rms(open_fraction, reference)
        g, tr = float(np.median(gen)), float(np.median(trace))
        us = 1000 * (g + tr) / K
        ours_us, bound = shadetool_us_per_vertex_at(ours, e)
        ours_txt, ratio = equal_error_cells(us, ours_us, bound)
        print(f"| {n_samples} | {e:.5f} | {g:.1f} | {tr:.1f} | {g + tr:.1f} | {us:.2f} | {ours_txt} | {ratio} |")
        rows.append((n_samples, e, g, tr, us, ours_us or float("nan")))
    with open(out_csv, "w") as f:
        f.write("samples,rms_error,numpy_ms,test_occlusions_ms,us_per_vertex,shadetool_us_per_vertex_equal_error\n")
        for r in rows:
            f.write(",".join(f"{x:.6g}" for x in r) + "\n")


if __name__ == "__main__":
    main()
