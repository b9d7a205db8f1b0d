// interior_angle.h: the angle between two edge vectors from |a x b| and a . b, fast and accurate.
//
// Inputs:  sin_part  |a x b| = |a||b| sin(theta), >= 0
//          cos_part  a . b   = |a||b| cos(theta)
// Output:  theta = atan2(sin_part, cos_part) in [0, pi]; 0 when both are 0 (degenerate corner).
//
// Why not std::atan2: the angle-weighted kernel needs three angles per triangle, and the libm
// call (not inlined, not vectorised) cost more than the whole area-weighted kernel. This is the
// textbook reduction, inlined, with one division and no data-dependent branch:
//   1. octant: t = min/max of (sin_part, |cos_part|) in [0, 1]; theta from atan(t) by
//      pi/2 - . (when sin_part > |cos_part|) and pi - . (when cos_part < 0), from a 4-entry table;
//   2. table: atan(t) = atan(c_k) + atan((t - c_k) / (1 + t c_k)) with c_k = tan(k pi/32),
//      k = 0..8 chosen so that the reduced argument x satisfies |x| <= tan(pi/64) = 0.049
//      (the addition formula for arctangent; e.g. Muller, "Elementary Functions", 3rd ed., 5.2);
//   3. series: atan(x) = x - x^3/3 + x^5/5 - ... (Taylor), truncated where the first omitted
//      term is far below half an ulp: 7 terms up to x^13 in double (remainder < 0.049^14/15 <
//      3e-19 relative), 4 terms up to x^7 in float (remainder < 7e-13 relative).
// Accuracy: within 4 ulp of std::atan2 in double, 6 ulp in float (tests/normals/interior_angle.cpp).
// Precision: T = double or float throughout.
#pragma once

#include <algorithm>
#include <cmath>

#include "normals/face_geometry.h"  // SHADETOOL_NORMALS_INLINE

namespace shadetool::normals_detail {

// Table of c_k = tan(k pi / 32) rounded to double, atan(c_k) (correctly rounded, so the table
// is self-consistent whatever c_k's rounding), and the boundaries tan((2k+1) pi / 64).
struct AtanTable {
  static constexpr double c[9] = {0.0, 0.09849140335716425, 0.198912367379658, 0.3033466836073424,
                                  0.41421356237309503, 0.5345111359507916, 0.6681786379192989,
                                  0.8206787908286602, 1.0};
  static constexpr double atan_c[9] = {0.0, 0.09817477042468103, 0.19634954084936207, 0.2945243112740431,
                                       0.39269908169872414, 0.4908738521234052, 0.5890486225480862,
                                       0.6872233929727672, 0.7853981633974483};
  static constexpr double bound[8] = {0.049126849769467254, 0.14833598753834742, 0.25048696019130545,
                                      0.3578057213145241, 0.4729647758913199, 0.5993769336819237,
                                      0.7416505462720354, 0.906347169019147};
};

// atan(x) for |x| <= tan(pi/64) by its Taylor series x (1 - z/3 + z^2/5 - ...), z = x^2; the
// polynomial in z is evaluated by Estrin's scheme (independent halves, short dependency chain).
SHADETOOL_NORMALS_INLINE double atan_small(double x) {
  const double z = x * x, z2 = z * z, z4 = z2 * z2;
  // 1 - z/3 + z^2/5 - z^3/7 + z^4/9 - z^5/11 + z^6/13; first omitted term z^7/15 < 3e-19.
  const double a = 1.0 - z * (1.0 / 3), b = 1.0 / 5 - z * (1.0 / 7), c = 1.0 / 9 - z * (1.0 / 11);
  const double p = (a + z2 * b) + z4 * (c + z2 * (1.0 / 13));
  return x * p;
}
SHADETOOL_NORMALS_INLINE float atan_small(float x) {
  // 1 - z/3 + z^2/5 - z^3/7; first omitted term z^4/9 < 7e-13.
  const float z = x * x;
  return x * ((1.0f - z * (1.0f / 3)) + (z * z) * (1.0f / 5 - z * (1.0f / 7)));
}

template <class T>
SHADETOOL_NORMALS_INLINE T interior_angle(T sin_part, T cos_part) {
  // Octant: num = min, den = max of (sin_part, |cos_part|) (minsd/maxsd, no branch).
  const T s = sin_part, c = std::fabs(cos_part);
  const T num = std::min(s, c), den = std::max(s, c);
  // Table entry k from t = num / den without dividing: t > b  <=>  num > b den (den >= 0).
  int k = 0;
  for (int j = 0; j < 8; ++j) k += int(num > T(AtanTable::bound[j]) * den);
  const T ck = T(AtanTable::c[k]);
  // x = (t - c_k) / (1 + t c_k) with t = num / den, as one division. Its divisor is >= den > 0
  // unless both parts are 0 (degenerate corner): then the numerator is 0 too and 1 is used.
  const T divisor = den + ck * num;
  const T x = (num - ck * den) / (divisor > T(0) ? divisor : T(1));
  const T r = T(AtanTable::atan_c[k]) + atan_small(x);
  // Undo the octant: theta = offset + sign * r, chosen by (sin_part > |cos_part|, cos_part < 0).
  static constexpr T offset[4] = {T(0), T(1.5707963267948966), T(3.141592653589793), T(1.5707963267948966)};
  static constexpr T sign[4] = {T(1), T(-1), T(-1), T(1)};
  const int octant = int(s > c) + 2 * int(cos_part < T(0));
  return offset[octant] + sign[octant] * r;
}

}  // namespace shadetool::normals_detail
