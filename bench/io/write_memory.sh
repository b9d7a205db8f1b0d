#!/usr/bin/env bash
# write_memory.sh BEFORE_BIN AFTER_BIN MESH_BASE [RUNS]: peak memory of `shadetool normals` on
# MESH_BASE.obj written to OBJ and to binary PLY, the two binaries alternating run by run.
# Prints CSV: binary,output,run,rss_anon_peak_bytes,vm_hwm_bytes,time_maxrss_kb,write_ms,arrays_bytes
#   rss_anon_peak  private (anonymous) resident memory, sampled every 0.5 ms (peak_memory.py)
#   vm_hwm         peak resident set, file-backed pages included (the mmap'd input counts there)
#   time_maxrss    /usr/bin/time -v's "Maximum resident set size" (the same VmHWM, of the largest
#                  process it waited for: shadetool)
#   arrays         what the mesh must hold, as bench/run.sh's memory row defines it: positions
#                  24 V, face_start 4 (F+1), corner_vertex 12 F, vertex normals 24 V
# Make the mesh with the bench generator (cmake -DSHADETOOL_BUILD_BENCH=ON):
#   shadetool_bench_generate --out DIR --surface sphere --size 4M --irregular
set -euo pipefail
before=$1 after=$2 base=$3 runs=${4:-5}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
read -r V F < <(awk '/^v /{v++} /^f /{f++} END{print v, f}' "$base.obj")
arrays=$((24 * V + 4 * (F + 1) + 12 * F + 24 * V))
echo "binary,output,run,rss_anon_peak_bytes,vm_hwm_bytes,time_maxrss_kb,write_ms,arrays_bytes"
for run in $(seq 1 "$runs"); do
  for out in obj ply; do
    for which in before after; do
      bin=$before; [ "$which" = after ] && bin=$after
      /usr/bin/time -v python3 "$here/peak_memory.py" "$bin" normals "$base.obj" -o "$tmp/out.$out" --json \
        >"$tmp/peak.txt" 2>"$tmp/err.txt"
      read -r anon hwm _ <"$tmp/peak.txt"
      maxrss=$(awk -F': ' '/Maximum resident set size/{print $2}' "$tmp/err.txt")
      write_ms=$(grep -o '"write":[0-9.]*' "$tmp/err.txt" | cut -d: -f2)
      echo "$which,$out,$run,$anon,$hwm,$maxrss,$write_ms,$arrays"
      rm -f "$tmp/out.$out"
    done
  done
done
