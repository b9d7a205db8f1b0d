#!/usr/bin/env python3
"""A mesh held in NumPy -> shadetool normals -> a PLY file, without a subprocess or a temporary file.

    PYTHONPATH=build/python /usr/bin/python3 examples/python_normals.py [OUT.ply]   (default torus.ply)

Builds a torus (R = 1, r = 0.4) as NumPy arrays, computes angle-weighted vertex normals with
shadetool.vertex_normals, compares them with the torus's analytic normals, bakes a sun light into
vertex colours and writes positions, normals and colours as binary PLY.
"""
import sys

import numpy as np

import shadetool

R, r, n_u, n_v = 1.0, 0.4, 96, 48
u, v = np.meshgrid(np.arange(n_u) * 2 * np.pi / n_u, np.arange(n_v) * 2 * np.pi / n_v, indexing="ij")
V = np.stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)], axis=-1).reshape(-1, 3)
i, j = np.meshgrid(np.arange(n_u), np.arange(n_v), indexing="ij")
a, b = i * n_v + j, ((i + 1) % n_u) * n_v + j  # this ring, next ring
c, d = ((i + 1) % n_u) * n_v + (j + 1) % n_v, i * n_v + (j + 1) % n_v
F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)]).astype(np.int32)

N = shadetool.vertex_normals(V, F, weight="angle")  # (n, 3) float64, unit length

analytic = np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=-1).reshape(-1, 3)
error_deg = np.degrees(np.arctan2(np.linalg.norm(np.cross(N, analytic), axis=1), np.sum(N * analytic, axis=1)))
print(f"{len(V)} vertices, {len(F)} triangles; normals vs analytic: max {error_deg.max():.3g} deg, "
      f"mean {error_deg.mean():.3g} deg")

sun = {"model": "lambert", "material": {"diffuse": [0.9, 0.6, 0.3]},
       "lights": [{"type": "directional", "direction": [-1, -1, -2]}]}
colors = shadetool.bake_lighting(V, F, N, sun)  # (n, 3) linear RGB

out = sys.argv[1] if len(sys.argv) > 1 else "torus.ply"
shadetool.write_mesh(out, shadetool.Mesh(V, F, vertex_normals=N, vertex_colors=np.clip(colors, 0, 1)))
print(f"wrote {out}")
