// Tests of transform/transform_normals: the normal matrix of each path against hand-computed
// cofactors, mirrors, huge and tiny maps, and zero / non-finite normals left as they are.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/classify_affine.h>
#include <shadetool/transform/transform_normals.h>

using namespace shadetool;

namespace {
std::vector<double> map_normals(const Affine3d& M, std::vector<double> n) {
  transform_normals(n, normal_map(M, classify_affine(M)));
  return n;
}
}  // namespace

TEST_CASE("transform_normals: diag(1,2,3) maps (1,1,1)/sqrt3 to (6,3,2)/7", "[transform_normals]") {
  // cof(diag(a,b,c)) = diag(bc, ca, ab) = diag(6, 3, 2); (6,3,2) has length sqrt(36+9+4) = 7.
  const double s = 1 / std::sqrt(3.0);
  const auto n = map_normals(scale_map({1, 2, 3}), {s, s, s, 1, 0, 0, 0, 0, -1});
  CHECK(n[0] == Approx(6.0 / 7).epsilon(2e-16));
  CHECK(n[1] == Approx(3.0 / 7).epsilon(2e-16));
  CHECK(n[2] == Approx(2.0 / 7).epsilon(2e-16));
  // Axis normals stay on their axes, exactly.
  CHECK((n[3] == 1 && n[4] == 0 && n[5] == 0));
  CHECK((n[6] == 0 && n[7] == 0 && n[8] == -1));
}

TEST_CASE("transform_normals: a mirror's normals come out with sign(det) cof(A)", "[transform_normals]") {
  // diag(-1,2,3): cof = diag(6,-3,-2), det = -6 < 0, so sign(det) cof = diag(-6,3,2):
  // (1,1,1)/sqrt3 -> (-6,3,2)/7, the mirror image of the unmirrored (6,3,2)/7.
  const double s = 1 / std::sqrt(3.0);
  const auto n = map_normals(scale_map({-1, 2, 3}), {s, s, s});
  CHECK(n[0] == Approx(-6.0 / 7).epsilon(2e-16));
  CHECK(n[1] == Approx(3.0 / 7).epsilon(2e-16));
  CHECK(n[2] == Approx(2.0 / 7).epsilon(2e-16));
  // --scale -1,1,1 (orthogonal mirror, rotation path): n' = A n = (-x, y, z).
  const auto m = map_normals(scale_map({-1, 1, 1}), {0.6, 0.8, 0});
  CHECK((m[0] == -0.6 && m[1] == 0.8 && m[2] == 0));
}

TEST_CASE("transform_normals: huge and tiny maps do not overflow the cofactor", "[transform_normals]") {
  // cof(1e300 diag(1,2,3)) would be 1e600 diag(6,3,2): computed on an exactly rescaled A instead.
  const double s = 1 / std::sqrt(3.0);
  for (double k : {1e300, 1e-300}) {
    Affine3d M = scale_map({k, 2 * k, 3 * k});
    const auto n = map_normals(M, {s, s, s});
    CAPTURE(k);
    CHECK(n[0] == Approx(6.0 / 7).epsilon(4e-16));
    CHECK(n[1] == Approx(3.0 / 7).epsilon(4e-16));
    CHECK(n[2] == Approx(2.0 / 7).epsilon(4e-16));
  }
  // A normal near DBL_MAX in magnitude is still mapped, not turned into the fallback.
  const double big = 1e308;
  const auto n = map_normals(scale_map({1, 2, 3}), {big, big, big});
  CHECK(n[0] == Approx(6.0 / 7).epsilon(4e-16));
}

TEST_CASE("transform_normals: rotation and uniform scale keep length without normalising", "[transform_normals]") {
  // A normal of length 0.5 keeps length 0.5: proof that these paths do not renormalise.
  const Affine3d R = rotation_map(37, {1, -2, 0.5});
  const auto n = map_normals(R, {0.3, 0.4, 0});
  CHECK(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) == Approx(0.5).epsilon(1e-15));
  Affine3d S = R;
  for (auto& row : S.A.m)
    for (auto& x : row) x *= 7;  // 7 R: normals rotated only, by R
  REQUIRE(classify_affine(S).path == TransformPath::UniformScale);
  const auto m = map_normals(S, {0.3, 0.4, 0});
  for (int i = 0; i < 3; ++i) CHECK(m[i] == Approx(n[i]).margin(1e-15));
}

TEST_CASE("transform_normals: zero and non-finite normals are left exactly as read", "[transform_normals]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Affine3d& M : {scale_map({1, 2, 3}), rotation_map(30, {0, 1, 0})}) {
    std::vector<double> n = {0, 0, 0, nan, 0, 1, 1, inf, 0, 0, 0, 1};
    const std::vector<double> before = n;
    const std::size_t left = transform_normals(n, normal_map(M, classify_affine(M)));
    CHECK(left == 3);
    CHECK(std::memcmp(n.data(), before.data(), 9 * sizeof(double)) == 0);
    CHECK(std::isfinite(n[9] + n[10] + n[11]));
  }
}

TEST_CASE("normal_map: identity and translation leave normals untouched; singular has no map", "[transform_normals]") {
  CHECK(normal_map(Affine3d{}, classify_affine(Affine3d{})).untouched);
  const Affine3d T = translation_map({1, 2, 3});
  CHECK(normal_map(T, classify_affine(T)).untouched);
  const Affine3d S = scale_map({1, 1, 0});
  CHECK_THROWS_AS(normal_map(S, classify_affine(S)), Error);
}

TEST_CASE("transform_normals: results do not depend on how the array is split over threads", "[transform_normals]") {
  // 50000 normals (above the serial cut-off, so TBB splits the loop) against the same normals
  // mapped one at a time: bitwise equal.
  std::vector<double> n;
  for (int i = 0; i < 50000; ++i) n.insert(n.end(), {std::sin(0.1 * i), std::cos(0.37 * i), 0.5 + std::sin(0.01 * i)});
  for (const Affine3d& M : {scale_map({1, 2, 3}), rotation_map(31, {1, 2, 2})}) {
    const NormalMap map = normal_map(M, classify_affine(M));
    std::vector<double> all = n;
    transform_normals(all, map);
    bool same = true;
    for (std::size_t i = 0; i < n.size() / 3; ++i) {
      std::vector<double> one(n.begin() + 3 * i, n.begin() + 3 * i + 3);
      transform_normals(one, map);
      same = same && std::memcmp(one.data(), &all[3 * i], 3 * sizeof(double)) == 0;
    }
    CHECK(same);
  }
}
