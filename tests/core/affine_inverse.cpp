// invert_affine and is_identity: an inverse that round-trips points, refusal of singular maps.
#include <catch2/catch.hpp>

#include <shadetool/core/affine.h>

using namespace shadetool;

TEST_CASE("invert_affine inverts, and refuses a singular map", "[lighting][affine_inverse]") {
  Affine3d M;
  M.A.m = {{{2, 1, 0}, {0, 1, 3}, {1, 0, 1}}};  // det = 2*1 - 1*(-3) + 0 = 5
  M.t = {1, -2, 3};
  Affine3d Mi;
  REQUIRE(invert_affine(M, Mi));
  const Vec3d p{0.3, -0.7, 2.5};
  const Vec3d back = transform_point(Mi, transform_point(M, p));
  CHECK(length(back - p) <= 1e-14);
  Affine3d S;
  S.A = Mat3d::diagonal(1, 0, 1);
  CHECK_FALSE(invert_affine(S, Mi));
  CHECK(is_identity(Affine3d{}));
  CHECK_FALSE(is_identity(M));
}
