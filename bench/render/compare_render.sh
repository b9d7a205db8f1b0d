#!/bin/bash
# compare_render.sh REF_BIN NEW_BIN OUTDIR: `render` runs (PNG and PFM; flat, Gouraud, Phong; 1 and 2x2
# samples; shadows; backgrounds; odd sizes; Phong in PFM under three scenes; three 1920x1080 frames) over data/ and the shared corpus
# with both binaries; lists the runs whose output (exit code, messages, image bytes) differs.
ref=$1; new=$2; out=$3; src="$(cd "$(dirname "$0")/../.." && pwd)"
rm -rf $out; mkdir -p $out/a $out/b
files=$(ls $src/data/*.{obj,ply,off,stl,gltf} /work/shared/corpus/*/*/*.{obj,ply,off,stl,STL,glb,gltf} 2>/dev/null)
n=0; d=0
run() { local name=$1 ext=$2; shift 2
  for side in a b; do bin=$ref; [ $side = b ] && bin=$new
    timeout 300 $bin "${@/OUT/$out/$side/$name.$ext}" > $out/$side/$name.stdout 2>&1; echo $? >> $out/$side/$name.stdout
  done
  n=$((n+1))
  if ! cmp -s $out/a/$name.stdout $out/b/$name.stdout || { { [ -e $out/a/$name.$ext ] || [ -e $out/b/$name.$ext ]; } && ! cmp -s $out/a/$name.$ext $out/b/$name.$ext; }; then d=$((d+1)); echo "DIFF $name: $*"; fi
  rm -f $out/a/$name.$ext $out/b/$name.$ext
}
for f in $files; do b=$(basename $f); b=${b%.*}
  run g_$b pfm render $f -o OUT --shading gouraud --size 331,197 --hdr -q --threads 2
  run gp_$b png render $f -o OUT --shading gouraud --size 640,360 -q --scene $src/data/scenes/window.json
  run f_$b pfm render $f -o OUT --shading flat --size 200,150 --samples 2 --hdr -q --background 0.2,0.3,0.1
  run p_$b png render $f -o OUT --size 333,250 -q --scene $src/data/scenes/studio.json
  run ps_$b pfm render $f -o OUT --size 160,120 -q --hdr --shadows --shadow-samples 4 --samples 2
  run ph_$b pfm render $f -o OUT --size 333,250 -q --hdr --scene $src/data/scenes/studio.json
  run phw_$b pfm render $f -o OUT --size 320,240 -q --hdr --scene $src/data/scenes/window.json --model phong
  run phd_$b pfm render $f -o OUT --size 256,256 -q --hdr --threads 1
done
for f in $src/data/torus.obj $src/data/torus_knot.ply /work/shared/corpus/c3d/spot/spot.obj; do b=$(basename $f); b=${b%.*}
  run hd_$b png render $f -o OUT --size 1920,1080 -q --scene $src/data/scenes/studio.json
  run hdg_$b pfm render $f -o OUT --size 1920,1080 -q --shading gouraud --hdr --threads 1
  run hdp_$b pfm render $f -o OUT --size 1920,1080 -q --hdr --scene $src/data/scenes/studio.json
done
echo "$n runs, $d differ"
