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
//   2. table: atan(t) = atan(c_k) + atan((t - c_k) / (1 + t c_k)) with c_k = tan(k pi/16),
//      k = 0..4 chosen so that the reduced argument x satisfies |x| <= tan(pi/32) = 0.0985
//      (the addition formula for arctangent; e.g. Muller, "Elementary Functions", 3rd ed., 5.2);
//   3. series: atan(x) = x - x^3/3 + x^5/5 - ... (Taylor), truncated where the first omitted
//      term is below half an ulp: 9 terms up to x^17 in double (remainder < 0.0985^18/19 < 1e-19
//      relative), 5 terms up to x^9 in float (remainder < 1e-11 relative).
// Accuracy: within 2 ulp of std::atan2 (tested in tests/normals/interior_angle.cpp).
// Precision: T = double or float throughout.
#pragma once

#include <algorithm>
#include <cmath>

#include "normals/face_geometry.h"  // SHADETOOL_NORMALS_INLINE

namespace shadetool::normals_detail {

// Table of c_k = tan(k pi / 16) rounded to double, atan(c_k) (correctly rounded, so the table
// is self-consistent whatever c_k's rounding), and the boundaries tan((2k+1) pi / 32).
struct AtanTable {
  static constexpr double c[5] = {0.0, 0.198912367379658, 0.41421356237309503, 0.6681786379192989, 1.0};
  static constexpr double atan_c[5] = {0.0, 0.19634954084936207, 0.39269908169872414, 0.5890486225480862,
                                       0.7853981633974483};
  static constexpr double bound[4] = {0.09849140335716425, 0.3033466836073424, 0.5345111359507916,
                                      0.8206787908286602};
};

// atan(x) for |x| <= tan(pi/32) by its Taylor series (Horner in x^2).
SHADETOOL_NORMALS_INLINE double atan_small(double x) {
  const double z = x * x;
  double p = 1.0 / 17;
  p = p * z - 1.0 / 15; p = p * z + 1.0 / 13; p = p * z - 1.0 / 11; p = p * z + 1.0 / 9;
  p = p * z - 1.0 / 7;  p = p * z + 1.0 / 5;  p = p * z - 1.0 / 3;
  return x + x * (p * z);
}
SHADETOOL_NORMALS_INLINE float atan_small(float x) {
  const float z = x * x;
  float p = 1.0f / 9;
  p = p * z - 1.0f / 7; p = p * z + 1.0f / 5; p = p * z - 1.0f / 3;
  return x + x * (p * z);
}

template <class T>
SHADETOOL_NORMALS_INLINE T interior_angle(T sin_part, T cos_part) {
  // Octant: num = min, den = max of (sin_part, |cos_part|) (minsd/maxsd, no branch).
  const T s = sin_part, c = std::fabs(cos_part);
  const T num = std::min(s, c), den = std::max(s, c);
  // Table entry k from t = num / den without dividing: t > b  <=>  num > b den (den >= 0).
  const int k = int(num > T(AtanTable::bound[0]) * den) + int(num > T(AtanTable::bound[1]) * den) +
                int(num > T(AtanTable::bound[2]) * den) + int(num > T(AtanTable::bound[3]) * den);
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
