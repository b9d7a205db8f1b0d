// Tests of normals/vertex_normals: every weighting against analytic normals and hand values.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

// OpenMesh's PropertyT<T>::push_back (push_back(T()) of a default VectorT) trips GCC 12's
// -Wmaybe-uninitialized when inlined here; the warning is in OpenMesh's code, not ours.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <tbb/task_arena.h>

#include <shadetool/core/error.h>
#include <shadetool/normals/vertex_normals.h>
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

namespace {

// Mean error at refinement levels that halve the edge length each time; the observed order of
// accuracy between consecutive levels is log2(e_k / e_{k+1}).
struct Convergence {
  std::vector<double> mean;
  double order(std::size_t k) const { return std::log2(mean[k] / mean[k + 1]); }
};

template <class Make>
Convergence refine(Weighting w, int levels, Make make) {
  Convergence c;
  for (int l = 0; l < levels; ++l) {
    const AnalyticMesh am = make(l);
    REQUIRE(folded_faces(am) == 0);
    const auto e = angular_error(vertex_normals(am.mesh, w).normals, am.exact_normals);
    REQUIRE(e.non_finite == 0);
    c.mean.push_back(e.mean_deg);
  }
  return c;
}

}  // namespace

TEST_CASE("vertex_normals: second-order convergence on regular tessellations of smooth surfaces", "[vertex_normals][convergence]") {
  // Measured orders (mean error, 4 levels, n = 16, 32, 64, 128; see the README table):
  //   torus 2n x n:            uniform 2.00, area 2.00, angle 2.00, max exact (1e-13)
  //   ellipsoid (3,2,1) 2n x n: uniform 2.01, area 1.82, angle 2.01, max 2.01
  //   UV sphere 2n x n:        uniform 1.99, area 1.78, angle 1.99, max exact
  // Bound asserted: order >= 1.7 between the two finest levels (area: >= 1.6), errors falling.
  struct Surface { const char* name; std::function<AnalyticMesh(int)> make; };
  const Surface surfaces[] = {
      {"torus", [](int l) { const int n = 16 << l; return torus(2 * n, n, 1, 0.4); }},
      {"ellipsoid", [](int l) { const int n = 16 << l; return uv_ellipsoid(2 * n, n, 3, 2, 1); }},
  };
  for (const auto& s : surfaces)
    for (Weighting w : kAll) {
      const Convergence c = refine(w, 4, s.make);
      INFO(s.name << " weighting " << int(w) << " mean errors " << c.mean[0] << " " << c.mean[1] << " " << c.mean[2] << " " << c.mean[3]);
      if (w == Weighting::Max && std::string(s.name) == "torus") {
        // Measured: Max reproduces this torus grid's normals to rounding (<= 1e-13 deg), although
        // its 1-rings are not cospherical (Max's sufficient condition); asserted as found.
        for (double m : c.mean) CHECK(m < 1e-10);
        continue;
      }
      for (int k = 0; k < 3; ++k) CHECK(c.mean[k + 1] < c.mean[k]);
      CHECK(c.order(2) >= (w == Weighting::Area ? 1.6 : 1.7));
      CHECK(c.order(2) <= 2.3);
    }
  // Finest-level bounds (degrees), about 1.2x the measured values.
  CHECK(refine(Weighting::Angle, 1, [](int) { return torus(256, 128, 1, 0.4); }).mean[0] < 0.0085);
  CHECK(refine(Weighting::Angle, 1, [](int) { return uv_ellipsoid(256, 128, 3, 2, 1); }).mean[0] < 0.0112);
}

TEST_CASE("vertex_normals: first-order convergence on irregular meshes (jitter + edge flips)", "[vertex_normals][convergence]") {
  // Irregular 1-rings break the symmetry that cancels the O(h) term: every weighting is first
  // order (measured 0.86..1.02 on the torus and icosphere). Max stays exact on the sphere.
  const auto torus_l = [](int l) { const int n = 16 << l; return irregular(torus(2 * n, n, 1, 0.4, 0.15, 3), 5); };
  const auto ico_l = [](int l) { return irregular(icosphere(l + 3, 0.3, 3), 5); };
  for (Weighting w : kAll) {
    const Convergence t = refine(w, 4, torus_l);
    INFO("weighting " << int(w) << " torus " << t.mean[0] << " " << t.mean[1] << " " << t.mean[2] << " " << t.mean[3]);
    for (int k = 0; k < 3; ++k) CHECK(t.mean[k + 1] < t.mean[k]);
    CHECK(t.order(2) >= 0.8);
    CHECK(t.mean[3] < 0.75);  // degrees (measured 0.40..0.59)
    if (w == Weighting::Max) {
      CHECK(refine(w, 3, ico_l).mean[2] < 1e-10);
      continue;
    }
    const Convergence i = refine(w, 3, ico_l);
    INFO("icosphere " << i.mean[0] << " " << i.mean[1] << " " << i.mean[2]);
    for (int k = 0; k < 2; ++k) CHECK(i.mean[k + 1] < i.mean[k]);
    CHECK(i.order(1) >= 0.8);
  }
}

TEST_CASE("vertex_normals: a planar-quad mesh equals its fan triangulation under angle weighting", "[vertex_normals][polygons]") {
  // The angle of a planar convex polygon at a vertex is the sum of its fan triangles' angles
  // there, and all have the same unit normal, so angle-weighted sums agree (the other weightings
  // count a polygon differently from its triangles and are not expected to agree).
  AnalyticMesh quads, fan;
  quad_uv_sphere(48, 24, quads, fan);
  REQUIRE(folded_faces(quads) == 0);
  REQUIRE(folded_faces(fan) == 0);
  for (Precision p : {Precision::Double, Precision::Float}) {
    const auto q = vertex_normals(quads.mesh, Weighting::Angle, p);
    const auto t = vertex_normals(fan.mesh, Weighting::Angle, p);
    double worst = 0;
    for (std::size_t v = 0; v < quads.mesh.num_vertices(); ++v)
      worst = std::max(worst, angle_degrees(get3(q.normals, v), get3(t.normals, v)));
    CHECK(worst < (p == Precision::Double ? 1e-10 : 1e-4));
  }
}

TEST_CASE("vertex_normals: a concave polygon counts its reflex corner as reflex", "[vertex_normals][polygons]") {
  // L-shaped prism: bottom and top are the concave hexagon (0,0),(2,0),(2,1),(1,1),(1,2),(0,2)
  // with its reflex corner at (1,1); height 1. Triangulated version: each hexagon as a fan from
  // the reflex corner (valid for an L), each side rectangle as two triangles. Angle weighting must
  // agree: the reflex corner weighs 3 pi / 2 in the polygon and pi/2 + pi/2 + pi/4 + pi/4 in the fan.
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Mesh poly, tri;
  for (Mesh* m : {&poly, &tri}) {
    for (int z = 0; z < 2; ++z)
      for (auto& p : xy) m->add_vertex({p[0], p[1], double(z)});
    m->precision = ValuePrecision::Double;
  }
  poly.add_face({5, 4, 3, 2, 1, 0});     // bottom, facing -z
  poly.add_face({6, 7, 8, 9, 10, 11});   // top, facing +z
  // bottom fan from vertex 3 (reflex), reversed orientation: (3,2,1), (3,1,0), (3,0,5), (3,5,4)
  tri.add_face({3, 2, 1}); tri.add_face({3, 1, 0}); tri.add_face({3, 0, 5}); tri.add_face({3, 5, 4});
  // top fan from vertex 9: (9,10,11), (9,11,6), (9,6,7), (9,7,8)
  tri.add_face({9, 10, 11}); tri.add_face({9, 11, 6}); tri.add_face({9, 6, 7}); tri.add_face({9, 7, 8});
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    poly.add_face({i, j, j + 6, i + 6});
    tri.add_face({i, j, j + 6});
    tri.add_face({i, j + 6, i + 6});
  }
  const auto p = vertex_normals(poly, Weighting::Angle);
  const auto t = vertex_normals(tri, Weighting::Angle);
  for (std::size_t v = 0; v < 12; ++v) CHECK(angle_degrees(get3(p.normals, v), get3(t.normals, v)) < 1e-12);
  // Reflex corner (1,1,0): bottom contributes 3pi/2 (0,0,-1), the two side walls x=1 (normal +x)
  // and y=1 (normal +y) pi/2 each: (pi/2, pi/2, -3pi/2) -> (1, 1, -3)/sqrt(11).
  CHECK(angle_degrees(get3(p.normals, 3), normalized_or(Vec3d{1, 1, -3}, Vec3d{})) < 1e-12);
}

TEST_CASE("vertex_normals: the result is bitwise the same on 1 and 2 threads", "[vertex_normals][parallel]") {
  AnalyticMesh quads, fan;
  quad_uv_sphere(300, 150, quads, fan);
  const Mesh meshes[] = {irregular(uv_sphere(300, 150, 0.15, 2)).mesh, quads.mesh,
                         shuffle_faces(irregular(icosphere(6, 0.3, 2)).mesh, 4)};
  for (const Mesh& m : meshes) {
    REQUIRE(m.num_faces() > 40000);  // above the serial threshold
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float}) {
        VertexNormals one, two;
        tbb::task_arena(1).execute([&] { one = vertex_normals(m, w, p); });
        tbb::task_arena(2).execute([&] { two = vertex_normals(m, w, p); });
        CHECK(one.normals == two.normals);
        CHECK(one.fallback_vertices == two.fallback_vertices);
      }
  }
}

TEST_CASE("vertex_normals: with a reused plan and output, bitwise the plain 1-thread result on 1, 2 and 3 threads",
          "[vertex_normals][parallel]") {
  // The plan only decides how the sum is split (its chunk count follows the concurrency of the
  // arena that builds it: one chunk per thread); the sums add every vertex's terms in corner order either
  // way (accumulate_by_vertex.h), so every combination of plan and arena must give the same bits.
  const Mesh meshes[] = {irregular(uv_sphere(300, 150, 0.15, 2)).mesh, shuffle_faces(irregular(icosphere(6, 0.3, 2)).mesh, 4)};
  for (const Mesh& m : meshes) {
    REQUIRE(m.num_faces() > 40000);  // above the serial threshold
    std::vector<VertexNormalsPlan> plans;
    for (int threads : {1, 2, 3}) tbb::task_arena(threads).execute([&] { plans.emplace_back(m); });
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float}) {
        VertexNormals reference;
        tbb::task_arena(1).execute([&] { reference = vertex_normals(m, w, p); });
        VertexNormals out;
        out.normals.assign(17, 5.0);  // a reused result: stale contents and the wrong size
        out.fallback_vertices = 99;
        for (const VertexNormalsPlan& plan : plans)
          for (int threads : {1, 2, 3}) {
            tbb::task_arena(threads).execute([&] { vertex_normals(m, plan, w, p, out); });
            CHECK(out.normals == reference.normals);
            CHECK(out.fallback_vertices == reference.fallback_vertices);
            CHECK(out.degenerate_faces == reference.degenerate_faces);
          }
        VertexNormals plain_reused = out;  // the overload without a plan, into a used result
        vertex_normals(m, w, p, plain_reused);
        CHECK(plain_reused.normals == reference.normals);
      }
  }
}

TEST_CASE("vertex_normals: a plan built for other counts is refused", "[vertex_normals]") {
  const AnalyticMesh a = uv_sphere(20, 10), b = uv_sphere(22, 10);
  const VertexNormalsPlan plan(a.mesh);
  CHECK(plan.fits(a.mesh));
  CHECK_FALSE(plan.fits(b.mesh));
  CHECK_FALSE(VertexNormalsPlan().fits(a.mesh));
  VertexNormals out;
  CHECK_THROWS_AS(vertex_normals(b.mesh, plan, Weighting::Area, Precision::Double, out), Error);
  vertex_normals(a.mesh, plan, Weighting::Area, Precision::Double, out);
  // Small mesh: the serial loop, the same as the plain call (3.2 deg max error against the exact
  // normals on this coarse 20 x 10 sphere, measured; the bound only guards against garbage).
  CHECK(out.normals == vertex_normals(a.mesh, Weighting::Area, Precision::Double).normals);
  CHECK(angular_error(out.normals, a.exact_normals).max_deg < 4);
}
