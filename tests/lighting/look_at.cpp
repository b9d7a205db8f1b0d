// look_at: the eye maps to the origin, the target onto -z, up into the +y half-plane; rigid.
#include <catch2/catch.hpp>

#include <shadetool/lighting/look_at.h>

using namespace shadetool;

TEST_CASE("look_at maps the eye to the origin and the target onto -z", "[lighting][look_at]") {
  Affine3d V;
  const Vec3d eye{4, 3, 6}, target{1, 0, -2}, up{0, 1, 0};
  REQUIRE(look_at(eye, target, up, V));
  const Vec3d e = transform_point(V, eye);
  CHECK(length(e) <= 1e-14);
  const Vec3d t = transform_point(V, target);
  const double distance = length(target - eye);  // sqrt(9 + 9 + 64) = sqrt(82)
  CHECK(t.x == Approx(0).margin(1e-14));
  CHECK(t.y == Approx(0).margin(1e-14));
  CHECK(t.z == Approx(-std::sqrt(82.0)).epsilon(1e-14));
  CHECK(distance == Approx(std::sqrt(82.0)));
  CHECK(transform_vector(V, up).y > 0);
  // rigid: V^T V = I, det +1
  const Mat3d G = transpose(V.A) * V.A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) CHECK(G.m[i][j] == Approx(i == j ? 1 : 0).margin(1e-15));
  CHECK(determinant(V.A) == Approx(1).epsilon(1e-15));
}

TEST_CASE("look_at refuses a degenerate camera", "[lighting][look_at]") {
  Affine3d V;
  V.t = {9, 9, 9};
  CHECK_FALSE(look_at({1, 2, 3}, {1, 2, 3}, {0, 1, 0}, V));  // no view direction
  CHECK_FALSE(look_at({0, 5, 0}, {0, 0, 0}, {0, 1, 0}, V));  // up parallel to the view direction
  CHECK(V.t == Vec3d{9, 9, 9});                               // untouched
}
