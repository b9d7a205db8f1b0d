// visibility_test_util.h: scenes whose open fractions are known in closed form, and the closed
// forms, computed without the code under test.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

namespace shadetool::testing {

// Cosine-weighted fraction of the hemisphere about unit n covered by a planar polygon seen from
// p (the polygon's form factor, Lambert 1760): F = 1/(2 pi) |sum_i gamma_i n.(a_i x a_{i+1})/|a_i x a_{i+1}||,
// a_i = v_i - p, gamma_i the angle between a_i and a_{i+1}. Exact for any polygon wholly above
// the horizon of n.
inline double polygon_form_factor(const Vec3d& p, const Vec3d& n, const std::vector<Vec3d>& polygon) {
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3d a = polygon[i] - p, b = polygon[(i + 1) % polygon.size()] - p;
    const Vec3d c = cross(a, b);
    const double lc = length(c);
    if (lc == 0) continue;
    const double gamma = std::atan2(lc, dot(a, b));
    sum += gamma * dot(n, c) / lc;
  }
  return std::fabs(sum) / (2 * 3.14159265358979323846);
}

// Regular `sides`-gon of circumradius r in the plane z = h, centred on the z axis.
inline std::vector<Vec3d> disc_polygon(double r, double h, int sides) {
  std::vector<Vec3d> v;
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / sides;
    v.push_back({r * std::cos(a), r * std::sin(a), h});
  }
  return v;
}

// A square plane z = 0, [-half, half]^2, as an n x n grid of quads (polygons) or triangles.
inline Mesh plane_grid(double half, int n, bool quads) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.add_vertex({-half + 2 * half * i / n, -half + 2 * half * j / n, 0});
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (quads) {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  m.precision = ValuePrecision::Double;
  return m;
}

// Appends a polygon face of new vertices.
inline void add_polygon(Mesh& m, const std::vector<Vec3d>& polygon) {
  std::vector<std::uint32_t> f;
  for (const Vec3d& p : polygon) f.push_back(m.add_vertex(p));
  m.add_face(f);
}

// The unit cube [0,1]^3 as 6 quads (outward), or only the three walls through the origin.
inline Mesh unit_cube(bool only_corner_walls) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.add_face({0, 2, 3, 1});  // z = 0
  m.add_face({0, 1, 5, 4});  // y = 0
  m.add_face({0, 4, 6, 2});  // x = 0
  if (!only_corner_walls) {
    m.add_face({4, 5, 7, 6});  // z = 1
    m.add_face({2, 6, 7, 3});  // y = 1
    m.add_face({1, 3, 7, 5});  // x = 1
  }
  m.precision = ValuePrecision::Double;
  return m;
}

inline void transform_positions(Mesh& m, double scale, const Vec3d& offset) {
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.set_position(v, m.position(v) * scale + offset);
}

}  // namespace shadetool::testing
