// lighting_test_util.h: small helpers shared by the lighting tests (no lighting logic here).
#pragma once

#include <vector>

#include "core/vec3.h"
#include "lighting/scene.h"
#include "lighting/shade_points.h"

namespace shadetool::testing {

// The colour of one object-space point with normal n, through the library's public entry point.
inline Vec3d shade_one(const Scene& scene, const Vec3d& p, const Vec3d& n, ShadeOptions options = {},
                       ShadeReport* report = nullptr) {
  const std::vector<double> P{p.x, p.y, p.z}, N{n.x, n.y, n.z};
  const std::vector<double> c = shade_points(scene, P, N, options, report);
  return {c[0], c[1], c[2]};
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

inline Affine3d camera_at(const Vec3d& eye) {  // a view whose eye is `eye` (translation only)
  Affine3d V;
  V.t = -eye;
  return V;
}

}  // namespace shadetool::testing
