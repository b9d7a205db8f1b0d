// stress_util.h: meshes whose exact answer is known by construction, for the numerical stress tests.
//
// Exact truth without trusting the code under test: triangles are built in a plane spanned by two
// dyadic vectors u = (1, 1/2, 1/4) and v = (-1/4, 1, 1/2). A point o + a u + b v with dyadic a, b
// (few significant bits) and a dyadic or integer offset o is exactly representable in double, so
// the stored triangle IS the intended one and its unit normal is exactly u x v / |u x v|:
//   u x v = (1/2 * 1/2 - 1/4 * 1, 1/4 * (-1/4) - 1 * 1/2, 1 * 1 - 1/2 * (-1/4)) = (0, -9/16, 9/8)
//   |u x v| = 9/16 * sqrt(1 + 4) = 9 sqrt(5) / 16,   n = (0, -1, 2) / sqrt(5).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

namespace shadetool::stress {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;  // 2^-53, unit roundoff of double
constexpr double kUf = std::numeric_limits<float>::epsilon() / 2;  // 2^-24, of float

inline const Vec3d kPlaneU{1.0, 0.5, 0.25};
inline const Vec3d kPlaneV{-0.25, 1.0, 0.5};
// The exact unit normal of the plane, (0, -1, 2) / sqrt(5), rounded once.
inline Vec3d plane_normal() {
  const double s = std::sqrt(5.0);
  return {0.0, -1.0 / s, 2.0 / s};
}

// o + a u + b v (exact when a, b and o are dyadic with few bits; the tests keep them so).
inline Vec3d in_plane(double a, double b, const Vec3d& o = {0, 0, 0}) {
  return {o.x + a * kPlaneU.x + b * kPlaneV.x, o.y + a * kPlaneU.y + b * kPlaneV.y, o.z + a * kPlaneU.z + b * kPlaneV.z};
}

// Angle in radians between a and b, accurate for tiny angles: atan2(|a x b|, a . b).
inline double angle_between(const Vec3d& a, const Vec3d& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

// Aspect ratio of a triangle in the sense used by the tests: longest edge^2 / (2 * area), i.e.
// longest edge / height onto it. 1 for a right isosceles triangle, 1e8 for a sliver 1e8 times
// longer than it is high. Computed in long double from the (exact) plane coordinates.
inline double aspect_ratio(double a0, double b0, double a1, double b1, double a2, double b2) {
  // In plane coordinates (a, b) the metric is the Gram matrix of u, v; area scales by |u x v|.
  auto metric = [](long double da, long double db) {
    const long double uu = 1.3125L, vv = 1.3125L, uv = 0.375L;  // u.u, v.v, u.v
    return da * da * uu + 2 * da * db * uv + db * db * vv;
  };
  const long double l0 = metric(a1 - a0, b1 - b0), l1 = metric(a2 - a1, b2 - b1), l2 = metric(a0 - a2, b0 - b2);
  const long double longest = std::max(l0, std::max(l1, l2));
  const long double det = std::fabs((long double)(a1 - a0) * (b2 - b0) - (long double)(a2 - a0) * (b1 - b0));
  const long double twice_area = det * (9.0L * std::sqrt(5.0L) / 16.0L);
  return double(longest / twice_area);
}

inline bool all_finite(const std::vector<double>& a) {
  for (double x : a)
    if (!std::isfinite(x)) return false;
  return true;
}

inline bool all_finite(const std::vector<float>& a) {
  for (float x : a)
    if (!std::isfinite(x)) return false;
  return true;
}

// Unit (to `tol`) or exactly zero: what every normal array may hold.
inline bool unit_or_zero(const Vec3d& n, double tol) {
  const double l = length(n);
  return l == 0.0 || std::fabs(l - 1.0) <= tol;
}

}  // namespace shadetool::stress
