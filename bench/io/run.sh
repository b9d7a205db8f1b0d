#!/usr/bin/env bash
# Builds and runs the IO reading benchmark (Release). Usage: bench/io/run.sh [NU NV REPS]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j2 --target bench_io_read
"$build/bench/bench_io_read" "${1:-1000}" "${2:-500}" "${3:-7}" "${TMPDIR:-/tmp}"
