#!/usr/bin/env bash
# bench/visibility/occlusion_cli_time.sh REF_BIN NEW_BIN MESH RUNS N: `BIN occlusion MESH -o OUT
# --samples N --stats` on one CPU (taskset -c 0), the two binaries alternated run by run. Per run:
# user + system CPU seconds and peak RSS (KiB) by /usr/bin/time, the compute ms of --stats, and
# whether both wrote the same bytes (results.md, "Occlusion loop").
set -euo pipefail
ref=$1 new=$2 mesh=$3 runs=$4 n=$5
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for r in $(seq 1 "$runs"); do
  for tag in ref new; do
    bin=$ref
    [ "$tag" = new ] && bin=$new
    /usr/bin/time -f '%U %S %M' -o "$tmp/t.$tag" taskset -c 0 "$bin" occlusion "$mesh" -o "$tmp/o.$tag.ply" \
      --samples "$n" --stats 2> "$tmp/s.$tag"
    echo "$tag $r $(awk '{printf "%.2f %d", $1+$2, $3}' "$tmp/t.$tag") $(grep -o 'compute [0-9.]*' "$tmp/s.$tag" | cut -d' ' -f2)"
  done
  if cmp -s "$tmp/o.ref.ply" "$tmp/o.new.ply"; then echo "run $r: same bytes"; else echo "run $r: OUTPUT DIFFERS"; fi
done
