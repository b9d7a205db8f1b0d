// output_image.cpp: see output_image.h.
#include <shadetool/render/output_image.h>

#include <shadetool/render/srgb8_encoder.h>

namespace shadetool {

Image render_output_image(const ImageRGB& rendered, bool linear_float) {
  Image out;
  out.width = std::size_t(rendered.width);
  out.height = std::size_t(rendered.height);
  out.channels = 3;
  if (linear_float) {
    out.pixel = Image::Pixel::F32;
    out.f32.assign(rendered.rgb.begin(), rendered.rgb.end());
  } else {
    out.pixel = Image::Pixel::U8;
    out.u8.resize(rendered.rgb.size());
    const Srgb8Encoder& encode = srgb8_encoder();  // bitwise encode_srgb_8bit, by table
    for (std::size_t i = 0; i < rendered.rgb.size(); ++i) out.u8[i] = encode(rendered.rgb[i]);
  }
  return out;
}

}  // namespace shadetool
