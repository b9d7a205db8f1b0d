// render/engine/gouraud_run_lanes.h: Gouraud colours of a run of pixels, four at a time, against
// the per-pixel definition (tile_raster.cpp's gouraud_run scalar loop: perspective_barycentrics,
// the corners' colours summed in screen order, the box filter's 0 + c and scale, to float) bit
// for bit.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include <shadetool/render/engine/gouraud_run_lanes.h>
#include <shadetool/render/perspective_barycentrics.h>

using namespace shadetool;
using namespace shadetool::render_engine;

TEST_CASE("gouraud_run_lanes gives the per-pixel floats bit for bit", "[render][gouraud]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> c(-0.5, 2), lam(0, 1), w(0.05, 3);
  std::size_t compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Vec3d rgb[3];
    for (Vec3d& v : rgb) v = {c(rng), c(rng), c(rng)};
    const double inv_w[3] = {1 / w(rng), 1 / w(rng), 1 / w(rng)};
    const int n = trial % 23;
    const double inv_samples = trial % 3 == 0 ? 0.25 : 1.0;
    std::vector<double> l1(n), l2(n);
    for (int i = 0; i < n; ++i) l1[i] = lam(rng), l2[i] = lam(rng) * (1 - l1[i]);
    std::vector<float> out(3 * std::size_t(n) + 3, -1.0f);
    const int done = gouraud_run_lanes(rgb, inv_w, l1.data(), l2.data(), n, inv_samples, out.data());
    REQUIRE(done % 4 == 0);
    REQUIRE(done <= n);
    for (int i = 0; i < done; ++i) {
      const double lambda[3] = {1.0 - l1[i] - l2[i], l1[i], l2[i]};
      double b[3];
      perspective_barycentrics(lambda, inv_w, b);
      Vec3d s{0, 0, 0};
      for (int k = 0; k < 3; ++k) s += rgb[k] * b[k];
      Vec3d sum{0, 0, 0};
      sum += s;
      INFO("trial " << trial << " pixel " << i);
      REQUIRE(out[3 * i] == float(sum.x * inv_samples));
      REQUIRE(out[3 * i + 1] == float(sum.y * inv_samples));
      REQUIRE(out[3 * i + 2] == float(sum.z * inv_samples));
      ++compared;
    }
  }
  if (compared == 0) WARN("no AVX2 here: the lanes are not used, nothing compared");
}
