// The fit's elements for a concave quad: two triangles through its reflex corner (geometry/
// polygon_triangles.h quad_is_concave and polygon_triangles, as render draws it), not the bilinear
// map on corners 0..3, which folds (its Jacobian changes sign at the reflex corner) and so counts
// the fold twice: the integral of |P_u x P_v| over the unit square exceeds the quad's area.
// Truth the code did not produce: the shoelace area and a crossing-number inside test
// (tests/geometry/polygon_outlines.h), triangle areas by the cross product and a bilinear element's
// area by a 400 x 400 midpoint rule, all computed here.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

#include <shadetool/fit/least_squares_fit.h>
#include "geometry/polygon_outlines.h"

using namespace shadetool;
using namespace shadetool_test;

namespace {

std::array<double, 3> at(const Mesh& m, std::uint32_t v) { return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]}; }

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::array<double, 3> sub(const std::array<double, 3>& a, const std::array<double, 3>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const std::array<double, 3>& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The area of the elements fit_elements made for the mesh: its triangles' and its bilinear quads'
// (the integral of |P_u x P_v| du dv, by the midpoint rule on a 400 x 400 grid).
double element_area(const Mesh& m, const FitElements& e, std::size_t& triangles, std::size_t& quads) {
  double sum = 0;
  triangles = e.triangles;
  quads = e.quad_face.size();
  for (std::size_t t = 0; t < e.triangles; ++t) {
    const std::uint32_t* v = e.triangle_vertices() + 3 * t;
    sum += norm(cross(sub(at(m, v[1]), at(m, v[0])), sub(at(m, v[2]), at(m, v[0])))) / 2;
  }
  for (std::size_t k = 0; k < quads; ++k) {
    std::array<double, 3> q[4];
    for (int j = 0; j < 4; ++j) q[j] = at(m, e.quad_vertex[4 * k + j]);
    const int n = 400;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = (i + 0.5) / n, v = (j + 0.5) / n;
        std::array<double, 3> pu, pv;  // P = (1-u)(1-v) q0 + u(1-v) q1 + uv q2 + (1-u)v q3
        for (int c = 0; c < 3; ++c) {
          pu[c] = (1 - v) * (q[1][c] - q[0][c]) + v * (q[2][c] - q[3][c]);
          pv[c] = (1 - u) * (q[3][c] - q[0][c]) + u * (q[2][c] - q[1][c]);
        }
        sum += norm(cross(pu, pv)) / (double(n) * n);
      }
  }
  return sum;
}

// The outline (x, y) placed on a tilted plane z = 0.3 x - 0.2 y (areas scale by sqrt(1 + 0.09 + 0.04)).
Mesh tilted_face(const Outline& p) {
  Mesh m;
  std::vector<std::uint32_t> face;
  for (const auto& q : p) face.push_back(m.add_vertex({q[0], q[1], 0.3 * q[0] - 0.2 * q[1]}));
  m.add_face(face);
  return m;
}

}  // namespace

TEST_CASE("fit: a concave quad's elements are two triangles inside its outline whose areas sum to its area; a convex quad stays one bilinear element",
          "[fit][polygon_triangles]") {
  const double tilt = std::sqrt(1 + 0.09 + 0.04);
  // Dart (0,0) (2,1) (0,2) (0.5,1), reflex at (0.5,1): shoelace area 1.5; from each corner, so the
  // reflex corner is at 3, 2, 1 and 0 (the 0-2 diagonal lies outside it at 1 and 3).
  const Outline dart{{0, 0}, {2, 1}, {0, 2}, {0.5, 1}};
  REQUIRE(shoelace_area(dart) == 1.5);
  for (std::size_t r = 0; r < 4; ++r) {
    Outline p;
    for (std::size_t k = 0; k < 4; ++k) p.push_back(dart[(r + k) % 4]);
    INFO("reflex corner at " << (3 + 4 - r) % 4);
    const Mesh m = tilted_face(p);
    const FitElements e = fit_elements(m);
    std::size_t triangles = 0, quads = 0;
    const double area = element_area(m, e, triangles, quads);
    CHECK(area == Approx(1.5 * tilt).epsilon(1e-12));
    CHECK(triangles == 2);
    CHECK(quads == 0);
    for (std::size_t t = 0; t < e.triangles; ++t) {
      const std::uint32_t* v = e.triangle_vertices() + 3 * t;
      CHECK(crossing_inside(p, (p[v[0]][0] + p[v[1]][0] + p[v[2]][0]) / 3, (p[v[0]][1] + p[v[1]][1] + p[v[2]][1]) / 3));
      CHECK((p[v[1]][0] - p[v[0]][0]) * (p[v[2]][1] - p[v[0]][1]) - (p[v[1]][1] - p[v[0]][1]) * (p[v[2]][0] - p[v[0]][0]) > 0);  // wound as the quad
    }
  }
  // A convex quad (0,0) (3,0) (2,2) (0,1): area (0 + 6 + 2 - 0) / 2 = 4, one bilinear element (its
  // 3x3 Gauss mass is exact on it), the bilinear area by the midpoint rule (degree 1 in u and v on a
  // planar quad: exact up to rounding).
  const Outline convex{{0, 0}, {3, 0}, {2, 2}, {0, 1}};
  const Mesh m = tilted_face(convex);
  const FitElements e = fit_elements(m);
  std::size_t triangles = 0, quads = 0;
  CHECK(element_area(m, e, triangles, quads) == Approx(4 * tilt).epsilon(1e-12));
  CHECK(triangles == 0);
  CHECK(quads == 1);
}
