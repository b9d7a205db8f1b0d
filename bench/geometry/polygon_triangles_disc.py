#!/usr/bin/env python3
"""polygon_triangles_disc.py BEFORE AFTER [RUNS] [DIR]: what geometry/polygon_triangles.h costs on one
large polygon that is convex only up to rounding, against one that is exactly convex.

Writes DIR/disc6.obj (one face: a 20,000-corner unit disc, coordinates written with 6 decimals, so
that about 9,500 corners turn right or go straight by rounding: it fails the O(n) convex test and
takes the ear search) and DIR/disc17.obj (the same disc with 17 significant digits: convex, the
O(n) fan) when absent, then runs `transform FILE --translate 1,0,0 -q -o DIR/NAME_BIN.glb` with
each binary, processes alternating round-robin (before, after, before, ...), RUNS rounds (default
7), and prints each binary's median process CPU time (user + sys from os.wait4), the ratio
BEFORE / AFTER, the load average before and after, and whether the two glb files are byte-equal
(the same triangles in the same order: they must be)."""
import math
import os
import statistics
import subprocess
import sys


def write_disc(path, n, fmt):
    with open(path, "w") as f:
        for k in range(n):
            f.write(("v " + fmt + " " + fmt + " 0\n") % (math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)))
        f.write("f " + " ".join(str(k + 1) for k in range(n)) + "\n")


def main():
    before, after = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 7
    d = sys.argv[4] if len(sys.argv) > 4 else "/tmp/polygon_triangles_disc"
    os.makedirs(d, exist_ok=True)
    cases = {"disc6": "%.6f", "disc17": "%.17g"}
    for name, fmt in cases.items():
        if not os.path.exists(os.path.join(d, name + ".obj")):
            write_disc(os.path.join(d, name + ".obj"), 20000, fmt)
    bins = {"before": before, "after": after}
    cpu = {(c, k): [] for c in cases for k in bins}
    print("load before:", open("/proc/loadavg").read().strip())
    for _ in range(runs):
        for c in cases:
            for k, b in bins.items():
                p = subprocess.Popen([b, "transform", os.path.join(d, c + ".obj"), "--translate", "1,0,0", "-q", "-o",
                                      os.path.join(d, "%s_%s.glb" % (c, k))], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                _, status, ru = os.wait4(p.pid, 0)
                if status != 0:
                    sys.exit("%s exited with status %d on %s" % (b, status, c))
                cpu[(c, k)].append(ru.ru_utime + ru.ru_stime)
    print("load after:", open("/proc/loadavg").read().strip())
    for c in cases:
        for k in bins:
            v = cpu[(c, k)]
            print("%-6s %-6s median %.4f s CPU  (%s)" % (c, k, statistics.median(v), " ".join("%.3f" % x for x in v)))
        m_after = statistics.median(cpu[(c, "after")])
        ratio = statistics.median(cpu[(c, "before")]) / m_after if m_after > 0 else float("inf")
        same = open(os.path.join(d, c + "_before.glb"), "rb").read() == open(os.path.join(d, c + "_after.glb"), "rb").read()
        print("%-6s before / after %.2f  glb byte-equal: %s" % (c, ratio, same))


if __name__ == "__main__":
    main()
