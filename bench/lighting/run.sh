#!/usr/bin/env bash
# Builds and runs bench_lighting; the report goes to stdout and bench/results/lighting.txt.
# Usage: bench/lighting/run.sh [REPEATS]   (default 7; medians of REPEATS runs per configuration)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target bench_lighting >/dev/null
mkdir -p "$root/bench/results"
"$build/bench/lighting/bench_lighting" "${1:-7}" | tee "$root/bench/results/lighting.txt.tmp"
mv "$root/bench/results/lighting.txt.tmp" "$root/bench/results/lighting.txt"
