#!/usr/bin/env bash
# Builds bench_obj_anchors (Release, bench build dir) and times shadetool's OBJ reader (1 and 2
# threads) against fast_obj and rapidobj on the 1M- and 4M-triangle irregular spheres of
# bench/generate. Usage: bench/io/obj_anchors.sh [REPS [--floors]]   (env: BUILD_DIR, MESH_DIR;
# --floors: bench_obj_anchors's rows that bound any reader, bench/io/results.md; WAIT_IDLE=SECONDS:
# first wait up to that long for 2 seconds in which the CPUs are at least 95% idle, and say whether
# they were: the 2-thread rows measure two threads only when no other process holds a CPU)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
meshes=${MESH_DIR:-${TMPDIR:-/tmp}/shadetool-obj-anchors}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j2 --target bench_obj_anchors shadetool_bench_generate > /dev/null
mkdir -p "$meshes"
for size in 1M 4M; do
  [ -s "$meshes/sphere_${size}_irregular.obj" ] ||
    "$build/bench/shadetool_bench_generate" --out "$meshes" --surface sphere --size $size --irregular --format obj > /dev/null
done
if [ "${WAIT_IDLE:-0}" -gt 0 ]; then
  start=$(date +%s)
  while :; do
    a=($(head -1 /proc/stat)); sleep 2; b=($(head -1 /proc/stat))
    total=0; for i in 1 2 3 4 5 6 7 8; do total=$((total + b[i] - a[i])); done
    idle=$(( (b[4] - a[4]) * 100 / (total > 0 ? total : 1) ))
    if [ "$idle" -ge 95 ]; then echo "idle: ${idle}% of the CPUs over 2 s, after $(( $(date +%s) - start )) s"; break; fi
    if [ $(( $(date +%s) - start )) -ge "$WAIT_IDLE" ]; then echo "idle: not reached in ${WAIT_IDLE} s (last 2 s: ${idle}%): another process holds a CPU"; break; fi
  done
fi
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'); load $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/bench_obj_anchors" --reps "${1:-9}" "${@:2}" "$meshes/sphere_1M_irregular.obj" "$meshes/sphere_4M_irregular.obj"
