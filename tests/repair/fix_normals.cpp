// Tests of fix_normals on small cases (the full scenarios are in repair_mesh.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include <shadetool/repair/fix_normals.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("a mesh without normals gets vertex normals, counted as missing", "[repair][normals]") {
  AnalyticMesh am = uv_sphere(32, 16);
  const NormalsFix fix = fix_normals(am.mesh);
  CHECK(fix.missing == am.mesh.num_vertices());
  REQUIRE(am.mesh.vertex_normals.size() == 3 * am.mesh.num_vertices());
  for (std::size_t v = 0; v < am.mesh.num_vertices(); ++v)
    CHECK(angle_degrees(get3(am.mesh.vertex_normals, v), am.exact_normals[v]) < 2.0);
}

TEST_CASE("an isolated vertex: a NaN normal is replaced, a valid one is never called flipped", "[repair][normals]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({5, 5, 5});  // isolated
  m.add_vertex({6, 6, 6});  // isolated
  m.add_face({0, 1, 2});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.vertex_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, nan, nan, nan, 0, 0, -1};
  const NormalsFix fix = fix_normals(m);
  CHECK(fix.nan == 1);
  CHECK(fix.flipped == 0);
  for (double x : m.vertex_normals) CHECK(std::isfinite(x));
  CHECK(get3(m.vertex_normals, 4) == Vec3d{0, 0, -1});
}

TEST_CASE("stored face normals: a degenerate face's NaN becomes zero, a flipped one is recomputed", "[repair][normals]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({2, 0, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 1, 3});  // collinear
  m.add_face({0, 1, 2});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.face_normals = {0, 0, 1, nan, nan, nan, 0, 0, -1};
  m.vertex_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const NormalsFix fix = fix_normals(m);
  CHECK(fix.face == 2);
  CHECK(m.face_normals == std::vector<double>{0, 0, 1, 0, 0, 0, 0, 0, 1});
  CHECK(fix.nan == 1);
  CHECK(fix.flipped == 1);
  CHECK(fix.vertex == 0);
}

TEST_CASE("a second pass over fixed normals changes nothing", "[repair][normals]") {
  AnalyticMesh am = icosphere(2);
  Mesh m = am.mesh;
  m.vertex_normals.assign(3 * m.num_vertices(), 0.0);
  const NormalsFix first = fix_normals(m);
  CHECK(first.zero == m.num_vertices());
  const std::vector<double> fixed = m.vertex_normals;
  CHECK(fix_normals(m).total() == 0);
  CHECK(std::memcmp(fixed.data(), m.vertex_normals.data(), fixed.size() * sizeof(double)) == 0);
}
