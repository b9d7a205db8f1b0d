// render/engine/phong_point_lanes.h: Phong's point and normal for a run of samples, four at a time,
// against the per-sample definition (tile_raster.cpp's phong_point: perspective_barycentrics, the
// corners summed in screen order, unit_or_zero_normal) bit for bit, for every run length (the
// vector loop and its scalar tail), with normals that cancel to zero.
#include <catch2/catch.hpp>

#include <random>

#include <shadetool/render/engine/phong_point_lanes.h>
#include <shadetool/render/perspective_barycentrics.h>

using namespace shadetool;
using namespace shadetool::render_engine;

TEST_CASE("phong_points_run gives the per-sample point and normal bit for bit for every run length",
          "[render][phong]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2, 2), lam(0, 1), w(0.05, 3);
  for (int trial = 0; trial < 200; ++trial) {
    Vec3d cp[3], cn[3];
    for (int k = 0; k < 3; ++k) {
      cp[k] = {u(rng), u(rng), u(rng)};
      cn[k] = {u(rng), u(rng), u(rng)};
    }
    if (trial % 10 == 0) cn[1] = -cn[0], cn[2] = cn[0] * 0.0;  // cancels at some samples: a zero normal
    const double inv_w[3] = {1 / w(rng), 1 / w(rng), 1 / w(rng)};
    const std::size_t count = std::size_t(trial % 14);
    std::vector<double> l1(count), l2(count), out(6 * count + 6);
    for (std::size_t i = 0; i < count; ++i) {
      l1[i] = lam(rng), l2[i] = lam(rng) * (1 - l1[i]);
      if (trial % 10 == 0 && i % 2 == 0) l1[i] = 0.5, l2[i] = 0;  // equal weights of opposite corners, if w allows
    }
    const PointRunOut o{&out[0], &out[count], &out[2 * count], &out[3 * count], &out[4 * count], &out[5 * count]};
    phong_points_run(cp, cn, inv_w, l1.data(), l2.data(), count, o);
    for (std::size_t i = 0; i < count; ++i) {
      const double lambda[3] = {1.0 - l1[i] - l2[i], l1[i], l2[i]};
      double b[3];
      perspective_barycentrics(lambda, inv_w, b);
      Vec3d p{0, 0, 0}, n{0, 0, 0};
      for (int k = 0; k < 3; ++k) p += cp[k] * b[k], n += cn[k] * b[k];
      n = unit_or_zero_normal(n);
      INFO("trial " << trial << " sample " << i);
      REQUIRE(o.px[i] == p.x);
      REQUIRE(o.py[i] == p.y);
      REQUIRE(o.pz[i] == p.z);
      REQUIRE(o.nx[i] == n.x);
      REQUIRE(o.ny[i] == n.y);
      REQUIRE(o.nz[i] == n.z);
      // and the normal is unit or zero (the property the lighting equation relies on)
      const double len2 = dot(n, n);
      CHECK((len2 == 0 || std::fabs(len2 - 1) < 1e-15));
    }
  }
}
