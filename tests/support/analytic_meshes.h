// analytic_meshes.h: test (and benchmark) meshes whose true normals are known in closed form.
//
// Every position is computed in double from its surface parameters, so it lies on the surface up
// to one double rounding (~1e-16 relative); the exact normal at that parameter is returned beside
// it. "Irregular" variants jitter the parameters (the vertex stays exactly on the surface) and flip
// random edges, so that a weighting cannot profit from a regular grid.
//
// Orientation: every face is wound counter-clockwise seen from outside (normals point outward).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

namespace shadetool::testing {

struct AnalyticMesh {
  Mesh mesh;
  std::vector<Vec3d> exact_normals;  // one unit normal per vertex
};

using shadetool::kPi;  // core/math_constants.h: one pi

// Angle between two vectors in degrees, accurate for tiny angles (atan2 of |a x b| and a.b).
inline double angle_degrees(const Vec3d& a, const Vec3d& b) {
  return std::atan2(length(cross(a, b)), dot(a, b)) * 180.0 / kPi;
}

// Flips each interior edge with probability `fraction` where the flip keeps the mesh valid
// (the new diagonal is not an existing edge and both new triangles keep positive orientation
// with respect to the vertices' exact normals).
inline void random_edge_flips(AnalyticMesh& am, double fraction, std::uint32_t seed) {
  Mesh& m = am.mesh;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  const std::size_t F = m.num_faces();
  auto key = [](std::uint32_t a, std::uint32_t b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edge_faces;
  for (std::uint32_t f = 0; f < F; ++f)
    for (int k = 0; k < 3; ++k) edge_faces[key(m.corner_vertex[3 * f + k], m.corner_vertex[3 * f + (k + 1) % 3])].push_back(f);
  std::vector<char> touched(F, 0);
  for (auto& [e, faces] : edge_faces) {
    if (faces.size() != 2 || u01(rng) >= fraction) continue;
    const std::uint32_t f0 = faces[0], f1 = faces[1];
    if (touched[f0] || touched[f1]) continue;  // keep flips independent: adjacency stays valid
    auto opposite = [&](std::uint32_t f) {
      for (int k = 0; k < 3; ++k) {
        std::uint32_t v = m.corner_vertex[3 * f + k];
        if (v != e.first && v != e.second) return std::make_pair(v, k);
      }
      return std::make_pair(std::uint32_t(-1), -1);
    };
    auto [c, kc] = opposite(f0);
    auto [d, kd] = opposite(f1);
    if (kc < 0 || kd < 0 || c == d || edge_faces.count(key(c, d))) continue;
    // f0 = (c, a, b) in its winding order starting at c; f1 contains b, a, d.
    const std::uint32_t a = m.corner_vertex[3 * f0 + (kc + 1) % 3], b = m.corner_vertex[3 * f0 + (kc + 2) % 3];
    const std::uint32_t t0[3] = {c, a, d}, t1[3] = {d, b, c};
    auto positive = [&](const std::uint32_t* t) {
      Vec3d n = cross(m.position(t[1]) - m.position(t[0]), m.position(t[2]) - m.position(t[0]));
      Vec3d ref = am.exact_normals[t[0]] + am.exact_normals[t[1]] + am.exact_normals[t[2]];
      return dot(n, ref) > 1e-3 * length(n) * length(ref);
    };
    if (!positive(t0) || !positive(t1)) continue;
    for (int k = 0; k < 3; ++k) { m.corner_vertex[3 * f0 + k] = t0[k]; m.corner_vertex[3 * f1 + k] = t1[k]; }
    touched[f0] = touched[f1] = 1;
  }
}

// Triangulates a (nu x nv) parameter grid, periodic in u and, if `periodic_v`, in v; vertices
// are given by `index(i, j)`. Triangles (i,j),(i+1,j),(i+1,j+1) and (i,j),(i+1,j+1),(i,j+1) are
// outward when dp/du x dp/dv points outward.
template <class Index>
void triangulate_grid(Mesh& m, int nu, int nv_cells, Index index) {
  for (int j = 0; j < nv_cells; ++j)
    for (int i = 0; i < nu; ++i) {
      const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      if (a != b && b != c && a != c) m.add_face({a, b, c});
      if (a != c && c != d && a != d) m.add_face({a, c, d});
    }
}

// Torus around z: p = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), n = (cos v cos u, cos v sin u, sin v).
inline AnalyticMesh torus(int nu, int nv, double R = 1.0, double r = 0.4, double jitter = 0.0, std::uint32_t seed = 1) {
  AnalyticMesh am;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> J(-jitter, jitter);
  const double du = 2 * kPi / nu, dv = 2 * kPi / nv;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = (i + J(rng)) * du, v = (j + J(rng)) * dv;
      am.mesh.add_vertex({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
      am.exact_normals.push_back({std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)});
    }
  // u increases east, v around the tube: du x dv points out of the tube.
  triangulate_grid(am.mesh, nu, nv, [&](int i, int j) { return std::uint32_t((j % nv) * nu + (i % nu)); });
  am.mesh.precision = ValuePrecision::Double;
  return am;
}

// A textured torus (radii R and r) as an n by n grid of triangles, each cell split along the same
// diagonal, with texture coordinates (i / n, j / n) split along the seams u = 1 and v = 1 ((n + 1)^2
// of them): positions and texture coordinates shared between corners by index, no normals in the
// mesh (exact_normals beside it). The mesh of bench/normals/bench_tangents and tests/normals/tangents.
inline AnalyticMesh textured_torus(int n, double R = 1.0, double r = 0.35) {
  AnalyticMesh am;
  Mesh& m = am.mesh;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / n;
      m.add_vertex({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
      am.exact_normals.push_back({std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)});
    }
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.texcoords.insert(m.texcoords.end(), {double(i) / n, double(j) / n});
  auto vid = [n](int i, int j) { return std::uint32_t((j % n) * n + (i % n)); };
  auto tid = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.add_face({vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)});
      m.corner_texcoord_index.insert(m.corner_texcoord_index.end(), {tid(i, j), tid(i + 1, j), tid(i + 1, j + 1)});
      m.add_face({vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)});
      m.corner_texcoord_index.insert(m.corner_texcoord_index.end(), {tid(i, j), tid(i + 1, j + 1), tid(i, j + 1)});
    }
  return am;
}

// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 as a UV grid: nu longitudes, nv latitude bands, single
// pole vertices. Normal ∝ (x/a^2, y/b^2, z/c^2). a = b = c = 1 is the UV sphere.
inline AnalyticMesh uv_ellipsoid(int nu, int nv, double a, double b, double c, double jitter = 0.0, std::uint32_t seed = 1) {
  AnalyticMesh am;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> J(-jitter, jitter);
  auto add = [&](double t, double p) {
    const Vec3d s{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
    am.mesh.add_vertex({a * s.x, b * s.y, c * s.z});
    am.exact_normals.push_back(normalized_or(Vec3d{s.x / a, s.y / b, s.z / c}, Vec3d{0, 0, 1}));
  };
  add(0, 0);  // north pole, vertex 0
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) add((j + J(rng)) * kPi / nv, (i + J(rng)) * 2 * kPi / nu);
  add(kPi, 0);  // south pole
  const std::uint32_t south = std::uint32_t(am.mesh.num_vertices() - 1);
  // theta increases southward, phi eastward; d/dtheta x d/dphi is outward, so the grid's u
  // direction runs westward (phi decreasing): du x dv = -dphi x dtheta = dtheta x dphi.
  triangulate_grid(am.mesh, nu, nv, [&](int i, int j) -> std::uint32_t {
    if (j == 0) return 0;
    if (j == nv) return south;
    return std::uint32_t(1 + (j - 1) * nu + ((nu - i % nu) % nu));
  });
  am.mesh.precision = ValuePrecision::Double;
  return am;
}

inline AnalyticMesh uv_sphere(int nu, int nv, double jitter = 0.0, std::uint32_t seed = 1) {
  return uv_ellipsoid(nu, nv, 1, 1, 1, jitter, seed);
}

// Icosphere: icosahedron subdivided `levels` times, every vertex projected onto the unit sphere
// (20 * 4^levels faces). `jitter` moves each vertex by up to jitter * edge length along the
// tangent plane, then back onto the sphere.
inline AnalyticMesh icosphere(int levels, double jitter = 0.0, std::uint32_t seed = 1) {
  AnalyticMesh am;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3d> P = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : P) p = normalized_or(p, p);
  std::vector<std::uint32_t> F = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2,
                                  10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5,
                                  2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto k = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(k);
      if (it != mid.end()) return it->second;
      const Vec3d m = P[a] + P[b];
      P.push_back(normalized_or(m, m));
      return mid[k] = std::uint32_t(P.size() - 1);
    };
    std::vector<std::uint32_t> G;
    for (std::size_t f = 0; f < F.size(); f += 3) {
      const std::uint32_t a = F[f], b = F[f + 1], c = F[f + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      G.insert(G.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    F.swap(G);
  }
  if (jitter > 0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> J(-1, 1);
    const double h = jitter * 1.1 / std::pow(2.0, levels);  // ~ edge length of the subdivision
    for (auto& p : P) {
      const Vec3d q = p + Vec3d{J(rng), J(rng), J(rng)} * h;
      const Vec3d tangent_move = q - p * dot(q - p, p);
      p = normalized_or(tangent_move, p);
    }
  }
  for (auto& p : P) { am.mesh.add_vertex(p); am.exact_normals.push_back(p); }
  for (std::size_t f = 0; f < F.size(); f += 3) am.mesh.add_face({F[f], F[f + 1], F[f + 2]});
  am.mesh.precision = ValuePrecision::Double;
  return am;
}

// Irregular versions: jittered parameters plus 30% random edge flips.
inline AnalyticMesh irregular(AnalyticMesh am, std::uint32_t seed = 7) {
  random_edge_flips(am, 0.3, seed);
  return am;
}

}  // namespace shadetool::testing
