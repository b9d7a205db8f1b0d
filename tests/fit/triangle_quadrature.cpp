// Tests for fit/triangle_quadrature.h against the closed form of the integral of a monomial in
// barycentric coordinates:  integral over T of l1^a l2^b l3^c dA = 2 A a! b! c! / (a + b + c + 2)!
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/fit/triangle_quadrature.h>

using namespace shadetool;

namespace {
double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
}  // namespace

TEST_CASE("Each triangle rule integrates every monomial up to its degree exactly, and fails above it",
          "[fit][quadrature]") {
  for (int points : {1, 3, 6, 12}) {
    const int degree = triangle_quadrature_degree(points);
    const auto rule = triangle_quadrature(points);
    REQUIRE(int(rule.size()) == points);
    bool fails_above = false;
    for (int a = 0; a <= degree + 1; ++a)
      for (int b = 0; a + b <= degree + 1; ++b)
        for (int c = 0; a + b + c <= degree + 1; ++c) {
          double sum = 0;
          for (const auto& p : rule)
            sum += p.weight * std::pow(p.barycentric[0], a) * std::pow(p.barycentric[1], b) * std::pow(p.barycentric[2], c);
          // the rule's weights are fractions of the area: compare with the exact mean over T
          const double exact = 2 * factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 2);
          if (a + b + c <= degree) {
            INFO("points " << points << " monomial " << a << b << c);
            CHECK(sum == Approx(exact).epsilon(1e-13));
          } else if (std::fabs(sum - exact) > 1e-9 * exact) {
            fails_above = true;
          }
        }
    INFO("points " << points << ": some monomial of degree " << degree + 1 << " is not exact");
    CHECK(fails_above);
  }
  CHECK_FALSE(triangle_quadrature_supported(4));
  CHECK(triangle_quadrature(4).empty());
}

TEST_CASE("Gauss-Legendre on [0, 1] with n points is exact to degree 2n - 1", "[fit][quadrature]") {
  for (int n : {1, 2, 3}) {
    const auto g = gauss_legendre_unit(n);
    for (int d = 0; d <= 2 * n - 1; ++d) {
      double sum = 0;
      for (const auto& p : g) sum += p.weight * std::pow(p.t, d);
      CHECK(sum == Approx(1.0 / (d + 1)).epsilon(1e-14));
    }
  }
}
