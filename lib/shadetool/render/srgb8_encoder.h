// srgb8_encoder.h: render/lighting_adapter.h's encode_srgb_8bit (linear -> 8-bit sRGB code:
// IEC 61966-2-1, then round(255 * clamp(c, 0, 1)); NaN -> 0) for float inputs, by table instead
// of a pow per channel: the same code for every one of the 2^32 floats.
//
// Method: the code is a non-decreasing function of the float (the curve and the rounding are), so
// it is the number of thresholds t_1 <= ... <= t_255 at or below x, t_k the smallest float whose
// code is at least k. The thresholds are found once, by bisection over the float bit patterns
// with encode_srgb_8bit itself (255 x 30 evaluations). A float in (0, t_255) then starts from the
// code of its bucket (its top 16 bits: sign, exponent, 7 mantissa bits; 16 KB of codes) and steps
// up past the few thresholds inside that bucket (a bucket spans at most 0.8 % of its value, under
// one code anywhere on the curve, so usually no step).
//
// Input:  linear  any float (negative, zero, NaN -> 0; at or above t_255, infinity included -> 255)
// Output: the 8-bit code, bitwise encode_srgb_8bit(double(linear)) (tests/render/srgb8_encoder.cpp
//         checks every float in [0, 1] and the special values against it).
// Why:    a 1920x1080 render is 6.2 million channels; pow for each took several times longer than
//         encoding the PNG (bench/render/results.md).
// Threads: srgb8_encoder() builds the table once (a function-local static); the table is then
//         read-only and shared.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

class Srgb8Encoder {
 public:
  Srgb8Encoder();

  std::uint8_t operator()(float linear) const {
    if (!(linear > 0)) return 0;  // negative, zero, NaN
    if (linear >= threshold_[255]) return 255;
    std::uint32_t bits;
    std::memcpy(&bits, &linear, sizeof bits);
    unsigned code = bucket_code_[bits >> 16];  // 0 < linear < t_255 < 1: bits < 0x3F800000
    code += linear >= threshold_[code + 1];  // without a branch: a bucket holds at most one threshold
    while (linear >= threshold_[code + 1]) ++code;  // so never taken; kept for exactness. Stops at 254: linear < t_255
    return std::uint8_t(code);
  }

  // t_k, k = 1..255 (t_0 = 0 unused): the smallest float with code >= k.
  float threshold(int k) const { return threshold_[k]; }

 private:
  float threshold_[256];
  std::vector<std::uint8_t> bucket_code_;  // 0x3F80 buckets: the code of the bucket's smallest float
};

// The one table, built on first use.
const Srgb8Encoder& srgb8_encoder();

}  // namespace shadetool
#pragma GCC visibility pop
