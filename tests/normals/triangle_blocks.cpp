// Tests of normals/engine/triangle_blocks: the vectorised arctangent of the triangle kernels
// against the one interior angle (geometry/interior_angle.h) and std::atan2.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <shadetool/geometry/interior_angle.h>
#include <shadetool/normals/engine/triangle_blocks.h>

TEST_CASE("interior_angles: NaN or Inf input gives NaN or an angle in [0, pi]", "[interior_angle]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto sane = [](double t) { return std::isnan(t) || (t >= 0 && t <= 3.141592653589794); };
  double t[2];
  const double s[2] = {nan, inf}, c[2] = {1.0, inf};
  shadetool::normals_detail::interior_angles(2, s, c, t);
  CHECK(sane(t[0]));
  CHECK(sane(t[1]));
}

TEST_CASE("interior_angles: within 1e-13 relative of std::atan2 over 12 decades, exact at the octant points", "[interior_angle]") {
  // triangle_blocks.h bounds the series' truncation by 1.8e-14 relative, plus a few ulp of
  // rounding; 1e-13 leaves room for the rounding and nothing more.
  using shadetool::normals_detail::interior_angles;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t n = 1000003;  // odd: the vector loop's remainder runs too
  std::vector<double> s(n), c(n), theta(n);
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = std::fabs(u(rng)) * std::pow(10.0, 6 * u(rng));
    c[i] = u(rng) * std::pow(10.0, 6 * u(rng));
  }
  interior_angles(n, s.data(), c.data(), theta.data());
  double worst = 0;
  double worst_vs_scalar = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double truth = std::atan2(s[i], c[i]);
    worst = std::max(worst, std::fabs(theta[i] - truth) / truth);
    // the one definition (geometry/interior_angle.h): the vector pass is within the same bound of it
    const double scalar = shadetool::interior_angle(s[i], c[i]);
    worst_vs_scalar = std::max(worst_vs_scalar, std::fabs(theta[i] - scalar) / scalar);
  }
  INFO("worst relative error " << worst << ", against interior_angle " << worst_vs_scalar);
  CHECK(worst_vs_scalar <= 1e-13);
  CHECK(worst <= 1e-13);
  CHECK(worst > 0);  // the comparison ran on inexact values (a test that cannot fail is no test)
  const double pi = 3.141592653589793;
  const double ss[] = {0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 1e-9, 1e-9};
  const double cc[] = {1.0, 1.0, 0.0, -1.0, -1.0, 0.0, 1.0, -1.0};
  double t[8];
  interior_angles(8, ss, cc, t);
  CHECK(t[0] == 0.0);
  CHECK(t[1] == pi / 4);
  CHECK(t[2] == pi / 2);
  CHECK(t[3] == 3 * pi / 4);
  CHECK(t[4] == pi);
  CHECK(t[5] == 0.0);
  CHECK(t[6] == Approx(1e-9).epsilon(1e-15));          // tiny angles keep relative accuracy
  CHECK(t[7] == Approx(pi - 1e-9).epsilon(1e-16));
}
