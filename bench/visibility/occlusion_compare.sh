#!/usr/bin/env bash
# bench/visibility/occlusion_compare.sh REF_BIN NEW_BIN OUTDIR [MESH ...]: `occlusion` with many
# options on data/, the corpus and the given meshes, both binaries; prints the runs whose exit code,
# messages or output bytes differ, then the count. Options: N = 1, 64, 300 per face, 64 with the
# new binary on one CPU (taskset -c 0: the same bytes for any thread count), 33 with --distance
# 0.3, --error 0.05, --fit least-squares.
set -uo pipefail
ref=$1 new=$2 out=$3
shift 3
src=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$out"
mkdir -p "$out"
files="$(ls "$src"/data/*.{obj,ply,off,stl,gltf} /work/shared/corpus/*/*/*.{obj,ply,off,stl,STL,glb,gltf} 2> /dev/null) $*"
n=0 d=0
run() {  # TAG FILE ONE_CPU ARGS...
  local tag=$1 f=$2 one=$3
  shift 3
  local b ext=ply side bin
  b=$(basename "$f")
  b=${b%.*}
  case $f in *.gltf | *.glb) ext=glb ;; esac
  for side in a b; do
    bin=$ref
    [ $side = b ] && bin=$new
    if [ "$one" = 1 ] && [ $side = b ]; then
      timeout 300 taskset -c 0 "$bin" occlusion "$f" -o "$out/$side.$tag.$b.$ext" "$@" > "$out/$side.$tag.$b.log" 2>&1
    else
      timeout 300 "$bin" occlusion "$f" -o "$out/$side.$tag.$b.$ext" "$@" > "$out/$side.$tag.$b.log" 2>&1
    fi
    echo "exit $?" >> "$out/$side.$tag.$b.log"
  done
  n=$((n + 1))
  if ! cmp -s "$out/a.$tag.$b.log" "$out/b.$tag.$b.log" ||
    { { [ -e "$out/a.$tag.$b.$ext" ] || [ -e "$out/b.$tag.$b.$ext" ]; } && ! cmp -s "$out/a.$tag.$b.$ext" "$out/b.$tag.$b.$ext"; }; then
    d=$((d + 1))
    echo "DIFF $tag $f $*"
  fi
}
for f in $files; do
  run n1 "$f" 0 --samples 1
  run n64 "$f" 0 --samples 64
  run n300 "$f" 0 --samples 300 --per face
  run n64one "$f" 1 --samples 64
  run dist "$f" 0 --samples 33 --distance 0.3
  run err "$f" 0 --error 0.05 --samples 256
  run fit "$f" 0 --samples 16 --fit least-squares
done
echo "$n runs, $d differ"
