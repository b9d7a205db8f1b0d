// image_png.h: an 8-bit RGB PNG in memory, marked sRGB (libpng, the reference PNG library; Debian
// libpng-dev).
//
// Inputs:  width, height  > 0
//          srgb8          height * width * 3 bytes, row 0 at the top, already sRGB-encoded
//                         (render/lighting_adapter.h encode_srgb_8bit does the linear -> sRGB step)
// Output:  the PNG file's bytes: IHDR (8-bit RGB, no interlace), sRGB (perceptual intent) with the
//          gAMA and cHRM chunks that PNG 1.2 recommends beside it for older decoders, IDAT, IEND.
// Errors:  shadetool::Error `NAME: cannot encode PNG: REASON` (libpng's message).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

std::string encode_png_srgb8(int width, int height, const std::vector<std::uint8_t>& srgb8, const std::string& name);

}  // namespace shadetool::io
#pragma GCC visibility pop
