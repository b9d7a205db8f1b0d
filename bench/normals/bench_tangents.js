// bench_tangents.js: the npm reference MikkTSpace (mikktspace, WebAssembly) timed in-process on the
// unindexed floats bench_tangents --dump wrote (8 per corner), median process CPU time.
// usage: node bench_tangents.js FILE [RUNS]
const fs = require('fs');
const { generateTangents } = require('mikktspace');
const bytes = fs.readFileSync(process.argv[2]);
const a = new Float32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length));
const n = a.length / 8, runs = Number(process.argv[3] || 7);
const p = new Float32Array(3 * n), nn = new Float32Array(3 * n), uv = new Float32Array(2 * n);
for (let i = 0; i < n; ++i) {
  for (let k = 0; k < 3; ++k) { p[3 * i + k] = a[8 * i + k]; nn[3 * i + k] = a[8 * i + 3 + k]; }
  uv[2 * i] = a[8 * i + 6]; uv[2 * i + 1] = a[8 * i + 7];
}
const t = [];
for (let k = 0; k < runs; ++k) {
  const s = process.cpuUsage();  // process CPU time (user + system), as bench_tangents reports
  generateTangents(p, nn, uv);
  const d = process.cpuUsage(s);
  t.push((d.user + d.system) / 1e3);
}
t.sort((x, y) => x - y);
const ms = t[Math.floor(t.length / 2)];
console.log(`| npm mikktspace 1.1.1 (WebAssembly, node ${process.version}) | ${ms.toFixed(2)} | ${(n / (ms / 1000)).toPrecision(3)} |`);
