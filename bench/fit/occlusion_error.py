#!/usr/bin/env python3
"""Rays and time for `occlusion --error E` against fixed `--samples N` to reach an RMS error
(issue 30). Reference: --samples 16384 (its own RMS error about 3e-4 at the N^-3/4 rate).
Usage: bench/fit/occlusion_error.py SHADETOOL MESH  (prints a markdown table)."""
import json, subprocess, sys, tempfile, os

def run(bin_, mesh, args):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "ao.ply")
        p = subprocess.run([bin_, "occlusion", mesh, "-o", out, "--as", "quality", "--ascii", "--json"] + args,
                           capture_output=True, text=True, check=True)
        s = json.loads(p.stdout)
        with open(out) as f:
            lines = f.read().split("\n")
        hdr = lines.index("end_header")
        props = [l.split()[-1] for l in lines[:hdr] if l.startswith("property") and "list" not in l]
        nv = int([l for l in lines if l.startswith("element vertex")][0].split()[-1])
        qi = props.index("quality")
        q = [float(lines[hdr + 1 + i].split()[qi]) for i in range(nv)]
        return q, s["stats"]["rays"], s["time_ms"]["compute"]

def rms(a, b):
    return (sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)) ** 0.5

bin_, mesh = sys.argv[1], sys.argv[2]
ref, _, _ = run(bin_, mesh, ["--samples", "16384"])
print("| run | RMS error vs 16384 rays | rays | compute ms |\n|---|---|---|---|")
for n in [32, 64, 128, 256, 512, 1024]:
    q, rays, ms = run(bin_, mesh, ["--samples", str(n)])
    print(f"| --samples {n} | {rms(q, ref):.5f} | {rays} | {ms:.0f} |")
for e in [0.04, 0.02, 0.01, 0.005]:
    q, rays, ms = run(bin_, mesh, ["--error", str(e)])
    print(f"| --error {e} | {rms(q, ref):.5f} | {rays} | {ms:.0f} |")
