#!/usr/bin/env bash
# bench/visibility/peak_memory.sh MESH.ply RUNS SAMPLES BIN [BIN ...]: peak memory of
# `BIN occlusion MESH -o OUT --samples SAMPLES --stats` for each binary, the binaries alternated
# run by run (RUNS rounds). Per run: peak RSS by /usr/bin/time (%M: what results.md's ratio to the
# mesh arrays uses), the peak of RssAnon (anonymous pages: heap, Embree's BVH, thread stacks; not
# the shared code pages nor a mapped input file) sampled from /proc/PID/status every 10 ms, and
# the command's compute time (--stats). Prints one line per run, then each binary's medians, and
# whether every binary wrote the same bytes as the first.
set -euo pipefail
mesh=$1 runs=$2 samples=$3
shift 3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

measure() {  # BIN TAG RUN -> "TAG RUN peak_rss_kib peak_anon_kib compute_ms"
  local bin=$1 tag=$2 run=$3 anon=0 pid child a
  /usr/bin/time -f '%M' -o "$tmp/rss" "$bin" occlusion "$mesh" -o "$tmp/$tag.ply" --samples "$samples" --stats \
    2> "$tmp/stats" &
  pid=$!
  while kill -0 "$pid" 2> /dev/null; do
    child=$(cut -d' ' -f1 "/proc/$pid/task/$pid/children" 2> /dev/null || true)
    if [ -n "$child" ]; then
      a=$(awk '/^RssAnon:/ {print $2}' "/proc/$child/status" 2> /dev/null || true)
      if [ -n "$a" ] && [ "$a" -gt "$anon" ]; then anon=$a; fi
    fi
    sleep 0.01
  done
  wait "$pid"
  echo "$tag $run $(tail -1 "$tmp/rss") $anon $(grep -o 'compute [0-9.]*' "$tmp/stats" | cut -d' ' -f2)"
}

for run in $(seq 1 "$runs"); do
  i=0
  for bin in "$@"; do
    i=$((i + 1))
    measure "$bin" "bin$i" "$run"
  done
done | tee "$tmp/runs"
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
range() { sort -n | awk 'NR==1 {lo=$1} {hi=$1} END {print lo "-" hi}'; }
i=0
for bin in "$@"; do
  i=$((i + 1))
  col() { awk -v t="bin$i" -v c="$1" '$1==t {print $c}' "$tmp/runs"; }
  echo "bin$i $bin: peak RSS $(col 3 | median) KiB ($(col 3 | range)), peak RssAnon $(col 4 | median) KiB" \
    "($(col 4 | range)), compute $(col 5 | median) ms ($(col 5 | range))"
  if [ "$i" -gt 1 ]; then
    if cmp -s "$tmp/bin1.ply" "$tmp/bin$i.ply"; then echo "  output: the same bytes as bin1"; else echo "  output: differs from bin1"; fi
  fi
done
