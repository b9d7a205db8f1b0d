// lighting_test_util.h: small helpers shared by the lighting tests (no lighting logic here).
#pragma once

#include <vector>

#include <catch2/catch.hpp>

#include <shadetool/core/vec3.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/shade_points.h>

namespace shadetool::testing {

// The colour of one object-space point with normal n, through the library's public entry point.
inline Vec3d shade_one(const Scene& scene, const Vec3d& p, const Vec3d& n, ShadeOptions options = {},
                       ShadeReport* report = nullptr) {
  const std::vector<double> P{p.x, p.y, p.z}, N{n.x, n.y, n.z};
  const std::vector<double> c = shade_points(scene, P, N, options, report);
  return {c[0], c[1], c[2]};
}

// Every counter of got equals want's (one CHECK per field, so a failure names the counter).
inline void check_same_counters(const ShadeCounters& got, const ShadeCounters& want) {
  CHECK(got.points == want.points);
  CHECK(got.vertex_light_evaluations == want.vertex_light_evaluations);
  CHECK(got.back_facing == want.back_facing);
  CHECK(got.outside_cone == want.outside_cone);
  CHECK(got.at_light == want.at_light);
  CHECK(got.zero_normals == want.zero_normals);
  CHECK(got.below_horizon == want.below_horizon);
  CHECK(got.inside_light == want.inside_light);
  CHECK(got.shadowed == want.shadowed);
}

// A scene with nothing in it: no ambient, no emission, black material ambient; tests add what
// they check, so each expected value has only the terms written out in the test.
inline Scene dark_scene(ShadingModel model) {
  Scene s;
  s.model = model;
  s.global_ambient = {0, 0, 0};
  s.material.ambient = {0, 0, 0};
  s.material.diffuse = {0, 0, 0};
  s.material.specular = {0, 0, 0};
  s.material.emission = {0, 0, 0};
  return s;
}

inline Light directional(const Vec3d& direction, const Vec3d& color = {1, 1, 1}) {
  Light L;
  L.type = LightType::Directional;
  L.direction = direction;
  L.diffuse = L.specular = color;
  return L;
}

inline Light point_light(const Vec3d& position, const Vec3d& attenuation = {1, 0, 0}, const Vec3d& color = {1, 1, 1}) {
  Light L;
  L.type = LightType::Point;
  L.position = position;
  L.attenuation = attenuation;
  L.diffuse = L.specular = color;
  return L;
}

inline Light spot_light(const Vec3d& position, const Vec3d& direction, double cutoff, double exponent) {
  Light L;
  L.type = LightType::Spot;
  L.position = position;
  L.direction = direction;
  L.cutoff_degrees = cutoff;
  L.exponent = exponent;
  return L;
}

// A sky light: radiance `sky` over the hemisphere about `up`, `ground` below it.
inline Light sky_light(const Vec3d& up, const Vec3d& sky, const Vec3d& ground) {
  Light L;
  L.type = LightType::Sky;
  L.up = up;
  L.diffuse = L.specular = sky;
  L.ground = ground;
  L.ambient = {0, 0, 0};
  return L;
}

inline Affine3d camera_at(const Vec3d& eye) {  // a view whose eye is `eye` (translation only)
  Affine3d V;
  V.t = -eye;
  return V;
}

// Blinn-Phong with a camera and one light of each kind (directional, point with attenuation,
// 30-degree spot): a scene that exercises every term and every skip decision.
inline Scene three_light_scene() {
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

}  // namespace shadetool::testing
