// cosine_directions.h: the float directions of a run of one point's rays, bit for bit what
// sample_sequence.h's scalar functions give ray by ray (machinery for engine/cosine_rays.h).
//
// Ray k of a point with seed s and unit axis n (basis t, b from orthonormal_basis) has the
// direction  Vec3f(t * w.x + b * w.y + n * w.z),  w = cosine_hemisphere(scrambled_sobol_2d(k, s)).
// cosine_directions(frame, first, count, dx, dy, dz) writes rays first .. first + count - 1
// (count <= kDirectionBlock) into three float arrays, computing in passes over the block instead of
// ray by ray, so that the passes without a libm call run as SIMD loops and the scalar ones are
// short:
//   1. the scrambled Sobol pair, in integers, with fewer steps than listing 5 written out (the same
//      bits): nested_uniform_scramble(reverse_bits(i), s) = reverse_bits(laine_karras(i, s)) since
//      reverse_bits is an involution, and sobol_dimension_1 is read from byte tables of its
//      bit-reversed values (it is linear over GF(2) in the bits of i, and so is the reversal), so
//      nested_uniform_scramble(sobol_dimension_1(i), s) = reverse_bits(laine_karras(table(i), s));
//   2. the concentric map up to its radius r and angle phi (cosine_hemisphere's expressions, in
//      the same order: one division, of the smaller |coordinate| by the larger);
//   3. cos(phi), sin(phi) (libm: the same calls, so the same bits);
//   4. the lift z = sqrt(max(0, 1 - x^2 - y^2)), the centre's (0, 0, 1), the rotation into
//      (t, b, n) and the rounding to float, in cosine_hemisphere's and the caller's order.
// Exactness: every step is the scalar code's IEEE operation on the same operands (2 u - 1 is
// computed as (x - 2^31) 2^-31, the same exact value; division and square root are correctly
// rounded in SIMD as in scalar; cosine_directions.cpp is built without FMA contraction, so its
// AVX-512, AVX2 and baseline clones agree); tests/visibility/cosine_directions.cpp compares every
// bit against the scalar functions over many seeds, axes and index ranges, and the centre.
// Cost (bench/visibility/results.md, "Occlusion loop"): the scalar code spent about 60 ns a ray,
// a third of a ray's traversal on a 100k-triangle mesh; the shuffled index's dimension-1 loop
// (up to 32 dependent steps) and the scalar division and square root were most of it.
// Precision: as sample_sequence.h (integers, then double), float at the end.
#pragma once

#include <cmath>
#include <cstdint>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/vec3.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool::visibility_engine {

constexpr std::uint32_t kDirectionBlock = 64;

// reverse_bits(sobol_dimension_1(i)) for i's byte b at byte position k: table[k][b]. The value for
// i is the XOR of its four bytes' entries (linearity over GF(2)).
struct ReversedSobolTable {
  std::uint32_t byte[4][256];
};

constexpr ReversedSobolTable make_reversed_sobol_table() {
  ReversedSobolTable t{};
  for (std::uint32_t k = 0; k < 4; ++k)
    for (std::uint32_t b = 0; b < 256; ++b) t.byte[k][b] = visibility::reverse_bits(visibility::sobol_dimension_1(b << (8 * k)));
  return t;
}

inline constexpr ReversedSobolTable kReversedSobol = make_reversed_sobol_table();

inline std::uint32_t reversed_sobol_dimension_1(std::uint32_t i) {
  return kReversedSobol.byte[0][i & 0xffu] ^ kReversedSobol.byte[1][(i >> 8) & 0xffu] ^
         kReversedSobol.byte[2][(i >> 16) & 0xffu] ^ kReversedSobol.byte[3][i >> 24];
}

// One point's sampling frame: its seed and its unit axis's basis (orthonormal_basis(n, t, b)).
struct CosineFrame {
  std::uint32_t seed = 0;
  Vec3d t, b, n;
};

// scrambled_sobol_2d(index, seed)'s two 32-bit coordinates (before the scaling by 2^-32).
inline void scrambled_sobol_2d_bits(std::uint32_t index, std::uint32_t seed, std::uint32_t seed_x, std::uint32_t seed_y,
                                    std::uint32_t& x, std::uint32_t& y) {
  using visibility::laine_karras_permutation;
  using visibility::reverse_bits;
  const std::uint32_t i = reverse_bits(laine_karras_permutation(reverse_bits(index), seed));  // the shuffled index
  x = reverse_bits(laine_karras_permutation(i, seed_x));
  y = reverse_bits(laine_karras_permutation(reversed_sobol_dimension_1(i), seed_y));
}

// Steps 2-4 for `count` <= kDirectionBlock samples given centred: sx = x - 2^31, sy = y - 2^31
// (signed, exact), so that u = x 2^-32 gives 2 u - 1 = sx 2^-31 exactly. The centre (sx = sy = 0,
// where cosine_hemisphere returns (0, 0, 1) at once) gets r = 0, phi = 0, which step 4 lifts to
// exactly (+0, +0, 1).
void cosine_directions_from_samples(const CosineFrame& f, const std::int32_t* sx, const std::int32_t* sy,
                                    std::uint32_t count, float* dx, float* dy, float* dz);

// Rays first .. first + count - 1 (count <= kDirectionBlock) of the point with frame f.
void cosine_directions(const CosineFrame& f, std::uint32_t first, std::uint32_t count, float* dx, float* dy, float* dz);

}  // namespace shadetool::visibility_engine
