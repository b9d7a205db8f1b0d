#!/usr/bin/env python3
"""polygon_split_cost.py BEFORE AFTER [RUNS] [DIR]: what splitting polygons of 5+ corners by
geometry/polygon_triangles.h (ear clipping) costs `render` against the fan from corner 0 it
replaced, on convex hexagons (where both give the same triangles, so the images must be equal),
and on the same hexagons written as 4 triangles each (the common case: what a triangle mesh pays).

Writes DIR/hexagons.obj (a 300 x 300 grid of regular hexagons, 90,000 faces, each with its own 6
vertices, z = 0.05 sin 6x cos 5y at the centre) and DIR/triangles.obj (the same, each hexagon as
the 4 triangles of its fan) when absent, then runs, per mesh,
`render MESH.obj -o DIR/MESH_NAME.png --size 400,400 --shading flat -q` with each binary,
processes alternating round-robin, RUNS rounds (default 9), and prints each binary's median process
CPU time (user + sys from os.wait4), the ratio AFTER / BEFORE, the load average before and after,
and whether the two PNG files are byte-equal."""
import math
import os
import statistics
import subprocess
import sys


def main():
    before, after = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 9
    d = sys.argv[4] if len(sys.argv) > 4 else "/tmp/polygon_split_cost"
    os.makedirs(d, exist_ok=True)
    for kind in ("hexagons", "triangles"):
        src = os.path.join(d, kind + ".obj")
        if not os.path.exists(src):
            n, r = 300, 0.5 / 300
            with open(src, "w") as f:
                k = 0
                for j in range(n):
                    for i in range(n):
                        cx, cy = (i + 0.5 * (j % 2)) / n, j * math.sqrt(3) / 2 / n
                        z = 0.05 * math.sin(6 * cx) * math.cos(5 * cy)
                        for a in range(6):
                            t = math.pi / 6 + a * math.pi / 3
                            f.write("v %.7f %.7f %.7f\n" % (cx + r * math.cos(t), cy + r * math.sin(t), z))
                        if kind == "hexagons":
                            f.write("f %s\n" % " ".join(str(k + a + 1) for a in range(6)))
                        else:
                            for a in range(1, 5):
                                f.write("f %d %d %d\n" % (k + 1, k + a + 1, k + a + 2))
                        k += 6
        bins = {"before": before, "after": after}
        cpu = {k: [] for k in bins}
        print("%s: load before:" % kind, open("/proc/loadavg").read().strip())
        for _ in range(runs):
            for k, b in bins.items():
                p = subprocess.Popen([b, "render", src, "-o", os.path.join(d, "%s_%s.png" % (kind, k)), "--size", "400,400",
                                      "--shading", "flat", "-q"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                _, status, ru = os.wait4(p.pid, 0)
                if status != 0:
                    sys.exit("%s exited with status %d" % (b, status))
                cpu[k].append(ru.ru_utime + ru.ru_stime)
        print("%s: load after:" % kind, open("/proc/loadavg").read().strip())
        for k, v in cpu.items():
            print("%s: %-6s median %.4f s CPU  (%s)" % (kind, k, statistics.median(v), " ".join("%.3f" % x for x in v)))
        print("%s: after / before %.3f" % (kind, statistics.median(cpu["after"]) / statistics.median(cpu["before"])))
        same = open(os.path.join(d, "%s_before.png" % kind), "rb").read() == open(os.path.join(d, "%s_after.png" % kind), "rb").read()
        print("%s: png byte-equal:" % kind, same)


if __name__ == "__main__":
    main()
