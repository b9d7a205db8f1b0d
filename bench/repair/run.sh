#!/usr/bin/env bash
# Builds and runs the repair benchmark (Release). Usage: bench/repair/run.sh [bench_repair args]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j2 --target bench_repair
"$build/bench/bench_repair" "$@"
