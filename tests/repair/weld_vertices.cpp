// Tests of weld_vertices against a brute-force O(V^2) reference of the same greedy rule.
#include <catch2/catch.hpp>

#include <random>

#include <shadetool/repair/weld_vertices.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
// Reference: vertex v joins the nearest earlier kept vertex within eps (lowest index on ties).
std::vector<std::uint32_t> brute_force(const Mesh& m, double eps) {
  std::vector<std::uint32_t> rep(m.num_vertices()), kept_index(m.num_vertices());
  std::vector<std::uint32_t> kept;
  for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
    std::uint32_t best = UINT32_MAX;
    double best_d = 0;
    for (std::uint32_t r : kept) {
      const double d = length(m.position(r) - m.position(v));
      if (d <= eps && (best == UINT32_MAX || d < best_d)) { best = r; best_d = d; }
    }
    if (best == UINT32_MAX) { kept_index[v] = std::uint32_t(kept.size()); kept.push_back(v); rep[v] = kept_index[v]; }
    else rep[v] = kept_index[best];
  }
  return rep;
}
}  // namespace

TEST_CASE("a random cloud: same clusters as the brute-force reference", "[repair][weld]") {
  Mesh m;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1), jitter(-0.004, 0.004);
  for (int i = 0; i < 1500; ++i) {
    const Vec3d p{u(rng), u(rng), u(rng)};
    m.add_vertex(p);
    if (i % 3 == 0) m.add_vertex(p + Vec3d{jitter(rng), jitter(rng), jitter(rng)});
  }
  for (double eps : {0.0, 0.002, 0.005, 0.03}) {
    Mesh w = m;
    const std::vector<std::uint32_t> expected = brute_force(m, eps);
    const WeldResult r = weld_vertices(w, eps);
    CHECK(r.old_to_new == expected);
    CHECK(w.num_vertices() == m.num_vertices() - r.removed);
  }
}

TEST_CASE("eps = 0 merges exact duplicates only; faces are remapped; attributes follow the first", "[repair][weld]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 0, 0});       // duplicate of 0
  m.add_vertex({1, 1e-300, 0});  // not a duplicate of 1
  m.add_face({0, 1, 3});
  m.add_face({2, 3, 1});
  m.vertex_normals = {0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4};
  m.vertex_colors = {0.f, 0.f, 0.f, 1.f, 1.f, 1.f, 2.f, 2.f, 2.f, 3.f, 3.f, 3.f};
  const WeldResult r = weld_vertices(m, 0.0);
  CHECK(r.removed == 1);
  CHECK(r.old_to_new == std::vector<std::uint32_t>{0, 1, 0, 2});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 1});
  CHECK(m.vertex_normals == std::vector<double>{0, 0, 1, 0, 0, 2, 0, 0, 4});
  CHECK(m.vertex_colors == std::vector<float>{0.f, 0.f, 0.f, 1.f, 1.f, 1.f, 3.f, 3.f, 3.f});
}

TEST_CASE("chains do not collapse: a ~ b ~ c with |a - c| > eps keeps a and c", "[repair][weld]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({0.6, 0, 0});
  m.add_vertex({1.2, 0, 0});
  const WeldResult r = weld_vertices(m, 1.0);
  CHECK(r.old_to_new == std::vector<std::uint32_t>{0, 0, 1});
}

TEST_CASE("a tiny eps on a huge extent still finds neighbours (cells wider than eps)", "[repair][weld]") {
  Mesh m;
  m.add_vertex({-1e12, 0, 0});
  m.add_vertex({1e12, 0, 0});
  m.add_vertex({0.5, 0.5, 0.5});
  m.add_vertex({0.5 + 1e-7, 0.5, 0.5});
  const WeldResult r = weld_vertices(m, 1e-6);
  CHECK(r.old_to_new == std::vector<std::uint32_t>{0, 1, 2, 2});
}

TEST_CASE("negative or NaN eps is refused", "[repair][weld]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  CHECK_THROWS(weld_vertices(m, -1));
  CHECK_THROWS(weld_vertices(m, std::numeric_limits<double>::quiet_NaN()));
}
