// Tests of geometry/scaled_length.h: the one safe length and normalise, for vectors whose squares
// under- or overflow (tiny and huge normal sums), against hand values.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <shadetool/geometry/scaled_length.h>

using namespace shadetool;

TEST_CASE("checked_length is exact for (1, 2, 2) 2^k at every exponent whose squares under- or overflow",
          "[scaled_length]") {
  for (int k = -1070; k <= 1020; k += 10) {
    INFO("2^" << k);
    const double s = std::ldexp(1.0, k);
    const Vec3d v{s, 2 * s, 2 * s};  // |v| = 3 s exactly
    if (k >= -1021) CHECK(checked_length(v) == 3 * s);
    else CHECK(checked_length(v) == Approx(3 * s).epsilon(1e-15));  // subnormal input: rounded
    double o[3];
    REQUIRE(normalise_checked(v.x, v.y, v.z, o));
    if (k >= -1021 && k <= 1020) {  // normal components: 1/3, 2/3, 2/3 rounded once, as at scale 1
      CHECK(o[0] == 1.0 / 3); CHECK(o[1] == 2.0 / 3); CHECK(o[2] == 2.0 / 3);
    }
  }
}

TEST_CASE("normalise_checked: the smallest subnormal gives its axis; zero, NaN and Inf give false", "[scaled_length]") {
  const double d = std::numeric_limits<double>::denorm_min(), inf = std::numeric_limits<double>::infinity();
  double o[3] = {7, 7, 7};
  REQUIRE(normalise_checked(0.0, -d, 0.0, o));
  CHECK(o[0] == 0.0); CHECK(o[1] == -1.0); CHECK(o[2] == 0.0);
  const double big = std::numeric_limits<double>::max();
  REQUIRE(normalise_checked(big, big, 0.0, o));  // |v| itself overflows; the direction does not
  CHECK(o[0] == Approx(std::sqrt(0.5)).epsilon(1e-15)); CHECK(o[1] == o[0]); CHECK(o[2] == 0.0);
  double at_unit[3];
  REQUIRE(normalise_checked(-0.3, 1e-5, 0.7, at_unit));
  for (int k : {-1000, -600, -140, 140, 600, 1000}) {  // tiny and huge sums: bitwise the unit-scale result
    INFO("2^" << k);
    const double s = std::ldexp(1.0, k);
    REQUIRE(normalise_checked(-0.3 * s, 1e-5 * s, 0.7 * s, o));
    CHECK(o[0] == at_unit[0]); CHECK(o[1] == at_unit[1]); CHECK(o[2] == at_unit[2]);
  }
  double u[3] = {7, 7, 7};
  CHECK_FALSE(normalise_checked(0.0, 0.0, 0.0, u));
  CHECK_FALSE(normalise_checked(std::nan(""), 1.0, 0.0, u));
  CHECK_FALSE(normalise_checked(inf, 1.0, 0.0, u));
  CHECK(u[0] == 7.0);  // untouched on failure
  CHECK(checked_length(Vec3d{inf, 0, 0}) == 0.0);
}
