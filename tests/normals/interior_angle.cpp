// Tests of normals/interior_angle: the inlined atan2 against std::atan2 and exact angles.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "normals/interior_angle.h"

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
  CHECK(interior_angle(0.0f, 0.0f) == 0.0f);
  CHECK(interior_angle(1.0f, 0.0f) == float(pi / 2));
}

TEST_CASE("interior_angle: within 4 (double) and 6 (float) ulp of std::atan2 over 12 decades", "[interior_angle]") {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst_d = 0, worst_f = 0;
  for (int i = 0; i < 2000000; ++i) {
    const double s = std::fabs(u(rng)) * std::pow(10.0, 6 * u(rng)), c = u(rng) * std::pow(10.0, 6 * u(rng));
    worst_d = std::max(worst_d, ulps(interior_angle(s, c), std::atan2(s, c)));
    worst_f = std::max(worst_f, ulps(interior_angle(float(s), float(c)), std::atan2(float(s), float(c))));
  }
  INFO("worst ulps: double " << worst_d << ", float " << worst_f);
  CHECK(worst_d <= 4);
  CHECK(worst_f <= 6);
}

TEST_CASE("interior_angle: tiny angles keep full relative accuracy (no acos cancellation)", "[interior_angle]") {
  // theta = 1e-9: sin ~ theta, cos ~ 1 - theta^2/2 = 1 in double; acos(dot) would give 0.
  CHECK(interior_angle(1e-9, 1.0) == Approx(1e-9).epsilon(1e-15));
  CHECK(interior_angle(1e-9, -1.0) == Approx(3.141592653589793 - 1e-9).epsilon(1e-16));
}
