// Tests of winding_number: solid angles with closed-form values, inside/outside of closed
// surfaces, and the error of the hierarchy against the exact sum.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <shadetool/geometry/winding_number.h>
#include "repair/repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
constexpr double kExact = std::numeric_limits<double>::infinity();
std::vector<std::uint32_t> all_faces(const Mesh& m) {
  std::vector<std::uint32_t> f(m.num_faces());
  std::iota(f.begin(), f.end(), 0u);
  return f;
}
}  // namespace

TEST_CASE("the octant triangle subtends 4 pi / 8 from the origin, signed by the side seen", "[repair][winding_number]") {
  const Vec3d x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1}, o{0, 0, 0};
  // (x, y, z) is counter-clockwise seen from (1,1,1): the origin sees its back, so positive.
  CHECK(triangle_solid_angle(x, y, z, o) == Approx(kPi / 2).epsilon(1e-15));
  CHECK(triangle_solid_angle(x, z, y, o) == Approx(-kPi / 2).epsilon(1e-15));
  // Far away along the normal: ~ area / d^2 = (sqrt(3)/2) / d^2, seen from the front: negative.
  const double d = 1e4;
  const Vec3d far = Vec3d{1, 1, 1} * (d / std::sqrt(3.0)) + Vec3d{1, 1, 1} * (1.0 / 3.0);
  CHECK(triangle_solid_angle(x, y, z, far) == Approx(-std::sqrt(3.0) / 2 / (d * d)).epsilon(1e-6));
}

TEST_CASE("a point in the triangle's plane gets the principal value 0", "[repair][winding_number]") {
  const Vec3d a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  CHECK(triangle_solid_angle(a, b, c, {0.25, 0.25, 0}) == 0.0);  // on the face itself
  CHECK(triangle_solid_angle(a, b, c, {5, 5, 0}) == 0.0);        // beside it
  CHECK(triangle_solid_angle(a, b, c, a) == 0.0);                // at a corner
}

TEST_CASE("closed sphere: w = 1 inside, 0 outside (exact sum)", "[repair][winding_number]") {
  const Mesh m = icosphere(3).mesh;
  const WindingNumberTree t = winding_number_tree(m, all_faces(m), {});
  CHECK(winding_number(t, {0, 0, 0}, WindingNumberTree::kNoFace, kExact) == Approx(1.0).margin(1e-12));
  CHECK(winding_number(t, {0.3, -0.5, 0.2}, WindingNumberTree::kNoFace, kExact) == Approx(1.0).margin(1e-12));
  CHECK(winding_number(t, {2, 0, 0}, WindingNumberTree::kNoFace, kExact) == Approx(0.0).margin(1e-12));
  // Reversed winding: -1 inside.
  const WindingNumberTree r = winding_number_tree(m, all_faces(m), std::vector<std::uint8_t>(m.num_faces(), 1));
  CHECK(winding_number(r, {0, 0, 0}, WindingNumberTree::kNoFace, kExact) == Approx(-1.0).margin(1e-12));
}

TEST_CASE("on the surface, leaving out the face gives ~1/2 (the principal value)", "[repair][winding_number]") {
  const Mesh m = icosphere(4).mesh;
  const WindingNumberTree t = winding_number_tree(m, all_faces(m), {});
  const std::uint32_t f = 100;
  Vec3d q{};
  for (int k = 0; k < 3; ++k) q += m.position(m.corner_vertex[3 * f + k]) * (1.0 / 3.0);
  CHECK(winding_number(t, q, f, kExact) == Approx(0.5).margin(0.01));
}

TEST_CASE("the hierarchy (beta = 2) stays within 5e-2 of the exact sum, far from the origin too", "[repair][winding_number]") {
  for (const Vec3d& offset : {Vec3d{0, 0, 0}, Vec3d{1e6, -1e6, 5e5}}) {
    Mesh m = testing::torus(120, 60).mesh;  // 14400 triangles
    transform_positions(m, 1.0, offset);
    const WindingNumberTree t = winding_number_tree(m, all_faces(m), {});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.6, 1.6);
    double worst = 0;
    for (int i = 0; i < 200; ++i) {
      const Vec3d q = offset + Vec3d{u(rng), u(rng), 0.5 * u(rng)};
      const double fast = winding_number(t, q), exact = winding_number(t, q, WindingNumberTree::kNoFace, kExact);
      worst = std::max(worst, std::abs(fast - exact));
      // Off the surface, the exact value of a closed surface is an integer.
      CHECK(std::abs(exact - std::round(exact)) < 1e-9);
    }
    INFO("worst |fast - exact| = " << worst);
    CHECK(worst < 5e-2);
  }
}

TEST_CASE("an open hemisphere: w at its centre is 1/2, with the sign of its winding", "[repair][winding_number]") {
  const Mesh m = hemisphere(64, 32);
  const WindingNumberTree t = winding_number_tree(m, all_faces(m), {});
  // Faces outward: the centre sees their backs over half of all directions.
  CHECK(winding_number(t, {0, 0, 0}, WindingNumberTree::kNoFace, kExact) == Approx(0.5).margin(1e-12));
}
