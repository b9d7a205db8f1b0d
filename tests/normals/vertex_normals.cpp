// Tests of normals/vertex_normals: every weighting against analytic normals and hand values.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "normals/vertex_normals.h"
#include "normals_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

const Weighting kAll[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};

// Corner of the unit cube cut off: v0 = origin, v1 = x, v2 = y, v3 = z; faces outward.
Mesh corner_tetrahedron() {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({0, 1, 0}); m.add_vertex({0, 0, 1});
  m.add_face({0, 2, 1});  // normal -z, area 1/2
  m.add_face({0, 1, 3});  // normal -y, area 1/2
  m.add_face({0, 3, 2});  // normal -x, area 1/2
  m.add_face({1, 2, 3});  // normal (1,1,1)/sqrt3, area sqrt3/2
  m.precision = ValuePrecision::Double;
  return m;
}

Vec3d unit(Vec3d v) { return normalized_or(v, Vec3d{}); }

}  // namespace

TEST_CASE("vertex_normals: libigl-style definitions at v1 of the corner tetrahedron, by hand", "[vertex_normals]") {
  // At v1 = (1,0,0) three faces meet: (0,2,1) with n = -z, angle 45 deg, 2A = 1, edges to the
  // neighbours of length^2 1 and 2; (0,1,3) with n = -y, likewise; (1,2,3) with
  // n = (1,1,1)/sqrt3, angle 60 deg, 2A = sqrt3, edges of length^2 2 and 2.
  const Mesh m = corner_tetrahedron();
  const double pi = kPi, s3 = std::sqrt(3.0);
  // uniform: -z - y + (1,1,1)/sqrt3
  const Vec3d uniform = unit({1 / s3, 1 / s3 - 1, 1 / s3 - 1});
  // area (sum of 2A n): (0,0,-1) + (0,-1,0) + (1,1,1) = (1,0,0)
  const Vec3d area{1, 0, 0};
  // angle: pi/4 (-z) + pi/4 (-y) + pi/3 (1,1,1)/sqrt3
  const Vec3d angle = unit({pi / (3 * s3), pi / (3 * s3) - pi / 4, pi / (3 * s3) - pi / 4});
  // max: 2A n / (|a|^2 |b|^2): (0,0,-1)/2 + (0,-1,0)/2 + (1,1,1)/4 = (1,-1,-1)/4; the four
  // vertices lie on the cube's circumsphere (centre (1,1,1)/2), where Max is exact:
  // v1 - centre = (1,-1,-1)/2.
  const Vec3d max = unit({1, -1, -1});
  const std::pair<Weighting, Vec3d> expected[] = {
      {Weighting::Uniform, uniform}, {Weighting::Area, area}, {Weighting::Angle, angle}, {Weighting::Max, max}};
  for (auto [w, e] : expected) {
    const auto r = vertex_normals(m, w);
    CHECK(r.fallback_vertices == 0);
    CHECK(angle_degrees(get3(r.normals, 1), e) < 1e-12);
  }
  // At v0 every weighting gives -(1,1,1)/sqrt3 (three equal right angles and areas).
  for (Weighting w : kAll) CHECK(angle_degrees(get3(vertex_normals(m, w).normals, 0), unit({-1, -1, -1})) < 1e-12);
}

TEST_CASE("vertex_normals: Max weighting is exact on every sphere tessellation (< 1e-6 deg)", "[vertex_normals]") {
  const AnalyticMesh meshes[] = {uv_sphere(24, 12), uv_sphere(64, 31, 0.35, 3), irregular(uv_sphere(80, 40, 0.4, 5)),
                                 icosphere(4), irregular(icosphere(4, 0.3, 9))};
  for (const auto& am : meshes) {
    const auto r = vertex_normals(am.mesh, Weighting::Max);
    const auto e = angular_error(r.normals, am.exact_normals);
    CHECK(e.non_finite == 0);
    CHECK(e.max_deg < 1e-6);
  }
}

TEST_CASE("vertex_normals: equals OpenMesh update_normals (uniform: sum of unit face normals) to 1e-6", "[vertex_normals]") {
  using OM = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraits>;
  const AnalyticMesh meshes[] = {irregular(uv_sphere(40, 20, 0.3, 2)), irregular(torus(40, 16, 1, 0.4, 0.3, 4)),
                                 irregular(icosphere(3, 0.3, 6))};
  for (const auto& am : meshes) {
    OM om;
    std::vector<OM::VertexHandle> vh;
    for (std::size_t v = 0; v < am.mesh.num_vertices(); ++v) {
      const Vec3d p = am.mesh.position(v);
      vh.push_back(om.add_vertex(OM::Point(float(p.x), float(p.y), float(p.z))));
    }
    for (std::size_t f = 0; f < am.mesh.num_faces(); ++f)
      REQUIRE(om.add_face(vh[am.mesh.corner_vertex[3 * f]], vh[am.mesh.corner_vertex[3 * f + 1]],
                          vh[am.mesh.corner_vertex[3 * f + 2]]).is_valid());
    om.request_face_normals();
    om.request_vertex_normals();
    om.update_normals();
    // OpenMesh holds float points: compare on the same float positions.
    Mesh same = am.mesh;
    for (auto& x : same.positions) x = double(float(x));
    const auto r = vertex_normals(same, Weighting::Uniform);
    double worst = 0;
    for (std::size_t v = 0; v < same.num_vertices(); ++v) {
      const auto n = om.normal(vh[v]);
      const Vec3d d = get3(r.normals, v) - Vec3d{n[0], n[1], n[2]};
      worst = std::max({worst, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    }
    CHECK(worst < 1e-6);
  }
}

TEST_CASE("vertex_normals: degenerate faces contribute nothing; isolated vertices get (0,0,1)", "[vertex_normals]") {
  Mesh m = corner_tetrahedron();
  const auto clean = vertex_normals(m, Weighting::Angle);
  m.add_face({1, 1, 2});                 // repeated index
  m.add_vertex({0.5, 0.5, 0});           // v4 on edge (1,2)... collinear with v1, v2
  m.add_face({1, 4, 2});                 // zero area
  m.add_vertex({7, 8, 9});               // v5 isolated
  m.add_vertex({std::numeric_limits<double>::quiet_NaN(), 0, 0});  // v6 NaN
  m.add_face({6, 1, 2});                 // face with a NaN position
  for (Weighting w : kAll) {
    for (Precision p : {Precision::Double, Precision::Float}) {
      const auto r = vertex_normals(m, w, p);
      for (double x : r.normals) CHECK(std::isfinite(x));
      CHECK(r.fallback_vertices == 3);  // v4, v5, v6
      for (std::size_t v : {4, 5, 6}) CHECK(get3(r.normals, v) == Vec3d(0, 0, 1));
      if (w == Weighting::Angle && p == Precision::Double)
        for (std::size_t v = 0; v < 4; ++v) CHECK(get3(r.normals, v) == get3(clean.normals, v));
    }
  }
}

TEST_CASE("vertex_normals: cancelled sums (two-sided sheet) fall back to the first valid face", "[vertex_normals]") {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});  // +z
  m.add_face({0, 2, 1});  // -z
  for (Weighting w : kAll) {
    const auto r = vertex_normals(m, w);
    CHECK(r.fallback_vertices == 3);
    for (std::size_t v = 0; v < 3; ++v) CHECK(get3(r.normals, v) == Vec3d(0, 0, 1));
  }
}

TEST_CASE("vertex_normals: float precision within 1e-3 deg of double", "[vertex_normals]") {
  const AnalyticMesh meshes[] = {irregular(uv_sphere(100, 50, 0.3, 2)), irregular(torus(80, 30, 1, 0.4, 0.3, 4)),
                                 irregular(icosphere(4, 0.3, 6)), uv_ellipsoid(60, 30, 3, 2, 1)};
  for (const auto& am : meshes)
    for (Weighting w : kAll) {
      const auto d = vertex_normals(am.mesh, w, Precision::Double);
      const auto f = vertex_normals(am.mesh, w, Precision::Float);
      double worst = 0;
      for (std::size_t v = 0; v < am.mesh.num_vertices(); ++v)
        worst = std::max(worst, angle_degrees(get3(d.normals, v), get3(f.normals, v)));
      CHECK(worst < 1e-3);
    }
}
