// scaled_length.h: the one safe length and the one safe normalise of a double 3-vector.
//
//   checked_length(v)      |v|, or 0 when v is zero or not finite (the caller treats 0 as "no
//                          direction" and never divides by it)
//   normalise_checked(v,o) o = v / |v| and true, or false (o untouched) when |v| is 0 or not finite
//
// The one rule: |v| = sqrt(v . v) while v . v lies in [kSquaresFrom, kSquaresTo] = [1e-280, 1e280],
// else the scaled length of core/vec3.h (largest component factored out; never over- or
// underflows for finite v). Why that range is safe: v . v >= 1e-280 means a component's square
// that underflowed to a subnormal or zero (absolute error <= 2^-1074 ~ 5e-324 each) changes the
// sum by < 1e-43 relative; v . v <= 1e280 is far below the overflow at 1.8e308. Inside it the
// direct square root is also the more accurate of the two (the scaled length divides by a
// non-power-of-two). Precision: double; the division is v.x / |v| per component (one rounding).
// Other modules' copies of this rule are listed in issue 15's report (to be replaced by the lead).
#pragma once

#include <cmath>

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/face_area_vector.h>  // SHADETOOL_INLINE

namespace shadetool {

constexpr double kSquaresFrom = 1e-280, kSquaresTo = 1e280;

SHADETOOL_INLINE double checked_length(const Vec3d& v) {
  const double l2 = dot(v, v);
  const double l = (l2 >= kSquaresFrom && l2 <= kSquaresTo) ? std::sqrt(l2) : length(v);
  return (l > 0.0 && std::isfinite(l)) ? l : 0.0;
}

SHADETOOL_INLINE bool normalise_checked(double x, double y, double z, double* o) {
  const double len = checked_length(Vec3d{x, y, z});
  if (!(len > 0.0)) return false;
  o[0] = x / len; o[1] = y / len; o[2] = z / len;  // divisor checked
  return true;
}

SHADETOOL_INLINE bool normalise_checked(const Vec3d& v, Vec3d& o) {
  double r[3];
  if (!normalise_checked(v.x, v.y, v.z, r)) return false;
  o = {r[0], r[1], r[2]};
  return true;
}

}  // namespace shadetool
