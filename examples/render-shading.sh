#!/usr/bin/env bash
# Flat, Gouraud and Phong shading of a coarse sphere side by side, and |Phong - Gouraud| (x4):
# Gouraud's Mach bands and its smeared highlight are where the difference image is bright.
#
#   examples/render-shading.sh [OUT_DIR]       (default: render-shading/)
#
# Writes OUT_DIR/coarse_sphere.obj (a 16 x 8 UV sphere), OUT_DIR/scene.json, the three renders
# (flat.png, gouraud.png, phong.png), and OUT_DIR/shading.png: flat | gouraud | phong | difference.
# Needs only shadetool and python3 (standard library: the PFMs are composed and written as PNG).
set -euo pipefail
out=${1:-render-shading}
shadetool=${SHADETOOL:-shadetool}
mkdir -p "$out"

python3 - "$out/coarse_sphere.obj" <<'PY'
import math, sys
nu, nv = 16, 8
lines = ["# UV sphere, %d x %d (examples/render-shading.sh)" % (nu, nv), "v 0 0 1"]
for j in range(1, nv):
    t = math.pi * j / nv
    for i in range(nu):
        p = 2 * math.pi * i / nu
        lines.append("v %.17g %.17g %.17g" % (math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)))
lines.append("v 0 0 -1")
south = 1 + nu * (nv - 1) + 1
ring = lambda j, i: 2 + (j - 1) * nu + i % nu  # 1-based OBJ index of ring j (1..nv-1), column i
for i in range(nu):
    lines.append("f 1 %d %d" % (ring(1, i), ring(1, i + 1)))
    lines.append("f %d %d %d" % (south, ring(nv - 1, i + 1), ring(nv - 1, i)))
    for j in range(1, nv - 1):
        lines.append("f %d %d %d %d" % (ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i + 1)))
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
PY

cat > "$out/scene.json" <<'JSON'
{
  "model": "blinn-phong",
  "camera": {"eye": [0, -3.2, 1.4], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y": 40},
  "ambient": [0.08, 0.08, 0.1],
  "material": {"ambient": [1, 1, 1], "diffuse": [0.75, 0.45, 0.25], "specular": [0.6, 0.6, 0.6], "shininess": 40},
  "lights": [
    {"type": "point", "position": [2, -3, 3], "color": [1, 1, 1], "intensity": 1.2, "attenuation": [1, 0, 0]},
    {"type": "directional", "direction": [1, 0.3, 0.2], "color": [0.3, 0.35, 0.5], "intensity": 1}
  ]
}
JSON

for shading in flat gouraud phong; do
  "$shadetool" render "$out/coarse_sphere.obj" --scene "$out/scene.json" --shading "$shading" \
    --size 320,320 --samples 3 -o "$out/$shading.png" --quiet
  "$shadetool" render "$out/coarse_sphere.obj" --scene "$out/scene.json" --shading "$shading" \
    --size 320,320 --samples 3 --hdr -o "$out/$shading.pfm" --quiet
done

python3 - "$out" <<'PY'
import struct, sys, zlib
out = sys.argv[1]

def read_pfm(path):
    data = open(path, "rb").read()
    header, rest = data.split(b"\n", 2)[:2], data.split(b"\n", 3)[3]
    w, h = map(int, data.split(b"\n")[1].split())
    floats = struct.unpack("<%df" % (w * h * 3), rest[: w * h * 12])
    rows = [floats[(h - 1 - y) * w * 3:(h - y) * w * 3] for y in range(h)]  # PFM rows are bottom-up
    return w, h, rows

def srgb8(c):
    c = min(max(c, 0.0), 1.0)
    s = 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return int(round(255 * s))

def write_png(path, w, h, rows):  # 8-bit RGB with the sRGB chunk
    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"sRGB", b"\x00") + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)

images = [read_pfm("%s/%s.pfm" % (out, s)) for s in ("flat", "gouraud", "phong")]
w, h = images[0][0], images[0][1]
gap = 8
total = 4 * w + 3 * gap
rows = []
mean = 0.0
for y in range(h):
    f, g, p = (img[2][y] for img in images)
    diff = [4 * abs(a - b) for a, b in zip(p, g)]
    mean += sum(abs(a - b) for a, b in zip(p, g))
    sep = [255] * (3 * gap)
    rows.append([srgb8(c) for c in f] + sep + [srgb8(c) for c in g] + sep + [srgb8(c) for c in p] + sep +
                [srgb8(c) for c in diff])
write_png("%s/shading.png" % out, total, h, rows)
print("%s/shading.png: flat | gouraud | phong | 4 x |phong - gouraud|; mean |phong - gouraud| = %.5f (linear)"
      % (out, mean / (w * h * 3)))
PY
