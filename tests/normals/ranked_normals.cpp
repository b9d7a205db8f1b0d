// Blender's Weighted Normal modes (normals/ranked_normals.h) against values computed by hand from
// the modifier's formula (MOD_weighted_normal.cc): sum of n v / w^rank, normalised.
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/ranked_normals.h>
#include <shadetool/normals/vertex_normals.h>

using namespace shadetool;

namespace {

// Vertex 0 is a corner of a 2 x 2 square in z = 0 (normal +z, area 4) and of a 1 x 1 square in
// x = 0 (normal +x, area 1); both corners are right angles.
Mesh big_and_small() {
  Mesh m;
  for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{2, 0, 0}, Vec3d{2, 2, 0}, Vec3d{0, 2, 0}, Vec3d{0, -1, 0}, Vec3d{0, -1, -1}, Vec3d{0, 0, -1}})
    m.add_vertex(p);
  m.add_face({0, 1, 2, 3});
  m.add_face({0, 4, 5, 6});
  return m;
}

double angle_to(const CornerNormals& cn, std::size_t row, Vec3d e) {
  const Vec3d n = get3(cn.normals, row), x = cross(n, e);
  return std::atan2(std::sqrt(dot(x, x)), dot(n, e));
}

}  // namespace

TEST_CASE("Weighted Normal: Blender's weight base from the strength", "[ranked]") {
  CHECK(ranked_weight_base(50) == 1.0);
  CHECK(ranked_weight_base(100) == 32767.0);
  CHECK(ranked_weight_base(1) == 1.0 / 32767.0);
  CHECK(ranked_weight_base(51) == Approx(1.02));  // (1.02 - 1) 25 = 0.5: not above 1
  CHECK(ranked_weight_base(75) == Approx(12.5));  // (1.5 - 1) 25
  CHECK(ranked_weight_base(25) == Approx(0.5));
  CHECK_THROWS_AS(ranked_weight_base(0), shadetool::Error);
}

TEST_CASE("Weighted Normal face-area: the larger face's rank dominates by w per rank", "[ranked]") {
  const Mesh m = big_and_small();
  const Vec3d z{0, 0, 1}, x{1, 0, 0};
  struct Case { int strength; double threshold; Vec3d expected; };
  for (const Case c : {Case{50, 0.01, z * 4.0 + x * 1.0},              // w = 1: plain area weighting
                       Case{75, 0.01, z * 4.0 + x * (1 / 12.5)},     // rank 1 divided by w = 12.5
                       Case{100, 0.01, z * 4.0 + x * (1 / 32767.0)},
                       Case{75, 3.0, z * 4.0 + x * 1.0}}) {            // |4 - 1| <= T: one rank
    RankedWeightingOptions o;
    o.strength = c.strength;
    o.threshold = c.threshold;
    const CornerNormals cn = ranked_normals(m, o);
    CHECK(angle_to(cn, 0, normalized_or(c.expected, Vec3d{})) < 1e-12);
  }
}

TEST_CASE("Weighted Normal corner-angle and face-area-angle: equal angles share a rank", "[ranked]") {
  const Mesh m = big_and_small();
  const Vec3d z{0, 0, 1}, x{1, 0, 0};
  RankedWeightingOptions o;
  o.strength = 100;
  o.mode = RankedWeighting::CornerAngle;  // both pi/2: one rank, the bisector
  CHECK(angle_to(ranked_normals(m, o), 0, normalized_or(z + x, Vec3d{})) < 1e-12);
  o.mode = RankedWeighting::FaceAreaAngle;  // 4 pi/2 and pi/2: two ranks
  o.strength = 75;
  CHECK(angle_to(ranked_normals(m, o), 0, normalized_or(z * (2 * kPi) + x * (kHalfPi / 12.5), Vec3d{})) < 1e-12);
}

TEST_CASE("Weighted Normal at strength 50 is area weighting (vertex_normals Area) on a real mesh", "[ranked]") {
  const Mesh m = read_mesh(std::string(SHADETOOL_SOURCE_DIR) + "/data/torus_knot.ply");
  RankedWeightingOptions o;
  const CornerNormals cn = ranked_normals(m, o);
  const VertexNormals vn = vertex_normals(m, Weighting::Area, Precision::Double);
  double worst = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) worst = std::max(worst, angle_to(cn, v, get3(vn.normals, v)));
  CHECK(worst < 1e-9);
}

TEST_CASE("Weighted Normal keep sharp: a crease splits the items", "[ranked]") {
  const Mesh m = big_and_small();  // the two faces share only vertex 0: two smooth groups there
  RankedWeightingOptions o;
  o.strength = 100;
  o.crease_angle = 30 * kRadiansPerDegree;
  const CornerNormals cn = ranked_normals(m, o);
  CHECK(angle_to(cn, cn.corner_index[0], {0, 0, 1}) < 1e-12);
  CHECK(angle_to(cn, cn.corner_index[4], {1, 0, 0}) < 1e-12);
}
