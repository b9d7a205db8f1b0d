#!/usr/bin/env python3
"""Writes data/sky_env.hdr: a small equirectangular Radiance (RGBE) sky for data/scenes/environment.json.

64 x 32 texels, uncompressed scanlines (8 KB), in lighting/environment_map.h's convention: row 0 at
the top (+y), the centre column looking along -z. A sky gradient (deep blue at the zenith, pale at
the horizon), a sun of radiance ~60 over a 2 x 2 texel patch at 35 degrees elevation toward -z+x, and
a brownish ground below the horizon. Encoded by truncation (as Radiance and stb_image_write do);
shadetool decodes with stb_image's convention m * 2^(e - 136) (no +0.5).

Usage: tests/lighting/make_environment_hdr.py [OUT]   (default data/sky_env.hdr next to this repo)
Standard library only (no numpy), deterministic: rerunning gives the same bytes.
"""
import math
import os
import sys

W, H = 64, 32


def radiance(row, col):
    theta = math.pi * (row + 0.5) / H          # from +y
    phi = 2 * math.pi * (col + 0.5) / W
    elevation = math.pi / 2 - theta
    if elevation < 0:                           # ground: darker toward the nadir
        k = 1 - 0.4 * (-elevation) / (math.pi / 2)
        return (0.30 * k, 0.24 * k, 0.18 * k)
    t = elevation / (math.pi / 2)               # 0 at the horizon, 1 at the zenith
    sky = (0.85 - 0.55 * t, 0.90 - 0.40 * t, 1.00 - 0.10 * t)
    sun_row, sun_col = int(H * (0.5 - 35 / 180)), int(W * 0.625)  # 35 degrees up, azimuth between -z and +x
    if sun_row - 1 <= row <= sun_row and sun_col - 1 <= col <= sun_col:
        return (60.0, 55.0, 45.0)
    return sky


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    frac, e = math.frexp(m)                     # m = frac * 2^e, frac in [0.5, 1)
    scale = frac * 256.0 / m
    return bytes((int(r * scale), int(g * scale), int(b * scale), e + 128))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "sky_env.hdr")
    data = bytearray(b"#?RADIANCE\n# shadetool tests/lighting/make_environment_hdr.py\nFORMAT=32-bit_rle_rgbe\n\n")
    data += b"-Y %d +X %d\n" % (H, W)
    for row in range(H):
        for col in range(W):
            data += rgbe(*radiance(row, col))
    with open(out, "wb") as f:
        f.write(data)


if __name__ == "__main__":
    main()
