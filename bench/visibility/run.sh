#!/usr/bin/env bash
# bench/visibility/run.sh [--quick] [--blender-samples 4,16,64]: builds bench_visibility and
# make_torus_knot (Release, -DSHADETOOL_BUILD_BENCH=ON), generates a (2,3) torus-knot tube of 1M
# triangles (--quick: 100k), and writes bench/visibility/results/: ao.md (the table printed),
# occlusion_loop.md (bench_occlusion_loop, 1 and 2 threads),
# ao.csv, error_vs_time.png (gnuplot-nox, a bench dependency already), memory.md (peak RSS of
# `shadetool occlusion` on the same mesh, /usr/bin/time), and the anchors on the same mesh, points
# and reference: open3d.md/.csv (python3-open3d, under embree_mask_shim.so, built here with cc) and
# blender.md/.csv (blender, headless Cycles AO bake). An anchor whose package is missing is skipped
# with a note; the shadetool numbers need nothing beyond the main build.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${BUILD_DIR:-$src/build-bench}
along=12500 points=4000 runs=5 blender_samples=4,16,64
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) along=1250 points=500 runs=3; shift ;;
    --blender-samples) blender_samples=$2; shift 2 ;;
    *) echo "usage: run.sh [--quick] [--blender-samples N,N,...]" >&2; exit 2 ;;
  esac
done
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON > /dev/null
cmake --build "$build" -j2 --target bench_visibility bench_occlusion_loop make_torus_knot shadetool_cli > /dev/null
out=$src/bench/visibility/results
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
"$build/bench/visibility/make_torus_knot" "$along" 40 "$tmp/knot.ply" > /dev/null
{
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  "$build/bench/visibility/bench_visibility" "$tmp/knot.ply" --points "$points" --runs "$runs" --full-n 64 --csv "$out/ao.csv" --export "$tmp/points.bin"
} | tee "$out/ao.md"
# shadetool's loop against bare Embree loops over the same rays, flags and forms (results.md,
# "Occlusion loop"); on the 1M knot every 8th vertex (--quick: every vertex of the 100k knot).
stride=8
[ "$along" = 1250 ] && stride=1
{
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  for t in 1 2; do
    "$build/bench/visibility/bench_occlusion_loop" "$tmp/knot.ply" --runs 7 --threads $t --stride $stride \
      --flags robust+compact,none,robust --forms single,stream-v,stream-4k,np-4k,packet8,packet16 \
      --other-forms stream-4k,np-4k,packet16
  done
} | tee "$out/occlusion_loop.md"
# Anchors on the same mesh floats, points and reference (bench_visibility --export).
here=$src/bench/visibility
if /usr/bin/python3 -c 'import open3d' 2> /dev/null; then
  cc -O2 -shared -fPIC "$here/embree_mask_shim.c" -o "$tmp/embree_mask_shim.so" -ldl
  LD_PRELOAD="$tmp/embree_mask_shim.so" /usr/bin/python3 "$here/anchor_open3d.py" "$tmp/points.bin" "$out/ao.csv" \
    "$out/open3d.csv" --runs "$runs" | tee "$out/open3d.md"
else
  echo "Open3D anchor skipped: python3-open3d is not installed" | tee "$out/open3d.md"
fi
if command -v blender > /dev/null; then
  build_ms=$(sed -n 's/.*; build \([0-9.]*\) ms$/\1/p' "$out/ao.md")
  blender -b --factory-startup --python-exit-code 1 --python "$here/anchor_blender.py" -- "$tmp/points.bin" \
    "$out/ao.csv" "$out/blender.csv" --samples "$blender_samples" --threads "$(nproc)" --shadetool-build-ms "$build_ms" > "$tmp/blender.log" 2>&1 ||
    { tail -20 "$tmp/blender.log" >&2; exit 1; }
  grep -E '^(\||Blender [0-9.]+:|shadetool.s BVH)' "$tmp/blender.log" | tee "$out/blender.md"
else
  echo "Blender anchor skipped: blender is not installed" | tee "$out/blender.md"
fi
# Peak memory of the whole command (read, BVH, rays, write) against the mesh's arrays.
/usr/bin/time -f '%M' -o "$tmp/rss" "$build/shadetool" occlusion "$tmp/knot.ply" -o "$tmp/ao.ply" --samples 16 --stats 2> "$tmp/stats"
rss_kb=$(tail -1 "$tmp/rss")
stats=$(tail -1 "$tmp/stats")
nv=$(echo "$stats" | sed -n 's/.* vertices=\([0-9]*\).*/\1/p')
nf=$(echo "$stats" | sed -n 's/.* faces=\([0-9]*\).*/\1/p')
nc=$((3 * nf))  # the knot is all triangles
arrays=$((24 * nv + 4 * nc + 4 * (nf + 1)))  # positions (double), corners, face starts (uint32)
{
  echo "\`shadetool occlusion knot.ply -o ao.ply --samples 16\` on the $nf-triangle knot:"
  echo
  echo "- mesh arrays: $arrays bytes ($(awk "BEGIN {printf \"%.1f\", $arrays / 1e6}") MB)"
  echo "- peak RSS: $rss_kb KiB ($(awk "BEGIN {printf \"%.1f MB, %.2fx the mesh arrays\", $rss_kb * 1024 / 1e6, $rss_kb * 1024 / $arrays}"))"
  echo "- stats: $stats"
} | tee "$out/memory.md"
if command -v gnuplot > /dev/null; then
  anchors=""
  if [ -s "$out/open3d.csv" ] && head -1 "$out/open3d.csv" | grep -q samples; then
    anchors="$anchors, \"$out/open3d.csv\" skip 1 using 5:2 with linespoints title \"Open3D RaycastingScene, numpy i.i.d. rays\""
  fi
  if [ -s "$out/blender.csv" ] && head -1 "$out/blender.csv" | grep -q samples; then
    anchors="$anchors, \"$out/blender.csv\" skip 1 using (1000*\$4/$nv):2 with linespoints title \"Blender 3.4 Cycles AO bake (whole job)\""
  fi
  gnuplot <<GP
set terminal pngcairo size 800,500
set output "$out/error_vs_time.png"
set datafile separator ","
set logscale xy
set xlabel "time per vertex (microseconds, 2 threads)"
set ylabel "RMS error of the open fraction (vs 4096 samples)"
set key top right
set grid
plot "$out/ao.csv" skip 1 using 6:2 with linespoints title "shadetool occlusion (N = 4..1024)", \
     "$out/ao.csv" skip 1 using (1000*\$4/$points):2 with linespoints title "bare Embree rtcOccluded1, same rays"$anchors
GP
fi
