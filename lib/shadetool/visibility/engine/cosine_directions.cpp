// cosine_directions.cpp: see cosine_directions.h (the passes, and why they give the scalar code's bits).
#include <shadetool/visibility/engine/cosine_directions.h>

#include <cmath>

namespace shadetool::visibility_engine {

// GCC: an AVX-512, an AVX2 and a baseline clone, picked at load time (ifunc), as
// normals/engine/triangle_blocks.cpp. This file is built with -fno-math-errno (sqrt without errno, so
// the lift loop vectorises), -fno-trapping-math (selects instead of branches) and -ffp-contract=off
// (no fused multiply-add in the AVX clones: every clone rounds each product and sum as the scalar
// code does; CMakeLists.txt). cos and sin stay libm's scalar calls in every clone.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SHADETOOL_DIRECTION_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SHADETOOL_DIRECTION_CLONES
#endif

SHADETOOL_DIRECTION_CLONES void cosine_directions_from_samples(const CosineFrame& f, const std::int32_t* sx, const std::int32_t* sy,
                                           std::uint32_t count, float* dx, float* dy, float* dz) {
  constexpr double k2pow31 = 1.0 / 2147483648.0;
  double r[kDirectionBlock], phi[kDirectionBlock], c[kDirectionBlock], s[kDirectionBlock];
  // 2. The concentric map's radius and angle (cosine_hemisphere's expressions).
  for (std::uint32_t j = 0; j < count; ++j) {
    const double a = double(sx[j]) * k2pow31, b = double(sy[j]) * k2pow31;
    const bool along_a = std::fabs(a) > std::fabs(b);
    const double q = (along_a ? b : a) / (along_a ? a : b);  // divisor: the larger |coordinate|; 0 only at the centre
    const double angle = along_a ? (kPi / 4) * q : kHalfPi - (kPi / 4) * q;
    r[j] = along_a ? a : b;
    phi[j] = (a == 0) & (b == 0) ? 0.0 : angle;
  }
  // 3. libm, the same calls as cosine_hemisphere.
  for (std::uint32_t j = 0; j < count; ++j) {
    c[j] = std::cos(phi[j]);
    s[j] = std::sin(phi[j]);
  }
  // 4. Lift to the hemisphere, rotate about the axis (t w.x + b w.y + n w.z), round to float.
  for (std::uint32_t j = 0; j < count; ++j) {
    const double x = r[j] * c[j], y = r[j] * s[j];
    const double zz = 1 - x * x - y * y;
    const double z = std::sqrt(zz > 0 ? zz : 0.0);  // fmax(0, zz): zz is never NaN here
    dx[j] = float(f.t.x * x + f.b.x * y + f.n.x * z);
    dy[j] = float(f.t.y * x + f.b.y * y + f.n.y * z);
    dz[j] = float(f.t.z * x + f.b.z * y + f.n.z * z);
  }
}

SHADETOOL_DIRECTION_CLONES void cosine_directions(const CosineFrame& f, std::uint32_t first, std::uint32_t count, float* dx, float* dy,
                              float* dz) {
  const std::uint32_t seed_x = visibility::hash_combine(f.seed, 0), seed_y = visibility::hash_combine(f.seed, 1);
  std::int32_t sx[kDirectionBlock], sy[kDirectionBlock];
  // 1. The samples' bits, centred (x - 2^31 as a signed integer: the top bit flipped).
  for (std::uint32_t j = 0; j < count; ++j) {
    std::uint32_t x, y;
    scrambled_sobol_2d_bits(first + j, f.seed, seed_x, seed_y, x, y);
    sx[j] = std::int32_t(x ^ 0x80000000u);
    sy[j] = std::int32_t(y ^ 0x80000000u);
  }
  cosine_directions_from_samples(f, sx, sy, count, dx, dy, dz);
}

}  // namespace shadetool::visibility_engine
