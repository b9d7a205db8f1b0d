#!/usr/bin/env bash
# bench/visibility/peak_memory.sh OLD_BIN NEW_BIN MESH.ply [RUNS] [SAMPLES]: peak memory of
# `shadetool occlusion MESH -o OUT --samples SAMPLES --stats` (default 5 runs, N = 16), the two
# binaries alternated run by run. Per run: peak RSS by /usr/bin/time (%M, what results.md's ratio
# uses) and the peak of RssAnon (anonymous pages: heap, Embree's BVH, thread stacks; not the
# shared code pages) sampled from /proc/PID/status every 10 ms, and the command's compute time.
# Prints one line per run and the medians; the outputs of the two binaries are compared with cmp.
set -euo pipefail
old=$1 new=$2 mesh=$3 runs=${4:-5} samples=${5:-16}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

measure() {  # BIN TAG RUN -> "TAG RUN peak_rss_kib peak_anon_kib compute_ms"
  local bin=$1 tag=$2 run=$3 anon=0 pid child a
  /usr/bin/time -f '%M' -o "$tmp/rss" "$bin" occlusion "$mesh" -o "$tmp/$tag.ply" --samples "$samples" --stats \
    2> "$tmp/stats" &
  pid=$!
  while kill -0 "$pid" 2> /dev/null; do
    child=$(cat "/proc/$pid/task/$pid/children" 2> /dev/null | cut -d' ' -f1 || true)
    if [ -n "$child" ]; then
      a=$(awk '/^RssAnon:/ {print $2}' "/proc/$child/status" 2> /dev/null || true)
      [ -n "$a" ] && [ "$a" -gt "$anon" ] && anon=$a
    fi
    sleep 0.01
  done
  wait "$pid"
  echo "$tag $run $(tail -1 "$tmp/rss") $anon $(grep -o 'compute [0-9.]*' "$tmp/stats" | cut -d' ' -f2)"
}

for run in $(seq 1 "$runs"); do
  measure "$old" old "$run"
  measure "$new" new "$run"
done | tee "$tmp/runs"
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
for tag in old new; do
  echo "$tag median: peak RSS $(awk -v t=$tag '$1==t {print $3}' "$tmp/runs" | median) KiB," \
    "peak RssAnon $(awk -v t=$tag '$1==t {print $4}' "$tmp/runs" | median) KiB," \
    "compute $(awk -v t=$tag '$1==t {print $5}' "$tmp/runs" | median) ms"
done
if cmp -s "$tmp/old.ply" "$tmp/new.ply"; then echo "output: the same bytes"; else echo "output: differs"; fi
