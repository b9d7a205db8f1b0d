// image.h: what the renderer produces: a linear float RGB image, row 0 at the top.
//
// Shape:  rgb  height * width * 3 floats, linear (not sRGB-encoded), unclamped; pixel (x, y) at
//              3 * (y * width + x). The writers (io/image_png.h, io/image_pfm.h) encode it.
#pragma once

#include <cstddef>
#include <vector>

namespace shadetool {

struct ImageRGB {
  int width = 0, height = 0;
  std::vector<float> rgb;

  float* pixel(int x, int y) { return rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)); }
  const float* pixel(int x, int y) const {
    return rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  }
};

}  // namespace shadetool
