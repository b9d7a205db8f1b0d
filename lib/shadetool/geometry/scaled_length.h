// scaled_length.h: the one safe length and the one safe normalise of a double 3-vector.
//
//   checked_length(v)      |v|, or 0 when v is zero or not finite (the caller treats 0 as "no
//                          direction" and never divides by it)
//   normalise_checked(v,o) o = v / |v| and true, or false (o untouched) when v is zero or not finite
//
// The one rule: |v| = sqrt(v . v) while v . v lies in [kSquaresFrom, kSquaresTo] = [1e-280, 1e280],
// else the scaled length of core/vec3.h (largest component factored out; never over- or
// underflows for finite v). Why that range is safe: v . v >= 1e-280 means a component's square
// that underflowed to a subnormal or zero (absolute error <= 2^-1074 ~ 5e-324 each) changes the
// sum by < 1e-43 relative; v . v <= 1e280 is far below the overflow at 1.8e308. Inside it the
// direct square root is also the more accurate of the two (the scaled length divides by a
// non-power-of-two). normalise_checked outside the range scales v by a power of two first (exact),
// not by the scaled length: its result is then bitwise that of v at unit scale, so normals are
// the same for tiny, huge and ordinary sums, and a v whose length overflows is still normalised.
// Precision: double; the division is v.x / |v| per component (one rounding).
// Other modules' copies of this rule are listed in issue 15's report (to be replaced by the lead).
#pragma once

#include <cmath>

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/face_area_vector.h>  // SHADETOOL_INLINE

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

constexpr double kSquaresFrom = 1e-280, kSquaresTo = 1e280;

SHADETOOL_INLINE double checked_length(const Vec3d& v) {
  const double l2 = dot(v, v);
  const double l = (l2 >= kSquaresFrom && l2 <= kSquaresTo) ? std::sqrt(l2) : length(v);
  return (l > 0.0 && std::isfinite(l)) ? l : 0.0;
}

SHADETOOL_INLINE bool normalise_checked(double x, double y, double z, double* o) {
  const double l2 = x * x + y * y + z * z;
  if (l2 >= kSquaresFrom && l2 <= kSquaresTo) {
    const double len = std::sqrt(l2);
    o[0] = x / len; o[1] = y / len; o[2] = z / len;  // divisor checked: in range
    return true;
  }
  // Tiny or huge: scale by 2^-e, e = ilogb(largest |component|), exact (but for components below
  // 2^-1022 of the largest), so the squares land in [1, 3] and the result has the bits the direct
  // route gives at unit scale; also works where |v| itself overflows (a length would not).
  const double m = std::fmax(std::fabs(x), std::fmax(std::fabs(y), std::fabs(z)));
  if (!(m > 0.0) || !std::isfinite(m) || std::isnan(x) || std::isnan(y) || std::isnan(z)) return false;
  const int e = std::ilogb(m);  // down to -1074 (subnormal): scalbn, as 2^1074 is not a double
  const double X = std::scalbn(x, -e), Y = std::scalbn(y, -e), Z = std::scalbn(z, -e);
  const double len = std::sqrt(X * X + Y * Y + Z * Z);  // in [1, sqrt 3]
  o[0] = X / len; o[1] = Y / len; o[2] = Z / len;       // divisor checked: >= 1
  return true;
}

SHADETOOL_INLINE bool normalise_checked(const Vec3d& v, Vec3d& o) {
  double r[3];
  if (!normalise_checked(v.x, v.y, v.z, r)) return false;
  o = {r[0], r[1], r[2]};
  return true;
}

}  // namespace shadetool
#pragma GCC visibility pop
