// engine/metric.h: lengths in a shading space's metric (lighting/shading_space.h), as the
// per-point loop reads them. Internal: not installed.
//
// Three policies with the same three calls, so the per-point loop is compiled once per kind:
//   norm2(v)    |v|_G^2 = v^T G v        (vectors: L, V, H, the spot axis)
//   lower(v)    G v                      (so that u.G v is a plain dot product)
//   conorm2(n)  |n|_{G^-1}^2 = n^T G^-1 n (normals, which are covectors)
// Identity: G = I. Scaled: G = s^2 I. General: G = B^T B, never formed (it would square cond(B)).
#pragma once

#include <cmath>

#include <shadetool/core/affine.h>
#include <shadetool/core/vec3.h>

namespace shadetool {
namespace lighting_engine {

struct IdentityMetric {
  double norm2(const Vec3d& v) const { return dot(v, v); }
  Vec3d lower(const Vec3d& v) const { return v; }
  double conorm2(const Vec3d& n) const { return dot(n, n); }
};
struct ScaledMetric {
  double s2, inv_s2;
  double norm2(const Vec3d& v) const { return s2 * dot(v, v); }
  Vec3d lower(const Vec3d& v) const { return v * s2; }
  double conorm2(const Vec3d& n) const { return inv_s2 * dot(n, n); }
};
struct GeneralMetric {
  Mat3d B, B_transpose, B_inverse_transpose;
  double norm2(const Vec3d& v) const { return squared_length(B * v); }
  Vec3d lower(const Vec3d& v) const { return B_transpose * (B * v); }
  double conorm2(const Vec3d& n) const { return squared_length(B_inverse_transpose * n); }
};

// v / |v|_G and |v|_G for any finite v, without underflow or overflow of |v|^2: when the plain
// squared length lies in [2^-1000, 2^1000] (every distance between 1e-150 and 1e150 in world
// units: all usual scenes) it is used directly; otherwise v is first scaled by the power of two
// 2^-e that brings its largest component near 1 (exact: only the exponent changes), the unit
// vector is taken from the scaled copy and the length scaled back. v = 0 gives length 0 and a
// zero unit vector; a length beyond double's range gives Inf with a correct unit vector.
//
// Why not core/vec3.h's length / normalized_or: those divide by the largest component (inexact
// in the last bit) and know no metric G; this rule scales by powers of two only, so in the usual
// range it is the plain v * (1 / sqrt(v.G v)) that the bitwise-pinned outputs were made with.
struct UnitAndLength {
  Vec3d unit;
  double length;
};
template <class Metric>
inline UnitAndLength metric_normalize(const Metric& g, const Vec3d& v) {
  constexpr double lo = 0x1p-1000, hi = 0x1p1000;
  const double d2 = g.norm2(v);
  if (d2 >= lo && d2 <= hi) {
    const double d = std::sqrt(d2);
    return {v * (1.0 / d), d};  // d >= 2^-500 > 0
  }
  const double m = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
  if (!(m > 0) || !std::isfinite(m)) return {{0, 0, 0}, m > 0 ? m : 0.0};
  const int e = std::ilogb(m);
  const Vec3d u{std::scalbn(v.x, -e), std::scalbn(v.y, -e), std::scalbn(v.z, -e)};
  const double du = std::sqrt(g.norm2(u));  // u has a component in [1, 2): du > 0 for regular G
  if (!(du > 0) || !std::isfinite(du)) return {{0, 0, 0}, 0.0};
  return {u * (1.0 / du), std::scalbn(du, e)};
}

}  // namespace lighting_engine
}  // namespace shadetool
