// inverse_bilinear.h: (u, v) of a point in a quadrilateral, the inverse of the bilinear map, so a
// point sample of a quad interpolates its corners' attributes by (u, v) (Heckbert, "Fundamentals of
// Texture Mapping and Image Warping", M.S. thesis, UC Berkeley, 1989: bilinear mappings, whose
// inverse is a quadratic; the cancellation-free roots as in Press et al., Numerical Recipes, 3rd
// ed., section 5.6 "Quadratic and Cubic Equations"):
//
//   P(u, v) = (1-v)((1-u) P00 + u P10) + v((1-u) P01 + u P11)
//           = P00 + u e + v f + u v g,   e = P10 - P00, f = P01 - P00, g = P00 - P10 + P11 - P01
//
// In 2D, with h = P - P00 and cross(a, b) = a.x b.y - a.y b.x, eliminating u gives the quadratic
//   k2 v^2 + k1 v + k0 = 0,  k2 = cross(g, f), k1 = cross(e, f) + cross(h, g), k0 = cross(h, e)
// solved without cancellation (q = -(k1 + sign(k1) sqrt(D)) / 2; roots q / k2 and k0 / q), then
//   u = (h - v f) / (e + v g)  on the component with the larger divisor.
// A parallelogram (k2 = 0) is linear: v = -k0 / k1.
//
// inverse_bilinear_3d: a quad in space is mapped to 2D by dropping the coordinate along which its
// normal (cross of the diagonals) is largest; P is expected on (or near) the quad.
//
// Output: true and (u, v) clamped to [0, 1]^2 when a root lies in the quad (tolerance 1e-9);
// false for a degenerate quad (zero-area, folded, or a point outside), when the caller falls back
// to the triangle's barycentrics. Precision: double.
#pragma once

#include <algorithm>
#include <cmath>

#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct QuadUV {
  double u = 0, v = 0;
};

inline double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

inline bool inverse_bilinear_2d(double px, double py, const double x[4], const double y[4], QuadUV& out) {
  // corners in cyclic order: 0 = P00, 1 = P10, 2 = P11, 3 = P01
  const double ex = x[1] - x[0], ey = y[1] - y[0];
  const double fx = x[3] - x[0], fy = y[3] - y[0];
  const double gx = x[0] - x[1] + x[2] - x[3], gy = y[0] - y[1] + y[2] - y[3];
  const double hx = px - x[0], hy = py - y[0];
  const double k2 = cross2(gx, gy, fx, fy);
  const double k1 = cross2(ex, ey, fx, fy) + cross2(hx, hy, gx, gy);
  const double k0 = cross2(hx, hy, ex, ey);
  const double scale = std::fabs(cross2(ex, ey, fx, fy)) + std::fabs(k2);  // the quad's area scale
  if (!(scale > 0)) return false;                                        // zero-area quad
  constexpr double tol = 1e-9;
  double roots[2];
  int count = 0;
  if (std::fabs(k2) <= 1e-12 * scale) {  // parallelogram: linear in v
    if (k1 == 0) return false;           // k1 = cross(e, f) + ... = 0: folded
    roots[count++] = -k0 / k1;           // divisor checked above
  } else {
    const double disc = k1 * k1 - 4 * k2 * k0;
    if (disc < 0) return false;
    const double q = -0.5 * (k1 + std::copysign(std::sqrt(disc), k1));
    roots[count++] = q / k2;                // k2 != 0 here
    if (q != 0) roots[count++] = k0 / q;    // divisor checked on the line
  }
  for (int r = 0; r < count; ++r) {
    const double v = roots[r];
    if (!(v >= -tol && v <= 1 + tol)) continue;
    const double dx = ex + v * gx, dy = ey + v * gy;
    double u;
    if (std::fabs(dx) >= std::fabs(dy)) {
      if (dx == 0) continue;
      u = (hx - v * fx) / dx;  // divisor checked on the line before
    } else {
      u = (hy - v * fy) / dy;  // |dy| > |dx| >= 0
    }
    if (!(u >= -tol && u <= 1 + tol)) continue;
    out.u = std::clamp(u, 0.0, 1.0);
    out.v = std::clamp(v, 0.0, 1.0);
    return true;
  }
  return false;
}

inline bool inverse_bilinear_3d(const Vec3d& p, const Vec3d q[4], QuadUV& out) {
  const Vec3d n = cross(q[2] - q[0], q[3] - q[1]);
  const Vec3d a{std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
  const int drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  const double x[4] = {q[0][i], q[1][i], q[2][i], q[3][i]};
  const double y[4] = {q[0][j], q[1][j], q[2][j], q[3][j]};
  return inverse_bilinear_2d(p[i], p[j], x, y, out);
}

}  // namespace shadetool
#pragma GCC visibility pop
