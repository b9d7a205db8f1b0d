#!/usr/bin/env bash
# Builds and runs the repair benchmark (Release).
#
#   bench/repair/run.sh [bench_repair args]                 one process: read, whole repair, stages
#   bench/repair/run.sh --processes N [bench_repair args]   N processes of read + whole repair
#       (--stages 0), then the median over the processes of their medians: on the development VM
#       two threads vary from one process to the next far more than within one (results.md), so a
#       single process's figure can be either mode.
#   bench/repair/run.sh --against OLD_BENCH --processes N [bench_repair args]
#       the same with another build's bench_repair (e.g. one built from an older commit) and this
#       one alternated process by process (old, new, old, new, ...), each line with its process
#       CPU ratio, then the medians of each side: an old/new comparison under the same load.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
processes=0
against=
while [[ "${1:-}" == "--processes" || "${1:-}" == "--against" ]]; do
  if [[ "$1" == "--processes" ]]; then processes=${2:?--processes needs a count}; else against=${2:?--against needs a bench_repair binary}; fi
  shift 2
done
if [[ -n "$against" ]] && (( processes == 0 )); then echo "--against needs --processes N" >&2; exit 2; fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" -j2 --target bench_repair
if (( processes == 0 )); then
  exec "$build/bench/bench_repair" "$@"
fi
sides=(new)
[[ -n "$against" ]] && sides=(old new)
declare -A wall_ratios cpu_ratios
for ((i = 1; i <= processes; ++i)); do
  for side in "${sides[@]}"; do
    bin=$build/bench/bench_repair
    [[ $side == old ]] && bin=$against
    out=$("$bin" "$@" --stages 0)
    line=$(awk -F'|' '/read binary PLY/ {rw = $3; rc = $5} /repair_mesh, whole/ {w = $3; c = $5}
      END {gsub(/ /, "", rw); gsub(/ /, "", rc); gsub(/ /, "", w); gsub(/ /, "", c);
           printf "%s %s %s %s %.2f %.2f", rw, w, rc, c, w / rw, c / rc}' <<< "$out")
    read -r read_ms repair_ms read_cpu repair_cpu wall_ratio cpu_ratio <<< "$line"
    control=$(sed -n 's/.*speed-up \([0-9.]*\)x.*/\1/p' <<< "$out")
    wall_ratios[$side]+="$wall_ratio "
    cpu_ratios[$side]+="$cpu_ratio "
    label="process $i"
    [[ -n "$against" ]] && label="$side $i"
    echo "$label: read $read_ms ms, repair $repair_ms ms, repair / read $wall_ratio wall, $cpu_ratio CPU (read $read_cpu, repair $repair_cpu ms CPU; control ${control}x; load $(cut -d' ' -f1 /proc/loadavg))"
  done
done
median() {
  tr ' ' '\n' | grep . | sort -n | awk '{a[NR] = $1} END {
    m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
    printf "median %.2f, range %.2f - %.2f", m, a[1], a[NR]}'
}
for side in "${sides[@]}"; do
  name="repair / read over $processes processes"
  [[ -n "$against" ]] && name="$side: $name"
  echo "$name: wall $(median <<< "${wall_ratios[$side]}"); CPU $(median <<< "${cpu_ratios[$side]}") (target < 3)"
done
