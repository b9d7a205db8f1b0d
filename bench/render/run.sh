#!/usr/bin/env bash
# Builds bench_render (needs libosmesa6-dev) and runs it for 1 and 2 threads; the tables go to
# stdout and bench/render/results.txt (bench/render/results.md is the reading of a committed run).
# Usage: bench/render/run.sh [REPEATS]   (default 5)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target bench_render >/dev/null
{
  "$build/bench/render/bench_render" 1 "${1:-5}"
  "$build/bench/render/bench_render" 2 "${1:-5}"
} | tee "$root/bench/render/results.txt.tmp"
mv "$root/bench/render/results.txt.tmp" "$root/bench/render/results.txt"
