// repair_test_meshes.h: meshes built in code for the repair tests, each with a known orientation
// (every face wound counter-clockwise seen from the side its normal should point to), and the
// ways to damage them (random face flips, whole inversion).
//
// Flips are done here by swapping corners 1 and 2 of a triangle (the usual way a winding goes
// wrong), never with the library's reverse_faces, so the tests do not check the code with itself.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>
#include "support/analytic_meshes.h"

namespace shadetool::testing {

// Swaps corners 1 and 2 of face f (a triangle (a, b, c) becomes (a, c, b)).
inline void swap_corners_1_2(Mesh& m, std::size_t f) {
  std::swap(m.corner_vertex[m.face_start[f] + 1], m.corner_vertex[m.face_start[f] + 2]);
  if (m.has_corner_normals()) std::swap(m.corner_normal_index[m.face_start[f] + 1], m.corner_normal_index[m.face_start[f] + 2]);
}

// Flips exactly round(fraction * F) faces chosen at random; returns them.
inline std::vector<std::size_t> flip_random_faces(Mesh& m, double fraction, std::uint32_t seed) {
  std::vector<std::size_t> faces(m.num_faces());
  for (std::size_t f = 0; f < faces.size(); ++f) faces[f] = f;
  std::mt19937 rng(seed);
  std::shuffle(faces.begin(), faces.end(), rng);
  faces.resize(std::size_t(std::llround(fraction * double(faces.size()))));
  for (std::size_t f : faces) swap_corners_1_2(m, f);
  return faces;
}

inline void invert_all(Mesh& m) {
  for (std::size_t f = 0; f < m.num_faces(); ++f) swap_corners_1_2(m, f);
}

// Appends b to a (vertex indices shifted).
inline void append(Mesh& a, const Mesh& b) {
  const std::uint32_t base = std::uint32_t(a.num_vertices());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (std::size_t f = 0; f < b.num_faces(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t c = b.face_start[f]; c < b.face_start[f + 1]; ++c) face.push_back(base + b.corner_vertex[c]);
    a.add_face(face);
  }
}

inline void transform_positions(Mesh& m, double scale, const Vec3d& offset) {
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.set_position(v, m.position(v) * scale + offset);
}

// Keeps the faces `keep` accepts (by centroid) and the vertices they use, in order.
inline Mesh keep_faces(const Mesh& m, const std::function<bool(const Vec3d&)>& keep) {
  Mesh out;
  out.precision = m.precision;
  std::vector<std::uint32_t> remap(m.num_vertices(), UINT32_MAX);
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    Vec3d c{};
    for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) c += m.position(m.corner_vertex[k]);
    if (!keep(c * (1.0 / double(m.face_size(f))))) continue;
    std::vector<std::uint32_t> face;
    for (std::uint32_t k = m.face_start[f]; k < m.face_start[f + 1]; ++k) {
      std::uint32_t& r = remap[m.corner_vertex[k]];
      if (r == UINT32_MAX) r = out.add_vertex(m.position(m.corner_vertex[k]));
      face.push_back(r);
    }
    out.add_face(face);
  }
  return out;
}

// Boundary of a union of unit voxels: a 7 x 3 x 1 slab with the voxels (1,1), (3,1), (5,1)
// removed, a genus-3 closed surface (Euler characteristic V - E + F = -4). Each exposed voxel side
// becomes two triangles wound counter-clockwise seen from outside. Integer coordinates.
inline Mesh genus3_slab() {
  const int NX = 7, NY = 3;
  auto filled = [&](int i, int j, int k) {
    if (i < 0 || j < 0 || k != 0 || i >= NX || j >= NY) return false;
    return !(j == 1 && (i == 1 || i == 3 || i == 5));
  };
  Mesh m;
  m.precision = ValuePrecision::Double;
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= NY; ++j)
      for (int i = 0; i <= NX; ++i) m.add_vertex({double(i), double(j), double(k)});
  auto id = [&](int i, int j, int k) { return std::uint32_t(i + (NX + 1) * (j + (NY + 1) * k)); };
  const int dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i) {
      if (!filled(i, j, 0)) continue;
      for (auto& d : dirs) {
        if (filled(i + d[0], j + d[1], d[2])) continue;
        // The side's four corners: the axis of d fixed at the near or far side of the voxel.
        const int axis = d[0] != 0 ? 0 : (d[1] != 0 ? 1 : 2);
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        std::uint32_t q[4];
        const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
        for (int n = 0; n < 4; ++n) {
          int p[3] = {i, j, 0};
          p[axis] += (d[axis] > 0 ? 1 : 0);
          p[u] += du[n];
          p[w] += dw[n];
          q[n] = id(p[0], p[1], p[2]);
        }
        // (u, w, axis) is a right-handed frame: u x w = axis, so q is counter-clockwise seen
        // from +axis; reverse it for a side facing -axis.
        if (d[axis] < 0) std::swap(q[1], q[3]);
        m.add_face({q[0], q[1], q[2]});
        m.add_face({q[0], q[2], q[3]});
      }
    }
  return m;
}

// Möbius strip: n segments around a circle of radius R, width 2 w, half a twist. Triangles wound
// consistently along the strip except where it closes (no consistent winding exists there).
inline Mesh mobius_strip(int n, double R = 1.0, double w = 0.3) {
  Mesh m;
  m.precision = ValuePrecision::Double;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * kPi * i / n;
    const Vec3d c{R * std::cos(u), R * std::sin(u), 0}, r{std::cos(u), std::sin(u), 0};
    const Vec3d d = r * std::cos(u / 2) + Vec3d{0, 0, 1} * std::sin(u / 2);
    m.add_vertex(c - d * w);
    m.add_vertex(c + d * w);
  }
  for (int i = 0; i < n; ++i) {
    const std::uint32_t a = 2 * i, b = 2 * i + 1;
    // After a full turn the strip comes back with its sides swapped.
    const std::uint32_t a1 = i + 1 < n ? 2 * (i + 1) : 1, b1 = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    m.add_face({a, a1, b1});
    m.add_face({a, b1, b});
  }
  return m;
}

// Upper half (z > 0) of a UV sphere: an open hemisphere with one boundary loop, normals outward.
inline Mesh hemisphere(int nu, int nv_full) {
  return keep_faces(uv_sphere(nu, nv_full).mesh, [](const Vec3d& c) { return c.z > 0; });
}

// Height field z = 0.05 sin(4 pi x) sin(6 pi y) on [0,1]^2, n x n cells, wound to face +z. Its
// bumps rise as much as they sink: no side is favoured by its shape.
inline Mesh bumpy_terrain(int n) {
  Mesh m;
  m.precision = ValuePrecision::Double;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      m.add_vertex({x, y, 0.05 * std::sin(4 * kPi * x) * std::sin(6 * kPi * y)});
    }
  auto id = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Three triangles sharing the edge (0, 1): a non-manifold edge, nothing else.
inline Mesh three_triangles_on_one_edge() {
  Mesh m;
  m.precision = ValuePrecision::Double;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0.5, 1, 0});
  m.add_vertex({0.5, -0.5, 0.8});
  m.add_vertex({0.5, -0.5, -0.8});
  m.add_face({0, 1, 2});
  m.add_face({1, 0, 3});
  m.add_face({0, 1, 4});
  return m;
}

// Euler characteristic V - E + F over the vertices the faces use.
inline long euler_characteristic(const Mesh& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::set<std::uint32_t> verts;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
      const std::uint32_t a = m.corner_vertex[c], b = m.corner_vertex[c + 1 < m.face_start[f + 1] ? c + 1 : m.face_start[f]];
      edges.insert({std::min(a, b), std::max(a, b)});
      verts.insert(a);
    }
  return long(verts.size()) - long(edges.size()) + long(m.num_faces());
}

// Sum over faces of the signed volume from the origin, computed independently of the library
// (long double, for closed test meshes near the origin).
inline long double volume_from_origin(const Mesh& m) {
  long double v = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t b = m.face_start[f];
    for (std::uint32_t c = b + 1; c + 1 < m.face_start[f + 1]; ++c) {
      const Vec3d p = m.position(m.corner_vertex[b]), q = m.position(m.corner_vertex[c]), r = m.position(m.corner_vertex[c + 1]);
      v += (long double)dot(p, cross(q, r)) / 6;
    }
  }
  return v;
}

// Number of manifold edges whose two faces traverse them in the same direction.
inline std::size_t same_direction_edges(const Mesh& m) {
  std::multiset<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c)
      directed.insert({m.corner_vertex[c], m.corner_vertex[c + 1 < m.face_start[f + 1] ? c + 1 : m.face_start[f]]});
  std::size_t n = 0;
  for (auto it = directed.begin(); it != directed.end(); it = directed.upper_bound(*it))
    if (directed.count(*it) == 2) ++n;
  return n;
}

// One small mesh with every kind of degenerate face, for the tests of repair/degenerate_faces and
// of the volume pass that classifies faces the same way.
// Seven triangles, expected kinds (DegenerateKind): None, RepeatedIndex, ZeroArea, None,
// NonFinite, ZeroArea, None.
inline Mesh degenerate_triangles_mesh() {
  Mesh m;
  m.add_vertex({0, 0, 0});                                         // 0
  m.add_vertex({1, 0, 0});                                         // 1
  m.add_vertex({0, 1, 0});                                         // 2
  m.add_vertex({2, 0, 0});                                         // 3: collinear with 0 and 1
  m.add_vertex({1e-20, 0, 0});                                     // 4
  m.add_vertex({0, 1e-20, 0});                                     // 5
  m.add_vertex({std::numeric_limits<double>::quiet_NaN(), 0, 0});  // 6
  m.add_vertex({1, 1e-15, 0});  // 7: 1e-15 off the line: sin(angle) ~ 5e-16, below 1.4e-14
  m.add_vertex({1, 1e-9, 0});   // 8: clearly off the line
  m.add_face({0, 1, 2});  // fine
  m.add_face({0, 1, 1});  // repeated index
  m.add_face({0, 1, 3});  // collinear: zero area
  m.add_face({0, 4, 5});  // 1e-20 wide, right-angled: fine
  m.add_face({0, 1, 6});  // NaN corner
  m.add_face({0, 3, 7});  // numerically collinear
  m.add_face({0, 3, 8});  // thin but real
  return m;
}

// Appends three faces that are not triangles; expected kinds: TooFewCorners, None, RepeatedIndex.
inline void add_degenerate_polygons(Mesh& m) {
  m.add_face({0, 1});        // too few corners
  m.add_face({0, 1, 8, 2});  // a quad: fine
  m.add_face({0, 1, 3, 1});  // quad with a repeated index
}

}  // namespace shadetool::testing
