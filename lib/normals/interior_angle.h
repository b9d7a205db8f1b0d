// interior_angle.h: the angle between two edge vectors from |a x b| and a . b, fast and accurate.
//
// Inputs:  sin_part  |a x b| = |a||b| sin(theta), >= 0
//          cos_part  a . b   = |a||b| cos(theta)
// Output:  theta = atan2(sin_part, cos_part) in [0, pi]; 0 when both are 0 (degenerate corner).
//          interior_angle_pair does two at once (the two angles a triangle kernel needs).
//          NaN or Inf input gives NaN or some angle in [0, pi], never an out-of-range table read.
//
// Why not std::atan2: the angle-weighted kernel needs two angles per triangle, and the libm call
// (not inlined, not vectorised) cost several times the whole area-weighted kernel. This is the
// textbook reduction, inlined, branch-free, and for pairs in SSE2 (both lanes at once):
//   1. octant: t = min / max of (sin_part, |cos_part|) in [0, 1]; theta from atan(t) by
//      pi/2 - . (when sin_part > |cos_part|) and pi - . (when cos_part < 0);
//   2. table: atan(t) = atan(c_k) + atan((t - c_k) / (1 + t c_k)) with c_k = k/8 (exact in
//      binary), k = round(8 t), so the reduced argument x satisfies |x| <= 1/16 (the addition
//      formula for arctangent; e.g. Muller, "Elementary Functions", 3rd ed., ch. 5);
//   3. series: atan(x) = x (1 - z/3 + z^2/5 - ... + z^6/13), z = x^2 (Taylor), evaluated by
//      Estrin's scheme; the first omitted term x^15/15 is below 2e-19 relative.
// Accuracy: within 4 ulp of std::atan2 (tests/normals/interior_angle.cpp), in double. The float
// kernels call the double version too (converting in and out): an angle costs the same either way.
#pragma once

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "normals/face_geometry.h"  // SHADETOOL_NORMALS_INLINE

namespace shadetool::normals_detail {

// atan(k/8), k = 0..8, correctly rounded.
struct AtanTable {
  static constexpr double atan_k8[9] = {0.0, 0.12435499454676144, 0.24497866312686414, 0.35877067027057225,
                                        0.4636476090008061, 0.5585993153435624, 0.6435011087932844,
                                        0.7188299996216245, 0.7853981633974483};
};

constexpr double kAtanPi = 3.141592653589793, kAtanHalfPi = 1.5707963267948966;

// 1 - z/3 + z^2/5 - z^3/7 + z^4/9 - z^5/11 + z^6/13 by Estrin's scheme.
SHADETOOL_NORMALS_INLINE double atan_series(double z) {
  const double z2 = z * z, z4 = z2 * z2;
  const double a = 1.0 - z * (1.0 / 3), b = 1.0 / 5 - z * (1.0 / 7), c = 1.0 / 9 - z * (1.0 / 11);
  return (a + z2 * b) + z4 * (c + z2 * (1.0 / 13));
}

SHADETOOL_NORMALS_INLINE double interior_angle(double sin_part, double cos_part) {
  const double s = sin_part, c = std::fabs(cos_part);
  const double num = std::min(s, c), den = std::max(s, c);
  const double t = den > 0.0 ? num / den : 0.0;  // divisor checked: both zero is a degenerate corner
  // Table index round(8 t), clamped to [0, 8] so that a NaN input cannot index outside the table.
  double tk = t * 8.0 + 0.5;
  if (!(tk >= 0.0)) tk = 0.0;
  if (tk > 8.5) tk = 8.5;
  const int k = int(tk);
  const double ck = k * 0.125;
  const double x = (t - ck) / (1.0 + t * ck);  // 1 + t c_k >= 1
  double r = AtanTable::atan_k8[k] + x * atan_series(x * x);
  if (s > c) r = kAtanHalfPi - r;
  if (cos_part < 0.0) r = kAtanPi - r;
  return r;
}

// theta0 = interior_angle(s0, c0), theta1 = interior_angle(s1, c1), computed together.
SHADETOOL_NORMALS_INLINE void interior_angle_pair(double s0, double c0, double s1, double c1, double& theta0,
                                                  double& theta1) {
#if defined(__SSE2__)
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  const __m128d sign_bit = _mm_set1_pd(-0.0);
  const __m128d s = _mm_set_pd(s1, s0), cos_part = _mm_set_pd(c1, c0);
  const __m128d c = _mm_andnot_pd(sign_bit, cos_part);  // |cos_part|
  const __m128d num = _mm_min_pd(s, c), den = _mm_max_pd(s, c);
  // t = num / den, or 0 where den == 0 (then num == 0 too): divide by 1 there.
  const __m128d den_zero = _mm_cmpeq_pd(den, zero);
  const __m128d t = _mm_div_pd(num, _mm_or_pd(_mm_andnot_pd(den_zero, den), _mm_and_pd(den_zero, one)));
  // round(8 t) clamped to [0, 8] as in interior_angle (max_pd returns its second operand, 0, for NaN)
  const __m128d tk = _mm_add_pd(_mm_mul_pd(t, _mm_set1_pd(8.0)), _mm_set1_pd(0.5));
  const __m128i k = _mm_cvttpd_epi32(_mm_min_pd(_mm_max_pd(tk, zero), _mm_set1_pd(8.5)));
  const __m128d ck = _mm_mul_pd(_mm_cvtepi32_pd(k), _mm_set1_pd(0.125));
  const __m128d x = _mm_div_pd(_mm_sub_pd(t, ck), _mm_add_pd(one, _mm_mul_pd(t, ck)));
  const int k0 = _mm_cvtsi128_si32(k), k1 = _mm_cvtsi128_si32(_mm_shuffle_epi32(k, 1));
  const __m128d base = _mm_set_pd(AtanTable::atan_k8[k1], AtanTable::atan_k8[k0]);
  // series (Estrin), as atan_series
  const __m128d z = _mm_mul_pd(x, x), z2 = _mm_mul_pd(z, z), z4 = _mm_mul_pd(z2, z2);
  const __m128d a = _mm_sub_pd(one, _mm_mul_pd(z, _mm_set1_pd(1.0 / 3)));
  const __m128d b = _mm_sub_pd(_mm_set1_pd(1.0 / 5), _mm_mul_pd(z, _mm_set1_pd(1.0 / 7)));
  const __m128d cc = _mm_sub_pd(_mm_set1_pd(1.0 / 9), _mm_mul_pd(z, _mm_set1_pd(1.0 / 11)));
  const __m128d p = _mm_add_pd(_mm_add_pd(a, _mm_mul_pd(z2, b)),
                               _mm_mul_pd(z4, _mm_add_pd(cc, _mm_mul_pd(z2, _mm_set1_pd(1.0 / 13)))));
  __m128d r = _mm_add_pd(base, _mm_mul_pd(x, p));
  // octant: where s > c, r = pi/2 - r; where cos_part < 0, r = pi - r (selects by bit masks).
  const __m128d swap = _mm_cmpgt_pd(s, c);
  r = _mm_or_pd(_mm_and_pd(swap, _mm_sub_pd(_mm_set1_pd(kAtanHalfPi), r)), _mm_andnot_pd(swap, r));
  const __m128d neg = _mm_cmplt_pd(cos_part, zero);
  r = _mm_or_pd(_mm_and_pd(neg, _mm_sub_pd(_mm_set1_pd(kAtanPi), r)), _mm_andnot_pd(neg, r));
  theta0 = _mm_cvtsd_f64(r);
  theta1 = _mm_cvtsd_f64(_mm_unpackhi_pd(r, r));
#else
  theta0 = interior_angle(s0, c0);
  theta1 = interior_angle(s1, c1);
#endif
}

}  // namespace shadetool::normals_detail
