#!/usr/bin/env bash
# Builds bench_obj_anchors (Release, bench build dir) and times shadetool's OBJ reader (1 and 2
# threads) against fast_obj and rapidobj on the 1M- and 4M-triangle irregular spheres of
# bench/generate. Usage: bench/io/obj_anchors.sh [REPS [--floors]]   (env: BUILD_DIR, MESH_DIR;
# --floors: bench_obj_anchors's rows that bound any reader, bench/io/results.md)
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
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'); load $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/bench_obj_anchors" --reps "${1:-9}" "${@:2}" "$meshes/sphere_1M_irregular.obj" "$meshes/sphere_4M_irregular.obj"
