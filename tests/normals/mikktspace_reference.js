// mikktspace_reference.js: the reference MikkTSpace (npm `mikktspace`, the gltf-rs port of
// mikktspace.c built to WebAssembly) on unindexed triangles, for tests/normals/tangents.cpp.
// usage: node mikktspace_reference.js IN OUT
//   IN:  little-endian float32, 8 per triangle corner: px py pz nx ny nz u v (3 corners per triangle)
//   OUT: little-endian float32, 4 per corner: the reference's tangent xyz and w, as it returns them
const fs = require('fs');
const { generateTangents } = require('mikktspace');
const bytes = fs.readFileSync(process.argv[2]);
const a = new Float32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length));
const n = a.length / 8;
const p = new Float32Array(3 * n), nn = new Float32Array(3 * n), uv = new Float32Array(2 * n);
for (let i = 0; i < n; ++i) {
  for (let k = 0; k < 3; ++k) { p[3 * i + k] = a[8 * i + k]; nn[3 * i + k] = a[8 * i + 3 + k]; }
  uv[2 * i] = a[8 * i + 6]; uv[2 * i + 1] = a[8 * i + 7];
}
const t = generateTangents(p, nn, uv);
fs.writeFileSync(process.argv[3], Buffer.from(t.buffer, t.byteOffset, t.byteLength));
