// Tests of geometry/degenerate_face: the one rule, and that info, repair and normals (every
// weighting, both precisions, every kernel path) call the same faces degenerate.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/info/mesh_info.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/repair/degenerate_faces.h>
#include <shadetool/repair/signed_volume.h>
#include <shadetool/core/edge_adjacency.h>

using namespace shadetool;

namespace {

// Random rotation (unit quaternion) applied to p.
struct Rotation {
  double w, x, y, z;
  Vec3d operator()(const Vec3d& p) const {
    const Vec3d u{x, y, z}, t = cross(u, p) * 2.0;
    return p + t * w + cross(u, t);
  }
};

Rotation random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  double q[4], n = 0;
  for (double& c : q) { c = g(rng); n += c * c; }
  n = std::sqrt(n);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

// Slivers around the rule's threshold: triangle (0,0,0), (1,0,0), (1/2, h, 0), whose largest angle
// has sin ~ 4 h, so the threshold 64 eps lies at h ~ 16 eps = 3.6e-15; h spans 1e-16 .. 1e-13.
// Each face has its own vertices, a random rotation, translation, power-of-two scale (2^-60 ..
// 2^60) and a random first corner; quads (a thin rectangle 1 by h, threshold h ~ 64 eps) too when
// with_quads. Plus one well-shaped face per sliver, so that no test is vacuous.
Mesh sliver_mesh(bool with_quads, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Mesh m;
  for (int i = 0; i < 600; ++i) {
    const double h = std::pow(10.0, -16 + 3 * u(rng));
    const Rotation r = random_rotation(rng);
    const double s = std::ldexp(1.0, int(120 * u(rng)) - 60);
    const Vec3d t{u(rng), u(rng), u(rng)};
    const bool quad = with_quads && i % 3 == 0;
    const std::vector<Vec3d> corners = quad ? std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {1, h, 0}, {0, h, 0}}
                                            : std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}};
    const std::uint32_t first = std::uint32_t(m.num_vertices()), n = std::uint32_t(corners.size());
    const std::uint32_t shift = std::uint32_t(u(rng) * n) % n;
    std::vector<std::uint32_t> face;
    for (std::uint32_t k = 0; k < n; ++k) {
      m.add_vertex((r(corners[(k + shift) % n]) + t) * s);
      face.push_back(first + k);
    }
    m.add_face(face);
    // a well-shaped neighbour (its own vertices too)
    const std::uint32_t w = std::uint32_t(m.num_vertices());
    for (const Vec3d& p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}}) m.add_vertex((r(p) + t) * s);
    m.add_face({w, w + 1, w + 2});
  }
  return m;
}

}  // namespace

TEST_CASE("degenerate rule: named kinds, scale-free, independent of the first corner", "[geometry][degenerate]") {
  Mesh m;
  for (auto p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{2, 0, 0}, Vec3d{0, 1, 0}, Vec3d{NAN, 0, 0},
                 Vec3d{1e-200, 1e-200, 0}, Vec3d{1, 1e-15, 0}})
    m.add_vertex(p);
  m.add_face({0, 1, 3});     // regular
  m.add_face({0, 1, 1});     // repeated index
  m.add_face({0, 1, 2});     // collinear
  m.add_face({0, 1, 4});     // NaN corner
  m.add_face({0, 1});        // two corners
  m.add_face({0, 1, 5});     // tiny (1e-200) but well-shaped: its largest angle is ~135 degrees
  m.add_face({0, 1, 6});     // a needle with a 1e-15 edge: its largest angle is ~90 degrees
  m.add_face({1, 6, 0});     // the same needle from another first corner
  using K = DegenerateKind;
  CHECK(face_degenerate_kind(m, 0) == K::None);
  CHECK(face_degenerate_kind(m, 1) == K::RepeatedIndex);
  CHECK(face_degenerate_kind(m, 2) == K::ZeroArea);
  CHECK(face_degenerate_kind(m, 3) == K::NonFinite);
  CHECK(face_degenerate_kind(m, 4) == K::TooFewCorners);
  CHECK(face_degenerate_kind(m, 5) == K::None);
  CHECK(face_degenerate_kind(m, 6) == K::None);
  CHECK(face_degenerate_kind(m, 7) == K::None);
}

TEST_CASE("degenerate rule: info, repair and normals agree face for face on slivers at the threshold",
          "[geometry][degenerate]") {
  for (bool with_quads : {false, true}) {
    const Mesh m = sliver_mesh(with_quads, with_quads ? 7 : 5);
    INFO("with quads " << with_quads);
    std::vector<std::uint8_t> degenerate(m.num_faces());
    std::size_t rule = 0;
    for (std::size_t f = 0; f < m.num_faces(); ++f) {
      degenerate[f] = face_degenerate_kind(m, f) != DegenerateKind::None;
      rule += degenerate[f];
    }
    // The slivers straddle the threshold: some are degenerate, some are not, every regular face is not.
    std::size_t degenerate_corners = 0;
    for (std::size_t f = 0; f < m.num_faces(); ++f) degenerate_corners += degenerate[f] * m.face_size(f);
    CHECK(rule > 50);
    CHECK(rule < m.num_faces() / 2 - 50);

    CHECK(info::mesh_info(m).degenerate.count() == rule);
    const DegenerateFaces repaired = degenerate_faces(m);
    CHECK(repaired.count() == rule);
    for (std::size_t f = 0; f < m.num_faces(); ++f) CHECK((repaired.kind[f] != DegenerateKind::None) == bool(degenerate[f]));
    // repair's volume pass classifies the faces it sums (triangles by the sufficient test
    // triangle_surely_valid, then the rule), kind for kind as the rule does.
    {
      EdgeAdjacencyOptions left_out;
      left_out.skip_unwound_faces = true;
      const ConsistentWinding winding = consistent_winding(m, edge_adjacency(m, left_out), left_out);
      DegenerateFaces by_volumes;
      component_signed_volumes(m, winding, &by_volumes);
      REQUIRE(by_volumes.kind.size() == m.num_faces());
      std::size_t differ = 0;
      for (std::size_t f = 0; f < m.num_faces(); ++f) differ += by_volumes.kind[f] != face_degenerate_kind(m, f);
      CHECK(differ == 0);
      CHECK(by_volumes.count() == rule);
    }

    for (Precision precision : {Precision::Double, Precision::Float}) {
      const std::vector<double> fn = face_normals(m, precision);
      std::size_t mismatched = 0;
      for (std::size_t f = 0; f < m.num_faces(); ++f) {
        const bool zero = fn[3 * f] == 0 && fn[3 * f + 1] == 0 && fn[3 * f + 2] == 0;
        mismatched += zero != bool(degenerate[f]);
      }
      CHECK(mismatched == 0);
      for (Weighting w : {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max}) {
        INFO("weighting " << int(w) << " precision " << int(precision));
        const VertexNormals vn = vertex_normals(m, w, precision);
        CHECK(vn.degenerate_faces == rule);
        // Each face has its own vertices: those of a degenerate face, and only those, get the
        // documented fallback (in double; in float a sliver's area or Max weight, ~1e-16 of its
        // neighbour's, may underflow after the per-mesh scale, and then its vertices take the
        // fallback too, counted: float's documented limit, not a disagreement on the rule).
        if (precision == Precision::Double) {
          CHECK(vn.fallback_vertices == degenerate_corners);
          std::size_t wrong = 0;
          for (std::size_t f = 0; f < m.num_faces(); ++f) {
            const std::uint32_t v = m.corner_vertex[m.face_start[f]];
            const bool fallback = vn.normals[3 * v] == 0 && vn.normals[3 * v + 1] == 0 && vn.normals[3 * v + 2] == 1;
            wrong += fallback != bool(degenerate[f]);
          }
          CHECK(wrong == 0);
        }
        CHECK(corner_normals(m, 0.5, w, precision).degenerate_faces == rule);
      }
    }
  }
}

TEST_CASE("degenerate rule: the sufficient test triangle_surely_valid never passes a face the rule calls degenerate",
          "[geometry][degenerate]") {
  // Slivers at the threshold, every first corner (the test uses the edges from corner 0, the rule
  // the two shortest): wherever the sufficient test says valid, the rule must say None. It must
  // also pass most well-shaped faces, or it saves nothing.
  const Mesh m = sliver_mesh(false, 11);
  std::size_t passed = 0, wrong = 0, regular_passed = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t* v = m.corner_vertex.data() + m.face_start[f];
    for (int first = 0; first < 3; ++first) {
      const Vec3d p0 = m.position(v[first]), p1 = m.position(v[(first + 1) % 3]), p2 = m.position(v[(first + 2) % 3]);
      const Vec3d e0 = p1 - p0, e2 = p2 - p0;
      if (!triangle_surely_valid(cross(e0, e2), e0, e2)) continue;
      ++passed;
      regular_passed += f % 2 == 1;  // odd faces are the well-shaped neighbours
      wrong += face_degenerate_kind(m, f) != DegenerateKind::None;
    }
  }
  CHECK(wrong == 0);
  CHECK(regular_passed == 3 * m.num_faces() / 2);
  CHECK(passed > regular_passed);  // some slivers above the threshold pass too
}
