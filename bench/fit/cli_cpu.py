#!/usr/bin/env python3
"""cli_cpu.py MESH SCENE BIN [BIN...] [--runs N]: process CPU time (user + sys, the whole command:
read, bake, write) of `BIN bake-lighting MESH --scene SCENE -o /tmp/... --fit point` and
`--fit least-squares --fit-samples 1|3`, without --stats (what a user runs), every binary and
method taken round-robin N times (default 11); prints medians and the ratio to the point bake."""
import os, resource, statistics, subprocess, sys, tempfile

args = [a for a in sys.argv[1:] if not a.startswith("--runs")]
runs = int(next((a.split("=")[1] for a in sys.argv[1:] if a.startswith("--runs=")), 11))
mesh, scene, bins = args[0], args[1], args[2:]
out = os.path.join(tempfile.mkdtemp(), "out.ply")
methods = [("point", ["--fit", "point"]), ("least squares, 1 pt", ["--fit", "least-squares", "--fit-samples", "1"]),
           ("least squares, 3 pt", ["--fit", "least-squares", "--fit-samples", "3"])]
cpu = {}
print(f"load average at the start: {open('/proc/loadavg').read().split()[0]}")
for _ in range(runs):
    for b in bins:
        for name, extra in methods:
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([b, "bake-lighting", mesh, "--scene", scene, "-o", out, "-q"] + extra, check=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu.setdefault((b, name), []).append(1000 * (after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime))
print(f"load average at the end: {open('/proc/loadavg').read().split()[0]}")
print("| binary | method | process CPU ms (median) | x point |\n|---|---|---|---|")
for b in bins:
    base = statistics.median(cpu[(b, "point")])
    for name, _ in methods:
        m = statistics.median(cpu[(b, name)])
        print(f"| {b} | {name} | {m:.1f} | {m / base:.2f} |")
