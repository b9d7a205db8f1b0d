// Tests of transform/classify_affine: each path on maps whose class is known by construction,
// relative_det against hand values, scale invariance, and the tolerances at their edges.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <shadetool/core/error.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/classify_affine.h>

using namespace shadetool;

namespace {
Affine3d with_A(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
  Affine3d M;
  M.A.m = {{{a, b, c}, {d, e, f}, {g, h, i}}};
  return M;
}
Affine3d scaled(const Affine3d& M, double s) {
  Affine3d r = M;
  for (auto& row : r.A.m)
    for (auto& x : row) x *= s;
  return r;
}
}  // namespace

TEST_CASE("classify_affine: identity and translation", "[classify_affine]") {
  CHECK(classify_affine(Affine3d{}).path == TransformPath::Identity);
  const AffineClass t = classify_affine(translation_map({1, -2, 0.5}));
  CHECK(t.path == TransformPath::Translation);
  CHECK_FALSE(t.mirror);
  // A quarter turn and its inverse compose to I exactly: still identity, not a rotation.
  CHECK(classify_affine(compose_in_order({rotation_map(90, {0, 0, 1}), rotation_map(-90, {0, 0, 1})})).path ==
        TransformPath::Identity);
  // 4 eps off the identity is still the identity; 8 eps is not.
  Affine3d near;
  near.A.m[0][1] = kIdentityTolerance;
  CHECK(classify_affine(near).path == TransformPath::Identity);
  near.A.m[0][1] = 2 * kIdentityTolerance;
  CHECK(classify_affine(near).path != TransformPath::Identity);
}

TEST_CASE("classify_affine: rotations, with and without a mirror", "[classify_affine]") {
  for (double deg : {90.0, 33.0, -170.0, 1e-5})
    for (Vec3d axis : {Vec3d{0, 0, 1}, Vec3d{1, 2, 3}, Vec3d{-1, 0.5, 0.25}}) {
      const AffineClass c = classify_affine(rotation_map(deg, axis));
      CAPTURE(deg, axis.x, axis.y, axis.z);
      CHECK(c.path == TransformPath::Rotation);
      CHECK_FALSE(c.mirror);
      CHECK(c.det == Approx(1).epsilon(1e-15));
      CHECK(c.relative_det == Approx(1).epsilon(1e-15));
    }
  // --scale -1,1,1 is orthogonal with det -1: a rotation path with a mirror.
  const AffineClass m = classify_affine(scale_map({-1, 1, 1}));
  CHECK(m.path == TransformPath::Rotation);
  CHECK(m.mirror);
  CHECK(m.det == -1.0);
  // Ten composed rotations stay within the orthogonality tolerance.
  std::vector<Affine3d> maps;
  for (int i = 0; i < 10; ++i) maps.push_back(rotation_map(17.0 * i + 3, {1.0 * i, 1, -2}));
  CHECK(classify_affine(compose_in_order(maps)).path == TransformPath::Rotation);
}

TEST_CASE("classify_affine: uniform scale with rotation, at any magnitude", "[classify_affine]") {
  const Affine3d R = rotation_map(40, {1, 1, 0});
  for (double s : {2.0, 0.001, 1e200, 1e-200, -3.0}) {
    const AffineClass c = classify_affine(scaled(R, s));
    CAPTURE(s);
    CHECK(c.path == TransformPath::UniformScale);
    CHECK(c.mirror == (s < 0));
    CHECK(c.relative_det == Approx(1).epsilon(1e-14));  // no overflow at 1e200, no underflow at 1e-200
    CHECK(c.uniform_scale == Approx(std::fabs(s)).epsilon(1e-15));
  }
}

TEST_CASE("classify_affine: general maps and relative_det by hand", "[classify_affine]") {
  // diag(1,2,3): det 6, ||A||_F^2 = 14, relative_det = 6 / (14/3)^(3/2) = 0.5951...
  const AffineClass d = classify_affine(scale_map({1, 2, 3}));
  CHECK(d.path == TransformPath::General);
  CHECK_FALSE(d.mirror);
  CHECK(d.det == 6.0);
  CHECK(d.relative_det == Approx(6.0 / std::pow(14.0 / 3.0, 1.5)).epsilon(1e-15));
  // Shear [[1, 1, 0], [0, 1, 0], [0, 0, 1]]: det 1, ||A||_F^2 = 4: relative_det = (3/4)^(3/2).
  const AffineClass s = classify_affine(with_A(1, 1, 0, 0, 1, 0, 0, 0, 1));
  CHECK(s.path == TransformPath::General);
  CHECK(s.relative_det == Approx(std::pow(0.75, 1.5)).epsilon(1e-15));
  // Mirror of a general map.
  const AffineClass g = classify_affine(scale_map({1, -2, 3}));
  CHECK(g.path == TransformPath::General);
  CHECK(g.mirror);
  CHECK(g.det == -6.0);
  // Scale invariance: the same class and relative_det at 1e300 and 1e-300.
  for (double k : {1e300, 1e-300}) {
    const AffineClass c = classify_affine(scaled(scale_map({1, 2, 3}), k));
    CHECK(c.path == TransformPath::General);
    CHECK(c.relative_det == Approx(d.relative_det).epsilon(1e-15));
  }
}

TEST_CASE("classify_affine: singular and near-singular maps", "[classify_affine]") {
  CHECK(classify_affine(scale_map({1, 1, 0})).path == TransformPath::Singular);
  CHECK(classify_affine(scale_map({0, 0, 0})).path == TransformPath::Singular);
  // Rank 2 but dense: rows 1 and 2 sum to row 3.
  CHECK(classify_affine(with_A(1, 2, 3, 4, 5, 6, 5, 7, 9)).path == TransformPath::Singular);
  // diag(1, 1, e): relative_det = e / ((2 + e^2) / 3)^(3/2) ~ 1.837 e. Refused below 1e-9.
  CHECK(classify_affine(scale_map({1, 1, 1e-10})).path == TransformPath::Singular);
  CHECK(classify_affine(scale_map({1, 1, 1e-9})).path == TransformPath::General);  // 1.8e-9
  CHECK(classify_affine(scale_map({1, 1, 1e-6})).path == TransformPath::General);
  // A mirror-flattening keeps its sign: det < 0.
  CHECK(classify_affine(scale_map({1, -1, 1e-12})).mirror);
}

TEST_CASE("classify_affine refuses non-finite entries", "[classify_affine]") {
  Affine3d M;
  M.A.m[1][2] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(classify_affine(M), Error);
  Affine3d T;
  T.t.y = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(classify_affine(T), Error);
}

TEST_CASE("path_name names every path", "[classify_affine]") {
  CHECK(std::string(path_name(TransformPath::Identity)) == "identity");
  CHECK(std::string(path_name(TransformPath::Translation)) == "translation");
  CHECK(std::string(path_name(TransformPath::Rotation)) == "rotation");
  CHECK(std::string(path_name(TransformPath::UniformScale)) == "uniform-scale");
  CHECK(std::string(path_name(TransformPath::General)) == "general");
  CHECK(std::string(path_name(TransformPath::Singular)) == "singular");
}
