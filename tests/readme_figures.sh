#!/usr/bin/env bash
# Every performance figure in the README reproduces: it stands in the table that
# `bench/run.sh --readme` writes, with the same value as a line of the latest results file
# (bench/results/readme.tsv), and no ratio or time stands anywhere else in the README, where no
# run would regenerate it. (bench/readme_figures.py check; the planted cases below show that the
# check fails on a figure outside the table and on a table value that the results do not hold.)
set -euo pipefail
src=$2
check="python3 $src/bench/readme_figures.py check --results $src/bench/results"
$check --readme "$src/README.md"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# planted: a speed claim in prose
{ cat "$src/README.md"; echo; echo "Reading is 3.1x faster than before."; } >"$tmp/prose.md"
if $check --readme "$tmp/prose.md" >"$tmp/out" 2>&1; then echo "a figure outside the table was not caught"; exit 1; fi
grep -q "'3.1x' outside the generated block" "$tmp/out" || { cat "$tmp/out"; exit 1; }
# planted: a table value edited by hand
python3 - "$src/README.md" "$tmp/edited.md" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
a = s.index("<!-- readme-figures: begin")
b = s.index("<!-- readme-figures: end")
block = s[a:b]
rows = [l for l in block.splitlines() if l.startswith("| ") and not l.startswith("| area ")]
assert rows, "the README's figure table is empty"
row = rows[0].split("|")
row[3] = " 99.99x "
s = s[:a] + block.replace(rows[0], "|".join(row), 1) + s[b:]
open(sys.argv[2], "w").write(s)
PY
if $check --readme "$tmp/edited.md" >"$tmp/out" 2>&1; then echo "a hand-edited figure was not caught"; exit 1; fi
grep -q "shows 99.99x but readme.tsv has" "$tmp/out" || { cat "$tmp/out"; exit 1; }
echo "3 passed, 0 failed"
