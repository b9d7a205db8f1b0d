// Tests of normals/corner_normals: crease grouping against exact cube normals, vertex normals,
// OpenMesh's update_halfedge_normals, and the rules for boundary, non-manifold, inconsistent and
// degenerate edges.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

// OpenMesh's PropertyT<T>::push_back trips GCC 12's -Wmaybe-uninitialized when inlined here.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <tbb/task_arena.h>

#include <shadetool/geometry/interior_angle.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include "normals_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

const Weighting kAll[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
constexpr double kDeg = kPi / 180;

Vec3d corner_normal(const CornerNormals& cn, std::size_t c) { return get3(cn.normals, cn.corner_index[c]); }

std::size_t distinct_at_vertex(const Mesh& m, const CornerNormals& cn, std::uint32_t v) {
  std::set<std::uint32_t> s;
  for (std::size_t c = 0; c < m.num_corners(); ++c)
    if (m.corner_vertex[c] == v) s.insert(cn.corner_index[c]);
  return s.size();
}

}  // namespace

TEST_CASE("corner_normals: cube with crease 30 gives every corner its face axis exactly", "[corner_normals]") {
  for (bool quads : {true, false}) {
    const Mesh m = cube(quads);
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float}) {
        const CornerNormals cn = corner_normals(m, 30 * kDeg, w, p);
        REQUIRE(cn.corner_index.size() == m.num_corners());
        CHECK(cn.normals.size() == 3 * 24);  // 8 vertices x 3 faces
        CHECK(cn.fallback_corners == 0);
        for (std::size_t f = 0; f < m.num_faces(); ++f)
          for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c)
            CHECK(corner_normal(cn, c) == cube_face_axis(quads ? f : f / 2));  // bitwise
      }
  }
}

TEST_CASE("corner_normals: cube with crease 180 gives the normalised diagonals", "[corner_normals]") {
  const double s = 1 / std::sqrt(3.0);
  auto check = [&](const Mesh& m, Weighting w) {
    const CornerNormals cn = corner_normals(m, 180 * kDeg, w);
    CHECK(cn.normals.size() == 3 * 8);
    for (std::size_t c = 0; c < m.num_corners(); ++c) {
      const std::uint32_t v = m.corner_vertex[c];
      const Vec3d diag{(v & 1) ? s : -s, (v & 2) ? s : -s, (v & 4) ? s : -s};
      const Vec3d n = corner_normal(cn, c);
      CHECK(std::fabs(n.x - diag.x) < 1e-15);
      CHECK(std::fabs(n.y - diag.y) < 1e-15);
      CHECK(std::fabs(n.z - diag.z) < 1e-15);
    }
  };
  for (Weighting w : kAll) check(cube(true), w);
  // The triangulated cube is symmetric only for the weightings that see each face's total
  // corner (angle: pi/2 = pi/4 + pi/4; max: sin/(|a||b|) = 1 = 1/2 + 1/2), not for uniform/area.
  check(cube(false), Weighting::Angle);
  check(cube(false), Weighting::Max);
}

namespace {

// Largest angle between the normals of two faces sharing an edge (consistently oriented meshes).
double max_dihedral(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> first;
  double worst = 0;
  auto fn = [&](std::size_t f) {
    const Vec3d a = m.position(m.corner_vertex[3 * f]), b = m.position(m.corner_vertex[3 * f + 1]),
                c = m.position(m.corner_vertex[3 * f + 2]);
    return normalized_or(cross(b - a, c - a), Vec3d{});
  };
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.corner_vertex[3 * f + k], b = m.corner_vertex[3 * f + (k + 1) % 3];
      auto it = first.find({b, a});
      if (it != first.end()) worst = std::max(worst, angle_degrees(fn(f), fn(it->second)));
      else first[{a, b}] = f;
    }
  return worst;
}

}  // namespace

TEST_CASE("corner_normals: with no crease in the way they equal vertex_normals bitwise", "[corner_normals]") {
  // The irregular meshes have steep slivers (dihedral angles up to 60-96 degrees after random
  // flips), so crease 30 is "no crease in the way" only on the regular ones (11 and 14 degrees);
  // crease 180 on all.
  const AnalyticMesh meshes[] = {irregular(uv_sphere(64, 32, 0.15, 3)), irregular(torus(64, 32, 1, 0.4, 0.15, 2)),
                                 irregular(icosphere(4, 0.3, 2)), torus(64, 32, 1, 0.4), icosphere(4)};
  std::size_t compared_at_30 = 0;
  for (const auto& am : meshes)
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float}) {
        const VertexNormals vn = vertex_normals(am.mesh, w, p);
        for (double crease : {30 * kDeg, kPi}) {
          if (crease < kPi && max_dihedral(am.mesh) >= 30) continue;
          compared_at_30 += crease < kPi;
          INFO("crease " << crease);
          const CornerNormals cn = corner_normals(am.mesh, crease, w, p);
          CHECK(cn.normals.size() == 3 * am.mesh.num_vertices());
          std::size_t differ = 0;
          for (std::size_t c = 0; c < am.mesh.num_corners(); ++c)
            differ += corner_normal(cn, c) != get3(vn.normals, am.mesh.corner_vertex[c]);
          CHECK(differ == 0);
        }
      }
  CHECK(compared_at_30 == 2 * 4 * 2);  // regular torus and icosphere, every weighting and precision
}

TEST_CASE("corner_normals: equal OpenMesh update_halfedge_normals (its uniform weighting) to 1e-6", "[corner_normals]") {
  // A coarse torus has dihedral angles from about 10 to 60 degrees: creases at 20, 35 and 50
  // split some fans and not others. OpenMesh's halfedge normal of h is the normal at corner
  // (face(h), to_vertex(h)); it sums unit face normals inside the fan, stopping at feature
  // edges (dot(n0, n1) < cos(angle)).
  struct DoubleTraits : OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
    HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
  };
  using OM = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
  const AnalyticMesh am = irregular(torus(14, 9, 1, 0.45, 0.15, 3), 4);
  const Mesh& m = am.mesh;
  OM om;
  std::vector<OM::VertexHandle> vh;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d p = m.position(v);
    vh.push_back(om.add_vertex(OM::Point(p.x, p.y, p.z)));
  }
  std::vector<OM::FaceHandle> fh;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    fh.push_back(om.add_face(vh[m.corner_vertex[3 * f]], vh[m.corner_vertex[3 * f + 1]], vh[m.corner_vertex[3 * f + 2]]));
  for (auto& h : fh) REQUIRE(h.is_valid());
  om.request_face_normals();
  om.request_halfedge_normals();
  om.update_face_normals();
  for (double deg : {20.0, 35.0, 50.0}) {
    om.update_halfedge_normals(deg * kDeg);
    const CornerNormals cn = corner_normals(m, deg * kDeg, Weighting::Uniform);
    std::size_t split = 0;
    double worst = 0;
    for (std::size_t f = 0; f < m.num_faces(); ++f)
      for (auto h : om.fh_range(fh[f])) {
        const auto v = std::uint32_t(om.to_vertex_handle(h).idx());
        int k = 0;
        while (m.corner_vertex[3 * f + k] != v) ++k;
        const auto n = om.normal(h);
        const Vec3d d = corner_normal(cn, 3 * f + k) - Vec3d{n[0], n[1], n[2]};
        worst = std::max({worst, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
      }
    for (std::uint32_t v = 0; v < m.num_vertices(); ++v) split += distinct_at_vertex(m, cn, v) > 1;
    INFO("crease " << deg << " split vertices " << split);
    CHECK(split > 0);  // the creases matter at these angles
    CHECK(worst < 1e-6);
  }
}

TEST_CASE("corner_normals: boundary edges do not split a fan; non-manifold edges do", "[corner_normals]") {
  // Open fan of 4 nearly flat triangles around vertex 0 (a boundary vertex): one group.
  Mesh fan;
  fan.add_vertex({0, 0, 0});
  for (int i = 0; i < 5; ++i) fan.add_vertex({std::cos(i * 0.5), std::sin(i * 0.5), 0.05 * i});
  for (std::uint32_t i = 1; i < 5; ++i) fan.add_face({0, i, i + 1});
  const CornerNormals a = corner_normals(fan, 30 * kDeg);
  CHECK(distinct_at_vertex(fan, a, 0) == 1);
  // Three coplanar-ish triangles sharing edge (0,1) (a fin): the edge is non-manifold, so even
  // at crease 180 the three faces keep separate normals at vertices 0 and 1.
  Mesh fin;
  fin.add_vertex({0, 0, 0}); fin.add_vertex({1, 0, 0});
  fin.add_vertex({0.5, 1, 0}); fin.add_vertex({0.5, -1, 0.01}); fin.add_vertex({0.5, -1, -0.01});
  fin.add_face({0, 1, 2}); fin.add_face({1, 0, 3}); fin.add_face({1, 0, 4});
  const CornerNormals b = corner_normals(fin, kPi);
  CHECK(distinct_at_vertex(fin, b, 0) == 3);
  CHECK(distinct_at_vertex(fin, b, 1) == 3);
  for (std::size_t f = 0; f < 3; ++f) {
    const Vec3d fn = normalized_or(cross(fin.position(fin.corner_vertex[3 * f + 1]) - fin.position(fin.corner_vertex[3 * f]),
                                         fin.position(fin.corner_vertex[3 * f + 2]) - fin.position(fin.corner_vertex[3 * f])),
                                   Vec3d{});
    CHECK(angle_degrees(corner_normal(b, 3 * f), fn) < 1e-12);
  }
}

TEST_CASE("corner_normals: an edge whose faces disagree in orientation is a crease", "[corner_normals]") {
  // Two flat triangles sharing edge (0,1), the second wound the same way along it (inconsistent):
  // their normals are opposite; even crease 180 must not average them to zero.
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({0.5, 1, 0}); m.add_vertex({0.5, -1, 0});
  m.add_face({0, 1, 2});  // +z
  m.add_face({0, 1, 3});  // -z, edge 0->1 in both
  const CornerNormals cn = corner_normals(m, kPi);
  CHECK(cn.fallback_corners == 0);
  CHECK(corner_normal(cn, 0) == Vec3d(0, 0, 1));
  CHECK(corner_normal(cn, 3) == Vec3d(0, 0, -1));
}

TEST_CASE("corner_normals: degenerate faces take the smooth vertex normal; isolated vertices none; never NaN", "[corner_normals]") {
  Mesh m = cube(true);
  m.add_face({0, 0, 1});      // repeated index at cube vertex 0 and 1
  m.add_vertex({5, 5, 5});    // v8
  m.add_vertex({6, 5, 5});    // v9
  m.add_face({8, 9, 8});      // only degenerate faces at v8, v9
  m.add_vertex({9, 9, 9});    // v10 isolated
  for (Weighting w : kAll) {
    const CornerNormals cn = corner_normals(m, 30 * kDeg, w);
    for (double x : cn.normals) CHECK(std::isfinite(x));
    // Cube vertex 0 has three groups (one per face): the degenerate corners get the smooth
    // vertex normal -(1,1,1)/sqrt3 (all weightings agree on the quad cube).
    const double s = 1 / std::sqrt(3.0);
    const std::size_t deg0 = m.face_start[6];
    CHECK(angle_degrees(corner_normal(cn, deg0), Vec3d{-s, -s, -s}) < 1e-12);
    // v8, v9: no valid face at all: (0, 0, 1), counted (3 corners).
    CHECK(corner_normal(cn, m.face_start[7]) == Vec3d(0, 0, 1));
    CHECK(cn.fallback_corners == 3);
    CHECK(cn.degenerate_faces == 2);
  }
}

TEST_CASE("corner_normals: bitwise the same on 1 and 2 threads", "[corner_normals][parallel]") {
  const Mesh m = irregular(uv_sphere(200, 100, 0.15, 2)).mesh;
  REQUIRE(m.num_faces() > 32768);
  CornerNormals one, two;
  tbb::task_arena(1).execute([&] { one = corner_normals(m, 5 * kDeg, Weighting::Angle); });
  tbb::task_arena(2).execute([&] { two = corner_normals(m, 5 * kDeg, Weighting::Angle); });
  CHECK(one.normals == two.normals);
  CHECK(one.corner_index == two.corner_index);
}

TEST_CASE("corner_group_normals: given corner_normals' own groups it returns its normals bitwise; "
          "corners in no group add nothing; bad groups throw", "[corner_normals][groups]") {
  const AnalyticMesh meshes[] = {irregular(torus(64, 32, 1, 0.4, 0.15, 2)), icosphere(3)};
  for (const auto& am : meshes)
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float}) {
        const CornerNormals cn = corner_normals(am.mesh, 30 * kDeg, w, p);
        const std::size_t G = cn.normals.size() / 3;
        const GroupNormals g = corner_group_normals(am.mesh, cn.corner_index, G, w, p);
        CHECK(g.failed.empty());
        CHECK(g.normals == cn.normals);
      }
  // One group holding the corners of face 0 only, the rest in no group: the face's unit normal
  // (every weighting multiplies it by a positive weight).
  const Mesh& m = meshes[1].mesh;
  std::vector<std::uint32_t> group(m.num_corners(), kNoGroup);
  for (std::uint32_t c = m.face_start[0]; c < m.face_start[1]; ++c) group[c] = 0;
  const Vec3d p0 = m.position(m.corner_vertex[0]), p1 = m.position(m.corner_vertex[1]), p2 = m.position(m.corner_vertex[2]);
  const Vec3d N = cross(p1 - p0, p2 - p0), n = N * (1.0 / std::sqrt(dot(N, N)));
  for (Weighting w : kAll) {
    const GroupNormals g = corner_group_normals(m, group, 1, w);
    REQUIRE(g.normals.size() == 3);
    CHECK(dot(get3(g.normals, 0), n) == Approx(1.0).epsilon(1e-14));
  }
  // A group with no corner cannot be normalised: reported, (0, 0, 0).
  const GroupNormals two = corner_group_normals(m, group, 2);
  CHECK(two.failed == std::vector<std::uint32_t>{1});
  CHECK(get3(two.normals, 1) == Vec3d{0, 0, 0});
  group[5] = 7;
  CHECK_THROWS(corner_group_normals(m, group, 2));
  CHECK_THROWS(corner_group_normals(m, std::vector<std::uint32_t>(3, 0), 1));
}

namespace {

// A regular pyramid fan: apex 0 at height h over `sides` base points on the unit circle, closed
// underneath by apex sides + 1 at depth `below`; faces listed apex fan first.
Mesh regular_pyramid(int sides, double h, double below = -1.0, Vec3d shift = {0, 0, 0}) {
  Mesh m;
  m.add_vertex(Vec3d{0, 0, h} + shift);
  for (int i = 0; i < sides; ++i) m.add_vertex(Vec3d{std::cos(2 * kPi * i / sides), std::sin(2 * kPi * i / sides), 0} + shift);
  m.add_vertex(Vec3d{0, 0, below} + shift);
  for (int i = 0; i < sides; ++i) m.add_face({0, 1 + std::uint32_t(i), 1 + std::uint32_t((i + 1) % sides)});
  for (int i = 0; i < sides; ++i)
    m.add_face({std::uint32_t(sides + 1), 1 + std::uint32_t((i + 1) % sides), 1 + std::uint32_t(i)});
  m.precision = ValuePrecision::Double;
  return m;
}

}  // namespace

TEST_CASE("corner_normals: a cone apex whose faces lie within half the crease angle is one group along the axis",
          "[corner_normals]") {
  // Apex face normals 5 degrees from the axis: any two within 10 degrees, all within 15 of any
  // one, so crease 30 cannot split the apex (the smooth-cone shortcut); by symmetry its normal is
  // the axis. Fans of 3 to 17 corners cross the 8- and 16-corner ring paths. A threshold half a
  // degree either side of the angle between neighbouring faces (which alone decides, not the
  // larger angles across the fan) keeps the apex whole or splits it into every face.
  for (int sides : {3, 5, 8, 9, 12, 16, 17}) {
    const double h = std::tan(5 * kDeg) * std::cos(kPi / sides);  // face normals 5 degrees from the axis
    const Mesh m = regular_pyramid(sides, h);
    for (Weighting w : kAll) {
      INFO(sides << " sides, " << weighting_name(w));
      const CornerNormals cn = corner_normals(m, 30 * kDeg, w);
      CHECK(distinct_at_vertex(m, cn, 0) == 1);
      CHECK(angle_degrees(corner_normal(cn, 0), {0, 0, 1}) < 1e-12);
      const double neighbours = angle_degrees(normalized_or(cross(m.position(1) - m.position(0), m.position(2) - m.position(0)), Vec3d{}),
                                              normalized_or(cross(m.position(2) - m.position(0), m.position(3) - m.position(0)), Vec3d{}));
      CHECK(distinct_at_vertex(m, corner_normals(m, (neighbours + 0.5) * kDeg, w), 0) == 1);
      CHECK(distinct_at_vertex(m, corner_normals(m, (neighbours - 0.5) * kDeg, w), 0) == std::size_t(sides));
    }
  }
}

TEST_CASE("corner_normals: two closed fans that share only a vertex are two groups, each its own fan's vertex normal",
          "[corner_normals]") {
  // A pinch: pyramid A and pyramid B (upside down, above A) meet at one apex vertex. No crease
  // (crease 179 degrees, both fans flat enough for the smooth-cone shortcut), but no edge joins the
  // fans: two groups. Each must equal vertex_normals of its pyramid alone at the apex, bit for bit
  // (same corners, same order).
  const int sides = 6;
  const Mesh a = regular_pyramid(sides, 0.05);
  Mesh b = regular_pyramid(sides, -0.05, 1.0, {0, 0, 0.1});  // apex at z = 0.05, base above it
  for (std::uint32_t f = 0; f < b.num_faces(); ++f) std::swap(b.corner_vertex[3 * f + 1], b.corner_vertex[3 * f + 2]);
  Mesh both = a;
  const std::uint32_t shift = std::uint32_t(a.num_vertices()) - 1;  // b's apex becomes vertex 0
  for (std::size_t v = 1; v < b.num_vertices(); ++v) both.add_vertex(b.position(v));
  auto map = [&](std::uint32_t v) { return v == 0 ? 0u : v + shift; };
  for (std::size_t f = 0; f < b.num_faces(); ++f)
    both.add_face({map(b.corner_vertex[3 * f]), map(b.corner_vertex[3 * f + 1]), map(b.corner_vertex[3 * f + 2])});
  REQUIRE(b.position(0) == both.position(0));
  for (Weighting w : kAll) {
    INFO(weighting_name(w));
    const CornerNormals cn = corner_normals(both, 179 * kDeg, w);
    CHECK(distinct_at_vertex(both, cn, 0) == 2);
    const Vec3d na = get3(vertex_normals(a, w).normals, 0), nb = get3(vertex_normals(b, w).normals, 0);
    CHECK(corner_normal(cn, 0) == na);                     // A's apex corner: face 0
    CHECK(corner_normal(cn, 3 * a.num_faces()) == nb);     // B's first apex corner: its face 0
    CHECK(na.z > 0.99);
    CHECK(nb.z < -0.99);
  }
}

TEST_CASE("corner_normals: a vertex on a fold (two crease edges) splits into the two planes' normals; a threshold "
          "equal to the fold's angle keeps it whole", "[corner_normals]") {
  // A 4 x 2 grid of unit squares folded along x = 2 by phi: left half in z = 0, right half rising
  // at phi. Vertex (2, 1) lies on the fold: its fan has two crease edges (along the fold line).
  for (double phi_deg : {10.0, 41.8, 90.0, 135.0}) {
    const double phi = phi_deg * kDeg;
    Mesh m;
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 4; ++i) {
        const double x = i <= 2 ? double(i) : 2 + (i - 2) * std::cos(phi), z = i <= 2 ? 0.0 : (i - 2) * std::sin(phi);
        m.add_vertex({x, double(j), z});
      }
    auto id = [](int i, int j) { return std::uint32_t(j * 5 + i); };
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i) {
        m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    m.precision = ValuePrecision::Double;
    const std::uint32_t v = id(2, 1);
    const Vec3d left{0, 0, 1}, right{-std::sin(phi), 0, std::cos(phi)};
    INFO("fold " << phi_deg << " degrees");
    const CornerNormals split = corner_normals(m, phi - 1e-6, Weighting::Angle);
    CHECK(distinct_at_vertex(m, split, v) == 2);
    for (std::size_t c = 0; c < m.num_corners(); ++c) {
      if (m.corner_vertex[c] != v) continue;
      const bool on_left = m.position(m.corner_vertex[3 * (c / 3)]).z + m.position(m.corner_vertex[3 * (c / 3) + 1]).z +
                               m.position(m.corner_vertex[3 * (c / 3) + 2]).z == 0.0;  // in the plane z = 0
      CHECK(angle_degrees(corner_normal(split, c), on_left ? left : right) < 1e-12);
    }
    // The threshold equal to the fold's angle as the rule measures it (interior_angle of the two
    // unit face normals): smooth (<=), one group; the next double below: split.
    // The fold's two edges at v: faces 2 | 5 (row 0) and 10 | 13 (row 1); one smooth edge joins
    // the fan, so the smaller angle is the threshold that keeps it whole.
    const std::vector<double> fn = face_normals(m);
    auto edge_angle = [&](std::size_t fa, std::size_t fb) {
      const Vec3d na = get3(fn, fa), nb = get3(fn, fb), x = cross(na, nb);
      return interior_angle(std::sqrt(dot(x, x)), dot(na, nb));
    };
    const double fold = std::min(edge_angle(2, 5), edge_angle(10, 13));
    CHECK(std::fabs(fold - phi) < 1e-12);
    CHECK(distinct_at_vertex(m, corner_normals(m, fold, Weighting::Angle), v) == 1);
    CHECK(distinct_at_vertex(m, corner_normals(m, std::nextafter(fold, 0.0), Weighting::Angle), v) == 2);
  }
}
