// check_colours.mjs TRUTH.glb BYTES.glb BYTES.ply: what three.js (npm `three`, its GLTFLoader and
// PLYLoader, as a web viewer loads files) shows for baked colours. TRUTH.glb is the bake with --hdr
// (float COLOR_0: the linear values themselves, clamped here to [0, 1] as the 8-bit files are);
// each vertex of the other two files, matched by position, must come out as the same
// linear colour within its quantisation: glTF ubyte COLOR_0 is linear (half a step, 0.5/255),
// PLY bytes are read as sRGB, linearised and stored back as bytes by PLYLoader (half an sRGB step,
// at most 0.5/255 times the curve's largest slope 2.28 = 0.00446, plus half a byte of the
// re-quantised linear value, 0.00196: 0.0065). Before the colour rule (issue 28 item 1) the PLY
// bytes were linear and this reads 0.288. Prints the largest differences; exits 1 over a bound.
import { readFileSync } from 'node:fs';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';

const [truthPath, glbPath, plyPath] = process.argv.slice(2);

function arrayBuffer(path) {
  const b = readFileSync(path);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
}

function gltfGeometries(path) {
  return new Promise((resolve, reject) => {
    new GLTFLoader().parse(arrayBuffer(path), '', (gltf) => {
      const geometries = [];
      gltf.scene.traverse((o) => { if (o.isMesh) geometries.push(o.geometry); });
      resolve(geometries);
    }, reject);
  });
}

// "x y z" rounded: the key of a vertex (data/torus.obj has no normals, so one colour per position).
function key(pos, i) {
  const r = (v) => Math.round(v * 1e4);
  return [pos.getX(i), pos.getY(i), pos.getZ(i)].map(r).join(' ');
}

function colours(geometries) {
  const map = new Map();
  for (const g of geometries) {
    const pos = g.getAttribute('position'), col = g.getAttribute('color');
    if (!pos || !col) throw new Error('a geometry without position or color');
    for (let i = 0; i < pos.count; ++i) map.set(key(pos, i), [col.getX(i), col.getY(i), col.getZ(i)]);
  }
  return map;
}

function compare(name, truth, other, bound) {
  let worst = 0, matched = 0;
  for (const [k, c] of other) {
    const t = truth.get(k);
    if (!t) continue;
    ++matched;
    for (let j = 0; j < 3; ++j) worst = Math.max(worst, Math.abs(c[j] - Math.min(1, Math.max(0, t[j]))));
  }
  const ok = matched >= 0.9 * other.size && worst <= bound;
  console.log(`${name}: ${matched} of ${other.size} vertices matched, largest |three.js linear - baked linear| ${worst.toFixed(5)} (bound ${bound})`);
  return ok;
}

const truth = colours(await gltfGeometries(truthPath));
const glb = colours(await gltfGeometries(glbPath));
const ply = colours([new PLYLoader().parse(arrayBuffer(plyPath))]);
const okGlb = compare('glTF COLOR_0 (ubyte, linear)', truth, glb, 0.5 / 255 + 1e-6);
const okPly = compare('PLY colours (bytes, read as sRGB)', truth, ply, 0.0065);
process.exit(okGlb && okPly ? 0 : 1);
