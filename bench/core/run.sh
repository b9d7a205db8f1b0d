#!/usr/bin/env bash
# bench/core/run.sh [BUILD_DIR]: builds bench_progress (SHADETOOL_BUILD_BENCH=ON) and runs it with
# the load average beside it. Results: bench/core/results.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build-bench}
cmake -S "$root" -B "$build" -DSHADETOOL_BUILD_BENCH=ON > /dev/null
cmake --build "$build" -j2 --target bench_progress > /dev/null
echo "load average before: $(cat /proc/loadavg)"
"$build/bench/core/bench_progress" "${@:2}"
echo "load average after: $(cat /proc/loadavg)"
