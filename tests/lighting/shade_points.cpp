// shade_points: the same colours for any number of threads; malformed inputs refused at the entry.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "lighting/shade_points.h"
#include "lighting_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

Scene lit_scene() {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.diffuse = {0.8, 0.6, 0.4};
  s.material.specular = {1, 1, 1};
  s.material.shininess = 16;
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 0, 5});
  s.lights = {directional({0, -1, -1}), point_light({2, 2, 2}, {1, 0.1, 0.01}),
              spot_light({0, 3, 0}, {0, -1, 0}, 30, 8)};
  return s;
}

}  // namespace

TEST_CASE("results do not depend on the number of threads", "[lighting][shade_points]") {
  AnalyticMesh t = torus(200, 100);  // 20000 points: several TBB blocks
  std::vector<double> N;
  for (const Vec3d& n : t.exact_normals) N.insert(N.end(), {n.x, n.y, n.z});
  const Scene s = lit_scene();
  ShadeOptions serial, parallel;
  serial.parallel = false;
  ShadeReport a, b;
  CHECK(shade_points(s, t.mesh.positions, N, serial, &a) == shade_points(s, t.mesh.positions, N, parallel, &b));
  CHECK(a.counters.vertex_light_evaluations == b.counters.vertex_light_evaluations);
  CHECK(a.counters.back_facing == b.counters.back_facing);
}

TEST_CASE("points and normals must both be #P by 3", "[lighting][shade_points]") {
  const Scene s = lit_scene();
  CHECK_THROWS_AS(shade_points(s, {0, 0, 0, 1}, {0, 0, 1, 0}), std::invalid_argument);
  CHECK_THROWS_AS(shade_points(s, {0, 0, 0}, {0, 0, 1, 0, 0, 1}), std::invalid_argument);
  CHECK(shade_points(s, {}, {}).empty());
}
