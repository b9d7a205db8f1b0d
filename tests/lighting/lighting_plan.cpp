// Skips: what the plan leaves out for each reason, the counters of what was evaluated, and that
// turning every skip off changes no bit of any colour.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include <shadetool/lighting/engine/skip_options.h>
#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/shade_points.h>
#include "lighting_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

Scene lit_scene() {
  Scene s = three_light_scene();
  s.material.ambient = {0.2, 0.2, 0.2};
  return s;
}

}  // namespace

TEST_CASE("specular is skipped for lambert, zero ks, or lights without specular", "[lighting][plan]") {
  Scene s = lit_scene();
  LightingPlan p = plan_lighting(s, ShadingModel::BlinnPhong);
  CHECK(p.specular);
  CHECK(p.view);

  p = plan_lighting(s, ShadingModel::Lambert);
  CHECK_FALSE(p.specular);
  CHECK(p.specular_skip_reason == "model is lambert");
  CHECK_FALSE(p.view);  // nothing else reads V

  s.material.specular = {0, 0, 0};
  p = plan_lighting(s, ShadingModel::Phong);
  CHECK_FALSE(p.specular);
  CHECK(p.specular_skip_reason == "material specular is zero");

  s = lit_scene();
  for (Light& L : s.lights) L.specular = {0, 0, 0};
  p = plan_lighting(s, ShadingModel::BlinnPhong);
  CHECK_FALSE(p.specular);
  CHECK(p.specular_skip_reason == "every light's specular is zero");

  // two-sided reads V even without specular
  s.two_sided = true;
  CHECK(plan_lighting(s, ShadingModel::Lambert).view);
}

TEST_CASE("dark lights are dropped, ambient lights folded into the constant term", "[lighting][plan]") {
  Scene s = lit_scene();
  s.material.specular = {0, 0, 0};
  s.material.diffuse = {1, 0, 0};
  Light green = point_light({1, 1, 1}, {1, 0, 0}, {0, 1, 0});  // kd*d = (1,0,0)*(0,1,0) = 0, ka*a = 0
  Light black = directional({0, 0, -1}, {0, 0, 0});
  Light amb;
  amb.type = LightType::Ambient;
  amb.ambient = {0.5, 0.5, 0.5};
  s.lights = {green, black, directional({0, 0, -1}), amb};
  s.global_ambient = {0.1, 0.1, 0.1};
  const LightingPlan p = plan_lighting(s, ShadingModel::BlinnPhong);
  CHECK(p.dark_lights_dropped == 2);
  REQUIRE(p.lights.size() == 1);
  CHECK(p.lights[0] == 2);
  // base = emission + ka * (global + ambient light) = 0.2 * (0.1 + 0.5) = 0.12
  CHECK(p.base.x == Approx(0.12));
  CHECK_FALSE(p.positions);  // one directional light, no V: positions never read

  const LightingPlan all = plan_lighting(s, ShadingModel::BlinnPhong, SkipOptions::none());
  CHECK(all.dark_lights_dropped == 0);
  CHECK(all.lights.size() == 3);
}

TEST_CASE("counters: vertex-light evaluations, back-facing and outside-cone stops", "[lighting][plan]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {1, 1, 1};
  s.lights = {directional({0, 0, -1}), spot_light({0, 0, 4}, {0, 0, -1}, 30, 1)};
  // Four points on z = 0: two facing up (+z), one facing down, one up but outside the cone.
  const std::vector<double> P{0, 0, 0, 1, 0, 0, 0, 0, 0, 10, 0, 0};
  const std::vector<double> N{0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 1};
  ShadeReport r;
  ShadeOptions o;
  o.space = ShadingSpace::World;
  const auto c = shade_points(s, P, N, o, &r);
  CHECK(r.counters.points == 4);
  CHECK(r.counters.vertex_light_evaluations == 8);  // 4 points x 2 lights
  CHECK(r.counters.back_facing == 2);               // the down-facing point, for both lights
  CHECK(r.counters.outside_cone == 1);              // (10,0,0): 68 degrees off the axis
  CHECK(has(r.skipped, "specular"));
  CHECK(has(r.skipped, "view_vector"));
  CHECK(has(r.skipped, "transforms"));  // M is the identity
  CHECK(c[3 * 2] == 0);                 // the down-facing point is black
  CHECK(c[3 * 3] == Approx(1.0));       // outside the cone: the directional light only
}

TEST_CASE("turning every skip off changes no bit of the result", "[lighting][plan]") {
  AnalyticMesh e = uv_ellipsoid(20, 12, 1, 0.7, 0.5);
  std::vector<double> N;
  for (const Vec3d& n : e.exact_normals) N.insert(N.end(), {n.x, n.y, n.z});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 12; ++trial) {
    Scene s = lit_scene();
    s.model = trial % 3 == 0 ? ShadingModel::Lambert : trial % 3 == 1 ? ShadingModel::Phong : ShadingModel::BlinnPhong;
    s.two_sided = trial % 2 == 1;
    if (trial % 4 == 2) s.material.specular = {0, 0, 0};
    s.lights.push_back(point_light({u(rng), u(rng), 3}, {1, 0, 0}, {0, 0, 0}));  // a dark light
    if (trial >= 6) {  // a sheared, translated M: transforms and metric
      s.world_from_object.A.m = {{{1, 0.4, 0}, {0, 2, 0.3}, {0, 0, 0.5}}};
      s.world_from_object.t = {0.2, -0.3, 0.1};
    }
    for (ShadingSpace space : {ShadingSpace::World, ShadingSpace::Camera, ShadingSpace::Object}) {
      ShadeOptions options;
      options.space = space;
      ShadeReport r_on, r_off;
      const auto a = shade_points(s, e.mesh.positions, N, options, &r_on);
      const auto b = shade_points(s, e.mesh.positions, N, options, SkipOptions::none(), &r_off);
      INFO("trial " << trial << " space " << shading_space_name(space));
      CHECK(a == b);
      CHECK(r_on.counters.vertex_light_evaluations < r_off.counters.vertex_light_evaluations);  // the dark light
      CHECK_FALSE(has(r_off.skipped, "dark_lights"));
      CHECK_FALSE(has(r_off.skipped, "view_vector"));
      CHECK(has(r_off.skipped, "specular") == (s.model == ShadingModel::Lambert));  // no term to compute
    }
  }
}
