#!/usr/bin/env bash
# Builds bench_fit and writes bench/fit/results.txt (the table) and bench/fit/side_by_side.png.
# Usage: bench/fit/run.sh [REPEATS] [MAX_TRIANGLES]   (default 7, 200000: the 10k and 100k tori
# with REPEATS repetitions; then the 1M torus with the point bake and least squares at 1 and 3
# points, its rows appended: the studio 9 repetitions, the window 7, every 1M bake in a fresh
# process of its own (`bench_fit fresh`: one bake per process as bake-lighting runs it, the methods
# alternating process by process; in one process the 1M point bake's time moved with the heap state
# the rows before it left: bench/fit/results.md, fit10). About 90 s together on an idle machine.
# results.md's other tables: `bench_fit breakdown SRC 11 20000`, `bench_fit variants SRC`,
# `bench_fit errors SRC 20000`, `FIT_MALLOC_KEEP=1 bench_fit floor SRC 11 20000` (the ratio's
# floor), and the base/branch rounds of `bench_fit table SRC 7 20000` (rounds.py; `--1m`: of the
# 1M torus) described there.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target bench_fit >/dev/null
"$build/bench/fit/bench_fit" table "$root" "${1:-7}" "${2:-200000}" | tee "$root/bench/fit/results.txt.tmp"
# The 1M torus (issue 30 asks for 10k, 100k and 1M): its rows appended to the table.
"$build/bench/fit/bench_fit" fresh "$root" 9 2000000 1000000 studio 1,3 | grep '^| torus' | tee -a "$root/bench/fit/results.txt.tmp"
"$build/bench/fit/bench_fit" fresh "$root" 7 2000000 1000000 window 1,3 | grep '^| torus' | tee -a "$root/bench/fit/results.txt.tmp"
mv "$root/bench/fit/results.txt.tmp" "$root/bench/fit/results.txt"
"$build/bench/fit/bench_fit" picture "$root" "$root/bench/fit/side_by_side.png"
