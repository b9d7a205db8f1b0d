// Tests of normals/weighting.h against the vectorised triangle kernels
// (normals/engine/triangle_blocks.h): the SIMD path computes the four scalar formulas.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/interior_angle.h>
#include <shadetool/geometry/scaled_length.h>
#include <shadetool/normals/engine/triangle_blocks.h>
#include <shadetool/normals/weighting.h>

using namespace shadetool;
using normals_detail::kTriangleBlock;

namespace {

// A block of random triangles: well-shaped, needles and caps (near-collinear), at scales
// 2^-40 .. 2^40. positions: 3 corners per triangle.
std::vector<Vec3d> random_triangles(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3d> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = std::ldexp(1.0, int(40 * u(rng)));
    const Vec3d a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    Vec3d c{u(rng), u(rng), u(rng)};
    if (i % 4 == 1) c = a + (b - a) * 0.3 + Vec3d{u(rng), u(rng), u(rng)} * 1e-9;  // cap
    if (i % 4 == 2) c = b + Vec3d{u(rng), u(rng), u(rng)} * 1e-9;                  // needle
    p.push_back(a * s); p.push_back(b * s); p.push_back(c * s);
  }
  return p;
}

// The block kernels' input: 9 rows of kTriangleBlock (x, y, z of corner 0, 1, 2).
void gather(const std::vector<Vec3d>& p, std::size_t first, std::size_t n, double* xyz) {
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) xyz[(3 * k + d) * kTriangleBlock + i] = p[3 * (first + i) + k][std::size_t(d)];
}

double relative(const Vec3d& got, const Vec3d& want) { return length(got - want) / length(want); }

}  // namespace

TEST_CASE("the vector pass computes weighting.h's formulas: uniform bitwise, angle within 1e-13, max within 1e-15",
          "[weighting]") {
  const std::size_t n = kTriangleBlock * 40;
  const std::vector<Vec3d> p = random_triangles(n, 11);
  std::vector<double> positions;
  for (const Vec3d& q : p) { positions.push_back(q.x); positions.push_back(q.y); positions.push_back(q.z); }
  double worst_angle = 0, worst_max = 0;
  std::size_t compared = 0, uniform_differ = 0, scalar_path = 0;
  alignas(64) double xyz[9 * kTriangleBlock], out_angle[9 * kTriangleBlock], out_max[9 * kTriangleBlock],
      out_uniform[9 * kTriangleBlock];
  for (std::size_t first = 0; first < n; first += kTriangleBlock) {
    gather(p, first, kTriangleBlock, xyz);
    normals_detail::triangle_block_angle(kTriangleBlock, xyz, out_angle);
    normals_detail::triangle_block_max(kTriangleBlock, xyz, out_max);
    normals_detail::triangle_block_uniform(kTriangleBlock, xyz, out_uniform);
    for (std::size_t i = 0; i < kTriangleBlock; ++i) {
      const std::uint32_t v0 = std::uint32_t(3 * (first + i)), v1 = v0 + 1, v2 = v0 + 2;
      const TriangleAreaVector t = triangle_area_vector(positions.data(), v0, v1, v2);
      const bool degenerate = triangle_is_degenerate(t, positions.data(), v0, v1, v2);
      if (std::isnan(out_angle[i])) {  // the vector pass declined: degenerate or out of its range
        ++scalar_path;
        continue;
      }
      REQUIRE(!degenerate);  // the vector pass never takes a face the rule calls degenerate
      const double len = checked_length(t.N);
      const Vec3d n_unit = unit_normal(t.N, len);
      const Vec3d P[3] = {p[v0], p[v1], p[v2]};
      double theta[3];
      for (int k = 0; k < 3; ++k) {
        const Vec3d a = P[(k + 1) % 3] - P[k], b = P[(k + 2) % 3] - P[k];
        theta[k] = interior_angle(len, dot(a, b));  // the one interior angle; |a x b| = |N|
        Vec3d want_max;
        REQUIRE(max_contribution(t.N, 1.0, dot(a, a) * dot(b, b), want_max));
        auto row = [&](const double* out) {
          return Vec3d{out[(3 * k) * kTriangleBlock + i], out[(3 * k + 1) * kTriangleBlock + i], out[(3 * k + 2) * kTriangleBlock + i]};
        };
        if (k < 2) worst_angle = std::max(worst_angle, relative(row(out_angle), angle_contribution(n_unit, theta[k])));
        worst_max = std::max(worst_max, relative(row(out_max), want_max));
        uniform_differ += row(out_uniform) != uniform_contribution(n_unit);
        ++compared;
      }
      // third corner: pi minus the other two in the kernel, against its own angle; the error is
      // absolute (a few ulp of pi), so it is measured relative to the angle sum pi
      const Vec3d third{out_angle[6 * kTriangleBlock + i], out_angle[7 * kTriangleBlock + i], out_angle[8 * kTriangleBlock + i]};
      worst_angle = std::max(worst_angle, length(third - angle_contribution(n_unit, theta[2])) / kPi);
    }
  }
  INFO("compared " << compared << " corners, " << scalar_path << " triangles on the scalar path; worst angle "
                   << worst_angle << ", max " << worst_max);
  CHECK(compared > 2 * n);
  CHECK(uniform_differ == 0);
  CHECK(worst_angle <= 1e-13);
  CHECK(worst_max <= 1e-15);
  CHECK(worst_max > 0);  // the kernel's q-trick rounds differently: the comparison is not vacuous
}
