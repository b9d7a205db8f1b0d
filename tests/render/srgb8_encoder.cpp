// Tests of render/srgb8_encoder.h: the table gives encode_srgb_8bit's code (the formula:
// IEC 61966-2-1 with pow, then round(255 * clamp)) for every float. The formula is the truth; the
// table is built from it only at 255 bisection points, so a float where the formula is not
// monotone, or a bucket step that is wrong, shows up as a mismatch here.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <shadetool/render/lighting_adapter.h>
#include <shadetool/render/srgb8_encoder.h>

using namespace shadetool;

namespace {

float float_of_bits(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}
std::uint32_t bits_of(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

// Floats with bit patterns in [begin, end) at the given stride where table and formula differ.
std::size_t mismatches(std::uint32_t begin, std::uint32_t end, std::uint32_t stride) {
  const Srgb8Encoder& encode = srgb8_encoder();
  std::atomic<std::size_t> bad{0};
  const std::uint64_t count = (std::uint64_t(end) - begin + stride - 1) / stride;
  tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, count, 1 << 16), [&](const tbb::blocked_range<std::uint64_t>& r) {
    std::size_t local = 0;
    for (std::uint64_t i = r.begin(); i < r.end(); ++i) {
      const float x = float_of_bits(std::uint32_t(begin + i * stride));
      local += encode(x) != encode_srgb_8bit(double(x));
    }
    bad += local;
  });
  return bad;
}

constexpr std::uint32_t kOneBits = 0x3F800000;

}  // namespace

TEST_CASE("Srgb8Encoder: the formula's code at and around every threshold, and on a stride of [0, 1]",
          "[render][image]") {
  const Srgb8Encoder& encode = srgb8_encoder();
  // Each threshold t_k is where the formula's code reaches k: k there, k - 1 one float below.
  for (int k = 1; k <= 255; ++k) {
    const float t = encode.threshold(k);
    CHECK(encode_srgb_8bit(double(t)) >= k);
    CHECK(encode_srgb_8bit(double(float_of_bits(bits_of(t) - 1))) < k);
    CHECK(mismatches(bits_of(t) - 64, bits_of(t) + 64, 1) == 0);  // the floats around it, one by one
  }
  // Hand-computed codes (IEC 61966-2-1): 0.5 -> 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536 -> 187.5 -> 188;
  // 0.002 -> 12.92 * 0.002 * 255 = 6.59 -> 7; 0.2 -> 0.48453 -> 123.6 -> 124.
  CHECK(encode(0.5f) == 188);
  CHECK(encode(0.002f) == 7);
  CHECK(encode(0.2f) == 124);
  CHECK(mismatches(0, kOneBits + 1, 1021) == 0);  // about a million floats of [0, 1]
}

TEST_CASE("Srgb8Encoder: negative, NaN, denormal, above one, infinity", "[render][image]") {
  const Srgb8Encoder& encode = srgb8_encoder();
  const float specials[] = {0.0f, -0.0f, -1.0f, -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                            1.0f, std::nextafter(1.0f, 2.0f), 2.0f, 1e30f, std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::infinity()};
  for (float x : specials) CHECK(int(encode(x)) == int(encode_srgb_8bit(double(x))));
  CHECK(mismatches(kOneBits, 0x7F800001u, 4099) == 0);  // (1, infinity]: all 255
}

// Every float of [0, 1] (2^30 + 1 of them; about a billion pow calls: run as its own ctest,
// render_srgb8_exhaustive, not in the default `test_render` run).
TEST_CASE("Srgb8Encoder: every float in [0, 1] gets the formula's code", "[.][exhaustive]") {
  CHECK(mismatches(0, kOneBits + 1, 1) == 0);
}
