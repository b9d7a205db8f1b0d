#!/usr/bin/env python3
"""obj_before_after.py BEFORE_BENCH AFTER_BENCH [ROUNDS [REPS]]: the OBJ reader of two builds of
bench_obj_anchors (bench/io/obj_anchors.cpp: `before`, e.g. built from the branch's base commit,
and `after`), on the 1M- and 4M-triangle irregular spheres (bench/io/obj_anchors.sh makes them in
MESH_DIR). Two programs cannot share a table, so each process's shadetool rows are taken as ratios
to fast_obj's row of the same table (the in-process anchor: the reader no build changes), processes
alternating before/after ROUNDS times (round-robin), and the medians of those ratios compared:
1-thread rows by process CPU time, 2-thread rows by wall time (as obj_anchors.cpp says) and by
CPU time (the work of both threads: what a busy machine still lets one compare). Prints
every process's ratios, the medians and /proc/loadavg at start and end."""
import os, re, statistics, subprocess, sys

before, after = sys.argv[1], sys.argv[2]
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 7
reps = sys.argv[4] if len(sys.argv) > 4 else "5"
meshes = os.environ.get("MESH_DIR", "/tmp/shadetool-obj-anchors")
files = [f"{meshes}/sphere_1M_irregular.obj", f"{meshes}/sphere_4M_irregular.obj"]
load = lambda: open("/proc/loadavg").read().split()[:3]
print("load at start:", *load())


def one(bench):
    out = subprocess.run([bench, "--reps", reps, "--only", "shadetool read_mesh,fast_obj", *files],
                         check=True, capture_output=True, text=True).stdout
    tables, mesh = {}, None
    for line in out.splitlines():
        m = re.match(r"^\S*sphere_(\w+)_irregular\.obj: ", line)
        if m:
            mesh = m.group(1)
            tables[mesh] = {}
            continue
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if mesh and len(c) == 8 and c[0] and not c[0].startswith("-") and c[0] != "reader":
            tables[mesh][c[0]] = (float(c[1]), float(c[5]))  # median wall ms, median CPU ms
    r = {}
    for mesh, rows in tables.items():
        fo = rows["fast_obj"]
        r[(mesh, "1 thread, CPU")] = rows["shadetool read_mesh, 1 thread"][1] / fo[1]
        r[(mesh, "2 threads, wall")] = rows["shadetool read_mesh, 2 threads"][0] / fo[0]
        # The work two threads did (on a busy machine the wall row measures the other processes)
        r[(mesh, "2 threads, CPU")] = rows["shadetool read_mesh, 2 threads"][1] / fo[1]
    return r


runs = {"before": [], "after": []}
for i in range(rounds):
    for side, bench in (("before", before), ("after", after)) if i % 2 == 0 else (("after", after), ("before", before)):
        r = one(bench)
        runs[side].append(r)
        print(f"round {i + 1} {side:6s} " + "  ".join(f"{m} {k}: {v:.3f}" for (m, k), v in sorted(r.items())), flush=True)
print("load at end:", *load())
print(f"\nmedians over {rounds} processes each of shadetool / fast_obj (below 1: faster than fast_obj)")
print("| mesh | row | before | after | after / before |")
print("|------|-----|--------|-------|----------------|")
for key in sorted(runs["before"][0]):
    b = statistics.median(r[key] for r in runs["before"])
    a = statistics.median(r[key] for r in runs["after"])
    print(f"| {key[0]} | shadetool {key[1]} | {b:.3f} | {a:.3f} | {a / b:.3f} |")
