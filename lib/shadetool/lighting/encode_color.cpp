// encode_color.cpp: see encode_color.h.
#include <shadetool/lighting/encode_color.h>

#include <cmath>

namespace shadetool {

double srgb_encode(double c) {
  if (!(c > 0.0031308)) return 12.92 * c;  // also NaN -> NaN and negative -> negative (linear part)
  return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

std::uint8_t quantize_8bit(double c) {
  if (!(c > 0)) return 0;  // negative, zero, NaN
  if (c >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(255.0 * c));
}

ColorEncoding output_color_encoding(bool eight_bit, bool gltf, bool linear) {
  ColorEncoding e;
  e.hdr = !eight_bit;
  e.srgb = eight_bit && !gltf && !linear;
  return e;
}

double clamp_displayable(double c) {
  if (!(c > 0)) return 0;  // negative, zero, NaN
  return c < 1 ? c : 1;
}

std::vector<float> encode_colors(const std::vector<double>& rgb, const ColorEncoding& encoding) {
  std::vector<float> out(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    const double c = encoding.srgb ? srgb_encode(rgb[i]) : rgb[i];
    out[i] = encoding.hdr ? static_cast<float>(c) : static_cast<float>(quantize_8bit(c) / 255.0);
  }
  return out;
}

}  // namespace shadetool
