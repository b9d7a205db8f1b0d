// interior_angle.h: the one interior angle: the angle between two edge vectors from |a x b| and
// a . b, fast and accurate; and the corner angle of a polygon, reflex corners included.
//
// Inputs:  sin_part  |a x b| = |a||b| sin(theta), >= 0
//          cos_part  a . b   = |a||b| cos(theta)
// Output:  theta = atan2(sin_part, cos_part) in [0, pi]; 0 when both are 0 (degenerate corner).
//          NaN or Inf input gives NaN or some angle in [0, pi], never an out-of-range table read.
//
// Why not std::atan2: the libm call (not inlined) cost several times the whole area-weighted
// kernel. This is the textbook reduction, inlined and branch-free. It is the definition every
// module uses (normals' scalar paths and crease test, repair, transform); the normals triangle
// kernels' vectorised pass has a table-free version of it (normals/engine/triangle_blocks.h),
// tested within 1e-13 relative of this one (tests/geometry/interior_angle.cpp):
//   1. octant: t = min / max of (sin_part, |cos_part|) in [0, 1]; theta from atan(t) by
//      pi/2 - . (when sin_part > |cos_part|) and pi - . (when cos_part < 0);
//   2. table: atan(t) = atan(c_k) + atan((t - c_k) / (1 + t c_k)) with c_k = k/8 (exact in
//      binary), k = round(8 t), so the reduced argument x satisfies |x| <= 1/16 (the addition
//      formula for arctangent; e.g. Muller, "Elementary Functions", 3rd ed., ch. 5);
//   3. series: atan(x) = x (1 - z/3 + z^2/5 - ... + z^6/13), z = x^2 (Taylor), evaluated by
//      Estrin's scheme; the first omitted term x^15/15 is below 2e-19 relative.
// Accuracy: within 4 ulp of std::atan2 (tests/geometry/interior_angle.cpp), in double. The float
// kernels call the double version too (converting in and out): an angle costs the same either way.
#pragma once

#include <algorithm>
#include <cmath>

#include <shadetool/core/math_constants.h>
#include <shadetool/geometry/face_area_vector.h>  // SHADETOOL_INLINE

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

namespace interior_angle_detail {

// atan(k/8), k = 0..8, correctly rounded.
struct __attribute__((visibility("hidden"))) AtanTable {  // internal: each binary keeps its own copy
  static constexpr double atan_k8[9] = {0.0, 0.12435499454676144, 0.24497866312686414, 0.35877067027057225,
                                        0.4636476090008061, 0.5585993153435624, 0.6435011087932844,
                                        0.7188299996216245, 0.7853981633974483};
};


// 1 - z/3 + z^2/5 - z^3/7 + z^4/9 - z^5/11 + z^6/13 by Estrin's scheme.
SHADETOOL_INLINE double atan_series(double z) {
  const double z2 = z * z, z4 = z2 * z2;
  const double a = 1.0 - z * (1.0 / 3), b = 1.0 / 5 - z * (1.0 / 7), c = 1.0 / 9 - z * (1.0 / 11);
  return (a + z2 * b) + z4 * (c + z2 * (1.0 / 13));
}

}  // namespace interior_angle_detail

SHADETOOL_INLINE double interior_angle(double sin_part, double cos_part) {
  using namespace interior_angle_detail;
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
  if (s > c) r = kHalfPi - r;
  if (cos_part < 0.0) r = kPi - r;
  return r;
}

// Angle at a polygon corner with edges a, b (to the next and previous corners), in [0, 2 pi):
// signed_sin = (a x b) . n about the face's unit normal n, cos_part = a . b. A reflex corner of a
// concave polygon (signed_sin < 0) counts as reflex, 2 pi - theta. 0 for a zero-length edge.
SHADETOOL_INLINE double polygon_corner_angle(double signed_sin, double cos_part) {
  const double theta = interior_angle(std::fabs(signed_sin), cos_part);
  return signed_sin < 0.0 ? kTwoPi - theta : theta;
}

}  // namespace shadetool
#pragma GCC visibility pop
