#!/usr/bin/env bash
# The shared driver of every subcommand: several inputs, --output-dir, -j, stdin/stdout, JSON
# Lines, a failing file that does not stop the others, exit codes, no output on failure.
set -uo pipefail
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
check() {  # check NAME CONDITION...
  local name=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL: $name"; fi
}
cp "$src/data/torus.obj" "$tmp/a.obj"; cp "$src/data/cube.obj" "$tmp/b.obj"
printf 'v 0 0 0\nf 1 2 3\n' > "$tmp/bad.obj"
mkdir "$tmp/out"

# Several inputs into a directory, in parallel; one bad file fails alone.
"$bin" normals "$tmp/a.obj" "$tmp/bad.obj" "$tmp/b.obj" --output-dir "$tmp/out" --format ply -j 2 --json > "$tmp/lines.jsonl" 2> "$tmp/err.txt"
code=$?
check "exit 1 when one of several files fails" test "$code" -eq 1
check "good outputs written" test -s "$tmp/out/a.ply" -a -s "$tmp/out/b.ply"
check "no output for the bad file" test ! -e "$tmp/out/bad.ply"
check "three JSON lines" test "$(wc -l < "$tmp/lines.jsonl")" -eq 3
check "JSON lines parse, 2 ok and 1 error" python3 -c '
import json,sys
rows=[json.loads(l) for l in open(sys.argv[1])]
st=sorted(r["status"] for r in rows)
assert st==["error","ok","ok"], st
bad=[r for r in rows if r["status"]=="error"][0]
assert "bad.obj" in bad["error"] and bad["input"].endswith("bad.obj")
ok=[r for r in rows if r["status"]=="ok"][0]
assert set(ok["time_ms"])=={"read","compute","write"} and ok["stats"]["faces"]>0
' "$tmp/lines.jsonl"
check "error line names the file" grep -q "bad.obj" "$tmp/err.txt"

# All good: exit 0.
"$bin" normals "$tmp/a.obj" "$tmp/b.obj" --output-dir "$tmp/out" -j 1 --quiet
check "exit 0 when all succeed" test $? -eq 0
check "extension from the input" test -s "$tmp/out/a.obj"

# stdin and stdout.
"$bin" normals - --input-format obj -o - --format ply < "$tmp/a.obj" > "$tmp/piped.ply"
check "stdin to stdout" test $? -eq 0 -a -s "$tmp/piped.ply"
check "stdout is a PLY" grep -qa '^end_header' "$tmp/piped.ply"

# Usage errors exit 2.
"$bin" normals "$tmp/a.obj" "$tmp/b.obj" -o "$tmp/x.ply" 2>/dev/null
check "-o with two inputs is a usage error" test $? -eq 2
"$bin" normals - -o "$tmp/x.ply" < /dev/null 2>/dev/null
check "stdin without --input-format is a usage error" test $? -eq 2
"$bin" normals "$tmp/a.obj" --no-such-flag 2>/dev/null
check "unknown flag exits 2" test $? -eq 2
"$bin" normals "$tmp/a.obj" --output-dir "$tmp/missing-dir" 2>/dev/null
check "missing output directory exits 1" test $? -eq 1

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
