#!/usr/bin/env python3
"""quad_is_concave_cost.py BEFORE AFTER [RUNS] [DIR]: what deciding per quad whether it is concave
(geometry/polygon_triangles.h quad_is_concave: the Newell normal, 4 projected corners, 4 turns)
costs `render`, `occlusion` and the least-squares fit on a mesh of convex quads, where it changes
nothing (the outputs must be byte-equal).

Writes DIR/quads.obj (a 700 x 700 grid of quads, 490,000 faces, z = 0.05 sin 6x cos 5y, as
bench/io/polygon_triangles_cost.py) when absent, then runs
  render   `render quads.obj -o DIR/r_NAME.png --scene SRC/data/scenes/studio.json --size 400,400 -q`
  occ      `occlusion quads.obj -o DIR/o_NAME.ply --samples 1 -q`
  fit      `bake-lighting quads.obj -o DIR/f_NAME.ply --scene SRC/data/scenes/studio.json --fit least-squares --fit-samples 1 -q`
with each binary, processes alternating round-robin, RUNS rounds (default 7), and prints each
binary's median process CPU time (user + sys from os.wait4), the ratio AFTER / BEFORE, the load
average before and after, and whether the outputs are byte-equal. SRC: the environment variable
SRC or this checkout."""
import math
import os
import statistics
import subprocess
import sys


def main():
    before, after = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    d = sys.argv[4] if len(sys.argv) > 4 else "/tmp/quad_is_concave_cost"
    src = os.environ.get("SRC", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    os.makedirs(d, exist_ok=True)
    mesh = os.path.join(d, "quads.obj")
    if not os.path.exists(mesh):
        n = 700
        with open(mesh, "w") as f:
            for j in range(n + 1):
                for i in range(n + 1):
                    x, y = i / n, j / n
                    f.write("v %.6f %.6f %.6f\n" % (x, y, 0.05 * math.sin(6 * x) * math.cos(5 * y)))
            for j in range(n):
                for i in range(n):
                    a = j * (n + 1) + i + 1
                    f.write("f %d %d %d %d\n" % (a, a + 1, a + n + 2, a + n + 1))
    studio = os.path.join(src, "data", "scenes", "studio.json")
    cases = {
        "render": lambda o: ["render", mesh, "-o", o + ".png", "--scene", studio, "--size", "400,400", "-q"],
        "occ": lambda o: ["occlusion", mesh, "-o", o + ".ply", "--samples", "1", "-q"],
        "fit": lambda o: ["bake-lighting", mesh, "-o", o + ".ply", "--scene", studio, "--fit", "least-squares",
                          "--fit-samples", "1", "-q"],
    }
    ext = {"render": ".png", "occ": ".ply", "fit": ".ply"}
    bins = {"before": before, "after": after}
    cpu = {(c, k): [] for c in cases for k in bins}
    print("load before:", open("/proc/loadavg").read().strip())
    for _ in range(runs):
        for c, args in cases.items():
            for k, b in bins.items():
                p = subprocess.Popen([b] + args(os.path.join(d, "%s_%s" % (c, k))), stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL)
                _, status, ru = os.wait4(p.pid, 0)
                if status != 0:
                    sys.exit("%s exited with status %d on %s" % (b, status, c))
                cpu[(c, k)].append(ru.ru_utime + ru.ru_stime)
    print("load after:", open("/proc/loadavg").read().strip())
    for c in cases:
        for k in bins:
            v = cpu[(c, k)]
            print("%-6s %-6s median %.4f s CPU  (%s)" % (c, k, statistics.median(v), " ".join("%.3f" % x for x in v)))
        m_before = statistics.median(cpu[(c, "before")])
        ratio = statistics.median(cpu[(c, "after")]) / m_before if m_before > 0 else float("inf")
        same = (open(os.path.join(d, c + "_before" + ext[c]), "rb").read() ==
                open(os.path.join(d, c + "_after" + ext[c]), "rb").read())
        print("%-6s after / before %.3f  byte-equal: %s" % (c, ratio, same))


if __name__ == "__main__":
    main()
