#!/usr/bin/env bash
# bench/normals/tangents.sh: tangents per second, ours against the npm reference (installed into the
# build tree; skipped loudly without node/npm) and against angle-weighted corner normals on the same
# mesh. Writes bench/normals/results/tangents.md. The figure: both rows in one process, round-robin,
# the allocator kept warm for both (bench_tangents' default, --malloc warm); beside it, one call per
# fresh process for each row (FRESH processes of each, interleaved: what one CLI run pays).
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$src/build-bench}
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON > /dev/null
cmake --build "$build" -j2 --target bench_tangents > /dev/null
out=$src/bench/normals/results/tangents.md
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
{
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  "$build/bench/normals/bench_tangents" --n "${N:-400}" --runs "${RUNS:-7}" --fresh "${FRESH:-7}" --dump "$tmp/in.f32"
  ref=$build/mikktspace-node
  if [ ! -d "$ref/node_modules/mikktspace" ] && command -v npm > /dev/null; then
    npm install --silent --no-audit --no-fund --prefix "$ref" mikktspace > /dev/null 2>&1 || true
  fi
  if command -v node > /dev/null && [ -d "$ref/node_modules/mikktspace" ]; then
    NODE_PATH=$ref/node_modules node "$src/bench/normals/bench_tangents.js" "$tmp/in.f32" "${RUNS:-7}"
  else
    echo "skipped: npm mikktspace (no node, npm or registry)"
  fi
  echo
  echo "where the time goes, step by step: tangents_steps.md"
} | tee "$out"
