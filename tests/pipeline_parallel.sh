#!/usr/bin/env bash
# The README's GNU parallel recipe (examples/normals-parallel.sh) over a folder of generated
# meshes: every output exists, every JSON line says ok, and the face counts are preserved.
set -uo pipefail
bin=$1 src=$2
if ! command -v parallel >/dev/null; then echo "GNU parallel is not installed"; exit 1; fi
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/in"
n=0
for mesh in "$src"/data/*.obj "$src"/data/*.ply "$src"/data/*.off; do
  [ -f "$mesh" ] || continue
  for k in 1 2 3 4 5; do
    "$bin" transform "$mesh" -o "$tmp/in/$(basename "${mesh%.*}")-$k.obj" --translate "$k,0,0" --quiet ||
      { echo "FAIL: transform $mesh"; echo "0 passed, 1 failed"; exit 1; }
    n=$((n + 1))
  done
done
SHADETOOL=$bin bash "$src/examples/normals-parallel.sh" "$tmp/in" "$tmp/out" -j 2 > "$tmp/lines.jsonl"
code=$?
python3 - "$tmp/lines.jsonl" "$tmp/out" "$n" "$code" <<'PY'
import json, os, sys
lines, out, n, code = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
rows = [json.loads(l) for l in open(lines)]
failures = []
if code != 0: failures.append(f"parallel exited {code}")
if len(rows) != n: failures.append(f"{len(rows)} JSON lines for {n} inputs")
for r in rows:
    if r.get("status") != "ok": failures.append(f"{r.get('input')}: {r.get('error')}")
    elif not os.path.getsize(r["output"]): failures.append(f"{r['output']} is empty")
if len(os.listdir(out)) != n: failures.append(f"{len(os.listdir(out))} outputs for {n} inputs")
for f in failures: print("FAIL:", f)
print(f"{0 if failures else n} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
PY
