// render/engine/depth_row_lanes.h: the depth test of a triangle over a row of samples, four at a
// time, against the definition written out here with 64-bit integer edge functions (fill_rule.h)
// as tile_raster.cpp's scalar loop does: the same owners, depths and barycentrics bit for bit,
// over random triangles drawn on top of each other (some samples already owned, some not).
#include <catch2/catch.hpp>

#include <limits>
#include <random>
#include <vector>

#include <shadetool/render/engine/depth_row_lanes.h>
#include <shadetool/render/fill_rule.h>

using namespace shadetool;
using namespace shadetool::render_engine;

TEST_CASE("depth_row_lanes gives the scalar depth test's owners, depths and barycentrics bit for bit",
          "[render][depth]") {
  constexpr int kRow = 45;  // samples in the row: not a multiple of four
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coord(-20 * 256, (kRow + 20) * 256), yc(-40 * 256, 40 * 256);
  std::uniform_real_distribution<double> zd(-1, 1);
  std::vector<ScreenTriangle> tris(400);
  std::vector<double> depth_a(kRow), depth_b(kRow), l1_a(kRow), l1_b(kRow), l2_a(kRow), l2_b(kRow);
  std::vector<const ScreenTriangle*> owner_a(kRow, nullptr), owner_b(kRow, nullptr);
  std::size_t lanes_taken = 0, written = 0;
  for (ScreenTriangle& t : tris) {
    std::int64_t X[3], Y[3];
    do {
      for (int i = 0; i < 3; ++i) X[i] = coord(rng), Y[i] = yc(rng);
    } while (orient(X[0], Y[0], X[1], Y[1], X[2], Y[2]) <= 0);
    for (int i = 0; i < 3; ++i) t.X[i] = std::int32_t(X[i]), t.Y[i] = std::int32_t(Y[i]), t.z[i] = zd(rng);
    if (!depth_row_lanes_exact(t)) continue;
    ++lanes_taken;
    const std::int64_t area = orient(X[0], Y[0], X[1], Y[1], X[2], Y[2]);
    const double inv_area = 1.0 / double(area);
    const std::int64_t bias[3] = {top_left_bias(X[1], Y[1], X[2], Y[2]), top_left_bias(X[2], Y[2], X[0], Y[0]),
                                  top_left_bias(X[0], Y[0], X[1], Y[1])};
    const std::int64_t px = 128, py = 128;  // the row: samples (0..kRow-1, 0)
    const std::int64_t E0[3] = {orient(X[1], Y[1], X[2], Y[2], px, py), orient(X[2], Y[2], X[0], Y[0], px, py),
                                orient(X[0], Y[0], X[1], Y[1], px, py)};
    const std::int64_t step[3] = {-(Y[2] - Y[1]) * 256, -(Y[0] - Y[2]) * 256, -(Y[1] - Y[0]) * 256};
    // the definition
    for (int s = 0; s < kRow; ++s) {
      std::int64_t E[3];
      bool inside = true;
      for (int i = 0; i < 3; ++i) E[i] = E0[i] + s * step[i], inside = inside && E[i] + bias[i] - 1 >= 0;
      if (!inside) continue;
      const double l0 = double(E[0]) * inv_area, l1 = double(E[1]) * inv_area, l2 = double(E[2]) * inv_area;
      const double z = l0 * t.z[0] + l1 * t.z[1] + l2 * t.z[2];
      if (z < (owner_a[s] ? depth_a[s] : std::numeric_limits<double>::infinity())) {
        depth_a[s] = z, owner_a[s] = &t, l1_a[s] = l1, l2_a[s] = l2;
        ++written;
      }
    }
    DepthRow row{{double(E0[0]), double(E0[1]), double(E0[2])},
                 {double(step[0]), double(step[1]), double(step[2])},
                 {bias[0], bias[1], bias[2]},
                 inv_area,
                 {t.z[0], t.z[1], t.z[2]}};
    depth_row_lanes(row, kRow, &t, depth_b.data(), owner_b.data(), l1_b.data(), l2_b.data());
    for (int s = 0; s < kRow; ++s) {
      INFO("triangle " << (&t - tris.data()) << " sample " << s);
      REQUIRE(owner_b[s] == owner_a[s]);
      if (!owner_a[s]) continue;
      REQUIRE(depth_b[s] == depth_a[s]);
      REQUIRE(l1_b[s] == l1_a[s]);
      REQUIRE(l2_b[s] == l2_a[s]);
    }
  }
  if (lanes_taken == 0) WARN("no AVX2 here: the lanes are not used, nothing compared");
  CHECK((lanes_taken == 0 || written > 100));  // the test drew something
}
