// normals_test_util.h: error measures and small meshes shared by the normals tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include "support/analytic_meshes.h"

namespace shadetool::testing {

struct AngularError {
  double mean_deg = 0, max_deg = 0;
  std::size_t non_finite = 0;
};

// Angle between each computed normal (#V by 3) and the exact one, in degrees.
inline AngularError angular_error(const std::vector<double>& normals, const std::vector<Vec3d>& exact) {
  AngularError e;
  for (std::size_t v = 0; v < exact.size(); ++v) {
    const Vec3d n = get3(normals, v);
    if (!is_finite(n)) { ++e.non_finite; continue; }
    const double a = angle_degrees(n, exact[v]);
    e.mean_deg += a;
    e.max_deg = std::max(e.max_deg, a);
  }
  e.mean_deg /= double(exact.size());
  return e;
}

// Faces whose geometric normal points away from the exact normals of their vertices: a folded
// test mesh, whose "truth" would be meaningless (checked before measuring errors).
inline std::size_t folded_faces(const AnalyticMesh& am) {
  const Mesh& m = am.mesh;
  std::size_t n = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t b = m.face_start[f], e = m.face_start[f + 1];
    Vec3d area{}, ref{};
    for (std::uint32_t c = b; c < e; ++c) {
      const std::uint32_t next = c + 1 < e ? c + 1 : b;
      area += cross(m.position(m.corner_vertex[c]), m.position(m.corner_vertex[next]));
      ref += am.exact_normals[m.corner_vertex[c]];
    }
    if (dot(area, ref) <= 0) ++n;
  }
  return n;
}

// Axis-aligned cube [-1,1]^3 with outward faces, as 6 quads or 12 triangles (each quad split
// along its first diagonal). Vertex i has coordinates ((i&1)?1:-1, (i&2)?1:-1, (i&4)?1:-1).
inline Mesh cube(bool quads) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
  const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& f : q) {
    if (quads) {
      m.add_face({f[0], f[1], f[2], f[3]});
    } else {
      m.add_face({f[0], f[1], f[2]});
      m.add_face({f[0], f[2], f[3]});
    }
  }
  m.precision = ValuePrecision::Double;
  return m;
}

// Outward axis of each cube face, in the order of cube(true) (face f of the quad cube; faces 2f
// and 2f+1 of the triangle cube).
inline Vec3d cube_face_axis(std::size_t quad) {
  const Vec3d axes[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  return axes[quad];
}

// UV sphere of planar quads (isosceles trapezoids between two latitudes and two longitudes) with
// triangle fans at the poles; `fan` = the same mesh with every quad split into two triangles
// (a, b, c), (a, c, d). Exact normals = positions.
inline void quad_uv_sphere(int nu, int nv, AnalyticMesh& quads, AnalyticMesh& fan) {
  for (AnalyticMesh* am : {&quads, &fan}) {
    Mesh& m = am->mesh;
    m = Mesh{};
    am->exact_normals.clear();
    auto add = [&](double t, double p) {
      const Vec3d s{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
      m.add_vertex(s);
      am->exact_normals.push_back(s);
    };
    add(0, 0);
    for (int j = 1; j < nv; ++j)
      for (int i = 0; i < nu; ++i) add(j * kPi / nv, i * 2 * kPi / nu);
    add(kPi, 0);
    const std::uint32_t south = std::uint32_t(m.num_vertices() - 1);
    auto idx = [&](int i, int j) { return std::uint32_t(1 + (j - 1) * nu + (i % nu)); };
    for (int i = 0; i < nu; ++i) m.add_face({0u, idx(i, 1), idx(i + 1, 1)});
    for (int j = 1; j + 1 < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        // theta grows southward, phi eastward: (i,j),(i,j+1),(i+1,j+1),(i+1,j) is outward.
        const std::uint32_t a = idx(i, j), b = idx(i, j + 1), c = idx(i + 1, j + 1), d = idx(i + 1, j);
        if (am == &quads) {
          m.add_face({a, b, c, d});
        } else {
          m.add_face({a, b, c});
          m.add_face({a, c, d});
        }
      }
    for (int i = 0; i < nu; ++i) m.add_face({south, idx(i + 1, nv - 1), idx(i, nv - 1)});
    m.precision = ValuePrecision::Double;
  }
}

// The same mesh with its faces in a pseudo-random order (positions and exact normals unchanged).
inline Mesh shuffle_faces(const Mesh& m, std::uint32_t seed) {
  std::vector<std::size_t> order(m.num_faces());
  for (std::size_t f = 0; f < order.size(); ++f) order[f] = f;
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  Mesh s;
  s.positions = m.positions;
  s.precision = m.precision;
  for (std::size_t f : order) {
    std::vector<std::uint32_t> face(m.corner_vertex.begin() + m.face_start[f], m.corner_vertex.begin() + m.face_start[f + 1]);
    s.add_face(face);
  }
  return s;
}

}  // namespace shadetool::testing
