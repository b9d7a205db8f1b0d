// Numerical stress tests of the normals kernels (lib/normals): slivers, needles and caps up to
// aspect ratio 1e8, triangles of area 1e-30, features far from the origin, whole meshes scaled to
// 1e-30 and 1e30. Each case states its expected outcome and where the bound comes from.
//
// Error model (double): the triangle's positions are exact (stress_util.h), its edges are exact
// differences, and the cross product of two edges has a rounding error of a few u |e1| |e2| per
// component (u = 2^-53), while its true length is 2A. The normal's angle error is therefore about
// c u |e1| |e2| / (2A) <= c u L^2 / (2A) = c u r with r the aspect ratio (longest edge / height).
// We allow c = 8: angle error <= 8 u r radians (1e-7 rad = 6e-6 degrees at r = 1e8).
// In float the same holds with u = 2^-24 while 8 u r < 1 rad; beyond that float cannot resolve the
// face at all, and the only promise is a unit normal or the degenerate zero, never NaN.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <shadetool/core/mesh.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include "stress/stress_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::stress;
using shadetool::testing::AnalyticMesh;

namespace {

struct PlaneTriangle {
  const char* what;
  double a[3], b[3];  // plane coordinates of the three corners (dyadic)
};

// One face per triangle, all in the plane, wound so that the normal is +plane_normal().
Mesh plane_triangles(const std::vector<PlaneTriangle>& tris, const Vec3d& offset = {0, 0, 0}) {
  Mesh m;
  m.precision = ValuePrecision::Double;
  for (const auto& t : tris) {
    const auto v0 = m.add_vertex(in_plane(t.a[0], t.b[0], offset));
    const auto v1 = m.add_vertex(in_plane(t.a[1], t.b[1], offset));
    const auto v2 = m.add_vertex(in_plane(t.a[2], t.b[2], offset));
    m.add_face({v0, v1, v2});
  }
  return m;
}

const double h27 = std::ldexp(1.0, -27);  // 7.45e-9: height of the aspect ~1e8 slivers
const double h13 = std::ldexp(1.0, -13);  // 1.22e-4: aspect ~1e4

// Slivers: caps (one angle near 180 degrees) and needles (one very short edge), from aspect 1e4 to
// 1.5e8, placed at different points of the plane.
const std::vector<PlaneTriangle> kSlivers = {
    {"cap, aspect ~1e4", {0, 1, 0.5}, {0, 0, h13}},
    {"cap, aspect ~1.5e8", {0, 1, 0.5}, {0, 0, h27}},
    {"cap, apex near an end, aspect ~1.5e8", {0, 1, 0.75}, {0, 0, h27}},
    {"needle, aspect ~1e4", {0, 1, 1}, {0, 0, h13}},
    {"needle, aspect ~1.5e8", {0, 1, 1}, {0, 0, h27}},
    {"needle far from the origin, aspect ~1.5e8", {3, 4, 4}, {-2, -2, -2 + h27}},
    {"cap along v, aspect ~1.5e8", {0, h27, 0}, {0, 0.5, 1}},
};

}  // namespace

TEST_CASE("stress: slivers, caps and needles up to aspect 1e8 keep their normal within 8 u r", "[stress][normals]") {
  const Mesh m = plane_triangles(kSlivers);
  const auto nd = face_normals(m, Precision::Double);
  const auto nf = face_normals(m, Precision::Float);
  const Vec3d truth = plane_normal();
  for (std::size_t f = 0; f < kSlivers.size(); ++f) {
    const auto& t = kSlivers[f];
    const double r = aspect_ratio(t.a[0], t.b[0], t.a[1], t.b[1], t.a[2], t.b[2]);
    INFO(t.what << ": aspect " << r);
    CHECK(r >= 1e3);
    // Double: within 8 u r of the exact normal, and unit.
    const Vec3d d = get3(nd, f);
    CHECK(angle_between(d, truth) <= 8 * kU * r);
    CHECK(std::fabs(length(d) - 1) <= 4 * kU);
    // Float: within 8 u_f r where that is a meaningful angle; else unit or zero, never NaN.
    const Vec3d s = get3(nf, f);
    CHECK(all_finite(std::vector<double>{s.x, s.y, s.z}));
    CHECK(unit_or_zero(s, 8 * kUf));
    if (8 * kUf * r < 0.1) CHECK(angle_between(s, truth) <= 8 * kUf * r);
  }
}

TEST_CASE("stress: triangles of area 1e-30 have exact normals in double and float", "[stress][normals]") {
  // Corners s*(0,0), s*(1,0), s*(0,1) in plane coordinates with s = 2^-49 (1.8e-15):
  // area = s^2 |u x v| / 2 = 2^-98 * 9 sqrt(5) / 32 = 1.98e-30. Well shaped (aspect ~1.3), so the
  // only risk is underflow: |u x v| s^2 ~ 4e-30 is fine in float, its square 1.6e-59 is not
  // (float's smallest normal is 1.2e-38), so the length must be taken without squaring directly.
  const double s = std::ldexp(1.0, -49);
  const std::vector<PlaneTriangle> tiny = {
      {"area 2e-30, well shaped", {0, s, 0}, {0, 0, s}},
      {"area 2e-30 at (1,1) in the plane", {1, 1 + s, 1}, {1, 1, 1 + s}},  // exact: 1 + 2^-49 fits in 53 bits
      {"area 1e-45 sliver, aspect ~1e8", {0, s, s / 2}, {0, 0, s * h27}},
  };
  const Mesh m = plane_triangles(tiny);
  const auto nd = face_normals(m, Precision::Double);
  const auto nf = face_normals(m, Precision::Float);
  for (std::size_t f = 0; f < tiny.size(); ++f) {
    const auto& t = tiny[f];
    const double r = aspect_ratio(t.a[0] / s, t.b[0] / s, t.a[1] / s, t.b[1] / s, t.a[2] / s, t.b[2] / s);
    INFO(t.what << ", aspect " << r);
    CHECK(angle_between(get3(nd, f), plane_normal()) <= 8 * kU * r);
    CHECK(std::fabs(length(get3(nd, f)) - 1) <= 4 * kU);
    CHECK(unit_or_zero(get3(nf, f), 8 * kUf));
    if (8 * kUf * r < 0.1) CHECK(angle_between(get3(nf, f), plane_normal()) <= 8 * kUf * r);
  }
}

TEST_CASE("stress: vertex normals in a flat fan of slivers and caps are the plane's normal", "[stress][normals]") {
  // A fan of 8 triangles around the centre vertex, all in the plane: every vertex normal, under
  // every weighting, is the plane normal. Two of the fan's triangles are caps of aspect ~1.5e8
  // (their apex sits 2^-27 off the line through the centre), so a weighting that let a sliver's
  // rounding dominate would show it. Expected: within 8 u * 1.5e8 = 1.7e-7 rad (the caps' own bound).
  Mesh m;
  m.precision = ValuePrecision::Double;
  const auto c = m.add_vertex(in_plane(0, 0));
  const double ring[][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  std::vector<std::uint32_t> rim;
  for (const auto& p : ring) rim.push_back(m.add_vertex(in_plane(p[0], p[1])));
  for (std::size_t k = 0; k < rim.size(); ++k) m.add_face({c, rim[k], rim[(k + 1) % rim.size()]});
  // Caps hanging off the rim: apex at the midpoint of a rim edge, pushed 2^-27 outward.
  const auto a1 = m.add_vertex(in_plane(1 + h27, 0.5));
  m.add_face({rim[0], a1, rim[1]});
  const auto a2 = m.add_vertex(in_plane(-1 - h27, -0.5));
  m.add_face({rim[4], a2, rim[5]});
  for (auto w : {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max}) {
    for (auto p : {Precision::Double, Precision::Float}) {
      const VertexNormals vn = vertex_normals(m, w, p);
      INFO("weighting " << int(w) << (p == Precision::Double ? " double" : " float"));
      REQUIRE(vn.normals.size() == 3 * m.num_vertices());
      CHECK(all_finite(vn.normals));
      // In float the caps are unresolvable (aspect 1.5e8 > 1 / u_f): their normal is noise or the
      // degenerate zero. Their apexes see only them (fallback allowed); the rim vertices they touch
      // are unharmed under angle, area and Max weighting (the cap's weight there is ~1e-8), but
      // uniform weighting gives the cap's noisy normal full weight, so those are only checked unit.
      if (p == Precision::Double) CHECK(vn.fallback_vertices == 0);
      else CHECK(vn.fallback_vertices <= 2);
      const double tol = p == Precision::Double ? 8 * kU * 1.6e8 : 8 * kUf * 1e4;
      for (std::size_t v = 0; v < m.num_vertices(); ++v) {
        INFO("vertex " << v);
        const bool touches_cap = v == a1 || v == a2 || v == rim[0] || v == rim[1] || v == rim[4] || v == rim[5];
        if (p == Precision::Float && (v == a1 || v == a2 || (w == Weighting::Uniform && touches_cap))) {
          CHECK(unit_or_zero(get3(vn.normals, v), 8 * kUf));
          continue;
        }
        CHECK(angle_between(get3(vn.normals, v), plane_normal()) <= tol);
      }
    }
  }
}

TEST_CASE("stress: features far from the origin (1e6, 1e8) get the same normals as at the origin", "[stress][normals]") {
  // Double positions: a unit feature on a 2^-10 grid at offset 1e6 or 1e8 (both exact integers)
  // is stored exactly (1e8 + k 2^-10 needs 37 bits < 53). Edges are formed in double from the
  // positions, so they are the same doubles as at the origin, and so are the normals: expected
  // bitwise identical, in both accumulation precisions. (A kernel that rounded positions to float
  // first would lose the feature entirely at 1e8, where float's spacing is 8.)
  AnalyticMesh sphere = testing::icosphere(2);
  for (double& x : sphere.mesh.positions) x = std::round(x * 1024) / 1024;  // onto the 2^-10 grid
  for (double offset : {1e6, 1e8}) {
    Mesh far = sphere.mesh;
    for (std::size_t i = 0; i < far.positions.size(); ++i) far.positions[i] += offset * (i % 3 == 1 ? -1 : 1);
    for (std::size_t i = 0; i < far.positions.size(); ++i)
      REQUIRE(far.positions[i] - offset * (i % 3 == 1 ? -1 : 1) == sphere.mesh.positions[i]);  // stored exactly
    for (auto p : {Precision::Double, Precision::Float}) {
      INFO("offset " << offset << (p == Precision::Double ? " double" : " float"));
      CHECK(face_normals(far, p) == face_normals(sphere.mesh, p));
      for (auto w : {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max})
        CHECK(vertex_normals(far, w, p).normals == vertex_normals(sphere.mesh, w, p).normals);
    }
  }
}

TEST_CASE("stress: float positions far from the origin: exact at 1e6, degenerate but finite at 1e8", "[stress][normals]") {
  // Float positions (what a binary PLY or STL file holds): at 1e6 float's spacing is 1/16, so a
  // feature on a 1/16 grid survives the float round trip exactly and must give the same normals as
  // at the origin. At 1e8 the spacing is 8: a unit feature collapses onto a few grid points; the
  // faces become degenerate. Expected then: no NaN or Inf anywhere, every normal unit or zero, the
  // collapsed vertices counted as fallbacks.
  AnalyticMesh sphere = testing::icosphere(1);
  for (double& x : sphere.mesh.positions) x = std::round(x * 16) / 16;  // onto the 1/16 grid
  const auto ref = face_normals(sphere.mesh);
  for (double offset : {1e6, 1e8}) {
    Mesh far = sphere.mesh;
    for (double& x : far.positions) x += offset;
    far.precision = ValuePrecision::Float;
    WriteOptions wo;
    wo.format = Format::Ply;
    const Mesh back = read_mesh_from_memory(write_mesh_to_memory(far, wo), Format::Ply, "far.ply");
    REQUIRE(back.num_faces() == far.num_faces());
    const auto fn = face_normals(back);
    const VertexNormals vn = vertex_normals(back);
    INFO("offset " << offset);
    CHECK(all_finite(fn));
    CHECK(all_finite(vn.normals));
    for (std::size_t v = 0; v < back.num_vertices(); ++v) CHECK(unit_or_zero(get3(vn.normals, v), 4 * kU));
    if (offset == 1e6) {
      CHECK(back.positions == far.positions);  // the 1/16 grid is exact in float at 1e6
      CHECK(fn == ref);
      CHECK(vn.fallback_vertices == 0);
    } else {
      std::size_t zero = 0;
      for (std::size_t f = 0; f < back.num_faces(); ++f) zero += length(get3(fn, f)) == 0;
      CHECK(zero > 0);  // the collapse happened (else this case tests nothing)
    }
  }
}

TEST_CASE("stress: meshes scaled to 1e-30 and 1e30 keep their normals", "[stress][normals]") {
  // Scaling by a power of two is exact, and so is every product and difference the kernels form
  // from the scaled positions, as long as nothing overflows or underflows; only the normalisation
  // may take another path (a length computed by scaling instead of squaring), which changes the
  // last bit. Expected: face normals within 16 u of the unscaled mesh's, vertex normals within
  // 64 u (sums of up to 6 weighted face normals), at 2^-100 (7.9e-31), 2^100 (1.3e30) and at the
  // decimal scales 1e-30 and 1e30 (where the scaled positions are themselves rounded, by u).
  // Double accumulation: |cross| ~ s^2 ~ 1e60 and its square 1e120 are far inside double's range.
  const AnalyticMesh sphere = testing::icosphere(3, 0.1, 5);  // jittered: irregular faces
  const auto ref_face = face_normals(sphere.mesh);
  std::vector<std::vector<double>> ref_vertex;
  const Weighting weightings[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
  for (auto w : weightings) ref_vertex.push_back(vertex_normals(sphere.mesh, w).normals);
  for (double s : {std::ldexp(1.0, -100), std::ldexp(1.0, 100), 1e-30, 1e30}) {
    Mesh scaled = sphere.mesh;
    for (double& x : scaled.positions) x *= s;
    INFO("scale " << s);
    const auto fn = face_normals(scaled);
    REQUIRE(all_finite(fn));
    for (std::size_t f = 0; f < scaled.num_faces(); ++f) CHECK(angle_between(get3(fn, f), get3(ref_face, f)) <= 16 * kU);
    for (std::size_t k = 0; k < 4; ++k) {
      const VertexNormals vn = vertex_normals(scaled, weightings[k]);
      INFO("weighting " << k);
      REQUIRE(all_finite(vn.normals));
      CHECK(vn.fallback_vertices == 0);
      for (std::size_t v = 0; v < scaled.num_vertices(); ++v)
        CHECK(angle_between(get3(vn.normals, v), get3(ref_vertex[k], v)) <= 64 * kU);
    }
  }
}

// Float accumulation at the same scales. The edges (~1e30 or ~1e-31) fit in float, but their cross
// product (~1e60 / ~1e-62) does not (float spans 1.4e-45 .. 3.4e38): the kernels form every
// contribution in double and, for the scale-dependent weightings (area ~ s^2, max ~ s^-2), multiply
// it by one power of two per mesh before rounding to float (lib/shadetool/normals/engine/corner_contributions.h).
// Expected (the "no overflow or underflow in lengths, normals unchanged"): float face
// normals at scale s equal those at scale 1 within 16 u_f and none is lost; float vertex normals
// of every weighting equal those at scale 1 within 64 u_f (one float rounding per term, at most 6
// terms) and none falls back. At 2^-100 and 2^100 the area and max contributions are exactly
// scaled in double and the chosen power of two undoes that scale exactly, so their float vertex
// normals are bit for bit those at scale 1 (unit normals may differ in the last bit: the length
// of a cross product ~2^+-200 is taken by scaling instead of squaring, checked_length).
TEST_CASE("stress: meshes scaled to 1e-30 and 1e30 with float accumulation", "[stress][normals]") {
  const AnalyticMesh sphere = testing::icosphere(2, 0.1, 5);
  const auto ref = face_normals(sphere.mesh, Precision::Float);
  const Weighting weightings[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
  std::vector<std::vector<double>> ref_vertex;
  for (auto w : weightings) ref_vertex.push_back(vertex_normals(sphere.mesh, w, Precision::Float).normals);
  for (double s : {std::ldexp(1.0, -100), std::ldexp(1.0, 100), 1e-30, 1e30}) {
    Mesh scaled = sphere.mesh;
    for (double& x : scaled.positions) x *= s;
    INFO("scale " << s);
    const bool exact_scale = s == std::ldexp(1.0, -100) || s == std::ldexp(1.0, 100);
    const auto fn = face_normals(scaled, Precision::Float);
    REQUIRE(all_finite(fn));
    std::size_t lost = 0;
    for (std::size_t f = 0; f < scaled.num_faces(); ++f) {
      lost += length(get3(fn, f)) == 0;
      CHECK(angle_between(get3(fn, f), get3(ref, f)) <= 16 * kUf);
    }
    CHECK(lost == 0);
    for (std::size_t k = 0; k < 4; ++k) {
      INFO("weighting " << k);
      const VertexNormals vn = vertex_normals(scaled, weightings[k], Precision::Float);
      REQUIRE(all_finite(vn.normals));
      CHECK(vn.fallback_vertices == 0);
      for (std::size_t v = 0; v < scaled.num_vertices(); ++v)
        CHECK(angle_between(get3(vn.normals, v), get3(ref_vertex[k], v)) <= 64 * kUf);
      const bool scale_dependent = weightings[k] == Weighting::Area || weightings[k] == Weighting::Max;
      if (exact_scale && scale_dependent) CHECK(vn.normals == ref_vertex[k]);
    }
  }
}

TEST_CASE("stress: faces beyond the vector pass's range (1e-70, 1e70) take the scalar path, interleaved with others",
          "[stress][normals]") {
  // The triangle kernels' vector pass (lib/shadetool/normals/engine/triangle_blocks.h) takes faces whose N . N lies
  // in [1e-250, 1e250]; at scale 1e-70 (N . N ~ 1e-283) and 1e70 (~1e277) every face falls to the
  // per-face scalar path, which scales lengths instead of squaring. Faces of a unit copy and a
  // scaled copy alternate, so every block of faces mixes both paths. Expected: each copy's vertex
  // normals equal the unit mesh's within 64 u (the scaled positions are rounded once, by u; the
  // rest as in the 1e-30 case above), none falls back, in every weighting.
  const AnalyticMesh sphere = testing::icosphere(3, 0.1, 5);
  const Mesh& unit = sphere.mesh;
  const std::size_t V = unit.num_vertices(), F = unit.num_faces();
  const Weighting weightings[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
  for (double scale : {1e-70, 1e70}) {
    INFO("scale " << scale);
    Mesh mixed;
    mixed.precision = ValuePrecision::Double;
    for (std::size_t v = 0; v < V; ++v) mixed.add_vertex(unit.position(v));
    for (std::size_t v = 0; v < V; ++v) mixed.add_vertex(unit.position(v) * scale);
    for (std::size_t f = 0; f < F; ++f)
      for (std::uint32_t offset : {0u, std::uint32_t(V)}) {
        const std::uint32_t* c = &unit.corner_vertex[unit.face_start[f]];
        mixed.add_face({c[0] + offset, c[1] + offset, c[2] + offset});
      }
    for (auto w : weightings) {
      INFO("weighting " << int(w));
      const auto ref = vertex_normals(unit, w).normals;
      const VertexNormals vn = vertex_normals(mixed, w);
      REQUIRE(all_finite(vn.normals));
      CHECK(vn.fallback_vertices == 0);
      CHECK(vn.degenerate_faces == 0);
      double worst = 0;
      for (std::size_t v = 0; v < V; ++v)
        worst = std::max({worst, angle_between(get3(vn.normals, v), get3(ref, v)),
                          angle_between(get3(vn.normals, V + v), get3(ref, v))});
      CHECK(worst <= 64 * kU);
    }
  }
}

TEST_CASE("stress: degenerate faces and isolated vertices never give NaN", "[stress][normals]") {
  // Zero-area faces of every kind next to a good one: repeated index, three coincident positions,
  // three collinear points, a polygon whose corners all coincide, a face touching a vertex only
  // degenerate faces use, and an isolated vertex. Expected: degenerate faces -> (0,0,0); vertices
  // with no valid face -> the documented fallback (unit, counted); nothing NaN; the good face's
  // normal exact.
  Mesh m;
  m.precision = ValuePrecision::Double;
  const auto a = m.add_vertex(in_plane(0, 0)), b = m.add_vertex(in_plane(1, 0)), c = m.add_vertex(in_plane(0, 1));
  m.add_face({a, b, c});                                        // good
  m.add_face({a, a, b});                                        // repeated index
  const auto p = m.add_vertex({5, 5, 5}), q = m.add_vertex({5, 5, 5}), r = m.add_vertex({5, 5, 5});
  m.add_face({p, q, r});                                        // coincident positions
  const auto l0 = m.add_vertex({0, 0, 7}), l1 = m.add_vertex({1, 1, 7}), l2 = m.add_vertex({2, 2, 7});
  m.add_face({l0, l1, l2});                                     // collinear
  m.add_face({p, q, r, p});                                     // degenerate quad
  m.add_vertex({9, 9, 9});                                      // isolated
  for (auto prec : {Precision::Double, Precision::Float}) {
    const auto fn = face_normals(m, prec);
    CHECK(all_finite(fn));
    CHECK(angle_between(get3(fn, 0), plane_normal()) <= 8 * (prec == Precision::Double ? kU : kUf));
    for (std::size_t f = 1; f < m.num_faces(); ++f) CHECK(length(get3(fn, f)) == 0);
    for (auto w : {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max}) {
      const VertexNormals vn = vertex_normals(m, w, prec);
      CHECK(all_finite(vn.normals));
      for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(std::fabs(length(get3(vn.normals, v)) - 1) <= 8 * kUf);
      CHECK(vn.fallback_vertices == 7);  // p q r l0 l1 l2 and the isolated vertex
    }
  }
}
