#!/usr/bin/env python3
"""polygon_triangles_cost.py BEFORE AFTER [RUNS] [DIR]: what ear clipping (geometry/polygon_triangles.h)
costs the glTF writer against the fan it replaced, on the common case, a mesh of convex quads.

Writes DIR/quads.obj (a 700 x 700 grid of quads, 490,000 faces, z = 0.05 sin 6x cos 5y) when absent,
then runs `transform quads.obj --translate 1,0,0 -q -o DIR/q_NAME.glb` with each binary, processes
alternating round-robin, RUNS rounds (default 9), and prints each binary's median process CPU time
(user + sys from os.wait4), the ratio AFTER / BEFORE, the load average before and after, and whether
the two glb files are byte-equal (convex quads: the same triangles, so they must be)."""
import math
import os
import statistics
import subprocess
import sys


def main():
    before, after = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 9
    d = sys.argv[4] if len(sys.argv) > 4 else "/tmp/polygon_triangles_cost"
    os.makedirs(d, exist_ok=True)
    src = os.path.join(d, "quads.obj")
    if not os.path.exists(src):
        n = 700
        with open(src, "w") as f:
            for j in range(n + 1):
                for i in range(n + 1):
                    x, y = i / n, j / n
                    f.write("v %.6f %.6f %.6f\n" % (x, y, 0.05 * math.sin(6 * x) * math.cos(5 * y)))
            for j in range(n):
                for i in range(n):
                    a = j * (n + 1) + i + 1
                    f.write("f %d %d %d %d\n" % (a, a + 1, a + n + 2, a + n + 1))
    bins = {"before": before, "after": after}
    cpu = {k: [] for k in bins}
    print("load before:", open("/proc/loadavg").read().strip())
    for _ in range(runs):
        for k, b in bins.items():
            p = subprocess.Popen([b, "transform", src, "--translate", "1,0,0", "-q", "-o", os.path.join(d, "q_%s.glb" % k)],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            _, status, ru = os.wait4(p.pid, 0)
            if status != 0:
                sys.exit("%s exited with status %d" % (b, status))
            cpu[k].append(ru.ru_utime + ru.ru_stime)
    print("load after:", open("/proc/loadavg").read().strip())
    for k, v in cpu.items():
        print("%-6s median %.4f s CPU  (%s)" % (k, statistics.median(v), " ".join("%.3f" % x for x in v)))
    print("after / before %.3f" % (statistics.median(cpu["after"]) / statistics.median(cpu["before"])))
    same = open(os.path.join(d, "q_before.glb"), "rb").read() == open(os.path.join(d, "q_after.glb"), "rb").read()
    print("glb byte-equal:", same)


if __name__ == "__main__":
    main()
