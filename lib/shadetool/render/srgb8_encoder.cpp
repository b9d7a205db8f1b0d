// srgb8_encoder.cpp: see srgb8_encoder.h.
#include <shadetool/render/srgb8_encoder.h>

#include <shadetool/render/lighting_adapter.h>

namespace shadetool {

namespace {

float float_of_bits(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

constexpr std::uint32_t kOneBits = 0x3F800000;  // 1.0f; encode_srgb_8bit(1) = 255

}  // namespace

Srgb8Encoder::Srgb8Encoder() : bucket_code_(kOneBits >> 16) {
  threshold_[0] = 0;
  // t_k: the smallest bit pattern b in (0, 1.0f] with code(b) >= k (positive floats order as their
  // bits). Invariant: code(lo) < k <= code(hi).
  std::uint32_t lo = 0;
  for (int k = 1; k <= 255; ++k) {
    std::uint32_t hi = kOneBits;
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (encode_srgb_8bit(double(float_of_bits(mid))) >= k) hi = mid;
      else lo = mid;
    }
    threshold_[k] = float_of_bits(hi);
    // the next threshold is at or above this one: lo stays valid (code(lo) < k < k + 1)
  }
  for (std::uint32_t b = 0; b < bucket_code_.size(); ++b) {
    const float smallest = float_of_bits(b << 16);
    unsigned code = 0;
    while (code < 255 && smallest >= threshold_[code + 1]) ++code;
    bucket_code_[b] = std::uint8_t(code);
  }
}

const Srgb8Encoder& srgb8_encoder() {
  static const Srgb8Encoder encoder;
  return encoder;
}

}  // namespace shadetool
