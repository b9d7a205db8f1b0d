#!/usr/bin/env bash
# One quad rendered two ways with Gouraud shading: as a quad (bilinear interpolation of its four
# corners through the inverse bilinear map: no seam) and as two triangles (each interpolates
# three corners: a crease along the diagonal).
#
#   examples/render-quad.sh [OUT_DIR]          (default: render-quad/)
#
# Writes OUT_DIR/quad.obj, OUT_DIR/triangles.obj, OUT_DIR/scene.json and OUT_DIR/quad-vs-triangles.png
# (left: quad, right: two triangles). Needs shadetool and python3 (standard library).
set -euo pipefail
out=${1:-render-quad}
shadetool=${SHADETOOL:-shadetool}
mkdir -p "$out"

# A trapezoid with a different normal at each corner (corner normals, one per vertex).
corners='v -1 -1 0
v 1.3 -1 0
v 0.7 1 0
v -0.8 1 0
vn -1 0.2 0.5
vn 0.2 -0.1 1
vn -0.3 1 0.5
vn -1 0.8 0.4'
printf '%s\nf 1//1 2//2 3//3 4//4\n' "$corners" > "$out/quad.obj"
printf '%s\nf 1//1 2//2 3//3\nf 1//1 3//3 4//4\n' "$corners" > "$out/triangles.obj"
cat > "$out/scene.json" <<'JSON'
{
  "model": "blinn-phong",
  "camera": {"eye": [0, -0.6, 3.2], "target": [0.1, 0, 0], "up": [0, 1, 0], "fov_y": 45},
  "ambient": [0.05, 0.05, 0.05],
  "material": {"ambient": [1, 1, 1], "diffuse": [0.8, 0.45, 0.2], "specular": [0.6, 0.6, 0.6], "shininess": 6},
  "lights": [{"type": "point", "position": [1.2, -0.8, 1.0], "color": [1, 1, 1], "intensity": 1.5}]
}
JSON
for shape in quad triangles; do
  "$shadetool" render "$out/$shape.obj" --scene "$out/scene.json" --shading gouraud --size 300,300 \
    --samples 3 --hdr -o "$out/$shape.pfm" --quiet
done

python3 - "$out" <<'PY'
import struct, sys, zlib
out = sys.argv[1]

def read_pfm(path):
    data = open(path, "rb").read()
    lines = data.split(b"\n", 3)
    w, h = map(int, lines[1].split())
    f = struct.unpack("<%df" % (w * h * 3), lines[3][: w * h * 12])
    return w, h, [f[(h - 1 - y) * w * 3:(h - y) * w * 3] for y in range(h)]  # PFM rows are bottom-up

def srgb8(c):
    c = min(max(c, 0.0), 1.0)
    return int(round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055)))

def write_png(path, w, h, rows):  # 8-bit RGB with the sRGB chunk
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                           chunk(b"sRGB", b"\x00") + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

(w, h, q), (_, _, t) = read_pfm(out + "/quad.pfm"), read_pfm(out + "/triangles.pfm")
rows = [[srgb8(c) for c in q[y]] + [255] * 24 + [srgb8(c) for c in t[y]] for y in range(h)]
write_png(out + "/quad-vs-triangles.png", 2 * w + 8, h, rows)
print(out + "/quad-vs-triangles.png: left the quad (bilinear), right two triangles (diagonal crease)")
PY
