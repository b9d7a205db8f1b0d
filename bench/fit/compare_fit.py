#!/usr/bin/env python3
"""compare_fit.py REF_BIN NEW_BIN [SRC [MESH...]] [--only]: `bake-lighting --fit least-squares` (studio and window,
--fit-samples 1 and 3; 8-bit, and --hdr: float colours, the double solve) and `occlusion --fit least-squares` (--samples 8, --fit-samples 1 and 3) over
SRC/data and the real-file corpus (/work/shared/corpus) with both binaries, ASCII PLY out; prints
per run the largest difference of any colour byte (and of any other number), how many numbers
differ, and the --json stats keys of the fit whose values differ; NEW_BIN is run again without
--json, and its output must be the same bytes (the fit must not depend on whether its stats are
shown). Summary: runs and numbers that differ, per run kind the largest difference and the CG
iterations (fit_cg_iterations) of REF and NEW: how many runs fewer / equal / more. MESH...: more
files to run (e.g. a 1M-triangle torus from shadetool_bench_generate, where the 8-bit solve stores
its vectors in float); --only: those alone. Exit 0."""
import glob, json, os, subprocess, sys, tempfile

only_extra = "--only" in sys.argv  # MESH... alone, not data/ and the corpus
argv = [a for a in sys.argv if a != "--only"]
ref, new = argv[1], argv[2]
src = argv[3] if len(argv) > 3 else os.path.join(os.path.dirname(__file__), "..", "..")
files = [] if only_extra else sorted(glob.glob(f"{src}/data/*.obj") + glob.glob(f"{src}/data/*.ply") + glob.glob(f"{src}/data/*.off") +
               glob.glob(f"{src}/data/*.stl") + glob.glob("/work/shared/corpus/*/*/*.obj") +
               glob.glob("/work/shared/corpus/*/*/*.ply") + glob.glob("/work/shared/corpus/*/*/*.off") +
               glob.glob("/work/shared/corpus/*/*/*.stl") + glob.glob("/work/shared/corpus/*/*/*.STL"))
files += argv[4:]
runs = []
for scene in ("studio", "window"):
    for n in (1, 3):
        runs.append((f"bake-{scene}-{n}", ["bake-lighting", "--scene", f"{src}/data/scenes/{scene}.json",
                                           "--fit", "least-squares", "--fit-samples", str(n)]))
        runs.append((f"bake-{scene}-{n}-hdr", ["bake-lighting", "--scene", f"{src}/data/scenes/{scene}.json",
                                               "--fit", "least-squares", "--fit-samples", str(n), "--hdr"]))
for n in (1, 3):
    runs.append((f"occ-{n}", ["occlusion", "--samples", "8", "--fit", "least-squares", "--fit-samples", str(n)]))


def run(binary, args, out, json_flag=True):
    p = subprocess.run([binary] + args + ["-o", out, "--ascii"] + (["--json"] if json_flag else []),
                       capture_output=True, text=True, timeout=300)
    stats = {}
    for line in p.stdout.splitlines():
        try:
            stats = json.loads(line).get("stats", {})
        except ValueError:
            pass
    body = open(out).read().split("end_header", 1)[-1].split() if p.returncode == 0 and os.path.exists(out) else []
    return p.returncode, stats, body


tmp = tempfile.mkdtemp()
worst, differ, total, numbers, failed = {}, 0, 0, 0, 0
numbers_differ, stats_dependent, iters = 0, 0, {}  # iters: kind -> [fewer, equal, more, ref list, new list]
for f in files:
    for name, args in runs:
        total += 1
        ra, sa, ba = run(ref, args[:1] + [f] + args[1:], f"{tmp}/a.ply")
        rb, sb, bb = run(new, args[:1] + [f] + args[1:], f"{tmp}/b.ply")
        rc, _, bc = run(new, args[:1] + [f] + args[1:], f"{tmp}/c.ply", json_flag=False)
        if rc != rb or bc != bb:
            stats_dependent += 1
            print(f"{os.path.basename(f)} {name}: NEW's output differs with and without --json")
        if "fit_cg_iterations" in sa and "fit_cg_iterations" in sb:
            it = iters.setdefault(name, [0, 0, 0, [], []])
            a, b = sa["fit_cg_iterations"], sb["fit_cg_iterations"]
            it[0 if b < a else (1 if b == a else 2)] += 1
            it[3].append(a)
            it[4].append(b)
        diff = 0.0
        sizes = {}  # |difference| -> how many numbers differ by it
        numbers += len(bb)
        failed += ra != 0
        if ra != rb or len(ba) != len(bb):
            diff = float("inf")
        else:
            for x, y in zip(ba, bb):
                if x != y:
                    diff = max(diff, abs(float(x) - float(y)))
                    numbers_differ += 1
                    sizes[abs(float(x) - float(y))] = sizes.get(abs(float(x) - float(y)), 0) + 1
        keys = [k for k in sa if k.startswith("fit") or k == "point_error"]
        changed = [k for k in keys if sa.get(k) != sb.get(k)]
        worst[name] = max(worst.get(name, 0), diff)
        if diff or changed:
            differ += 1
            by_size = ", ".join(f"{n} by {d:g}" for d, n in sorted(sizes.items())[:4]) + (" ..." if len(sizes) > 4 else "")
            print(f"{os.path.basename(f)} {name}: rc {ra}/{rb}, max number difference {diff:g} ({by_size}); stats differ: " +
                  ", ".join(f"{k} {sa.get(k)} -> {sb.get(k)}" for k in changed))
print(f"{total} runs over {len(files)} files ({failed} refused by the reference, {numbers} numbers compared), {differ} differ "
      f"({numbers_differ} numbers); NEW with and without --json: {stats_dependent} differ; largest difference per run kind: " +
      ", ".join(f"{k} {v:g}" for k, v in worst.items()))
for k, (fewer, equal, more, a, b) in iters.items():
    print(f"CG iterations {k}: REF {min(a)}-{max(a)} (sum {sum(a)}), NEW {min(b)}-{max(b)} (sum {sum(b)}); "
          f"NEW fewer on {fewer}, equal on {equal}, more on {more} of {len(a)} runs")
