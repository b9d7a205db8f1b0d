#!/usr/bin/env python3
"""bench/readme_figures.py: every performance figure the README quotes, from one fresh run.

  bench/readme_figures.py collect [--build-dir DIR] [--results DIR] [--only AREA,...]
      runs the benchmarks behind the README's figures (after `bench/run.sh` has written the core
      results into DIR: kernels.csv, read.csv, e2e.csv, memory.csv), and writes DIR/readme.tsv:
      one line per figure (key, area, what, value as printed, goal, verdict, source), headed by
      the date, commit, machine and the load average before and after the run.
  bench/readme_figures.py readme [--results DIR] [--readme README.md]
      rewrites the README's block between the two `readme-figures` markers from readme.tsv.
  bench/readme_figures.py check [--results DIR] [--readme README.md]
      exits 1 when a figure in the README has no line with the same value in readme.tsv, or when a
      performance figure (a ratio such as "2.3x", a time in ns/us/ms, a throughput) stands outside
      the generated block, where no run would regenerate it. tests/readme_figures.sh runs this.

`bench/run.sh --readme` runs the three in order. A source whose tools are missing (an anchor's
package, node, OSMesa) gives "not measured" lines with the reason: a figure is never carried over
from an older run.

Ratios are between rows of one program run (the rows interleaved round-robin by each benchmark),
medians; which time (wall or process CPU) each figure uses is said in its `what`.
"""
import argparse
import csv
import datetime
import math
import os
import platform
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(HERE)
BEGIN = "<!-- readme-figures: begin (written by bench/run.sh --readme from bench/results/readme.tsv; do not edit) -->"
END = "<!-- readme-figures: end -->"
COLUMNS = ["key", "area", "what", "value", "goal", "verdict", "source"]


class Figure:
    def __init__(self, key, area, what, value, goal="", verdict="", source=""):
        self.key, self.area, self.what, self.value = key, area, what, value
        self.goal, self.verdict, self.source = goal, verdict, source

    def row(self):
        return [self.key, self.area, self.what, self.value, self.goal, self.verdict, self.source]


def ratio(x, digits=2):
    return "not measured" if x is None or math.isnan(x) else f"{x:.{digits}f}x"


def judged(key, area, what, value, goal, source, higher_is_better=True, unit="x", digits=2):
    """A figure with a goal: `goal` is the bound, `value` a float (None: not measured)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        sep = "" if unit in ("x", "%") else " "
        return Figure(key, area, what, "not measured", f"{'>=' if higher_is_better else '<='} {goal}{sep}{unit}", "-", source)
    ok = value >= goal if higher_is_better else value <= goal
    sep = "" if unit in ("x", "%") else " "
    return Figure(key, area, what, f"{value:.{digits}f}{sep}{unit}", f"{'>=' if higher_is_better else '<='} {goal}{sep}{unit}",
                  "met" if ok else "missed", source)


def log(msg):
    print(f"[readme-figures {time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def run(cmd, timeout=3600, env=None):
    """Runs a benchmark command; returns its stdout (raises on failure, with its stderr's tail)."""
    log("running: " + " ".join(cmd))
    p = subprocess.run(cmd, cwd=SRC, capture_output=True, text=True, timeout=timeout, env=env)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd[:2])} exited {p.returncode}: {p.stderr.strip().splitlines()[-1:] }")
    return p.stdout


def num(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return float("nan")


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


# ---- sources: each returns a list of Figures ----------------------------------------------------

def core(args):
    """bench/run.sh's own run (kernels in one process against OpenMesh and Open3D; reading; end to
    end against assimp; peak memory), read from the CSV files it has just written."""
    d = args.results
    k = read_csv(os.path.join(d, "kernels.csv"))
    src = "bench/results/results.md"
    if not k:
        raise RuntimeError("no kernels.csv: bench/run.sh did not run")
    mesh = max({r["mesh"] for r in k if r["program"] == "ours"}, key=lambda m: ("1M" in m, "irregular" in m, m))

    def find(**kw):
        return next((r for r in k if r["mesh"] == mesh and all(r.get(a) == b for a, b in kw.items())), None)

    def ours(program, weighting, threads="1", precision="double", prepared=False):
        method = "shadetool vertex_normals (prepared)" if prepared else "shadetool vertex_normals"
        return find(program=program, method=method, weighting=weighting, precision=precision, threads=threads)

    def over(slow, fast, col="median_ms"):
        return num(slow[col]) / num(fast[col]) if slow and fast else None

    out = []
    om = find(program="openmesh", method="OpenMesh update_normals", precision="double")
    out.append(judged("normals.openmesh", "normals", f"OpenMesh `update_normals` time / our area-weighted vertex normals (double, 1 thread, {mesh}, wall)",
                      over(om, ours("openmesh", "area")), 5, src))
    o3 = find(program="open3d", method="Open3D ComputeVertexNormals", threads="1")
    out.append(judged("normals.open3d", "normals", f"Open3D `ComputeVertexNormals` time / ours, area (1 thread, wall)",
                      over(o3, ours("open3d", "area")), 2, src))
    out.append(judged("normals.angle_over_area", "normals", "our angle weighting (default) / our area weighting (1 thread)",
                      over(ours("ours", "angle"), ours("ours", "area")), 2, src, higher_is_better=False))
    out.append(judged("normals.threads", "normals", "2 threads / 1 thread speed-up, angle weighting, prepared call",
                      over(ours("ours", "angle", "1", prepared=True), ours("ours", "angle", "2", prepared=True)), 1.7, src))
    area = ours("ours", "area")
    if area:
        out.append(Figure("normals.area_ms", "normals", f"our area-weighted vertex normals, {mesh}, 1 thread (median wall)",
                          f"{num(area['median_ms']):.2f} ms", "", "", src))
    reads = read_csv(os.path.join(d, "read.csv"))
    if reads:
        rmesh = max({r["mesh"] for r in reads}, key=lambda m: ("1M" in m, m))
        f = lambda **kw: next((r for r in reads if r["mesh"] == rmesh and all(r.get(a) == b for a, b in kw.items())), None)
        out.append(judged("read.obj_openmesh", "reading", f"OpenMesh `IO::read_mesh` OBJ time / ours ({rmesh})",
                          over(f(method="OpenMesh IO::read_mesh", weighting="obj"), f(method="shadetool read_mesh", weighting="obj", threads="1")), 5, src))
        out.append(judged("read.ply_fread", "reading", "our binary PLY read / `fread` of the whole file into a fresh buffer",
                          over(f(method="shadetool read_mesh", weighting="ply", threads="1"), f(method="fread", weighting="ply")), 3, src,
                          higher_is_better=False))
    e2e = read_csv(os.path.join(d, "e2e.csv"))
    ours_e = next((r for r in e2e if r["command"].startswith("shadetool normals OBJ->PLY (area)")), None)
    asm = next((r for r in e2e if r["command"] == "assimp export -gsn OBJ->PLY"), None)
    out.append(judged("e2e.assimp", "end to end", "`assimp export -gsn` time / `shadetool normals` time, 1M-triangle OBJ -> binary PLY (hyperfine, wall)",
                      over(asm, ours_e, "median"), 5, src))
    mem = read_csv(os.path.join(d, "memory.csv"))
    out.append(judged("memory.normals_rss", "memory", f"peak RSS of `shadetool normals` / the mesh arrays it holds ({mem[0]['mesh'] if mem else '4M triangles'}; the mapped input counts)",
                      num(mem[0]["ratio"]) if mem else None, 2, src, higher_is_better=False))
    return out


def lighting(args):
    txt = run(["bash", "bench/lighting/run.sh", str(args.reps)])
    src = "bench/results/lighting.txt"
    out = []
    names = {"specular": "specular skipped when ks = 0", "early_tests": "back-facing and spot-cone tests first",
             "dark_lights": "dark lights dropped", "all": "all skips, studio scene"}
    for line in txt.splitlines():
        m = re.match(r"^(\w+)\s+.*\s(\d+\.\d+)x\s+\d+\s+\d+\s*$", line)
        if m and m.group(1) in names:
            out.append(Figure(f"lighting.skip.{m.group(1)}", "lighting", f"time saved by {names[m.group(1)]} (1M points, 1 thread, thread CPU)",
                              f"{float(m.group(2)):.2f}x", "", "", src))
    if not out:
        raise RuntimeError("bench/lighting/run.sh printed no skip table")
    return out


def render(args):
    txt = run(["bash", "bench/render/run.sh", str(args.reps)])
    src = "bench/render/results.txt"
    out, threads = [], None
    for line in txt.splitlines():
        m = re.match(r"# bench_render: .*?(\d+) thread", line)
        if m:
            threads = int(m.group(1))
        f = line.split()
        if threads == 1 and len(f) >= 9 and f[0].isdigit():
            tri, shading, cpu_ratio = int(f[0]), f[1], float(f[7])
            goal = 1.2 if tri <= 10000 else (2 if shading == "gouraud" else 3)
            out.append(judged(f"render.mesa.{shading}.{tri}", "render", f"our render stage / Mesa llvmpipe's, {shading}, {tri:,} triangles, 1920x1080, 1 thread (process CPU)",
                              cpu_ratio, goal, src, higher_is_better=False))
    if not out:
        raise RuntimeError("bench/render/run.sh printed no table (libosmesa6-dev missing?)")
    png = run(["bash", "bench/render/png_encode.sh", str(max(args.reps, 7))])
    frame, worst = "", None
    for line in png.splitlines():
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(c) == 6 and c[0] and not c[1]:
            frame = c[0]
        elif len(c) == 6 and c[1] == "shadetool level 1 (default)":
            if worst is None or float(c[2]) > worst[0]:
                worst = (float(c[2]), int(c[4]), frame)
    out.append(judged("render.png_ms", "render", "PNG encoding of a 1920x1080 frame at the default level 1, the slowest of the frames "
                      f"({worst[2] if worst else '-'}, {worst[1] if worst else 0:,} bytes; median CPU ms)",
                      worst[0] if worst else None, 20, "bench/render/png_encode.sh", higher_is_better=False, unit="ms", digits=1))
    return out


def fit(args):
    # Issue 30's table: every mesh of bench/fit/results.txt (10k and 99k tori, args.reps
    # repetitions in one process; the 1M torus, run.sh's `bench_fit fresh`: every bake in a fresh
    # process of its own, 9 repetitions under the studio and 7 under the window, 1- and 3-point
    # rules only), both scenes, 1- and 3-point rules. The time goal (<= 3x point sampling)
    # is the studio's at every size; the error goal (>= 30% lower) the 10k mesh's; the window's
    # lines carry the same bounds for comparison.
    run(["bash", "bench/fit/run.sh", str(args.reps)])
    src = "bench/fit/results.txt"
    out = []
    for line in open(os.path.join(SRC, src)).read().splitlines():
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        # | mesh | scene | method | wall ms | CPU ms | x point (CPU) | relative L2 error | vs point |
        if len(c) == 8 and c[0].startswith("torus ") and c[2] in ("least squares, 1 pt", "least squares, 3 pt"):
            pts = c[2][-4]
            size = c[0].split()[1]  # 10k, 99k, 1000k
            suffix = "" if size == "10k" else f".{size}"
            out.append(judged(f"fit.{c[1]}.time.{pts}{suffix}", "least squares", f"least-squares vertex colours / point samples, process CPU time ({c[0]}, {c[1]}, {pts}-point rule)",
                              float(c[5]), 3, src, higher_is_better=False))
            if pts == "3":
                out.append(judged(f"fit.{c[1]}.error{suffix}", "least squares", f"relative L2 error against Phong, change from point samples ({c[0]}, {c[1]}, 3-point rule)",
                                  float(c[7].rstrip("%")), -30, src, higher_is_better=False, unit="%", digits=0))
    if not any(f.key.startswith("fit.studio.time.") for f in out):
        raise RuntimeError("bench/fit/results.txt has no studio rows")
    # The error goal's floor on the studio: the least error any vertex colours in [0, 1] can have
    # under this measure (the box-constrained minimum with the reference's own 12-point rule,
    # `bench_fit variants`, bench/fit/results.md "The error goal"), as a change from point samples.
    txt = run([os.path.join(args.build_dir, "bench", "fit", "bench_fit"), "variants", SRC])
    m = re.search(r"^\| torus 10k tri \| studio \| 12 \|(?:[^|]*\|){5} *(-?\d+(?:\.\d+)?)% *\|", txt, re.M)
    out.append(Figure("fit.studio.error_floor", "least squares",
                      "the least error any vertex colours in [0, 1] can have, change from point samples (torus 10k tri, studio; box-constrained minimum, 12-point rule)",
                      f"{float(m.group(1)):.1f}%" if m else "not measured", "", "", "bench/fit/results.md"))
    # The same fit without the 8-bit bounds (`--hdr`: target and colours unclamped), where the
    # floor above does not apply: `bench_fit errors` (12-point reference, λ = 0, 3-point rule).
    txt = run([os.path.join(args.build_dir, "bench", "fit", "bench_fit"), "errors", SRC, "20000"])
    m = re.search(r"^\| torus 10k tri \| studio \| HDR \|(?:[^|]*\|){5} *([+-]?\d+)% *\|", txt, re.M)
    out.append(judged("fit.studio.error_hdr", "least squares",
                      "relative L2 error against Phong without the 8-bit bounds (`--hdr`), change from point samples (torus 10k tri, studio, 3-point rule)",
                      float(m.group(1)) if m else None, -30, "bench/fit/results.md", higher_is_better=False, unit="%", digits=0))
    return out


def tangents(args):
    # Three processes, the median of their ratios. Until tangents4 a process's tangents time was
    # bimodal on this VM (fresh huge pages the host had dropped: bench/normals/results/
    # tangents_steps.md, "Bimodality"); the median of three is kept as a guard.
    src = "bench/normals/results/tangents.md"
    # Since tangents6 the figure is taken with the allocator kept warm for both rows (bench_tangents
    # --malloc warm: glibc's trim and mmap heuristics no longer make the rows fault in each other's
    # pages); one call per fresh process (faults included) is reported beside it, not judged.
    ratios, ours_ms, npm_ms, fresh = [], [], [], []
    for _ in range(3):
        txt = run(["bash", "bench/normals/tangents.sh"])
        txt += open(os.path.join(SRC, src)).read()
        m = re.search(r"tangents / normals: (\d+(?:\.\d+)?)x", txt)
        if m:
            ratios.append(float(m.group(1)))
        ours = re.search(r"MikkTSpace tangents \(ours\) \| (\d+(?:\.\d+)?)", txt)
        npm = re.search(r"npm mikktspace[^|]*\| (\d+(?:\.\d+)?)", txt)
        if ours:
            ours_ms.append(float(ours.group(1)))
        if npm:
            npm_ms.append(float(npm.group(1)))
        f = re.search(r"ratio per fresh process: (\d+(?:\.\d+)?)x", txt)
        if f:
            fresh.append(float(f.group(1)))
    med = lambda xs: sorted(xs)[len(xs) // 2] if xs else None
    out = [judged("tangents.over_normals", "tangents",
                  "MikkTSpace tangents / angle-weighted corner normals, same mesh, 1 thread, allocator kept warm (median of 3 processes)",
                  med(ratios), 3, src, higher_is_better=False)]
    out.append(Figure("tangents.fresh_over_normals", "tangents",
                      "the same ratio for one call per fresh process (faults included, 7 processes of each interleaved; median of 3 runs)",
                      ratio(med(fresh)) if fresh else "not measured", "", "", src))
    out.append(Figure("tangents.npm", "tangents", "npm `mikktspace` (the reference, WebAssembly) time / ours (medians of 3 processes)",
                      ratio(med(npm_ms) / med(ours_ms)) if ours_ms and npm_ms else "not measured", "", "", src))
    return out


def repair(args):
    # Read and repair alternate repetition by repetition in one process (bench_repair). 1 thread:
    # the goal's case, process CPU time (equal to wall on a free core, steadier under load).
    # 2 threads: what `shadetool repair` uses on this 2-core machine by default, wall time.
    env = dict(os.environ, BUILD_DIR=args.build_dir)
    src = "bench/repair/results.md"
    what = "repair (winding, orientation, normals) / reading the binary PLY"
    out = []
    for threads, key, clock, label in ((1, "repair.over_read", "CPU", "1 thread (process CPU)"),
                                       (2, "repair.over_read_2t", "wall", "2 threads, the CLI's default here (wall)")):
        txt = run(["bash", "bench/repair/run.sh", "--reps", str(max(args.reps, 7)), "--threads", str(threads), "--stages", "0"], env=env)
        m = re.search(r"repair / read, wall = (\d+(?:\.\d+)?)[^\n]*CPU = (\d+(?:\.\d+)?)", txt)
        value = float(m.group(1 if clock == "wall" else 2)) if m else None
        out.append(judged(key, "repair", f"{what}, {label}", value, 3, src, higher_is_better=False))
    return out


def gltf(args):
    env = dict(os.environ, BUILD_DIR=args.build_dir)
    txt = run(["bash", "bench/gltf/run.sh", str(args.reps)], env=env)
    src = "bench/gltf/results.md"
    out = []
    for line in txt.splitlines():
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(c) != 4:
            continue
        m = re.match(r"(\d+(?:\.\d+)?)x", c[3])
        if c[0].startswith("glb read+write") and "fresh memory" in c[0] and m:
            out.append(judged("gltf.io_over_fread", "glTF", "glb read + write in process / `fread` + `fwrite` of its bytes (1M triangles, fresh memory, process CPU time, alternating reps)",
                              float(m.group(1)), 2, src, higher_is_better=False))
        elif "assimp" in c[0] and m:
            out.append(judged("gltf.assimp", "glTF", "`assimp export -gsn` time / `shadetool normals`, 1M-triangle glb end to end",
                              float(m.group(1)), 5, src))
        elif "gltf-transform" in c[0] and m:
            out.append(Figure("gltf.gltf_transform", "glTF", "`gltf-transform copy` (read + write only) time / `shadetool normals`, same glb",
                              f"{float(m.group(1)):.1f}x", "", "", src))
    if not out:
        raise RuntimeError("bench/gltf/run.sh printed no table")
    return out


def pipeline(args):
    n = 200
    run(["bash", "bench/pipeline/run.sh", args.build_dir, str(n)])
    src = "bench/results/pipeline.md"
    rate = {}
    for line in open(os.path.join(SRC, src)).read().splitlines():
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(c) == 4 and c[0] in ("one-call-j2", "gnu-parallel-j2", "shell-loop"):
            rate[c[0]] = float(c[3])
    if "one-call-j2" not in rate:
        raise RuntimeError("no pipeline table")
    out = [Figure("pipeline.files_per_s", "pipelines", f"one call with `-j 2`, {n} meshes of 10,000 triangles, OBJ -> binary PLY (files/s)",
                  f"{rate['one-call-j2']:.0f}", "", "", src)]
    for k, what in (("shell-loop", "a shell loop, one call per file"), ("gnu-parallel-j2", "GNU parallel -j 2, one call per file")):
        if k in rate:
            out.append(Figure(f"pipeline.over_{k.replace('-', '_')}", "pipelines", f"one call with `-j 2` against {what} (files/s ratio)",
                              ratio(rate["one-call-j2"] / rate[k]), "", "", src))
    return out


def python(args):
    env = dict(os.environ, PYTHONPATH=os.path.join(args.main_build, "python"))
    txt = run(["/usr/bin/python3", "bench/python/bench_normals.py", "--build", args.main_build, "--rounds", "15"], env=env)
    src = "bench/python/results.md"
    out = []
    for line in txt.splitlines():
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(c) == 4 and c[0] == "shadetool.vertex_normals(V, F) area (arrays)":
            out.append(judged("python.open3d", "Python", "Open3D `compute_vertex_normals` / `shadetool.vertex_normals` from the same NumPy arrays (1M triangles, area weighting both, conversions included, memory recycled)",
                              float(c[3].rstrip("x")), 2, src))
        m = re.match(r"area: Python \(arrays\) / C\+\+ call = (\d+(?:\.\d+)?)x", line)
        if m:
            out.append(judged("python.over_cpp", "Python", "Python call / the C++ call on the same arrays (area)",
                              float(m.group(1)), 1.1, src, higher_is_better=False))
    if not out:
        raise RuntimeError("bench/python/bench_normals.py printed no table")
    return out


def memory(args):
    """Peak private memory (RssAnon, sampled by bench/io/peak_memory.py) of `shadetool normals` on
    the 4M-triangle irregular sphere as OBJ, written to OBJ, over the arrays the mesh must hold
    (positions 24 V, face_start 4 (F + 1), corner_vertex 12 F, vertex normals 24 V): issue 31's
    streaming goal. Median of 3 runs."""
    gen = os.path.join(args.build_dir, "bench", "shadetool_bench_generate")
    cli = os.path.join(args.build_dir, "shadetool")
    meshes = os.path.join(args.build_dir, "meshes")
    base = os.path.join(meshes, "sphere_4M_irregular")
    if not os.path.exists(base + ".obj"):
        run([gen, "--out", meshes, "--surface", "sphere", "--size", "4M", "--irregular"])
    v = f = 0
    with open(base + ".obj", "rb") as fh:
        for line in fh:
            if line.startswith(b"v "):
                v += 1
            elif line.startswith(b"f "):
                f += 1
    arrays = 24 * v + 4 * (f + 1) + 12 * f + 24 * v
    peaks = []
    out_path = os.path.join(meshes, "memory_out.obj")
    for _ in range(3):
        txt = run(["python3", "bench/io/peak_memory.py", cli, "normals", base + ".obj", "-o", out_path, "-q"])
        peaks.append(int(txt.split()[0]))
        os.remove(out_path)
    peaks.sort()
    return [judged("memory.normals_private", "memory", f"peak private memory of `shadetool normals` on the 4M-triangle OBJ, written to OBJ / the mesh arrays ({arrays / 2**20:.0f} MiB; median of 3)",
                   peaks[1] / arrays, 1.25, "bench/io/results.md", higher_is_better=False)]


def crease(args):
    """bench_crease: corner normals split at 30 degrees against angle-weighted vertex normals on the
    same mesh, one thread, process CPU (issue 31 goal 3: at most 2x)."""
    run(["cmake", "--build", args.build_dir, "-j2", "--target", "bench_crease"])
    exe = os.path.join(args.build_dir, "bench", "normals", "bench_crease")
    if not os.path.exists(exe):
        exe = os.path.join(args.build_dir, "bench", "bench_crease")
    # the corpus lies beside the source tree (/work/main -> /work/shared/corpus); from a worktree
    # (/work/wt/NAME) it is one level further up: the nearest ancestor that has one
    corpus, up = "", SRC
    while not corpus and os.path.dirname(up) != up:
        up = os.path.dirname(up)
        if os.path.isdir(os.path.join(up, "shared", "corpus")):
            corpus = os.path.join(up, "shared", "corpus")
    if not corpus:
        raise RuntimeError("crease: no shared/corpus beside any parent of " + SRC)
    files = []
    for root, _, names in os.walk(corpus):
        files += [os.path.join(root, n) for n in names if n in ("counter.unitsmm.STL", "turbineblade.ply")]
    cmd = [exe, "--reps", str(max(args.reps, 7)), "--no-reference", "--no-floor", "--no-paths"]
    for f in sorted(files):
        cmd += ["--file", f]
    txt = run(cmd)
    out = []
    for line in txt.splitlines():
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(c) == 6 and c[2] == "corner_normals angle, crease 30":
            out.append(judged(f"crease.{c[0]}", "normals", f"corner normals split at 30 degrees / angle-weighted vertex normals, {c[0]} ({int(c[1]):,} triangles, 1 thread, CPU)",
                              float(c[5].rstrip("x")), 2, "bench/normals/results/notes.md", higher_is_better=False))
    if not out:
        raise RuntimeError("bench_crease printed no rows")
    return out


def objread(args):
    """bench/io/obj_anchors.sh: our OBJ reader (1 and 2 threads) against fast_obj and rapidobj on
    the 1M- and 4M-triangle irregular spheres, one program, rows interleaved (issue 31 goal 1).
    Three processes, the median of their ratios (as tangents): on this VM a process's fresh huge
    pages are sometimes slow to touch for the whole process (bench/io/results.md, objread6), which
    moves one table's rows by up to 1.5x; the median of three is kept as a guard, every run's ratio
    printed to the log."""
    # WAIT_IDLE: the 2-thread rows need both CPUs; wait up to 2 minutes for them to be idle (the
    # script prints whether they were, and the other processes' CPU during each table).
    env = dict(os.environ, BUILD_DIR=args.build_dir, WAIT_IDLE=os.environ.get("WAIT_IDLE", "120"))

    def one_run(txt):
        tables, mesh = {}, None
        for line in txt.splitlines():
            m = re.match(r"^(\S+\.obj): [\d.]+ MB", line)
            if m:
                mesh = os.path.basename(m.group(1))[:-4]
                tables[mesh] = {"rows": {}, "others": None}
                continue
            m = re.match(r"^other processes' CPU while the table ran: .*\((\d+)% of one CPU", line)
            if m and mesh:
                tables[mesh]["others"] = float(m.group(1))
                continue
            c = [x.strip() for x in line.strip().strip("|").split("|")]
            if mesh and len(c) == 8 and not c[0].startswith("-") and c[0] != "reader":
                tables[mesh]["rows"][c[0]] = float(c[1])
        return tables

    runs = [one_run(run(["bash", "bench/io/obj_anchors.sh", str(max(args.reps, 7))], env=env)) for _ in range(3)]
    med = lambda xs: sorted(xs)[len(xs) // 2] if xs else None
    out = []
    for mesh in runs[0]:
        ratios = {"one": [], "two": [], "ro": []}
        others = []
        for r in runs:
            t = r.get(mesh)
            if not t:
                continue
            rows = t["rows"]
            one, two, fo, ro = (rows.get(k) for k in ("shadetool read_mesh, 1 thread", "shadetool read_mesh, 2 threads", "fast_obj", "rapidobj, 1 thread"))
            if one and fo:
                ratios["one"].append(fo / one)
            if two and fo:
                ratios["two"].append(fo / two)
            if one and ro:
                ratios["ro"].append(ro / one)
            if t["others"] is not None:
                others.append(t["others"])
        log(f"objread {mesh}: per run 1 thread {ratios['one']}, 2 threads {ratios['two']}, others {others}")
        if others:
            out.append(Figure(f"read.others.{mesh}", "reading", f"CPU other processes used while the OBJ reading tables ran, the most of 3 ({mesh}; the 2-thread rows need both CPUs)",
                              f"{max(others):.0f}% of one CPU", "", "", "bench/io/results.md"))
        if ratios["one"]:
            out.append(judged(f"read.fast_obj.{mesh}", "reading", f"fast_obj time / our OBJ read, 1 thread ({mesh}; ours correctly rounded, wall; median of 3 processes)",
                              med(ratios["one"]), 1, "bench/io/results.md"))
        if ratios["ro"]:
            out.append(Figure(f"read.rapidobj.{mesh}", "reading", f"rapidobj (1 thread) time / our OBJ read, 1 thread ({mesh}, wall; median of 3 processes)",
                              ratio(med(ratios["ro"])), "", "", "bench/io/results.md"))
        if ratios["two"]:
            out.append(judged(f"read.threads.{mesh}", "reading", f"fast_obj time / our OBJ read on 2 threads ({mesh}, wall; median of 3 processes)",
                              med(ratios["two"]), 1.8, "bench/io/results.md"))
    if not out:
        raise RuntimeError("bench/io/obj_anchors.sh printed no table")
    return out


def occlusion(args):
    """bench_occlusion_loop: our occlusion loop against bare Embree loops over the same rays (issue
    31 goal 2), the 1M-triangle torus knot, every 8th vertex, N = 64, process CPU."""
    run(["cmake", "--build", args.build_dir, "-j2", "--target", "bench_occlusion_loop", "make_torus_knot"])
    bench = os.path.join(args.build_dir, "bench", "visibility")
    knot = os.path.join(args.build_dir, "meshes", "knot1m.ply")
    os.makedirs(os.path.dirname(knot), exist_ok=True)
    if not os.path.exists(knot):
        run([os.path.join(bench, "make_torus_knot"), "12500", "40", knot])
    out = []
    for t in (1, 2):
        txt = run([os.path.join(bench, "bench_occlusion_loop"), knot, "--runs", "7", "--threads", str(t), "--stride", "8",
                   "--flags", "robust+compact,none", "--forms", "stream-4k,np-4k,packet8", "--other-forms", "stream-4k,np-4k"])
        m = re.search(r"shadetool against the fastest bare row with its flags: ([\d.]+); against the fastest bare row of any flags: ([\d.]+)", txt)
        mr = re.search(r"\| shadetool ambient_occlusion\S* \| [\d.]+ \| [\d.]+ \| ([\d.]+) \|", txt)
        src = "bench/visibility/results.md"
        out.append(judged(f"occlusion.bare.{t}", "occlusion", f"our occlusion loop / the fastest bare Embree loop over the same rays, same BVH flags (1M-triangle knot, N = 64, {t} thread{'s' if t > 1 else ''}, CPU)",
                          float(m.group(1)) if m else None, 1.2, src, higher_is_better=False))
        out.append(Figure(f"occlusion.nonrobust.{t}", "occlusion", f"the same against the fastest bare loop without ROBUST and COMPACT (the cost of watertight rays and a compact BVH), {t} thread{'s' if t > 1 else ''}",
                          ratio(float(m.group(2))) if m else "not measured", "", "", src))
        out.append(Figure(f"occlusion.mrays.{t}", "occlusion", f"our occlusion rays per second per thread (1M-triangle knot, {t} thread{'s' if t > 1 else ''})",
                          f"{float(mr.group(1)):.2f} Mrays/s" if mr else "not measured", "", "", src))
    return out


SOURCES = {"core": core, "memory": memory, "crease": crease, "objread": objread, "occlusion": occlusion, "lighting": lighting, "render": render, "fit": fit, "tangents": tangents, "repair": repair,
           "gltf": gltf, "pipeline": pipeline, "python": python}


def machine():
    cpu = "unknown cpu"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def loadavg():
    try:
        return " ".join(open("/proc/loadavg").read().split()[:3])
    except OSError:
        return "unknown"


def collect(args):
    started = time.time()
    head = {"date": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
            "commit": subprocess.run(["git", "-C", SRC, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip() or "unknown",
            "machine": machine(), "load_before": loadavg()}
    figures = []
    only = args.only.split(",") if args.only else list(SOURCES)
    for name in only:
        try:
            figures += SOURCES[name](args)
        except Exception as e:  # a missing anchor or tool: say so, never carry an old figure over
            log(f"{name}: not measured: {e}")
            figures.append(Figure(f"{name}.not_measured", name, f"{name}: not measured ({e})", "not measured", "", "-", ""))
    head["load_after"] = loadavg()
    head["duration_s"] = f"{time.time() - started:.0f}"
    path = os.path.join(args.results, "readme.tsv")
    with open(path, "w") as f:
        for k, v in head.items():
            f.write(f"# {k}: {v}\n")
        f.write("\t".join(COLUMNS) + "\n")
        for fig in figures:
            f.write("\t".join(str(x).replace("\t", " ") for x in fig.row()) + "\n")
    log(f"{len(figures)} figures in {path}")


def load(results):
    path = os.path.join(results, "readme.tsv")
    head, rows = {}, []
    with open(path) as f:
        lines = f.read().splitlines()
    body = []
    for line in lines:
        if line.startswith("# "):
            k, _, v = line[2:].partition(": ")
            head[k] = v
        else:
            body.append(line)
    for r in csv.DictReader(body, delimiter="\t", quoting=csv.QUOTE_NONE):
        rows.append(r)
    return head, rows


def block(head, rows):
    lines = [BEGIN,
             f"Measured by `bench/run.sh --readme` on {head.get('date', '?')} (commit {head.get('commit', '?')}; "
             f"{head.get('machine', '?')}; load average {head.get('load_before', '?')} before and {head.get('load_after', '?')} after; "
             f"{head.get('duration_s', '?')} s). Every line of `bench/results/readme.tsv`; ratios between rows of one program run, medians.",
             "",
             "| area | figure | measured | goal | |",
             "|---|---|---:|---:|---|"]
    for r in rows:
        lines.append(f"| {r['area']} | {r['what']} | {r['value']} | {r['goal']} | {r['verdict']} |")
    lines.append(END)
    return lines


def readme(args):
    head, rows = load(args.results)
    text = open(args.readme).read().splitlines()
    try:
        a, b = text.index(BEGIN), text.index(END)
    except ValueError:
        sys.exit(f"{args.readme}: no readme-figures markers")
    text[a:b + 1] = block(head, rows)
    with open(args.readme, "w") as f:
        f.write("\n".join(text) + "\n")
    log(f"{args.readme}: {len(rows)} figures")


# A performance figure: a ratio ("2.3x", "1.5-2x"), a time in ns/us/ms, a throughput.
FIGURE = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?:\s*[-–]\s*\d+(?:\.\d+)?)?x(?![\w])"
                    r"|(?<![\w.])\d+(?:\.\d+)?\s?(?:ns|us|µs|ms)\b"
                    r"|\b(?:Mrays/s|MB/s|files/s|corners per second)")


def check(args):
    problems = []
    head, rows = load(args.results)
    text = open(args.readme).read().splitlines()
    if BEGIN not in text or END not in text:
        problems.append(f"{args.readme}: no readme-figures block")
        a = b = -1
    else:
        a, b = text.index(BEGIN), text.index(END)
        for n, line in enumerate(text[a + 1:b], a + 2):
            if not line.startswith("| ") or line.startswith("| area ") or line.startswith("|---"):
                continue
            c = [x.strip() for x in line.strip().strip("|").split("|")]
            match = [r for r in rows if r["what"] == c[1]]
            if not match:
                problems.append(f"{args.readme}:{n}: figure '{c[1]}' has no line in readme.tsv")
            elif match[0]["value"] != c[2] or match[0]["goal"] != c[3]:
                problems.append(f"{args.readme}:{n}: '{c[1]}' shows {c[2]} but readme.tsv has {match[0]['value']}")
        if block(head, rows)[1:-1] != text[a + 1:b]:
            problems.append(f"{args.readme}:{a + 1}: the block differs from what readme.tsv gives (run bench/readme_figures.py readme)")
    fenced = False
    for n, line in enumerate(text, 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced or a < n - 1 <= b:
            continue
        for m in FIGURE.finditer(line):
            problems.append(f"{args.readme}:{n}: performance figure '{m.group(0)}' outside the generated block: "
                            "no run regenerates it (move it into bench/readme_figures.py, or to a bench/*/results.md)")
    for p in problems:
        print(p)
    print(f"readme figures: {len(rows)} in readme.tsv ({head.get('date', '?')}), {len(problems)} problems")
    return 1 if problems else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("command", choices=["collect", "readme", "check"])
    ap.add_argument("--results", default=os.path.join(HERE, "results"))
    ap.add_argument("--readme", default=os.path.join(SRC, "README.md"))
    ap.add_argument("--build-dir", default=os.path.join(SRC, "build-bench"))
    ap.add_argument("--main-build", default=os.path.join(SRC, "build"), help="build with the Python module")
    ap.add_argument("--only", default="")
    ap.add_argument("--reps", type=int, default=7)
    args = ap.parse_args()
    if args.command == "collect":
        collect(args)
    elif args.command == "readme":
        readme(args)
    else:
        sys.exit(check(args))


if __name__ == "__main__":
    main()
