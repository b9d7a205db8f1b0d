// bench_meshes.h: the benchmark's catalogue of analytic meshes (shared by bench/generate and
// bench/compare, so that files on disk and in-process meshes are the same meshes).
//
//   surface    sphere (UV sphere, r = 1), icosphere (r = 1), torus (R = 1, r = 0.4),
//              ellipsoid (UV grid, semi-axes 1.5, 1, 0.5)
//   size       10k, 1M, 4M triangles, approximately (icosphere: 20 * 4^l = 20k, 1.3M, 5.2M)
//   irregular  parameters jittered by 0.3 of a cell along the surface (every vertex stays exactly
//              on it) and 30% of the interior edges flipped at random (fast_edge_flips.h), as
//              tests/support/analytic_meshes.h `irregular` does; regular = exact grid, no flips
//   degenerate the 10k irregular sphere plus what real files contain and the analytic meshes do
//              not: faces with a repeated index, faces with two coincident positions, collinear
//              (zero-area) faces, and isolated vertices, each attached to vertices of their own
//              (so the exact normals of the sphere's vertices are unchanged); the extra vertices
//              are flagged in `at_risk` and excluded from the angular error, only counted.
// Exact normals: one unit normal per vertex in closed form (analytic_meshes.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "fast_edge_flips.h"
#include "support/analytic_meshes.h"

namespace shadetool::bench {

enum class Surface { Sphere, Icosphere, Torus, Ellipsoid };
enum class SizeClass { S10k, S1M, S4M };

inline const char* surface_name(Surface s) {
  switch (s) {
    case Surface::Sphere: return "sphere";
    case Surface::Icosphere: return "icosphere";
    case Surface::Torus: return "torus";
    case Surface::Ellipsoid: return "ellipsoid";
  }
  return "?";
}
inline const char* size_name(SizeClass s) {
  switch (s) {
    case SizeClass::S10k: return "10k";
    case SizeClass::S1M: return "1M";
    case SizeClass::S4M: return "4M";
  }
  return "?";
}
inline Surface parse_surface(const std::string& s) {
  for (Surface x : {Surface::Sphere, Surface::Icosphere, Surface::Torus, Surface::Ellipsoid})
    if (s == surface_name(x)) return x;
  throw std::runtime_error("unknown surface '" + s + "' (sphere, icosphere, torus, ellipsoid)");
}
inline SizeClass parse_size(const std::string& s) {
  for (SizeClass x : {SizeClass::S10k, SizeClass::S1M, SizeClass::S4M})
    if (s == size_name(x)) return x;
  throw std::runtime_error("unknown size '" + s + "' (10k, 1M, 4M)");
}

struct BenchMesh {
  std::string name;                 // e.g. "sphere_1M_irregular"
  testing::AnalyticMesh am;
  std::vector<char> at_risk;        // per vertex: 1 = belongs to a degenerate face or isolated
  std::size_t degenerate_faces = 0;
  std::size_t isolated_vertices = 0;
};

inline BenchMesh make_bench_mesh(Surface surface, SizeClass size, bool irregular) {
  using namespace testing;
  const int k = size == SizeClass::S10k ? 1 : size == SizeClass::S1M ? 10 : 20;  // grid scale
  const double jitter = irregular ? 0.3 : 0.0;
  BenchMesh b;
  b.name = std::string(surface_name(surface)) + "_" + size_name(size) + (irregular ? "_irregular" : "_regular");
  switch (surface) {
    case Surface::Sphere: b.am = uv_sphere(100 * k, 50 * k, jitter, 2); break;
    case Surface::Ellipsoid: b.am = uv_ellipsoid(100 * k, 50 * k, 1.5, 1.0, 0.5, jitter, 3); break;
    case Surface::Torus: b.am = torus(100 * k, 50 * k, 1.0, 0.4, jitter, 4); break;
    case Surface::Icosphere: {
      const int levels = size == SizeClass::S10k ? 5 : size == SizeClass::S1M ? 8 : 9;
      b.am = icosphere(levels, jitter, 6);
      break;
    }
  }
  if (irregular) random_edge_flips_sorted(b.am, 0.3, 7);
  b.at_risk.assign(b.am.mesh.num_vertices(), 0);
  return b;
}

// The 10k irregular sphere with `n` of each kind of degenerate element appended (see above).
inline BenchMesh make_degenerate_mesh(int n = 100) {
  BenchMesh b = make_bench_mesh(Surface::Sphere, SizeClass::S10k, true);
  b.name = "sphere_10k_degenerate";
  Mesh& m = b.am.mesh;
  auto add = [&](const Vec3d& p) {
    const std::uint32_t v = m.add_vertex(p);
    b.am.exact_normals.push_back(normalized_or(p, Vec3d{0, 0, 1}));
    b.at_risk.push_back(1);
    return v;
  };
  for (int i = 0; i < n; ++i) {
    // Points just outside the sphere, away from the surface mesh, so no face touches the sphere's
    // vertices: each group is a small fan of its own.
    const double t = 0.3 + 2.5 * (i + 0.5) / n, phi = 2.399963 * i;
    const Vec3d p{1.1 * std::sin(t) * std::cos(phi), 1.1 * std::sin(t) * std::sin(phi), 1.1 * std::cos(t)};
    const Vec3d u = normalized_or(cross(p, Vec3d{0, 0, 1}), Vec3d{1, 0, 0}), w = normalized_or(cross(p, u), Vec3d{0, 1, 0});
    const double h = 1e-3;
    // (1) repeated index: (a, a, b)
    const std::uint32_t a = add(p), bb = add(p + u * h);
    m.add_face({a, a, bb});
    // (2) two coincident positions: (c, d, e) with pos(d) == pos(c)
    const std::uint32_t c = add(p + w * h), d = add(p + w * h), e = add(p + (u + w) * h);
    m.add_face({c, d, e});
    // (3) collinear: (f, g, q) with g the midpoint of f and q (zero area up to rounding)
    const Vec3d pf = p - u * h, pq = p - u * (3 * h);
    const std::uint32_t f = add(pf), g = add((pf + pq) * 0.5), q = add(pq);
    m.add_face({f, g, q});
    // (4) isolated vertex
    add(p - w * h);
    b.degenerate_faces += 3;
    b.isolated_vertices += 1;
  }
  return b;
}

}  // namespace shadetool::bench
