// polygon_outlines.h (tests): the concave outlines the polygon-splitting tests share (render,
// visibility, fit, tangents) and the two truths they are checked against, computed here and not
// by the library: the shoelace area and a crossing-number point-in-polygon test.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace shadetool_test {

using Outline = std::vector<std::array<double, 2>>;

// An L hexagon of three unit squares (notch (1,1)-(2,2)), corner 0 at (2,1): the fan from corner 0
// covers the notch (its triangles' areas sum to 4, not 3).
inline Outline l_hexagon() { return {{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}}; }

// A comb: base 0..5 x 0..1, teeth at x in [0,1], [2,3], [4,5] up to y = 2 (area 8), corner 0 at a
// reflex corner.
inline Outline comb() {
  return {{3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}};
}

// Signed area (> 0 counter-clockwise), by the shoelace formula.
inline double shoelace_area(const Outline& p) {
  double a = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto &u = p[k], &v = p[(k + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return a / 2;
}

// Whether (x, y) is inside the outline, by the crossing number of a ray towards +x.
inline bool crossing_inside(const Outline& p, double x, double y) {
  bool in = false;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto &a = p[k], &b = p[(k + 1) % p.size()];
    if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))  // divisor: b.y != a.y here
      in = !in;
  }
  return in;
}

}  // namespace shadetool_test
