#!/usr/bin/env bash
# Pipelines at scale: start-up cost, and files per second for 1000 ~10k-triangle meshes with
#  (a) one call, -j 2;  (b) GNU parallel, one call per file, -j 2;  (c) a plain shell loop.
# Usage: bench/pipeline/run.sh [BUILD_DIR] [N]   (needs hyperfine and parallel: apt-get install)
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$src/build}
n=${2:-1000}
bin=$build/shadetool
out=$src/bench/results/pipeline.md
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
command -v hyperfine > /dev/null || apt-get install -y hyperfine > /dev/null
command -v parallel > /dev/null || apt-get install -y parallel > /dev/null
python3 "$src/bench/pipeline/make_meshes.py" "$tmp/in" "$n"
mkdir -p "$tmp/out"
hyperfine --warmup 3 --runs 30 --export-json "$tmp/startup.json" \
  "$bin --version" "$bin info $src/data/cube.obj" > /dev/null
hyperfine --warmup 1 --runs 5 --export-json "$tmp/files.json" \
  -n one-call-j2 "$bin normals $tmp/in/*.obj --output-dir $tmp/out --format ply -j 2 --quiet" \
  -n gnu-parallel-j2 "ls $tmp/in/*.obj | parallel -j 2 $bin normals {} -o $tmp/out/{/.}.ply --quiet" \
  -n shell-loop "for f in $tmp/in/*.obj; do $bin normals \$f -o $tmp/out/\$(basename \$f .obj).ply --quiet; done" \
  > /dev/null
# Where the time goes inside one call: the driver's own per-stage times (--json), summed.
"$bin" normals "$tmp"/in/*.obj --output-dir "$tmp/out" --format ply -j 1 --json > "$tmp/stages.jsonl"
python3 - "$tmp/startup.json" "$tmp/files.json" "$tmp/stages.jsonl" "$n" "$(nproc)" > "$out" <<'PY'
import json, sys
startup, files, stages, n, cores = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
print(f"# Pipelines: {n} meshes of 10,000 triangles (OBJ in, binary PLY out), {cores} cores\n")
print("Medians (hyperfine).\n\n| command | median | per file | files/s |\n|---|---|---|---|")
for r in json.load(open(files))["results"]:
    m = r["median"]
    print(f"| {r['command']} | {m:.2f} s | {1000*m/n:.2f} ms | {n/m:.0f} |")
print("\n| start-up | median |\n|---|---|")
for r in json.load(open(startup))["results"]:
    print(f"| `{r['command'].split('/')[-1]}` | {1000*r['median']:.2f} ms |")
tot = {"read": 0.0, "compute": 0.0, "write": 0.0}
for line in open(stages):
    d = json.loads(line)
    for k in tot: tot[k] += d["time_ms"][k]
s = sum(tot.values())
print("\nWhere the time of one call goes (-j 1, sum over files of the driver's stage times):\n")
print("| stage | total | share |\n|---|---|---|")
for k, v in tot.items(): print(f"| {k} | {v/1000:.2f} s | {100*v/s:.0f}% |")
PY
cat "$out"
