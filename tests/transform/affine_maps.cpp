// Tests of transform/affine_maps: elementary maps against hand-computed matrices, composition
// order, and the refusal of malformed matrices (wrong count, non-finite, projective last row).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/classify_affine.h>

using namespace shadetool;

namespace {

double max_abs_diff(const Mat3d& a, const Mat3d& b) {
  double d = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::max(d, std::fabs(a.m[i][j] - b.m[i][j]));
  return d;
}

Mat3d rows(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
  Mat3d m;
  m.m = {{{a, b, c}, {d, e, f}, {g, h, i}}};
  return m;
}

}  // namespace

TEST_CASE("sin_cos_degrees is exact at multiples of 90 degrees and has no -0", "[affine_maps]") {
  struct Case { double deg, s, c; };
  for (Case k : {Case{0, 0, 1}, Case{90, 1, 0}, Case{180, 0, -1}, Case{270, -1, 0}, Case{360, 0, 1},
                 Case{-90, -1, 0}, Case{-180, 0, -1}, Case{450, 1, 0}, Case{-720, 0, 1}}) {
    double s, c;
    sin_cos_degrees(k.deg, s, c);
    CAPTURE(k.deg);
    CHECK(s == k.s);
    CHECK(c == k.c);
    CHECK(!std::signbit(s == 0 ? s : 1.0));
    CHECK(!std::signbit(c == 0 ? c : 1.0));
  }
  // sin 30 = 1/2, cos 30 = sqrt(3)/2, sin 135 = cos 135 * -1 = sqrt(2)/2: to one rounding.
  double s, c;
  sin_cos_degrees(30, s, c);
  CHECK(s == Approx(0.5).epsilon(2e-16));
  CHECK(c == Approx(std::sqrt(3.0) / 2).epsilon(2e-16));
  sin_cos_degrees(135, s, c);
  CHECK(s == Approx(std::sqrt(0.5)).epsilon(2e-16));
  CHECK(c == Approx(-std::sqrt(0.5)).epsilon(2e-16));
}

TEST_CASE("rotation_map: a quarter turn about z is the exact integer matrix", "[affine_maps]") {
  // Counter-clockwise seen from +z: x -> y, y -> -x.
  const Affine3d R = rotation_map(90, {0, 0, 1});
  CHECK(max_abs_diff(R.A, rows(0, -1, 0, 1, 0, 0, 0, 0, 1)) == 0.0);
  CHECK(R.t == Vec3d(0, 0, 0));
  // The axis need not be unit: (0, 0, 5) is the same axis.
  CHECK(max_abs_diff(rotation_map(90, {0, 0, 5}).A, R.A) == 0.0);
  // About x by 90: y -> z, z -> -y.
  CHECK(max_abs_diff(rotation_map(90, {1, 0, 0}).A, rows(1, 0, 0, 0, 0, -1, 0, 1, 0)) == 0.0);
  // About y by 90: z -> x, x -> -z.
  CHECK(max_abs_diff(rotation_map(90, {0, 1, 0}).A, rows(0, 0, 1, 0, 1, 0, -1, 0, 0)) == 0.0);
}

TEST_CASE("rotation_map: 120 degrees about (1,1,1) permutes the axes x -> y -> z -> x", "[affine_maps]") {
  const Affine3d R = rotation_map(120, {1, 1, 1});
  CHECK(max_abs_diff(R.A, rows(0, 0, 1, 1, 0, 0, 0, 1, 0)) < 4e-16);
}

TEST_CASE("rotation_map: tiny angles keep R orthonormal (versine without cancellation)", "[affine_maps]") {
  // For a = 1e-6 degrees about z: R = [[cos a, -sin a, 0], [sin a, cos a, 0], [0, 0, 1]],
  // sin a = a (rad) to 1e-28 relative.
  const double a = 1e-6 * 3.14159265358979323846 / 180;
  const Affine3d R = rotation_map(1e-6, {0, 0, 1});
  CHECK(R.A.m[1][0] == Approx(a).epsilon(1e-15));
  CHECK(R.A.m[0][1] == Approx(-a).epsilon(1e-15));
  // About a skew axis the off-diagonal k_i k_j (1 - cos a) terms must be right too: R^T R = I.
  const Affine3d S = rotation_map(1e-7, {1, 2, 3});
  const Mat3d G = transpose(S.A) * S.A;
  CHECK(max_abs_diff(G, Mat3d::identity()) < 4e-16);
  CHECK(classify_affine(S).path == TransformPath::Rotation);
}

TEST_CASE("rotation_map refuses a zero axis and non-finite numbers", "[affine_maps]") {
  CHECK_THROWS_WITH(rotation_map(30, {0, 0, 0}), Catch::Contains("--rotate") && Catch::Contains("zero length"));
  CHECK_THROWS_AS(rotation_map(std::numeric_limits<double>::quiet_NaN(), {0, 0, 1}), Error);
  CHECK_THROWS_AS(rotation_map(30, {0, std::numeric_limits<double>::infinity(), 1}), Error);
  CHECK_THROWS_AS(scale_map({1, std::numeric_limits<double>::quiet_NaN(), 1}), Error);
  CHECK_THROWS_AS(translation_map({1, 0, std::numeric_limits<double>::infinity()}), Error);
}

TEST_CASE("scale_map and translation_map", "[affine_maps]") {
  const Affine3d S = scale_map({1, 2, 3});
  CHECK(max_abs_diff(S.A, rows(1, 0, 0, 0, 2, 0, 0, 0, 3)) == 0.0);
  const Affine3d T = translation_map({4, 5, 6});
  CHECK(max_abs_diff(T.A, Mat3d::identity()) == 0.0);
  CHECK(T.t == Vec3d(4, 5, 6));
}

TEST_CASE("affine_from_row_major: 12 numbers are [A | t] row by row", "[affine_maps]") {
  const Affine3d M = affine_from_row_major({1, 2, 3, 10, 4, 5, 6, 20, 7, 8, 9, 30});
  CHECK(max_abs_diff(M.A, rows(1, 2, 3, 4, 5, 6, 7, 8, 9)) == 0.0);
  CHECK(M.t == Vec3d(10, 20, 30));
  const Affine3d N = affine_from_row_major({1, 2, 3, 10, 4, 5, 6, 20, 7, 8, 9, 30, 0, 0, 0, 1});
  CHECK(max_abs_diff(N.A, M.A) == 0.0);
  CHECK(N.t == M.t);
}

TEST_CASE("affine_from_row_major refuses a projective last row, a wrong count and NaN", "[affine_maps]") {
  const std::vector<double> base = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  for (std::vector<double> last : {std::vector<double>{0, 0, 0.5, 1}, {0, 0, 0, 2}, {1, 0, 0, 1}, {0, 0, 0, 0}}) {
    std::vector<double> v = base;
    v.insert(v.end(), last.begin(), last.end());
    CHECK_THROWS_WITH(affine_from_row_major(v, "m.txt"),
                      Catch::StartsWith("m.txt: the last row of a 4x4 matrix must be 0 0 0 1") &&
                          Catch::Contains("projective"));
  }
  CHECK_THROWS_WITH(affine_from_row_major({1, 2, 3}), Catch::Contains("expected 12 or 16 numbers") && Catch::Contains("got 3"));
  std::vector<double> v = base;
  v[5] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(affine_from_row_major(v), Catch::Contains("row 2, column 2"));
}

TEST_CASE("compose_in_order: the first map acts first (M = M2 M1)", "[affine_maps]") {
  // rotate 90 about z, then translate (1,0,0): (1,0,0) -> (0,1,0) -> (1,1,0).
  const Affine3d RT = compose_in_order({rotation_map(90, {0, 0, 1}), translation_map({1, 0, 0})});
  CHECK(transform_point(RT, {1, 0, 0}) == Vec3d(1, 1, 0));
  // translate first, then rotate: (1,0,0) -> (2,0,0) -> (0,2,0).
  const Affine3d TR = compose_in_order({translation_map({1, 0, 0}), rotation_map(90, {0, 0, 1})});
  CHECK(transform_point(TR, {1, 0, 0}) == Vec3d(0, 2, 0));
  CHECK(RT.t == Vec3d(1, 0, 0));
  CHECK(TR.t == Vec3d(0, 1, 0));
  // scale then translate vs translate then scale: t = (1,0,0) vs (2,0,0).
  CHECK(compose_in_order({scale_map({2, 2, 2}), translation_map({1, 0, 0})}).t == Vec3d(1, 0, 0));
  CHECK(compose_in_order({translation_map({1, 0, 0}), scale_map({2, 2, 2})}).t == Vec3d(2, 0, 0));
  CHECK(compose_in_order({}).t == Vec3d(0, 0, 0));
}
