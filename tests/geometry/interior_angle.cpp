// Tests of geometry/interior_angle: the one interior angle (inlined atan2) against std::atan2 and
// exact angles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <shadetool/geometry/interior_angle.h>

using shadetool::interior_angle;
using shadetool::polygon_corner_angle;

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
}

TEST_CASE("interior_angle: tiny angles keep full relative accuracy (no acos cancellation)", "[interior_angle]") {
  // theta = 1e-9: sin ~ theta, cos ~ 1 - theta^2/2 = 1 in double; acos(dot) would give 0.
  CHECK(interior_angle(1e-9, 1.0) == Approx(1e-9).epsilon(1e-15));
  CHECK(interior_angle(1e-9, -1.0) == Approx(3.141592653589793 - 1e-9).epsilon(1e-16));
}

TEST_CASE("polygon_corner_angle: a reflex corner counts 2 pi - theta, a convex one theta", "[interior_angle]") {
  const double pi = 3.141592653589793;
  // corner at the origin, a = (1, 0, 0), b = (0, 1, 0) about n = +z: (a x b) . n = +1, 90 degrees
  CHECK(polygon_corner_angle(1.0, 0.0) == pi / 2);
  // the same corner seen from -z: (a x b) . n = -1, the reflex 270 degrees
  CHECK(polygon_corner_angle(-1.0, 0.0) == Approx(1.5 * pi).epsilon(1e-16));
  CHECK(polygon_corner_angle(-1.0, 0.0) == 2 * pi - interior_angle(1.0, 0.0));
}
