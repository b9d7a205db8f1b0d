// shade_points: the same colours for any number of threads; malformed inputs refused at the entry.
#include <catch2/catch.hpp>

#include <stdexcept>

#include <shadetool/lighting/shade_points.h>
#include "lighting_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("results do not depend on the number of threads", "[lighting][shade_points]") {
  AnalyticMesh t = torus(200, 100);  // 20000 points: several TBB blocks
  std::vector<double> N;
  for (const Vec3d& n : t.exact_normals) N.insert(N.end(), {n.x, n.y, n.z});
  const Scene s = three_light_scene();
  ShadeOptions serial, parallel;
  serial.parallel = false;
  ShadeReport a, b;
  CHECK(shade_points(s, t.mesh.positions, N, serial, &a) == shade_points(s, t.mesh.positions, N, parallel, &b));
  CHECK(a.counters.vertex_light_evaluations == b.counters.vertex_light_evaluations);
  CHECK(a.counters.back_facing == b.counters.back_facing);
}

TEST_CASE("points and normals must both be #P by 3", "[lighting][shade_points]") {
  const Scene s = three_light_scene();
  CHECK_THROWS_AS(shade_points(s, {0, 0, 0, 1}, {0, 0, 1, 0}), std::invalid_argument);
  CHECK_THROWS_AS(shade_points(s, {0, 0, 0}, {0, 0, 1, 0, 0, 1}), std::invalid_argument);
  CHECK(shade_points(s, {}, {}).empty());
}
