#!/usr/bin/env bash
# Builds and runs bench/transform: shadetool vs Open3D vs assimp on normals under a non-uniform
# scale. Installs the bench-only Debian packages (libopen3d-dev, libassimp-dev) when missing.
# Usage: bench/transform/run.sh [BUILD_DIR] [-- bench arguments]; results also go to
# BUILD_DIR/bench_transform_results.txt.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$src/build-bench}
shift || true
[ "${1:-}" = "--" ] && shift
if ! dpkg -s libopen3d-dev libassimp-dev >/dev/null 2>&1; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update && apt-get install -y libopen3d-dev libassimp-dev
fi
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target bench_transform
"$build/bench/transform/bench_transform" "$@" | tee "$build/bench_transform_results.txt"
