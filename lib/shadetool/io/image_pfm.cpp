// image_pfm.cpp: see image_pfm.h.
#include <shadetool/io/image_pfm.h>

#include <cstdint>
#include <cstring>

#include <shadetool/core/error.h>

namespace shadetool::io {

std::string encode_pfm(int width, int height, const float* linear_rgb, std::size_t count, const std::string& name) {
  if (width <= 0 || height <= 0 || count != std::size_t(width) * std::size_t(height) * 3)
    fail(name, 0, "cannot encode PFM: the pixel buffer does not match the image size");
  std::string out = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  const std::size_t row = std::size_t(width) * 3;
  out.reserve(out.size() + count * 4);
  for (int y = height - 1; y >= 0; --y) {
    for (std::size_t i = 0; i < row; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, &linear_rgb[std::size_t(y) * row + i], 4);
      const char le[4] = {char(bits & 0xff), char((bits >> 8) & 0xff), char((bits >> 16) & 0xff), char(bits >> 24)};
      out.append(le, 4);
    }
  }
  return out;
}

}  // namespace shadetool::io
