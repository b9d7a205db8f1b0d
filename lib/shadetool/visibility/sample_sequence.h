// sample_sequence.h: the deterministic sample points every visibility estimate uses, and the maps
// from the unit square to the hemisphere.
//
//   scrambled_sobol_2d(i, seed)  point i of the first two Sobol dimensions (dimension 0: the van
//       der Corput sequence, the bit reversal of i; dimension 1: the Pascal-matrix generator
//       v_1 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1)), Owen-scrambled and index-shuffled by hashing
//       (Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020, listings 1-5; the
//       Laine-Karras permutation). Every seed gives a different randomisation that keeps the net
//       property: the first 2^m points are a (0,m,2)-net in base 2. For an integrand with a
//       discontinuity along a curve (visibility), the RMS error over scrambles falls as
//       N^(-3/4) (Owen 1997; He & Wang, Math. Comp. 84, 2015), against N^(-1/2) for independent
//       random samples; tests/visibility/convergence.cpp asserts it.
//   point_seed(id, salt)  the seed of one point (vertex id, face id, ...): a 64-bit finaliser
//       (splitmix64) of id mixed with salt, so neighbouring ids get unrelated scrambles.
//   cosine_hemisphere(u, v)  a direction about +z with density cos(theta)/pi: Shirley & Chiu's
//       concentric map of the square to the disc ("A Low Distortion Map Between Disk and
//       Square", JGT 2(3), 1997), lifted to the hemisphere (Malley's method). Its low distortion
//       keeps the net's stratification; z = sqrt(1 - x^2 - y^2) >= 0.
//   orthonormal_basis(n)  t, b with (t, b, n) right-handed orthonormal for unit n (Duff et al.,
//       "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017, listing 3), no branch on n
//       except its sign.
//
// Precision: the sequence is exact integer arithmetic (uint32), turned into doubles in [0, 1) as
// k * 2^-32 (exact); the maps are evaluated in double. Nothing depends on threads or time.
#pragma once

#include <cmath>
#include <cstdint>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::visibility {

constexpr std::uint32_t reverse_bits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// Burley 2020, listing 3 (Laine & Karras 2011 with Burley's constants).
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Burley 2020, listing 4: an Owen scramble of all 32 bits.
inline std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

constexpr std::uint32_t sobol_dimension_1(std::uint32_t i) {
  std::uint32_t r = 0;
  for (std::uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1)
    if (i & 1u) r ^= v;
  return r;
}

// Burley 2020, listing 1 (boost::hash_combine).
inline std::uint32_t hash_combine(std::uint32_t seed, std::uint32_t v) {
  return seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2));
}

inline std::uint32_t point_seed(std::uint64_t id, std::uint32_t salt) {
  std::uint64_t z = id + 0x9e3779b97f4a7c15ull * (std::uint64_t(salt) + 1);  // splitmix64
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return std::uint32_t(z ^ (z >> 32));
}

struct UnitSquarePoint {
  double u = 0, v = 0;  // in [0, 1)
};

// Burley 2020, listing 5: shuffled, scrambled Sobol in two dimensions.
inline UnitSquarePoint scrambled_sobol_2d(std::uint32_t index, std::uint32_t seed) {
  const std::uint32_t i = nested_uniform_scramble(index, seed);
  const std::uint32_t x = nested_uniform_scramble(reverse_bits(i), hash_combine(seed, 0));
  const std::uint32_t y = nested_uniform_scramble(sobol_dimension_1(i), hash_combine(seed, 1));
  constexpr double k2pow32 = 1.0 / 4294967296.0;
  return {double(x) * k2pow32, double(y) * k2pow32};
}

// Shirley & Chiu 1997 (the form in pbrt-v4's SampleUniformDiskConcentric), then z = sqrt(1 - r^2).
inline Vec3d cosine_hemisphere(double u, double v) {
  const double a = 2 * u - 1, b = 2 * v - 1;
  if (a == 0 && b == 0) return {0, 0, 1};  // the centre: straight up (and no 0/0 below)
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) {
    r = a;
    phi = (kPi / 4) * (b / a);  // divisor checked: |a| > |b| >= 0
  } else {
    r = b;
    phi = kHalfPi - (kPi / 4) * (a / b);  // divisor checked: |b| >= |a| and not both 0
  }
  const double x = r * std::cos(phi), y = r * std::sin(phi);
  return {x, y, std::sqrt(std::fmax(0.0, 1 - x * x - y * y))};
}

// Duff et al. 2017, listing 3.
inline void orthonormal_basis(const Vec3d& n, Vec3d& t, Vec3d& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);  // divisor checked: |sign + n.z| >= 1 for unit n
  const double c = n.x * n.y * a;
  t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

}  // namespace shadetool::visibility
#pragma GCC visibility pop
