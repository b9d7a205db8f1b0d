#!/usr/bin/env python3
"""rounds.py BASE_BENCH_FIT NEW_BENCH_FIT SRC [ROUNDS] [REPEATS] [LABEL=BENCH_FIT ...] [--99k|--1m [studio|window]]:
`bench_fit table SRC REPEATS 20000` (the 10k torus, studio and window; with --99k or --1m the 99k
or 1M torus alone, `bench_fit table SRC REPEATS MAX MIN [SCENE]`) of two builds (and any
further LABEL=path builds, run in the same rotation, before "branch") in alternating processes, ROUNDS rounds (default
7, REPEATS 7). Per round each build's rows give the CPU ratio to its own point bake (medians of
REPEATS round-robin repetitions); printed: per (scene, method, build) the median and range of the
rounds' ratios, the median CPU ms, and the error column (deterministic), with the load average."""
import subprocess, sys, statistics

args = sys.argv[:]
size = ["20000"]
for flag, triangles in (("--1m", ["2000000", "1000000"]), ("--99k", ["200000", "90000"])):
    if flag in args:
        i = args.index(flag)
        scene = args[i + 1:i + 2] if i + 1 < len(args) and args[i + 1] in ("studio", "window") else []
        size = triangles + scene
        del args[i:i + 1 + len(scene)]
sys.argv = args
base, new, src = sys.argv[1], sys.argv[2], sys.argv[3]
rounds = int(sys.argv[4]) if len(sys.argv) > 4 else 7
reps = sys.argv[5] if len(sys.argv) > 5 else "7"
builds = [("base", base)] + [tuple(a.split("=", 1)) for a in sys.argv[6:]] + [("branch", new)]
load = lambda: open("/proc/loadavg").read().split()[0]
print(f"load average at the start: {load()}")
rows = {}  # (scene, method, build) -> list of (ratio, cpu, error, vs)
for r in range(rounds):
    for build, binary in builds:
        out = subprocess.run([binary, "table", src, reps] + size, capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            c = [x.strip() for x in line.strip().strip("|").split("|")]
            if len(c) == 8 and c[0].startswith("torus"):
                rows.setdefault((c[1], c[2], build), []).append((float(c[5]), float(c[4]), c[6], c[7]))
print(f"load average at the end: {load()}")
print("| scene | method | build | CPU ms | x point (CPU), median of rounds | range | relative L2 error | vs point |")
print("|---|---|---|---|---|---|---|---|")
for (scene, method, build), v in rows.items():
    ratios = [x[0] for x in v]
    cpu = statistics.median(x[1] for x in v)
    rng = f"{min(ratios):.2f}-{max(ratios):.2f}" if method != "point" else ""
    print(f"| {scene} | {method} | {build} | {cpu:.1f} | {statistics.median(ratios):.2f} | {rng} | {v[0][2]} | {v[0][3]} |")
