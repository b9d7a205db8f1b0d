// Tests of visibility/shadow_visibility.h: a disc over a plane casts the shadow geometry says it
// casts (directional and point lights), a sampled light unoccluded gives exactly 1, and a sky light
// sampled through the caller's sampler reproduces the disc's open fraction (Lambert).
#include <catch2/catch.hpp>

#include <cmath>

#include <tbb/global_control.h>

#include <shadetool/core/error.h>
#include <shadetool/visibility/sample_sequence.h>
#include <shadetool/visibility/shadow_visibility.h>
#include <shadetool/visibility/visibility_scene.h>
#include "visibility_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// A plane z = 0 of side 16 and a disc of radius 1 at height 1; points on the plane along x.
struct DiscScene {
  Mesh mesh;
  std::vector<double> points, normals;
  DiscScene() : mesh(plane_grid(8.0, 8, false)) {
    add_polygon(mesh, disc_polygon(1.0, 1.0, 128));
    for (int i = 0; i <= 60; ++i) {
      points.insert(points.end(), {-3.0 + 0.1 * i, 0.0, 0.0});
      normals.insert(normals.end(), {0.0, 0.0, 1.0});
    }
  }
  double x(std::size_t i) const { return points[3 * i]; }
};

}  // namespace

TEST_CASE("A directional light casts the disc's shadow where geometry puts it", "[visibility][shadow]") {
  const DiscScene s;
  const VisibilityScene scene(s.mesh);
  // Straight down: shadow is the disc's (128-gon's) footprint; light from 45 degrees along +x: the
  // footprint moves by -1 (height 1).
  const auto up = shadow_visibility_directional(scene, s.points, s.normals, {0, 0, 1});
  const auto slanted = shadow_visibility_directional(scene, s.points, s.normals, {1, 0, 1});
  const double inradius = std::cos(3.14159265358979323846 / 128);
  for (std::size_t i = 0; i < up.size(); ++i) {
    const double x = s.x(i);
    INFO("x = " << x);
    if (std::fabs(std::fabs(x) - 1) > 1e-6) REQUIRE(up[i] == (std::fabs(x) > inradius ? 1 : 0));
    if (std::fabs(std::fabs(x + 1) - 1) > 1e-6) REQUIRE(slanted[i] == (std::fabs(x + 1) > inradius ? 1 : 0));
  }
  // Below the surface: the ray leaves on the other side and meets nothing.
  const auto below = shadow_visibility_directional(scene, s.points, s.normals, {0, 0, -1});
  for (auto v : below) REQUIRE(v == 1);
}

TEST_CASE("A point light is blocked only by what lies between it and the point", "[visibility][shadow]") {
  const DiscScene s;
  const VisibilityScene scene(s.mesh);
  // Light at height 2 on the axis: the shadow of a radius-1 disc at height 1 has radius 2.
  const auto above = shadow_visibility_point(scene, s.points, s.normals, {0, 0, 2});
  // Light at height 0.5, under the disc: nothing between it and the plane.
  const auto under = shadow_visibility_point(scene, s.points, s.normals, {0, 0, 0.5});
  const double inradius = std::cos(3.14159265358979323846 / 128);
  for (std::size_t i = 0; i < above.size(); ++i) {
    const double x = s.x(i);
    INFO("x = " << x);
    if (std::fabs(std::fabs(x) - 2 * inradius) > 1e-3) REQUIRE(above[i] == (std::fabs(x) > 2 * inradius ? 1 : 0));
    REQUIRE(under[i] == 1);
  }
  // The light at a point itself: visible.
  REQUIRE(shadow_visibility_point(scene, {0.5, 0, 0}, {0, 0, 1}, {0.5, 0, 0})[0] == 1);
}

TEST_CASE("A sampled light with nothing in the way gives exactly 1", "[visibility][shadow]") {
  const DiscScene s;
  const VisibilityScene scene(s.mesh);
  // A square area light at height 3 far to the side (x = 40): no occluder between; weights vary.
  const LightSampler square = [](std::size_t, const Vec3d& p, double u, double v) {
    LightSample ls;
    ls.target = {40 + u, v, 3};
    const Vec3d d = ls.target - p;
    ls.weight = d.z / std::pow(dot(d, d), 1.5) * (0.5 + u);  // any positive weights
    return ls;
  };
  const auto vis = shadow_visibility_sampled(scene, s.points, s.normals, {}, square, {64, 0});
  for (double v : vis) REQUIRE(v == 1.0);
  // All weights zero: 1 by definition.
  const LightSampler none = [](std::size_t, const Vec3d&, double, double) { return LightSample{{0, 0, 5}, false, 0.0}; };
  for (double v : shadow_visibility_sampled(scene, s.points, s.normals, {}, none, {8, 0})) REQUIRE(v == 1.0);
}

TEST_CASE("A sky light sampled by the caller reproduces the disc's open fraction", "[visibility][shadow]") {
  const DiscScene s;
  const VisibilityScene scene(s.mesh);
  // Uniform hemisphere directions weighted by cos: the weighted fraction is the cosine-weighted
  // open fraction, 1 - Lambert's form factor of the disc polygon.
  const LightSampler sky = [](std::size_t, const Vec3d&, double u, double v) {
    const double z = u, r = std::sqrt(std::fmax(0.0, 1 - z * z)), phi = 2 * 3.14159265358979323846 * v;
    return LightSample{{r * std::cos(phi), r * std::sin(phi), z}, true, z};
  };
  const auto vis = shadow_visibility_sampled(scene, s.points, s.normals, {}, sky, {4096, 7});
  for (std::size_t i = 0; i < vis.size(); ++i) {
    const Vec3d p = get3(s.points, i);
    const double truth = 1 - polygon_form_factor(p, {0, 0, 1}, disc_polygon(1.0, 1.0, 128));
    INFO("x = " << p.x);
    REQUIRE(vis[i] == Approx(truth).margin(4e-3));
  }
  // Same bits with 1 and 2 threads.
  std::vector<double> one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = shadow_visibility_sampled(scene, s.points, s.normals, {}, sky, {256, 7});
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = shadow_visibility_sampled(scene, s.points, s.normals, {}, sky, {256, 7});
  }
  REQUIRE(one == two);
}

TEST_CASE("Shadow queries refuse bad input", "[visibility][shadow]") {
  const DiscScene s;
  const VisibilityScene scene(s.mesh);
  REQUIRE_THROWS_AS(shadow_visibility_directional(scene, s.points, s.normals, {0, 0, 0}), Error);
  REQUIRE_THROWS_AS(shadow_visibility_directional(scene, s.points, {0, 0, 1}, {0, 0, 1}), Error);
  REQUIRE_THROWS_AS(shadow_visibility_point(scene, s.points, s.normals, {0, std::nan(""), 1}), Error);
  REQUIRE_THROWS_AS(shadow_visibility_point(scene, {std::nan(""), 0, 0}, {0, 0, 1}, {0, 0, 1}), Error);
  const LightSampler negative = [](std::size_t, const Vec3d&, double, double) { return LightSample{{0, 0, 5}, false, -1.0}; };
  REQUIRE_THROWS_AS(shadow_visibility_sampled(scene, s.points, s.normals, {}, negative, {4, 0}), Error);
  const LightSampler ok = [](std::size_t, const Vec3d&, double, double) { return LightSample{{0, 0, 5}, false, 1.0}; };
  REQUIRE_THROWS_AS(shadow_visibility_sampled(scene, s.points, s.normals, {}, ok, {0, 0}), Error);
  REQUIRE_THROWS_AS(shadow_visibility_sampled(scene, s.points, s.normals, {1, 2}, ok, {4, 0}), Error);
  // A point without a usable normal still gets an answer (offset along the ray).
  REQUIRE(shadow_visibility_directional(scene, {0, 0, 0}, {0, 0, 0}, {0, 0, 1})[0] == 0);
  REQUIRE(shadow_visibility_directional(scene, {5, 0, 0}, {0, 0, 0}, {0, 0, 1})[0] == 1);
}
