// shade_point (lighting/shade_point.h), the one-point-at-a-time entry for renderers, against
// shade_points in world space: the same equation, so the same bits, for every model.
#include <catch2/catch.hpp>

#include <random>

#include <shadetool/core/mesh.h>
#include <shadetool/lighting/shade_point.h>
#include <shadetool/lighting/shade_points.h>
#include "lighting_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("shade_point gives shade_points' world-space colours bit for bit", "[lighting][shade_point]") {
  Scene scene = three_light_scene();
  scene.two_sided = true;
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<double> points, normals;
  for (int i = 0; i < 500; ++i) {
    for (int k = 0; k < 3; ++k) points.push_back(u(rng));
    for (int k = 0; k < 3; ++k) normals.push_back(u(rng));
  }
  for (ShadingModel model : {ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    ShadeOptions o;
    o.model = model;
    o.space = ShadingSpace::World;
    ShadeReport report;
    const std::vector<double> all = shade_points(scene, points, normals, o, &report);
    const PointLighting lit = prepare_point_lighting(scene, model);
    ShadeCounters counters;
    for (std::size_t i = 0; i < 500; ++i) {
      const Vec3d c = shade_point(lit, get3(points, i), get3(normals, i), &counters);
      REQUIRE(c.x == all[3 * i]);
      REQUIRE(c.y == all[3 * i + 1]);
      REQUIRE(c.z == all[3 * i + 2]);
    }
    CHECK(counters.vertex_light_evaluations == report.counters.vertex_light_evaluations);
    CHECK(counters.back_facing == report.counters.back_facing);
  }
}
