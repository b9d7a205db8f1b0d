#!/usr/bin/env bash
# Builds and runs the repair benchmark (Release).
#
#   bench/repair/run.sh [bench_repair args]                 one process: read, whole repair, stages
#   bench/repair/run.sh --processes N [bench_repair args]   N processes of read + whole repair
#       (--stages 0), then the median over the processes of their medians: on the development VM
#       two threads vary from one process to the next far more than within one (results.md), so a
#       single process's figure can be either mode.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
processes=0
if [[ "${1:-}" == "--processes" ]]; then
  processes=${2:?--processes needs a count}
  shift 2
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j2 --target bench_repair
if (( processes == 0 )); then
  exec "$build/bench/bench_repair" "$@"
fi
ratios=()
for ((i = 1; i <= processes; ++i)); do
  out=$("$build/bench/bench_repair" "$@" --stages 0)
  read_ms=$(awk -F'|' '/read binary PLY/ {gsub(/ /, "", $3); print $3}' <<< "$out")
  repair_ms=$(awk -F'|' '/repair_mesh, whole/ {gsub(/ /, "", $3); print $3}' <<< "$out")
  control=$(sed -n 's/.*speed-up \([0-9.]*\)x.*/\1/p' <<< "$out")
  ratio=$(awk -v r="$repair_ms" -v d="$read_ms" 'BEGIN {printf "%.2f", r / d}')
  ratios+=("$ratio")
  echo "process $i: read $read_ms ms, repair $repair_ms ms, repair / read $ratio (control ${control}x)"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{a[NR] = $1} END {
  m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
  printf "repair / read over %d processes: median %.2f, range %.2f - %.2f (target < 3)\n", NR, m, a[1], a[NR]}'
