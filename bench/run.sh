#!/usr/bin/env bash
# bench/run.sh: shadetool's benchmarks, side by side with OpenMesh, CGAL, Open3D, assimp and
# MeshLab, on one machine. Writes bench/results/ (CSV, results.md, error_vs_time.png).
#
#   bench/run.sh            everything (about 10 minutes on 2 cores once built)
#   bench/run.sh --quick    a subset in under a minute (10k meshes, fewer runs); results go to
#                           build-bench/results-quick unless --out is given
#   bench/run.sh --readme   everything, then the module benchmarks behind the README's figures
#                           (bench/readme_figures.py: bench/results/readme.tsv), and rewrites the
#                           README's figure table from them (about 8 minutes on 2 quiet cores once built)
#   options: --no-install (do not apt-get), --build-dir DIR (default build-bench),
#            --out DIR (default bench/results), --jobs N (build jobs, default 2)
#
# It installs the anchors' Debian packages itself (apt-get, when run as root or with sudo):
# libcgal-dev libopen3d-dev libassimp-dev assimp-utils hyperfine gnuplot-nox time xvfb python3 libosmesa6-dev (the render anchor, Mesa llvmpipe),
# and meshlab when the archive has it. The main build never needs them: the benchmark targets exist
# only with -DSHADETOOL_BUILD_BENCH=ON, in a build directory of their own.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
src=$(cd "$here/.." && pwd)
quick=0 install=1 build="$src/build-bench" out="" jobs=2 readme=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --readme) readme=1 ;;
    --no-install) install=0 ;;
    --build-dir) build=$2; shift ;;
    --out) out=$2; shift ;;
    --jobs) jobs=$2; shift ;;
    -h|--help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench/run.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
  shift
done
[ $readme = 0 ] || [ $quick = 0 ] || { echo "bench/run.sh: --readme needs the full run, not --quick" >&2; exit 2; }
[ -n "$out" ] || { if [ $quick = 1 ]; then out="$build/results-quick"; else out="$here/results"; fi; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
log() { printf '[bench %s] %s\n' "$(date +%T)" "$*" >&2; }
started=$(date +%s)

# ---- 1. packages ---------------------------------------------------------------------------------
if [ $install = 1 ]; then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo=$(command -v sudo || true)
  if [ "$(id -u)" = 0 ] || [ -n "$sudo" ]; then
    want="libcgal-dev libopen3d-dev libassimp-dev assimp-utils hyperfine gnuplot-nox time xvfb python3 libosmesa6-dev"
    missing=""
    for p in $want meshlab; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
    if [ -n "$missing" ]; then
      log "installing:$missing"
      $sudo apt-get update -qq
      # meshlab only if the archive has a candidate for it
      if ! apt-cache policy meshlab 2>/dev/null | grep -q 'Candidate: [0-9]'; then
        missing=${missing/ meshlab/}
        log "meshlab has no installation candidate here: its row is skipped"
      fi
      DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing >/dev/null
    fi
  else
    log "not root and no sudo: not installing packages (missing anchors are skipped)"
  fi
fi

# ---- 2. build ------------------------------------------------------------------------------------
log "configuring $build"
mkdir -p "$build"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHADETOOL_BUILD_BENCH=ON -DSHADETOOL_BUILD_TESTS=OFF >"$build/bench-cmake.log" 2>&1 \
  || { cat "$build/bench-cmake.log" >&2; exit 1; }
grep '^-- bench:' "$build/bench-cmake.log" >&2 || true
targets="shadetool_bench_generate bench_compare_ours bench_compare_openmesh"
for t in cgal open3d assimp read; do
  grep -q "bench_compare_$t skipped" "$build/bench-cmake.log" || targets="$targets bench_compare_$t"
done
grep -q "bench_compare_read skipped" "$build/bench-cmake.log" || targets="$targets bench_check_sphere_normals"
log "building $targets shadetool_cli"
cmake --build "$build" -j"$jobs" --target $targets >"$build/bench-build.log" 2>&1 || { tail -40 "$build/bench-build.log" >&2; exit 1; }
# The CLI separately: a missing subcommand or link error skips the end-to-end part, not the rest.
cli="$build/shadetool"
if ! cmake --build "$build" -j"$jobs" --target shadetool_cli >>"$build/bench-build.log" 2>&1; then
  log "shadetool CLI did not build: end-to-end and memory rows skipped"; cli=""
elif ! "$cli" --help 2>/dev/null | grep -q '^ *normals '; then
  log "shadetool has no 'normals' subcommand yet: end-to-end and memory rows skipped"; cli=""
fi
bin="$build/bench"
meshes="$build/meshes"
# The generator's sorted edge flips must equal tests/support's map-based ones (same meshes).
"$bin/shadetool_bench_generate" --self-check >&2 || { log "generator self-check failed"; exit 1; }
mkdir -p "$meshes"

# ---- 3. machine --------------------------------------------------------------------------------
{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "mode: $([ $quick = 1 ] && echo quick || echo full)"
  echo "commit: $(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores"
  echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "compiler: $(c++ --version | head -1)"
  for p in libopenmesh-dev libcgal-dev libopen3d-dev libassimp-dev assimp-utils meshlab hyperfine libtbb-dev; do
    echo "package $p: $(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || echo 'not installed')"
  done
} >"$out/machine.txt"

# ---- 4. kernels: same mesh, same process, IO excluded -----------------------------------------
if [ $quick = 1 ]; then
  kmesh="--mesh sphere_10k_irregular --mesh degenerate"; reps=5
  refine="--mesh sphere_10k_irregular --mesh torus_10k_irregular"
else
  kmesh="--mesh sphere_1M_irregular --mesh degenerate"; reps=9
  refine="--refinement"
fi
kcsv="$out/kernels.csv"
"$bin/bench_compare_ours" $kmesh --repeats $reps >"$kcsv"
log "ours done"
for p in openmesh cgal open3d assimp; do
  if [ -x "$bin/bench_compare_$p" ]; then
    "$bin/bench_compare_$p" $kmesh --repeats $reps --no-header >>"$kcsv"
    log "$p done"
  fi
done
log "refinement"
if [ $quick = 1 ]; then
  "$bin/bench_compare_ours" $refine --repeats 3 --threads 1 >"$out/refinement.csv"
else
  # error is the point here; one timed run per row keeps 24 meshes (8 of 4M) within budget
  "$bin/bench_compare_ours" $refine --repeats 1 --threads 1 >"$out/refinement.csv"
fi
if [ -x "$bin/bench_compare_read" ]; then
  log "reading"
  "$bin/bench_compare_read" --dir "$meshes" $kmesh --repeats 5 --threads 1,2 >"$out/read.csv"
else
  rm -f "$out/read.csv"
fi

# ---- 5. end to end (hyperfine) and peak memory -------------------------------------------------
e2e_size=$([ $quick = 1 ] && echo 10k || echo 1M)
mem_size=$([ $quick = 1 ] && echo 1M || echo 4M)
"$bin/shadetool_bench_generate" --out "$meshes" --surface sphere --size $e2e_size --irregular >&2
"$bin/shadetool_bench_generate" --out "$meshes" --surface sphere --size $mem_size --irregular --format ply >&2
in="$meshes/sphere_${e2e_size}_irregular"
tmp=$(mktemp -d)
xvfb_pid=""
cleanup() { if [ -n "$xvfb_pid" ]; then kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true; fi; rm -rf "$tmp"; }
trap cleanup EXIT
runs=$([ $quick = 1 ] && echo 3 || echo 5)
cmds=()
names=()
outputs=()  # the file each command writes, checked for accuracy afterwards
# shadetool: 1 warm-up + $runs runs; the anchors (seconds per run at 1M): no warm-up (the input is
# in the page cache already), 3 runs. hyperfine's own median, mean and user+sys CPU are kept.
anchor_runs=3
if [ -n "$cli" ]; then
  cmds+=("$cli normals $in.obj -o $tmp/ours_obj.ply --weight area")
  names+=("shadetool normals OBJ->PLY (area)")
  outputs+=("$tmp/ours_obj.ply")
  cmds+=("$cli normals $in.obj -o $tmp/ours_obj_angle.ply")
  names+=("shadetool normals OBJ->PLY (angle = default)")
  outputs+=("$tmp/ours_obj_angle.ply")
  cmds+=("$cli normals $in.ply -o $tmp/ours_ply.ply --weight area")
  names+=("shadetool normals PLY->PLY (area)")
  outputs+=("$tmp/ours_ply.ply")
fi
if command -v assimp >/dev/null; then
  cmds+=("assimp export $in.obj $tmp/assimp_obj.ply -fplyb -gsn")
  names+=("assimp export -gsn OBJ->PLY")
  outputs+=("$tmp/assimp_obj.ply")
  cmds+=("assimp export $in.obj $tmp/assimp_obj_jiv.ply -fplyb -gsn -jiv")
  names+=("assimp export -gsn -jiv OBJ->PLY")
  outputs+=("$tmp/assimp_obj_jiv.ply")
  cmds+=("assimp export $in.ply $tmp/assimp_ply.ply -fplyb -gsn")
  names+=("assimp export -gsn PLY->PLY")
  outputs+=("$tmp/assimp_ply.ply")
fi
if command -v meshlabserver >/dev/null && command -v Xvfb >/dev/null; then
  # meshlabserver needs an OpenGL context even without a window: a virtual X server (Mesa), on a
  # display number it picks itself (-displayfd), stopped by its pid at exit.
  Xvfb -displayfd 3 -screen 0 640x480x24 3>"$tmp/display" >/dev/null 2>&1 &
  xvfb_pid=$!
  for _ in 1 2 3 4 5 6 7 8 9 10; do [ -s "$tmp/display" ] && break; sleep 0.5; done
  display=":$(head -1 "$tmp/display" 2>/dev/null)"
  cat >"$tmp/normals.mlx" <<'EOF'
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Re-Compute Vertex Normals">
  <Param type="RichEnum" value="1" name="weightMode" enum_val0="Simple Average" enum_val1="By Area" enum_val2="By Angle" enum_val3="As defined by N. Max" enum_cardinality="4"/>
 </filter>
</FilterScript>
EOF
  if DISPLAY=$display meshlabserver -i "$in.ply" -o "$tmp/probe.ply" -m vn -s "$tmp/normals.mlx" >"$tmp/meshlab.log" 2>&1 && [ -s "$tmp/probe.ply" ]; then
    # No OBJ row: Debian's meshlabserver 2020.09 aborts on every OBJ file (vcglib import_obj.h:640
    # assertion `(numTriangles +numVertices) == numVerticesPlusFaces+extraTriangles`), even one triangle.
    cmds+=("env DISPLAY=$display meshlabserver -i $in.ply -o $tmp/meshlab_ply.ply -m vn -s $tmp/normals.mlx")
    names+=("meshlabserver Re-Compute Vertex Normals (area) PLY->PLY")
    outputs+=("$tmp/meshlab_ply.ply")
  else
    log "meshlabserver did not run under Xvfb: its rows are skipped"; tail -5 "$tmp/meshlab.log" >&2
  fi
fi
rm -f "$out/e2e.csv" "$out/e2e.txt" "$out/e2e.json" "$out/e2e_accuracy.csv"
if [ ${#cmds[@]} -gt 0 ]; then
  log "end to end: ${#cmds[@]} commands"
  for i in "${!cmds[@]}"; do
    # One hyperfine per command: a command that fails loses its own row only.
    case "${names[$i]}" in
      shadetool*) h="--warmup 1 --runs $runs" ;;
      *) h="--warmup 0 --runs $anchor_runs" ;;
    esac
    if hyperfine -N $h --export-csv "$tmp/e2e_$i.csv" -n "${names[$i]}" "${cmds[$i]}" >>"$out/e2e.txt" 2>&1; then
      if [ -s "$out/e2e.csv" ]; then tail -n +2 "$tmp/e2e_$i.csv" >>"$out/e2e.csv"; else cp "$tmp/e2e_$i.csv" "$out/e2e.csv"; fi
    else
      log "failed: ${names[$i]} (see $out/e2e.txt)"
    fi
  done
  echo "input: sphere_${e2e_size}_irregular ($(stat -c %s "$in.obj") bytes OBJ, $(stat -c %s "$in.ply") bytes binary PLY)" >>"$out/e2e.txt"
  # Accuracy of what each command wrote (vertices on the unit sphere: exact normal = position).
  if [ -x "$bin/bench_check_sphere_normals" ]; then
    echo "command,file,vertices,mean_deg,p99_deg,max_deg,nan_or_zero,no_normals" >"$out/e2e_accuracy.csv"
    for i in "${!cmds[@]}"; do
      [ -s "${outputs[$i]}" ] || continue
      "$bin/bench_check_sphere_normals" "${outputs[$i]}" 2>/dev/null | tail -n +2 | sed "s|^$tmp/|${names[$i]},|" >>"$out/e2e_accuracy.csv" || true
    done
  fi
fi
if [ -n "$cli" ]; then
  log "peak memory on sphere_${mem_size}_irregular"
  m="$meshes/sphere_${mem_size}_irregular.ply"
  # shadetool must hold: positions 24 V, face_start 4 (F+1), corner_vertex 12 F, vertex normals 24 V.
  read -r V F < <(head -c 400 "$m" | awk '/element vertex/{v=$3} /element face/{f=$3} END{print v, f}')
  /usr/bin/time -v "$cli" normals "$m" -o "$tmp/mem.ply" --weight area 2>"$tmp/time.txt" >/dev/null \
    || { log "shadetool normals failed on $m:"; tail -5 "$tmp/time.txt" >&2; }
  rss_kb=$(awk -F': ' '/Maximum resident set size/{print $2}' "$tmp/time.txt")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/{print $2}' "$tmp/time.txt")
  {
    echo "mesh,vertices,triangles,file_bytes,array_bytes,peak_rss_bytes,ratio,wall"
    arrays=$((24 * V + 4 * (F + 1) + 12 * F + 24 * V))
    echo "sphere_${mem_size}_irregular.ply,$V,$F,$(stat -c %s "$m"),$arrays,$((rss_kb * 1024)),$(awk -v a=$arrays -v r=$((rss_kb * 1024)) 'BEGIN{printf "%.2f", r/a}'),$wall"
  } >"$out/memory.csv"
else
  rm -f "$out/memory.csv"
fi

echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out/machine.txt"
echo "wall seconds: $(( $(date +%s) - started ))" >>"$out/machine.txt"

# ---- 6. report -----------------------------------------------------------------------------------
log "report"
python3 "$here/report.py" "$out"
log "done in $(( $(date +%s) - started )) s: $out/results.md"

# ---- 7. the README's figures --------------------------------------------------------------------
if [ $readme = 1 ]; then
  python3 "$here/readme_figures.py" collect --results "$out" --build-dir "$build"
  python3 "$here/readme_figures.py" readme --results "$out"
  python3 "$here/readme_figures.py" check --results "$out"
fi
