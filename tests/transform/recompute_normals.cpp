// Tests of transform/recompute_normals (`--normals recompute`): normals rebuilt from the faces,
// with the input's smoothing groups kept, against hand-computed normals of sheared cubes and
// flat patches.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "support/analytic_meshes.h"
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/recompute_normals.h>
#include <shadetool/transform/transform_mesh.h>

using namespace shadetool;

namespace {

// Cube [-1,1]^3 as 6 outward quads; vertex i has x > 0 iff bit 0, y iff bit 1, z iff bit 2.
// Face order +x, -x, +y, -y, +z, -z (the pool index of a flat-shaded corner is its face).
Mesh cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  m.add_face({1, 3, 7, 5});
  m.add_face({0, 4, 6, 2});
  m.add_face({2, 6, 7, 3});
  m.add_face({0, 1, 5, 4});
  m.add_face({4, 5, 7, 6});
  m.add_face({0, 2, 3, 1});
  return m;
}

const Vec3d kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

Mesh flat_shaded_cube() {
  Mesh m = cube();
  for (const Vec3d& a : kAxes) m.corner_normals.insert(m.corner_normals.end(), {a.x, a.y, a.z});
  for (std::uint32_t f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) m.corner_normal_index.push_back(f);
  m.face_normals = m.corner_normals;
  return m;
}

Affine3d shear() {  // A = [[1,1,0],[0,1,0],[0,0,2]]
  Affine3d M;
  M.A.m = {{{1, 1, 0}, {0, 1, 0}, {0, 0, 2}}};
  return M;
}

// Hand computation: A^-1 = [[1,-1,0],[0,1,0],[0,0,1/2]], so A^-T = [[1,0,0],[-1,1,0],[0,0,1/2]]
// and the mapped face normals A^-T e / |.| are:
const double r2 = 1 / std::sqrt(2.0);
const Vec3d kShearedAxes[6] = {{r2, -r2, 0}, {-r2, r2, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

}  // namespace

TEST_CASE("recompute_normals: flat-shaded sheared cube gets its faces' normals, groups kept", "[recompute_normals]") {
  Mesh m = flat_shaded_cube();
  TransformOptions o;
  o.normals = NormalsPolicy::Recompute;
  const TransformReport r = transform_mesh(m, shear(), o);
  CHECK(std::string(r.normals) == "recomputed");
  CHECK(r.fallback_normals == 0);
  // One group per (vertex, face): 24 pool entries, each corner its own.
  REQUIRE(m.corner_normals.size() == 24 * 3);
  for (std::size_t f = 0; f < 6; ++f) {
    CHECK(length(get3(m.face_normals, f) - kShearedAxes[f]) < 1e-15);
    for (std::size_t c = 4 * f; c < 4 * f + 4; ++c)
      CHECK(length(get3(m.corner_normals, m.corner_normal_index[c]) - kShearedAxes[f]) < 1e-15);
  }
  // The transform path (cofactor) gives the same normals: two independent routes agree.
  Mesh t = flat_shaded_cube();
  transform_mesh(t, shear());
  for (std::size_t f = 0; f < 6; ++f) CHECK(length(get3(t.face_normals, f) - kShearedAxes[f]) < 1e-15);
}

TEST_CASE("recompute_normals: a smooth group at a cube corner is the normalised diagonal", "[recompute_normals]") {
  // All three corners of a vertex share one pool entry: angle-weighted (pi/2 each) mean of the
  // three face normals = (+-1, +-1, +-1) / sqrt 3.
  Mesh m = cube();
  m.corner_normals.assign(3, 0.0);  // one stale entry, to be replaced
  m.corner_normal_index.assign(m.num_corners(), 0);
  const std::size_t fallbacks = recompute_normals(m);
  CHECK(fallbacks == 0);
  REQUIRE(m.corner_normals.size() == 8 * 3);  // pool index 0 at 8 vertices: 8 groups
  const double s = 1 / std::sqrt(3.0);
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const Vec3d p = m.position(m.corner_vertex[c]);
    CHECK(length(get3(m.corner_normals, m.corner_normal_index[c]) - p * s) < 1e-15);
  }
}

TEST_CASE("recompute_normals: vertex normals of a sheared flat patch equal the mapped plane's normal",
          "[recompute_normals]") {
  // Fan in the plane z = 0 (normal +z). After A = [[1,1,0],[0,1,0],[0,0,2]] the plane is still
  // z = 0 and every recomputed vertex normal is (0, 0, 1), whatever the weights.
  Mesh m;
  m.add_vertex({0, 0, 0});
  for (int k = 0; k < 5; ++k) m.add_vertex({std::cos(1.2 * k + 0.3), std::sin(1.2 * k + 0.3) * (1 + 0.1 * k), 0});
  for (std::uint32_t k = 0; k < 5; ++k) m.add_face({0, 1 + k, 1 + (k + 1) % 5});
  m.vertex_normals.assign(6 * 3, 0.0);  // stale zeros, to be replaced
  TransformOptions o;
  o.normals = NormalsPolicy::Recompute;
  transform_mesh(m, shear(), o);
  for (std::size_t v = 0; v < 6; ++v) {
    CAPTURE(v);
    CHECK(length(get3(m.vertex_normals, v) - Vec3d(0, 0, 1)) < 1e-15);  // one normalisation's rounding
  }
}

TEST_CASE("recompute_normals: a mirror's recomputed normals point outward", "[recompute_normals]") {
  testing::AnalyticMesh ico = testing::icosphere(3);
  Mesh m = ico.mesh;
  m.vertex_normals.assign(3 * m.num_vertices(), 0.0);
  TransformOptions o;
  o.normals = NormalsPolicy::Recompute;
  const TransformReport r = transform_mesh(m, scale_map({-1, 1, 1}), o);
  CHECK(r.winding_reversed);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    // Unit sphere: outward normal at p is p; the discrete normal is within a degree of it.
    CHECK(testing::angle_degrees(get3(m.vertex_normals, v), m.position(v)) < 1.0);
  }
}

TEST_CASE("recompute_normals: a group whose faces are all degenerate falls back to its vertex", "[recompute_normals]") {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({0, 1, 0}); m.add_vertex({2, 0, 0});
  m.add_face({0, 1, 2});  // valid, normal +z
  m.add_face({0, 1, 3});  // collinear: zero area
  m.corner_normals = {0, 0, 1, 0, 1, 0};
  m.corner_normal_index = {0, 0, 0, 1, 1, 1};  // the degenerate face's corners form their own groups
  const std::size_t fallbacks = recompute_normals(m);
  // Groups: (0,0) (1,0) (2,0) from face 0; (0,1) (1,1) (3,1) from face 1, degenerate: 3 fallbacks.
  CHECK(fallbacks == 3);
  REQUIRE(m.corner_normals.size() == 6 * 3);
  for (std::size_t c = 0; c < 3; ++c) CHECK(get3(m.corner_normals, m.corner_normal_index[c]) == Vec3d(0, 0, 1));
  // Vertices 0 and 1 have a valid face: their vertex normal (+z) is the fallback.
  CHECK(get3(m.corner_normals, m.corner_normal_index[3]) == Vec3d(0, 0, 1));
  CHECK(get3(m.corner_normals, m.corner_normal_index[4]) == Vec3d(0, 0, 1));
  for (double x : m.corner_normals) CHECK(std::isfinite(x));
}

TEST_CASE("recompute_normals: a mesh without normals is left without normals", "[recompute_normals]") {
  Mesh m = cube();
  CHECK(recompute_normals(m) == 0);
  CHECK_FALSE(m.has_vertex_normals());
  CHECK_FALSE(m.has_corner_normals());
  CHECK_FALSE(m.has_face_normals());
}
