#!/usr/bin/env python3
"""ply_off_before_after.py BEFORE_BIN AFTER_BIN DIR [ROUNDS]: the PLY and OFF readers of two
builds of the CLI (io8: faces of fewer than 3 vertices skipped; the per-face loops of
engine/ply_body.cpp and off_format.cpp gained a flag and a corner mark), on three files in DIR
that take the general per-face loops (made by gen_torus_faces in this script: a 500k-vertex,
1M-triangle torus with a uchar face colour per face, as ascii PLY, binary PLY and OFF). Each
process runs `info --stats` and the read stage's time is taken from its report (read X ms: the
reader alone, wall time of one thread). Processes alternate before/after ROUNDS times
(round-robin, order flipped every round); medians compared. Prints /proc/loadavg at start and end."""
import math, os, re, statistics, struct, subprocess, sys


def gen_torus_faces(d, nu=1000, nv=500):
    V = [((1 + 0.3 * math.cos(2 * math.pi * j / nv)) * math.cos(2 * math.pi * i / nu),
          (1 + 0.3 * math.cos(2 * math.pi * j / nv)) * math.sin(2 * math.pi * i / nu),
          0.3 * math.sin(2 * math.pi * j / nv)) for i in range(nu) for j in range(nv)]
    F = []
    for i in range(nu):
        for j in range(nv):
            a, b, c, e = i * nv + j, ((i + 1) % nu) * nv + j, ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            F += [(a, b, c), (a, c, e)]
    col = lambda k: (k * 37 % 256, k * 91 % 256, k * 13 % 256)
    hdr = lambda fmt: ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face %d\nproperty list uchar int vertex_indices\nproperty uchar red\n"
                       "property uchar green\nproperty uchar blue\nend_header\n" % (fmt, len(V), len(F)))
    with open(os.path.join(d, "torus_ascii.ply"), "w") as f:
        f.write(hdr("ascii") + "".join("%.6g %.6g %.6g\n" % p for p in V))
        f.write("".join("3 %d %d %d %d %d %d\n" % (t + col(k)) for k, t in enumerate(F)))
    with open(os.path.join(d, "torus_bin.ply"), "wb") as f:
        f.write(hdr("binary_little_endian").encode() + b"".join(struct.pack("<3f", *p) for p in V))
        f.write(b"".join(struct.pack("<B3i3B", 3, *t, *col(k)) for k, t in enumerate(F)))
    with open(os.path.join(d, "torus.off"), "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)) + "".join("%.6g %.6g %.6g\n" % p for p in V))
        f.write("".join("3 %d %d %d %d %d %d\n" % (t + col(k)) for k, t in enumerate(F)))


before, after, d = sys.argv[1], sys.argv[2], sys.argv[3]
rounds = int(sys.argv[4]) if len(sys.argv) > 4 else 7
files = ["torus_ascii.ply", "torus_bin.ply", "torus.off"]
if not all(os.path.exists(os.path.join(d, f)) for f in files):
    os.makedirs(d, exist_ok=True)
    gen_torus_faces(d)
load = lambda: " ".join(open("/proc/loadavg").read().split()[:3])
print("load at start:", load())


def read_ms(binary, f):
    err = subprocess.run([binary, "info", "--stats", os.path.join(d, f)], check=True, capture_output=True, text=True).stderr
    return float(re.search(r"read ([0-9.]+) ms", err).group(1))


t = {(s, f): [] for s in ("before", "after") for f in files}
for i in range(rounds):
    for f in files:
        for side, b in (("before", before), ("after", after)) if i % 2 == 0 else (("after", after), ("before", before)):
            t[(side, f)].append(read_ms(b, f))
    print(f"round {i + 1}: " + "  ".join(f"{f} {t[('before', f)][-1]:.0f}/{t[('after', f)][-1]:.0f} ms" for f in files), flush=True)
print("load at end:", load())
print(f"\nmedian read stage over {rounds} processes each (ms)")
print("| file | before | after | after / before |")
print("|------|--------|-------|----------------|")
for f in files:
    b, a = statistics.median(t[("before", f)]), statistics.median(t[("after", f)])
    print(f"| {f} | {b:.0f} | {a:.0f} | {a / b:.3f} |")
