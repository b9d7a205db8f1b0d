// Tests of normals/update_mesh_normals: the keep / compute policy of `shadetool normals`.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <shadetool/normals/update_mesh_normals.h>
#include <shadetool/normals/vertex_fallback.h>
#include "normals_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("update_mesh_normals: existing vertex normals are kept bitwise, nothing computed", "[update_mesh_normals]") {
  Mesh m = cube(true);
  for (std::size_t v = 0; v < 8; ++v) {  // deliberately odd but valid normals
    m.vertex_normals.push_back(0.1 + v); m.vertex_normals.push_back(-1e-300); m.vertex_normals.push_back(12345.678);
  }
  const std::vector<double> before = m.vertex_normals;
  for (NormalKind kind : {NormalKind::Vertex, NormalKind::Corner}) {
    NormalsRequest r;
    r.kind = kind;
    r.crease_angle = 0.5;
    const NormalsReport rep = update_mesh_normals(m, r);
    CHECK(rep.kept);
    CHECK(rep.kept_what == "vertex normals");
    CHECK(rep.invalid_existing == 0);
    CHECK(m.vertex_normals == before);
    CHECK_FALSE(m.has_corner_normals());
    CHECK_FALSE(m.has_face_normals());
  }
}

TEST_CASE("update_mesh_normals: invalid existing normals are counted and left alone", "[update_mesh_normals]") {
  Mesh m = cube(true);
  m.vertex_normals.assign(24, 1.0);
  m.vertex_normals[3] = std::numeric_limits<double>::quiet_NaN();
  m.vertex_normals[6] = m.vertex_normals[7] = m.vertex_normals[8] = 0.0;
  Mesh copy = m;
  const NormalsReport rep = update_mesh_normals(m, NormalsRequest{});
  CHECK(rep.kept);
  CHECK(rep.existing == 8);
  CHECK(rep.invalid_existing == 2);
  CHECK(m.vertex_normals.size() == copy.vertex_normals.size());
  CHECK(std::isnan(m.vertex_normals[3]));
  // With recompute they are replaced by the diagonals.
  NormalsRequest r;
  r.recompute = true;
  const NormalsReport rep2 = update_mesh_normals(m, r);
  CHECK_FALSE(rep2.kept);
  CHECK(rep2.discarded == 8);
  CHECK(rep2.computed == 8);
  const double s = 1 / std::sqrt(3.0);
  CHECK(std::fabs(m.vertex_normals[0] + s) < 1e-15);
}

TEST_CASE("update_mesh_normals: face normals (STL facets) do not stop vertex normals and pass through", "[update_mesh_normals]") {
  Mesh m = cube(false);
  m.face_normals.assign(36, 0.0);
  for (std::size_t f = 0; f < 12; ++f) m.face_normals[3 * f + 2] = 7.0;  // odd but valid, kept as is
  const std::vector<double> facets = m.face_normals;
  const NormalsReport rep = update_mesh_normals(m, NormalsRequest{});
  CHECK_FALSE(rep.kept);
  CHECK(m.has_vertex_normals());
  CHECK(m.face_normals == facets);
  // Asking for face normals keeps them instead.
  NormalsRequest faces;
  faces.kind = NormalKind::Face;
  CHECK(update_mesh_normals(m, faces).kept);
  CHECK(m.face_normals == facets);
}

TEST_CASE("update_mesh_normals: --faces computes unit face normals, drops shading normals, degenerate gets (0,0,1)", "[update_mesh_normals]") {
  Mesh m = cube(true);
  m.add_face({0, 1, 1});
  NormalsRequest r;
  r.kind = NormalKind::Face;
  r.recompute = false;
  m.vertex_normals.assign(24, 1.0);
  // Vertex normals present but kind Face: face normals are computed; the vertex normals are dropped.
  const NormalsReport rep = update_mesh_normals(m, r);
  CHECK_FALSE(rep.kept);
  CHECK(rep.dropped == 8);
  CHECK_FALSE(m.has_vertex_normals());
  REQUIRE(m.face_normals.size() == 3 * 7);
  for (std::size_t f = 0; f < 6; ++f) CHECK(get3(m.face_normals, f) == cube_face_axis(f));
  CHECK(get3(m.face_normals, 6) == Vec3d(kFallbackNormal[0], kFallbackNormal[1], kFallbackNormal[2]));
  CHECK(rep.degenerate_faces == 1);
  CHECK(rep.fallback == 1);
}

TEST_CASE("update_mesh_normals: corner normals with a crease replace vertex normals", "[update_mesh_normals]") {
  Mesh m = cube(true);
  NormalsRequest r;
  r.kind = NormalKind::Corner;
  r.crease_angle = 30 * kPi / 180;
  const NormalsReport rep = update_mesh_normals(m, r);
  CHECK(rep.computed == 24);
  CHECK(m.corner_normal_index.size() == 24);
  CHECK_FALSE(m.has_vertex_normals());
  // Existing corner normals (an OBJ with vn) are kept on the next run.
  const std::vector<double> pool = m.corner_normals;
  CHECK(update_mesh_normals(m, NormalsRequest{}).kept_what == "corner normals");
  CHECK(m.corner_normals == pool);
}

TEST_CASE("update_mesh_normals: corner normal indices outside the pool count as invalid", "[update_mesh_normals]") {
  Mesh m = cube(false);
  m.corner_normals = {0, 0, 1, 0, 1, 0};
  m.corner_normal_index.assign(m.num_corners(), 1);
  m.corner_normal_index[0] = 0xffffffffu;
  m.corner_normal_index[5] = 2;
  const NormalsReport rep = update_mesh_normals(m, NormalsRequest{});
  CHECK(rep.kept);
  CHECK(rep.invalid_existing == 2);
}
