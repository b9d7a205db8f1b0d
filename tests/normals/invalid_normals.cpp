// Tests of normals/invalid_normals.
#include <catch2/catch.hpp>

#include <limits>

#include <shadetool/normals/invalid_normals.h>

TEST_CASE("count_invalid_normals: NaN, Inf and zero rows are invalid; non-unit finite rows are not", "[invalid_normals]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<double> n = {0, 0, 1,   nan, 0, 0,   0, 0, 0,   0.3, 0.4, 12,   0, -inf, 0,   -0.0, 0.0, -0.0};
  CHECK(shadetool::count_invalid_normals(n) == 4);  // rows 2, 3, 5, 6
  CHECK(shadetool::count_invalid_normals({}) == 0);
}
