// Tests of visibility/engine/cosine_directions.h and the batched tracing of engine/cosine_rays.h
// against the scalar definitions they must reproduce bit for bit: sample_sequence.h's
// scrambled_sobol_2d (Burley 2020, listing 5, written out) and cosine_hemisphere, rotated about
// the axis and rounded to float as ambient_occlusion.cpp did ray by ray, and count_cosine_hits
// point by point. Occlusion outputs are bytes users compare between runs and versions: a faster
// path that moved one ray would change them.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

#include <shadetool/visibility/engine/cosine_directions.h>
#include <shadetool/visibility/engine/cosine_rays.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/sample_sequence.h>
#include <shadetool/visibility/visibility_scene.h>
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::visibility_engine;

namespace {

std::uint32_t bits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

// The scalar definition: ray k's float direction about unit n, as ambient_occlusion.cpp made it.
Vec3f scalar_direction(const Vec3d& n, std::uint32_t seed, std::uint32_t k) {
  Vec3d t, b;
  visibility::orthonormal_basis(n, t, b);
  const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(k, seed);
  const Vec3d w = visibility::cosine_hemisphere(s.u, s.v);
  return Vec3f(t * w.x + b * w.y + n * w.z);
}

Vec3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const Vec3d v{g(rng), g(rng), g(rng)};
    const double l = length(v);
    if (l > 1e-3) return v * (1.0 / l);  // divisor checked
  }
}

}  // namespace

TEST_CASE("The shortened Sobol steps give scrambled_sobol_2d's bits for any index and seed") {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200000; ++trial) {
    const std::uint32_t index = trial < 4096 ? std::uint32_t(trial) : rng(), seed = rng();
    std::uint32_t x, y;
    scrambled_sobol_2d_bits(index, seed, visibility::hash_combine(seed, 0), visibility::hash_combine(seed, 1), x, y);
    const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(index, seed);
    REQUIRE(double(x) / 4294967296.0 == s.u);
    REQUIRE(double(y) / 4294967296.0 == s.v);
  }
  // The byte tables against the generator-matrix loop, on every single bit and random words.
  for (std::uint32_t k = 0; k < 32; ++k)
    REQUIRE(reversed_sobol_dimension_1(1u << k) == visibility::reverse_bits(visibility::sobol_dimension_1(1u << k)));
  for (int trial = 0; trial < 100000; ++trial) {
    const std::uint32_t i = rng();
    REQUIRE(reversed_sobol_dimension_1(i) == visibility::reverse_bits(visibility::sobol_dimension_1(i)));
  }
}

TEST_CASE("cosine_directions gives the scalar directions bit for bit, for any axis, seed and run of indices") {
  std::mt19937_64 rng(11);
  std::vector<Vec3d> axes = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0.6, 0, -0.8}};
  for (int i = 0; i < 300; ++i) axes.push_back(random_unit(rng));
  const std::uint32_t firsts[] = {0, 1, 63, 64, 1000, 65536 - 17, 0xFFFFFFC0u};
  float dx[kDirectionBlock], dy[kDirectionBlock], dz[kDirectionBlock];
  std::size_t checked = 0;
  for (const Vec3d& n : axes)
    for (const std::uint32_t first : firsts) {
      CosineFrame f;
      f.seed = std::uint32_t(rng());
      f.n = n;
      visibility::orthonormal_basis(n, f.t, f.b);
      const std::uint32_t count = 1 + std::uint32_t(rng() % kDirectionBlock);
      cosine_directions(f, first, count, dx, dy, dz);
      for (std::uint32_t j = 0; j < count; ++j) {
        const Vec3f s = scalar_direction(n, f.seed, first + j);
        REQUIRE(bits(dx[j]) == bits(s.x));
        REQUIRE(bits(dy[j]) == bits(s.y));
        REQUIRE(bits(dz[j]) == bits(s.z));
        ++checked;
      }
    }
  REQUIRE(checked > 10000);
}

TEST_CASE("The centre of the square, where the concentric map has no angle, goes straight up the axis") {
  // x = y = 2^31 (u = v = 1/2): cosine_hemisphere returns (0, 0, 1) before dividing; the passes give
  // r = 0, phi = 0 and must land on the same float bits, for axes of both signs of z.
  const std::int32_t zero[1] = {0};
  for (const Vec3d& n : {Vec3d{0, 0, 1}, Vec3d{0, 0, -1}, Vec3d{0.48, -0.6, 0.64}, Vec3d{-0.36, 0.48, -0.8}}) {
    CosineFrame f;
    f.n = n;
    visibility::orthonormal_basis(n, f.t, f.b);
    float dx, dy, dz;
    cosine_directions_from_samples(f, zero, zero, 1, &dx, &dy, &dz);
    const Vec3d w = visibility::cosine_hemisphere(0.5, 0.5);
    REQUIRE(w == Vec3d{0, 0, 1});
    const Vec3f s(f.t * w.x + f.b * w.y + n * w.z);
    REQUIRE(bits(dx) == bits(s.x));
    REQUIRE(bits(dy) == bits(s.y));
    REQUIRE(bits(dz) == bits(s.z));
  }
}

TEST_CASE("CosineRayBatch counts each point's hits as count_cosine_hits does point by point, for any stream size") {
  // Points in the hole of a closed torus (|p| = 0.3 < R - r = 0.6) see it around them: rays near
  // the equator hit, rays near the poles escape.
  const Mesh mesh = testing::torus(48, 24, 1.0, 0.4).mesh;
  const VisibilityScene scene(mesh);
  RTCScene rtc = scene.impl().scene;
  std::mt19937_64 rng(3);
  struct Point {
    Vec3f p;
    Vec3d n;
    std::uint32_t seed;
  };
  std::vector<Point> points;
  for (int i = 0; i < 40; ++i) {
    const Vec3d n = random_unit(rng);
    points.push_back({scene.to_local(n * 0.3), n, std::uint32_t(rng())});
  }
  for (const std::uint32_t samples : {1u, 7u, 64u, 100u, 5000u}) {
    std::vector<std::uint32_t> expected;
    for (const Point& q : points) expected.push_back(count_cosine_hits(rtc, q.p, q.n, q.seed, 0, samples, INFINITY));
    for (const std::size_t capacity : {std::size_t(1), std::size_t(63), std::size_t(64), std::size_t(1000), std::size_t(kBatchRays)}) {
      std::vector<std::uint32_t> got(points.size(), ~0u);
      std::vector<std::size_t> order;
      CosineRayBatch batch(rtc, INFINITY, capacity);
      const auto done = [&](std::size_t slot, std::uint32_t hits) {
        got[slot] = hits;
        order.push_back(slot);
      };
      for (std::size_t i = 0; i < points.size(); ++i) batch.add(i, points[i].p, points[i].n, points[i].seed, samples, done);
      batch.finish(done);
      REQUIRE(got == expected);
      REQUIRE(order.size() == points.size());
      for (std::size_t i = 0; i < order.size(); ++i) REQUIRE(order[i] == i);  // in the order added
    }
    std::uint64_t total = 0;
    for (std::uint32_t h : expected) total += h;
    if (samples >= 64) REQUIRE(total > 0);                                   // the case is not trivial:
    if (samples >= 64) REQUIRE(total < std::uint64_t(samples) * points.size());  // some hit, some escape
  }
}
