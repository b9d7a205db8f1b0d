// Tests of render/output_image.h: the one float-to-8-bit conversion of a render (CLI PNG and
// Python's uint8 array). Expected codes from IEC 61966-2-1 written out by hand:
//   c <= 0.0031308: 12.92 c; else 1.055 c^(1/2.4) - 0.055; code = round(255 * clamp(., 0, 1)).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <shadetool/render/output_image.h>

using namespace shadetool;

TEST_CASE("render_output_image: 8-bit sRGB codes of the IEC curve, or the floats unchanged", "[render][image]") {
  ImageRGB im;
  im.width = 3;
  im.height = 2;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // 0.5 -> 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536 -> 187.5 -> 188; 0.002 -> 12.92 * 0.002 * 255 = 6.59 -> 7;
  // 0.2 -> 0.48453 -> 123.6 -> 124.
  const std::vector<float> values = {0.0f, 1.0f, 0.5f, 0.002f, 0.2f, 2.0f, -1.0f, nan, 1.0f,
                                     0.0f, 0.0f, 0.0f, 0.5f,   0.5f, 0.5f, 1.0f,  1.0f, 1.0f};
  im.rgb.assign(values.begin(), values.end());
  const Image u8 = render_output_image(im, false);
  CHECK(u8.width == 3);
  CHECK(u8.height == 2);
  CHECK(u8.channels == 3);
  REQUIRE(u8.pixel == Image::Pixel::U8);
  const std::vector<std::uint8_t> expected = {0, 255, 188, 7, 124, 255, 0, 0, 255, 0, 0, 0, 188, 188, 188, 255, 255, 255};
  CHECK(u8.u8 == expected);

  const Image f32 = render_output_image(im, true);
  REQUIRE(f32.pixel == Image::Pixel::F32);
  REQUIRE(f32.f32.size() == values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    CHECK((std::isnan(values[i]) ? std::isnan(f32.f32[i]) : f32.f32[i] == values[i]));
}
