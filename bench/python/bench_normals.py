#!/usr/bin/env python3
"""bench/python/bench_normals.py: shadetool.vertex_normals from Python against Open3D's
compute_vertex_normals and against the C++ call, on the same 1M-triangle arrays, in one run.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/bench_normals.py [--build build] [--rounds 11]

Mesh: an irregular UV sphere held in NumPy (V (n, 3) float64, F (m, 3) int32, ~1M triangles):
vertices jittered along the sphere by 0.3 of a cell, so one-rings are irregular but on the surface.
Rows, each timed once per round, the rounds interleaving the methods (the machine is shared and
noisy), medians and minima over the rounds; conversion included wherever a method needs one:
  shadetool (arrays)      shadetool.vertex_normals(V, F, weight): V and F read in place (a MeshView of
                          the NumPy memory, core/mesh_view.h; F's indices checked by one min/max pass),
                          then the library call; a fresh array out
  shadetool (Mesh)        shadetool.vertex_normals(mesh) on a shadetool.Mesh built once: no copy in
  Open3D                  TriangleMesh(Vector3dVector(V), Vector3iVector(F)), compute_vertex_normals(),
                          np.asarray(mesh.vertex_normals): Open3D's conversion in, area weighting
  C++ call                shadetool::vertex_normals(mesh, weight) in a C++ process on the same arrays
                          (bench/python/cpp_vertex_normals.cpp, compiled here against build/libshadetool.a),
                          on a Mesh built beforehand; median of 3 calls per round
  C++ view call           shadetool::vertex_normals(MeshView::triangles(V, F), weight) on the same arrays
                          in place (no index check); median of 3 calls per round
Memory (--memory): glibc's dynamic mmap threshold otherwise decides, from round to round, whether
a method's big blocks (Open3D allocates about 60 MB per call, we 12 MB) are fresh pages to fault in or
recycled ones, which made Open3D's time bimodal (about 15 or 37 ms in one run). The policy is fixed
for the whole process before it starts (the script re-executes itself with glibc's tunables set):
  recycled (default)  MALLOC_MMAP_THRESHOLD_=32 MiB, MALLOC_TRIM_THRESHOLD_=4 GiB: every block of
                      these sizes is reused, no page faults for anyone (Open3D at its fastest; a
                      script calling in a loop)
  fresh               MALLOC_MMAP_THRESHOLD_=1 MiB: every big block is a fresh mapping (one call
                      in a fresh process)
  as-is               glibc's defaults (the bimodal case)
Checks: Python's and C++'s normals are the same bits; Open3D's (area) agree with ours within 1e-9 deg.
Goals (issue 20): shadetool >= 2x Open3D; Python within 1.1x of the C++ call.
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import shadetool

HERE = Path(__file__).resolve().parent
SOURCE = HERE.parents[1]


def irregular_uv_sphere(n_theta, n_phi, jitter=0.3, seed=1):
    rng = np.random.default_rng(seed)
    i = np.arange(1, n_theta)
    j = np.arange(n_phi)
    t = (i[:, None] + rng.uniform(-jitter, jitter, (n_theta - 1, n_phi))) * np.pi / n_theta
    p = (j[None, :] + rng.uniform(-jitter, jitter, (n_theta - 1, n_phi))) * 2 * np.pi / n_phi
    ring = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1).reshape(-1, 3)
    V = np.vstack([[0, 0, 1.0], ring, [0, 0, -1.0]])
    south = len(V) - 1
    idx = 1 + (np.arange(n_theta - 1)[:, None] * n_phi + np.arange(n_phi)[None, :])  # ring vertex ids
    nxt = np.roll(idx, -1, axis=1)
    north_fan = np.stack([np.zeros(n_phi, int), idx[0], nxt[0]], axis=1)
    south_fan = np.stack([np.full(n_phi, south), nxt[-1], idx[-1]], axis=1)
    a, b, c, d = idx[:-1], idx[1:], nxt[1:], nxt[:-1]
    quads1 = np.stack([a, b, c], axis=-1).reshape(-1, 3)
    quads2 = np.stack([a, c, d], axis=-1).reshape(-1, 3)
    F = np.vstack([north_fan, quads1, quads2, south_fan]).astype(np.int32)
    return np.ascontiguousarray(V), np.ascontiguousarray(F)


MEMORY_POLICIES = {
    "recycled": {"MALLOC_MMAP_THRESHOLD_": str(32 << 20), "MALLOC_TRIM_THRESHOLD_": str(4 << 30)},
    "fresh": {"MALLOC_MMAP_THRESHOLD_": str(1 << 20)},
    "as-is": {},
}


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return (time.perf_counter() - t0) * 1e3, out


def build_cpp(build, out):
    src = HERE / "cpp_vertex_normals.cpp"
    # The headers are the source tree's lib/ (include paths are real paths) plus the build's
    # generated ones; the static library's own dependencies are its pkg-config Libs.private.
    cmd = ["c++", "-O3", "-DNDEBUG", "-std=c++17", f"-I{SOURCE}/lib", f"-I{build}/generated", str(src),
           f"{build}/libshadetool.a", "-ltbb", "-lembree3", "-lpng", "-ldraco", "-lmeshoptimizer", "-lpthread", "-o", str(out)]
    subprocess.run(cmd, check=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=str(SOURCE / "build"))
    ap.add_argument("--rounds", type=int, default=11)
    ap.add_argument("--theta", type=int, default=500, help="rings (triangles = 2 * theta * phi - 2 * phi)")
    ap.add_argument("--phi", type=int, default=1000)
    ap.add_argument("--memory", choices=MEMORY_POLICIES, default="recycled",
                    help="glibc memory policy for the whole run (see the module doc)")
    args = ap.parse_args()
    policy = MEMORY_POLICIES[args.memory]
    if any(os.environ.get(k) != v for k, v in policy.items()):  # set before the process starts: re-execute
        env = {k: v for k, v in os.environ.items() if not k.startswith("MALLOC_")}
        env.update(policy)
        os.execve(sys.executable, [sys.executable] + sys.argv, env)
    import open3d as o3d

    V, F = irregular_uv_sphere(args.theta, args.phi)
    tmp = Path(tempfile.mkdtemp(prefix="bench_python_"))
    V.tofile(tmp / "V.f64")
    F.tofile(tmp / "F.i32")
    cpp = tmp / "cpp_vertex_normals"
    build_cpp(args.build, cpp)
    mesh = shadetool.Mesh(V, F)

    def open3d_normals():
        m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))
        m.compute_vertex_normals()
        return np.asarray(m.vertex_normals)

    rows = {}
    cases = []
    for w in ("area", "angle"):
        cases.append((f"shadetool.vertex_normals(V, F) {w} (arrays)", lambda w=w: shadetool.vertex_normals(V, F, weight=w)))
        cases.append((f"shadetool.vertex_normals(mesh) {w} (Mesh)", lambda w=w: shadetool.vertex_normals(mesh, weight=w)))
    cases.append(("Open3D compute_vertex_normals (area, conversion included)", open3d_normals))
    for _, fn in cases:  # warm-up
        fn()
    results = {}
    for r in range(args.rounds):
        order = cases[r % len(cases):] + cases[: r % len(cases)]
        for name, fn in order:
            ms, out = timed(fn)
            rows.setdefault(name, []).append(ms)
            results[name] = out
        for w in ("area", "angle"):
            got = subprocess.run([str(cpp), str(tmp / "V.f64"), str(tmp / "F.i32"), w, "3", str(tmp / f"N_{w}.f64")],
                                 check=True, capture_output=True, text=True)
            t = json.loads(got.stdout)
            rows.setdefault(f"C++ shadetool::vertex_normals {w} (call)", []).append(statistics.median(t["call"]))
            rows.setdefault(f"C++ shadetool::vertex_normals {w} (view of the arrays)", []).append(statistics.median(t["view_call"]))

    # Same bits from Python and C++; Open3D (area weighting) agrees up to rounding.
    for w in ("area", "angle"):
        cpp_n = np.fromfile(tmp / f"N_{w}.f64").reshape(-1, 3)
        py_n = results[f"shadetool.vertex_normals(V, F) {w} (arrays)"]
        assert py_n.tobytes() == cpp_n.tobytes(), f"{w}: Python and C++ normals differ"
        assert results[f"shadetool.vertex_normals(mesh) {w} (Mesh)"].tobytes() == cpp_n.tobytes()
    o3d_n = results["Open3D compute_vertex_normals (area, conversion included)"]
    ours = results["shadetool.vertex_normals(V, F) area (arrays)"]
    cos = np.clip(np.sum(o3d_n * ours, axis=1), -1, 1)
    max_deg = float(np.degrees(np.max(np.arctan2(np.linalg.norm(np.cross(o3d_n, ours), axis=1), cos))))

    med = {k: statistics.median(v) for k, v in rows.items()}
    o3d_ms = med["Open3D compute_vertex_normals (area, conversion included)"]
    load = os.getloadavg()
    print(f"machine: {os.cpu_count()} cores, {platform.processor() or platform.machine()}; "
          f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; Python {platform.python_version()}, "
          f"NumPy {np.__version__}, Open3D {o3d.__version__}")
    print(f"mesh: irregular UV sphere, {len(V)} vertices, {len(F)} triangles (V float64, F int32); "
          f"{args.rounds} rounds, methods interleaved; C++: median of 3 calls per round; memory {args.memory}\n")
    print("| method | median ms | min ms | Open3D time / this |")
    print("|---|---:|---:|---:|")
    for name, v in rows.items():
        print(f"| {name} | {med[name]:.2f} | {min(v):.2f} | {o3d_ms / med[name]:.2f}x |")
    print()
    for w in ("area", "angle"):
        arrays = med[f"shadetool.vertex_normals(V, F) {w} (arrays)"]
        on_mesh = med[f"shadetool.vertex_normals(mesh) {w} (Mesh)"]
        call = med[f"C++ shadetool::vertex_normals {w} (call)"]
        view_call = med[f"C++ shadetool::vertex_normals {w} (view of the arrays)"]
        print(f"{w}: Python (arrays) / C++ call = {arrays / call:.2f}x; Python (Mesh) / C++ call = {on_mesh / call:.2f}x; "
              f"Python (arrays) / C++ view call = {arrays / view_call:.2f}x; Open3D / Python (arrays) = {o3d_ms / arrays:.2f}x")
    print(f"\nchecks: Python and C++ normals bitwise equal (area, angle); Open3D vs ours (area) max {max_deg:.2e} deg")


if __name__ == "__main__":
    main()
