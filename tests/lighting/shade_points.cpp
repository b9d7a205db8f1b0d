// shade_points: the same colours for any number of threads; malformed inputs refused at the entry.
#include <catch2/catch.hpp>

#include <stdexcept>

#include <shadetool/lighting/shade_point.h>
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

TEST_CASE("polygon lights computed for blocks of points in vector lanes give the per-point path's bits and counters",
          "[lighting][shade_points][area]") {
  // shade_points batches polygon lights whose specular term is not needed (engine/lambert_lanes.h:
  // blocks of kPointLanes points); lighting/shade_point.h's shade_point evaluates one point with
  // the scalar polygon_light_terms. Points on a torus under a one-sided rect, beside a two-sided pentagon, a
  // sphere and a point light: behind, below the horizon, crossing it and wholly above; zero normals;
  // 2501 points (the last block is partial).
  AnalyticMesh t = torus(61, 41);
  std::vector<double> N;
  for (const Vec3d& n : t.exact_normals) N.insert(N.end(), {n.x, n.y, n.z});
  for (std::size_t i = 0; i < N.size(); i += 3 * 97) N[i] = N[i + 1] = N[i + 2] = 0;
  Light rect;
  rect.type = LightType::Area;
  rect.shape = AreaShape::Polygon;
  rect.vertices = {{-1, 0.5, 1.2}, {1, 0.5, 1.2}, {1, -0.5, 1.2}, {-1, -0.5, 1.2}};  // emits down (-z), at the torus
  rect.diffuse = {1, 0.8, 0.6};
  rect.specular = {0, 0, 0};  // no specular: batched in every model
  rect.ambient = {0.01, 0.01, 0.01};
  Light pentagon = rect;
  pentagon.two_sided = true;
  pentagon.vertices = {{1.5, -0.4, -0.3}, {1.5, 0.3, -0.5}, {1.5, 0.6, 0.1}, {1.5, 0.1, 0.6}, {1.5, -0.5, 0.3}};
  pentagon.specular = {0.5, 0.5, 0.5};  // batched only where the model has no lobe (Lambert)
  Light sphere = rect;
  sphere.shape = AreaShape::Sphere;
  sphere.center = {-1.5, 0, 0.5};
  sphere.radius = 0.3;
  for (ShadingModel model : {ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong})
    for (bool two_sided : {false, true}) {
      Scene s = dark_scene(model);
      s.material.diffuse = {0.8, 0.6, 0.4};
      s.material.specular = {0.5, 0.5, 0.5};
      s.material.shininess = 8;
      s.has_camera = true;
      s.camera_from_world = camera_at({0.3, 0.5, 4});
      s.two_sided = two_sided;
      s.lights = {rect, point_light({0, 2, 2}), pentagon, sphere};
      ShadeOptions o;
      o.space = ShadingSpace::World;
      o.parallel = false;
      ShadeReport report;
      const std::vector<double> got = shade_points(s, t.mesh.positions, N, o, &report);
      const PointLighting lighting = prepare_point_lighting(s);
      ShadeCounters want_counters;
      INFO("model " << shading_model_name(model) << ", two-sided " << two_sided);
      for (std::size_t i = 0; i < got.size() / 3; ++i) {
        const Vec3d p{t.mesh.positions[3 * i], t.mesh.positions[3 * i + 1], t.mesh.positions[3 * i + 2]};
        const Vec3d want = shade_point(lighting, p, Vec3d{N[3 * i], N[3 * i + 1], N[3 * i + 2]}, &want_counters);
        INFO("point " << i);
        REQUIRE(got[3 * i] == want.x);
        REQUIRE(got[3 * i + 1] == want.y);
        REQUIRE(got[3 * i + 2] == want.z);
      }
      const ShadeCounters& c = report.counters;
      check_same_counters(c, want_counters);
      CHECK(c.below_horizon > 300);  // the cases are there
      CHECK(c.zero_normals == 26);

      // Shadows: each light's visible fraction per point (0, 1 or between), batched or not.
      std::vector<double> visibility(2 * lighting.frame.lights.size() * (got.size() / 3));
      for (std::size_t i = 0; i < visibility.size(); ++i)
        visibility[i] = i % 5 == 0 ? 0.0 : i % 5 == 1 ? 1.0 : 0.125 * (i % 7);
      o.visibility = &visibility;
      ShadeReport shadowed_report;
      const std::vector<double> got_shadowed = shade_points(s, t.mesh.positions, N, o, &shadowed_report);
      ShadeCounters want_shadowed;
      const std::size_t row = 2 * lighting.frame.lights.size();
      for (std::size_t i = 0; i < got.size() / 3; ++i) {
        const Vec3d p{t.mesh.positions[3 * i], t.mesh.positions[3 * i + 1], t.mesh.positions[3 * i + 2]};
        const Vec3d want = shade_point_shadowed(lighting, p, Vec3d{N[3 * i], N[3 * i + 1], N[3 * i + 2]},
                                                visibility.data() + row * i, &want_shadowed);
        INFO("shadowed point " << i);
        REQUIRE(got_shadowed[3 * i] == want.x);
        REQUIRE(got_shadowed[3 * i + 1] == want.y);
        REQUIRE(got_shadowed[3 * i + 2] == want.z);
      }
      CHECK(shadowed_report.counters.shadowed == want_shadowed.shadowed);
      CHECK(shadowed_report.counters.shadowed > 0);
      CHECK(shadowed_report.counters.below_horizon == want_shadowed.below_horizon);
    }
}
