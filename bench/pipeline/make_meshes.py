#!/usr/bin/env python3
"""Writes N copies of a ~10k-triangle UV sphere OBJ (each shifted, so files differ) into DIR."""
import math, os, sys
out, n = sys.argv[1], int(sys.argv[2])
nu, nv = 100, 51          # 100 * (2 * 49 + 2) = 10,000 triangles
os.makedirs(out, exist_ok=True)
verts = [(0.0, 0.0, 1.0)]
for j in range(1, nv):
    t = math.pi * j / nv
    for i in range(nu):
        p = 2 * math.pi * i / nu
        verts.append((math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)))
verts.append((0.0, 0.0, -1.0))
south = len(verts)  # 1-based index of the south pole
def idx(i, j):
    if j == 0: return 1
    if j == nv: return south
    return 2 + (j - 1) * nu + (i % nu)
faces = []
for j in range(nv):
    for i in range(nu):
        a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
        if len({a, b, c}) == 3: faces.append((a, b, c))
        if len({a, c, d}) == 3: faces.append((a, c, d))
face_text = "".join(f"f {a} {b} {c}\n" for a, b, c in faces)
for k in range(n):
    dx = 3.0 * k
    with open(os.path.join(out, f"sphere{k:04d}.obj"), "w") as f:
        f.write("".join(f"v {x + dx:.9g} {y:.9g} {z:.9g}\n" for x, y, z in verts))
        f.write(face_text)
print(f"{n} meshes of {len(faces)} triangles in {out}")
