// image_png.h: an 8-bit RGB PNG in memory, marked sRGB (libpng, the reference PNG library; Debian
// libpng-dev).
//
// Inputs:  width, height  > 0
//          srgb8          height * width * 3 bytes, row 0 at the top, already sRGB-encoded
//                         (render/lighting_adapter.h encode_srgb_8bit does the linear -> sRGB step)
//          level          0..9, how hard to compress (the same pixels whatever the level):
//                           0     stored: no compression
//                           1     the default: zlib level 1 with the Up filter on every row and the
//                                 run-length strategy (Z_RLE): a rendered frame's rows repeat the
//                                 row above (background, flat shading), which Up turns into zeros
//                                 and RLE codes cheaply. Chosen by bench/render/png_encode.cpp on
//                                 1920x1080 frames: about 5x faster than libpng's default (zlib 6,
//                                 adaptive filters), files 16-37% larger (bench/render/results.md).
//                           2..9  zlib level `level` with libpng's adaptive filters (6 is libpng's
//                                 default; 9 the smallest file, the slowest)
// Output:  the PNG file's bytes: IHDR (8-bit RGB, no interlace), sRGB (perceptual intent) with the
//          gAMA and cHRM chunks that PNG 1.2 recommends beside it for older decoders, IDAT, IEND.
// Errors:  shadetool::Error `NAME: cannot encode PNG: REASON` (libpng's message).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

constexpr int kPngDefaultCompression = 1;

std::string encode_png_srgb8(int width, int height, const std::vector<std::uint8_t>& srgb8, const std::string& name,
                             int level = kPngDefaultCompression);

}  // namespace shadetool::io
#pragma GCC visibility pop
