// image_pfm.h: a float RGB image as a Portable Float Map (PFM, Debevec's HDRShop format, read by
// Blender, GIMP, OpenImageIO, ImageMagick): "PF\n<W> <H>\n-1.0\n", then little-endian (scale < 0)
// 32-bit floats, RGB per pixel, rows from the BOTTOM of the image to the top (the format's order).
//
// Inputs:  width, height > 0; linear_rgb  height * width * 3 floats (count), row 0 at the top, unclamped
// Output:  the file's bytes; values are written as given (linear, not sRGB-encoded).
// Errors:  shadetool::Error when the buffer does not match the size.
#pragma once

#include <cstddef>
#include <string>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

std::string encode_pfm(int width, int height, const float* linear_rgb, std::size_t count, const std::string& name);

}  // namespace shadetool::io
#pragma GCC visibility pop
