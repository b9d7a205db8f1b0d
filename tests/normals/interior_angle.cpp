// Tests of normals/interior_angle: the inlined atan2 against std::atan2 and exact angles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <shadetool/normals/interior_angle.h>
#include <shadetool/normals/triangle_blocks.h>

using shadetool::normals_detail::interior_angle;

namespace {

template <class T>
double ulps(T a, T b) {
  return std::fabs(double(a) - double(b)) / double(std::nextafter(b, T(10)) - b);
}

}  // namespace

TEST_CASE("interior_angle: exact at 0, pi/4, pi/2, 3pi/4, pi and for the degenerate (0, 0)", "[interior_angle]") {
  const double pi = 3.141592653589793;
  CHECK(interior_angle(0.0, 1.0) == 0.0);
  CHECK(interior_angle(1.0, 1.0) == pi / 4);
  CHECK(interior_angle(1.0, 0.0) == pi / 2);
  CHECK(interior_angle(1.0, -1.0) == 3 * pi / 4);
  CHECK(interior_angle(0.0, -1.0) == pi);
  CHECK(interior_angle(0.0, 0.0) == 0.0);
}

TEST_CASE("interior_angle: within 4 ulp of std::atan2 over 12 decades", "[interior_angle]") {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    const double s0 = std::fabs(u(rng)) * std::pow(10.0, 6 * u(rng)), c0 = u(rng) * std::pow(10.0, 6 * u(rng));
    const double s1 = std::fabs(u(rng)) * std::pow(10.0, 6 * u(rng)), c1 = u(rng) * std::pow(10.0, 6 * u(rng));
    const double a0 = interior_angle(s0, c0), a1 = interior_angle(s1, c1);
    worst = std::max({worst, ulps(a0, std::atan2(s0, c0)), ulps(a1, std::atan2(s1, c1))});
  }
  INFO("worst ulps " << worst);
  CHECK(worst <= 4);
}

TEST_CASE("interior_angle: NaN or Inf input reads no table entry out of range", "[interior_angle]") {
  // The kernels never pass NaN (degenerate faces are skipped first); this guards the table index.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto sane = [](double t) { return std::isnan(t) || (t >= 0 && t <= 3.141592653589794); };
  CHECK(sane(interior_angle(nan, 1.0)));
  CHECK(sane(interior_angle(1.0, nan)));
  CHECK(sane(interior_angle(inf, inf)));
  double t[2];
  const double s[2] = {nan, inf}, c[2] = {1.0, inf};
  shadetool::normals_detail::interior_angles(2, s, c, t);
  CHECK(sane(t[0]));
  CHECK(sane(t[1]));
}

TEST_CASE("interior_angle: tiny angles keep full relative accuracy (no acos cancellation)", "[interior_angle]") {
  // theta = 1e-9: sin ~ theta, cos ~ 1 - theta^2/2 = 1 in double; acos(dot) would give 0.
  CHECK(interior_angle(1e-9, 1.0) == Approx(1e-9).epsilon(1e-15));
  CHECK(interior_angle(1e-9, -1.0) == Approx(3.141592653589793 - 1e-9).epsilon(1e-16));
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
  for (std::size_t i = 0; i < n; ++i) {
    const double truth = std::atan2(s[i], c[i]);
    worst = std::max(worst, std::fabs(theta[i] - truth) / truth);
  }
  INFO("worst relative error " << worst);
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
