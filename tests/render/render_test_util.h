// render_test_util.h: scenes, meshes and image comparisons for tests/render.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <shadetool/lighting/look_at.h>
#include <shadetool/render/render_mesh.h>
#include "support/analytic_meshes.h"

namespace shadetool::render_testing {

inline Light directional_light(const Vec3d& direction) {
  Light L;
  L.type = LightType::Directional;
  L.direction = direction;
  return L;
}

inline Light point_light(const Vec3d& position) {
  Light L;
  L.type = LightType::Point;
  L.position = position;
  L.attenuation = {1, 0.05, 0.01};
  return L;
}

// A lit scene with diffuse, specular (blinn-phong) and ambient terms, camera at `eye`.
inline Scene lit_scene(const Vec3d& eye, const Vec3d& target = {0, 0, 0}, const Vec3d& up = {0, 1, 0}) {
  Scene s;
  s.model = ShadingModel::BlinnPhong;
  s.global_ambient = {0.05, 0.05, 0.05};
  s.material.diffuse = {0.7, 0.5, 0.3};
  s.material.specular = {0.5, 0.5, 0.5};
  s.material.shininess = 24;
  s.lights = {directional_light({-1, -2, -3}), point_light({2, 3, 4})};
  look_at(eye, target, up, s.camera_from_world);
  s.has_camera = true;
  return s;
}

// Orthographic camera over the square [0, side]^2 of the plane z = 0 (world units = pixels):
// world (X, Y) lands on image column X and row side - Y, exactly (every step is dyadic).
inline Scene pixel_exact_scene(int side) {
  Scene s;
  s.global_ambient = {0.2, 0.2, 0.2};
  s.lights = {directional_light({0, 0, -1})};
  const double c = side / 2.0;
  look_at({c, c, 10}, {c, c, 0}, {0, 1, 0}, s.camera_from_world);
  s.has_camera = true;
  s.lens.orthographic_height = side;
  return s;
}

// The mean absolute difference of two images over all channels.
inline double mean_abs_difference(const ImageRGB& a, const ImageRGB& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::fabs(double(a.rgb[i]) - double(b.rgb[i]));
  return a.rgb.empty() ? 0.0 : sum / double(a.rgb.size());
}

inline double max_abs_difference(const ImageRGB& a, const ImageRGB& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) m = std::max(m, std::fabs(double(a.rgb[i]) - double(b.rgb[i])));
  return m;
}

}  // namespace shadetool::render_testing
