#!/usr/bin/env bash
# bench/normals/run.sh [--quick]: builds bench_normals (Release, -DSHADETOOL_BUILD_BENCH=ON) and
# runs it on the irregular UV sphere and icosphere (about 1M triangles; --quick: 100k, 5 runs).
# Writes bench/normals/results/{uv,ico}.md (the tables printed) and .csv.
# Only OpenMesh is needed (a dependency of the main build already); no package is installed.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$src/build-bench}
args=()
if [ "${1:-}" = "--quick" ]; then args=(--quick); fi
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j2 --target bench_normals > /dev/null
out=$src/bench/normals/results
mkdir -p "$out"
for mesh in uv ico; do
  {
    echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
    "$build/bench/normals/bench_normals" "${args[@]}" --mesh "$mesh" --csv "$out/$mesh.csv"
  } | tee "$out/$mesh.md"
done
