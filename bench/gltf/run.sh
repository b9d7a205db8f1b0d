#!/usr/bin/env bash
# bench/gltf/run.sh [REPS]: glTF speed, every contender in the same run, medians of REPS runs.
#  1. bench_gltf_io: read + write of a 1M-triangle .glb in one process vs fread + fwrite of its bytes,
#     the two alternating rep by rep; the ratio is of process CPU time (wall time printed beside it).
#  2. End to end, the same file: `shadetool normals` (vertex normals computed, NORMAL added, GLB
#     written) vs `assimp export -gsn` (assimp-utils: smooth normals, glb2) vs `gltf-transform copy`
#     (npm @gltf-transform/cli 4.x has no normals command; `copy` is its read + write with no
#     processing, the floor of any step of it; installed into the build tree on first use).
# Prints a Markdown table (copy it into bench/gltf/results.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build}
reps=${1:-5}
work=${TMPDIR:-/tmp}/shadetool-bench-gltf
mkdir -p "$work"
cmake -S "$root" -B "$build" -DSHADETOOL_BUILD_BENCH=ON > /dev/null
cmake --build "$build" -j2 --target bench_gltf_io shadetool_cli > /dev/null
echo "| measurement | shadetool | reference | ratio |"
echo "|---|---:|---:|---:|"
notes=$work/notes.txt
"$build/bench/bench_gltf_io" 708 707 9 "$work" 2> "$notes"                       # fresh memory, as in one CLI run
BENCH_GLTF_WARM=1 "$build/bench/bench_gltf_io" 708 707 9 "$work" 2>> "$notes"   # glibc recycling memory between repetitions
glb=$work/torus_1m.glb

gt_dir=$build/gltf-transform-node
if [ ! -x "$gt_dir/node_modules/.bin/gltf-transform" ] && command -v npm > /dev/null; then
  npm install --silent --no-audit --no-fund --prefix "$gt_dir" @gltf-transform/cli > /dev/null 2>&1 || true
fi

# median_ms CMD...: median wall time of REPS runs, in ms.
median_ms() {
  local times=()
  for _ in $(seq "$reps"); do
    local t0 t1
    t0=$(date +%s%N)
    "$@" > /dev/null 2>&1
    t1=$(date +%s%N)
    times+=($(( (t1 - t0) / 1000000 )))
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
ours=$(median_ms "$build/shadetool" normals "$glb" -o "$work/ours.glb")
echo "| \`shadetool normals\` 1M-triangle glb, end to end | $ours ms | | |"
if command -v assimp > /dev/null; then
  ai=$(median_ms assimp export "$glb" "$work/assimp.glb" -gsn)
  echo "| vs \`assimp export -gsn\` (glb) | $ours ms | $ai ms | $(awk "BEGIN {printf \"%.1fx faster\", $ai / $ours}") |"
fi
if [ -x "$gt_dir/node_modules/.bin/gltf-transform" ]; then
  gt=$(median_ms "$gt_dir/node_modules/.bin/gltf-transform" copy "$glb" "$work/gt.glb")
  echo "| vs \`gltf-transform copy\` (no normals step exists; its read + write) | $ours ms | $gt ms | $(awk "BEGIN {printf \"%.1fx faster\", $gt / $ours}") |"
else
  echo "(gltf-transform skipped: npm install @gltf-transform/cli failed)"
fi
echo
cat "$notes"
rm -rf "$work"
