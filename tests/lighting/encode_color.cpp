// Colour encoding: the sRGB curve at known points and 8-bit quantisation round(255 clamp(c)).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <shadetool/lighting/encode_color.h>

using namespace shadetool;

TEST_CASE("sRGB encoding at known values", "[lighting][encode]") {
  // linear part: 12.92 * 0.002 = 0.02584
  CHECK(srgb_encode(0.002) == Approx(0.02584).epsilon(1e-12));
  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7353569830524495 (mid-grey 0.5 -> 187.5/255)
  CHECK(srgb_encode(0.5) == Approx(0.7353569830524495).epsilon(1e-12));
  // 18% grey: 0.46135612950044164
  CHECK(srgb_encode(0.18) == Approx(0.46135612950044164).epsilon(1e-12));
  CHECK(srgb_encode(0) == 0);
  CHECK(srgb_encode(1) == Approx(1).epsilon(1e-15));
  // the two pieces meet at 0.0031308: 12.92 * 0.0031308 = 0.040449936
  CHECK(srgb_encode(0.0031308) == Approx(0.040449936).epsilon(1e-12));
  CHECK(srgb_encode(0.0031309) == Approx(0.040449936).epsilon(1e-4));
}

TEST_CASE("8-bit quantisation is round(255 * clamp(c, 0, 1))", "[lighting][encode]") {
  CHECK(quantize_8bit(0.5) == 128);  // 127.5 rounds up
  CHECK(quantize_8bit(0.4990) == 127);  // 127.245
  CHECK(quantize_8bit(1.7) == 255);
  CHECK(quantize_8bit(-0.2) == 0);
  CHECK(quantize_8bit(std::numeric_limits<double>::quiet_NaN()) == 0);
  CHECK(quantize_8bit(1.0 / 510) == 1);  // 0.5 rounds up
}

TEST_CASE("encode_colors: 8-bit values survive a writer's round(255 c); hdr keeps values above 1", "[lighting][encode]") {
  std::vector<double> all;
  for (int k = 0; k <= 255; ++k) all.push_back(k / 255.0);
  const std::vector<float> q = encode_colors(all, {});
  for (int k = 0; k <= 255; ++k) CHECK(std::lround(255.0 * double(q[k])) == k);

  ColorEncoding srgb;
  srgb.srgb = true;
  CHECK(encode_colors({0.5}, srgb)[0] == float(188 / 255.0));  // 0.73535... * 255 = 187.52 -> 188

  ColorEncoding hdr;
  hdr.hdr = true;
  CHECK(encode_colors({2.5, 0.25}, hdr) == std::vector<float>{2.5f, 0.25f});
  hdr.srgb = true;
  // above 1 the curve continues: 1.055 * 2.5^(1/2.4) - 0.055
  CHECK(encode_colors({2.5}, hdr)[0] == Approx(1.055 * std::pow(2.5, 1 / 2.4) - 0.055).epsilon(1e-7));
}

TEST_CASE("the colour convention: 8-bit sRGB unless --linear, float and glTF linear (issue 28)", "[lighting][encode]") {
  // man shadetool, COLOUR: viewers read 8-bit colours as sRGB; glTF 2.0 3.7.2.1 makes COLOR_0
  // linear in every component type; float (--hdr) outputs are linear.
  for (bool gltf : {false, true})
    for (bool linear : {false, true}) {
      INFO("gltf " << gltf << ", linear " << linear);
      const ColorEncoding eight = output_color_encoding(true, gltf, linear);
      CHECK_FALSE(eight.hdr);
      CHECK(eight.srgb == (!gltf && !linear));
      const ColorEncoding flt = output_color_encoding(false, gltf, linear);
      CHECK(flt.hdr);
      CHECK_FALSE(flt.srgb);
    }
  // the byte a PLY gets for linear 0.5: 188 by default, 128 with --linear (round(127.5))
  CHECK(std::lround(255.0 * encode_colors({0.5}, output_color_encoding(true, false, false))[0]) == 188);
  CHECK(std::lround(255.0 * encode_colors({0.5}, output_color_encoding(true, false, true))[0]) == 128);
  CHECK(std::lround(255.0 * encode_colors({0.5}, output_color_encoding(true, true, false))[0]) == 128);
}

TEST_CASE("clamp_displayable: [0, 1], NaN to 0", "[lighting][encode]") {
  CHECK(clamp_displayable(2.5) == 1);
  CHECK(clamp_displayable(-0.25) == 0);
  CHECK(clamp_displayable(0.375) == 0.375);
  CHECK(clamp_displayable(std::nan("")) == 0);
}
