// output_image.h: a rendered picture as the image that is written or handed out: 8-bit sRGB (the
// PNG's bytes, Python's render(hdr=False)) or linear float (the PFM's values). The one home of the
// float-to-8-bit conversion of a render, for the CLI and Python.
//
// Input:   rendered      render/image.h: height * width * 3 linear floats, row 0 at the top
//          linear_float  true: copy the floats (unclamped); false: per channel
//                        encode_srgb_8bit (render/lighting_adapter.h: IEC 61966-2-1, then
//                        round(255 * clamp(c, 0, 1)); NaN -> 0), computed by its table
//                        (render/srgb8_encoder.h: the same code for every float)
// Output:  io/image_io.h Image, width x height x 3, Pixel::F32 or Pixel::U8, same row order.
#pragma once

#include <shadetool/io/image_io.h>
#include <shadetool/render/image.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

Image render_output_image(const ImageRGB& rendered, bool linear_float);

}  // namespace shadetool
#pragma GCC visibility pop
