// validate_scene.cpp: see validate_scene.h.
#include <shadetool/lighting/validate_scene.h>

#include <cmath>
#include <sstream>

#include <shadetool/core/affine.h>
#include <shadetool/core/error.h>
#include <shadetool/lighting/area_light.h>

namespace shadetool {

namespace {

std::string number_text(double x) {
  std::ostringstream s;
  s.precision(12);
  s << x;
  return s.str();
}

std::string vec_text(const Vec3d& v) {
  return "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
}

void require_finite_point(const Vec3d& p, const std::string& name, const std::string& path) {
  if (!is_finite(p)) fail(name, 0, path + ": must be finite, got " + vec_text(p));
}

void require_direction(const Vec3d& d, const std::string& name, const std::string& path) {
  require_finite_point(d, name, path);
  if (!(length(d) > 0)) fail(name, 0, path + ": zero-length direction");
}

void require_finite_affine(const Affine3d& M, const std::string& name, const std::string& path) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(M.A.m[r][c])) fail(name, 0, path + ": has an entry that is not finite");
    if (!std::isfinite(M.t[r])) fail(name, 0, path + ": has an entry that is not finite");
  }
}

void validate_light(const Light& L, const std::string& name, const std::function<std::string(const std::string&)>& at) {
  require_colour(L.ambient, name, at("ambient"));
  require_colour(L.diffuse, name, at("diffuse"));
  require_colour(L.specular, name, at("specular"));
  const auto attenuation = [&] {
    for (int i = 0; i < 3; ++i) require_non_negative(L.attenuation[i], name, at("attenuation"));
    if (L.attenuation == Vec3d{0, 0, 0}) fail(name, 0, at("attenuation") + ": is [0, 0, 0]: 1/(kc + kl d + kq d^2) has no finite value");
  };
  switch (L.type) {
    case LightType::Ambient:
      break;
    case LightType::Directional:
      require_direction(L.direction, name, at("direction"));
      break;
    case LightType::Point:
      require_finite_point(L.position, name, at("position"));
      attenuation();
      break;
    case LightType::Spot:
      require_finite_point(L.position, name, at("position"));
      require_direction(L.direction, name, at("direction"));
      attenuation();
      if (!((L.cutoff_degrees >= 0 && L.cutoff_degrees <= 90) || L.cutoff_degrees == 180))
        fail(name, 0, at("cutoff") + ": must be in [0, 90] degrees or 180 (no cone), got " + number_text(L.cutoff_degrees));
      require_non_negative(L.exponent, name, at("exponent"));
      break;
    case LightType::Area:
      switch (L.shape) {
        case AreaShape::Polygon:
          if (L.vertices.size() < 3 || L.vertices.size() > std::size_t(kMaxAreaVertices))
            fail(name, 0, at("vertices") + ": must be 3 to " + std::to_string(kMaxAreaVertices) + " points, got " +
                              std::to_string(L.vertices.size()));
          for (const Vec3d& v : L.vertices) require_finite_point(v, name, at("vertices"));
          break;
        case AreaShape::Sphere:
          require_finite_point(L.center, name, at("center"));
          if (!(L.radius > 0) || !std::isfinite(L.radius))
            fail(name, 0, at("radius") + ": must be > 0, got " + number_text(L.radius));
          break;
      }
      break;
    case LightType::Sky:
      require_direction(L.up, name, at("up"));
      require_colour(L.ground, name, at("ground"));
      break;
    case LightType::Environment:
      if (!L.environment) fail(name, 0, at("image") + ": an environment light needs its map");
      break;
  }
}

}  // namespace

ScenePaths ScenePaths::json() {
  ScenePaths p;
  p.scene = [](const std::string& field) { return "$." + field; };
  p.light = [](std::size_t i, const std::string& field) { return "$.lights[" + std::to_string(i) + "]." + field; };
  return p;
}

void require_colour(const Vec3d& c, const std::string& name, const std::string& path) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(c[i]))
      fail(name, 0, path + ": must be finite in every channel (beyond double's range?), got " + vec_text(c));
    if (c[i] < 0) fail(name, 0, path + ": colour channels must be >= 0, got " + vec_text(c));
  }
}

void require_non_negative(double x, const std::string& name, const std::string& path) {
  if (!std::isfinite(x)) fail(name, 0, path + ": must be a finite number, got " + number_text(x));
  if (x < 0) fail(name, 0, path + ": must be >= 0, got " + number_text(x));
}

void validate_scene(const Scene& s, const std::string& name, const ScenePaths& paths) {
  require_finite_affine(s.world_from_object, name, paths.scene("world_from_object"));
  Affine3d inverse;
  if (!invert_affine(s.world_from_object, inverse))
    fail(name, 0, paths.scene("world_from_object") + ": the 3x3 part is singular (determinant 0): the map has no inverse");
  if (s.has_camera) {
    require_finite_affine(s.camera_from_world, name, paths.scene("camera"));
    if (!invert_affine(s.camera_from_world, inverse))
      fail(name, 0, paths.scene("camera") + ": the view matrix is singular: the eye has no position");
  }
  const CameraLens& lens = s.lens;
  if (!(lens.fov_y_degrees > 0 && lens.fov_y_degrees < 180))
    fail(name, 0, paths.scene("camera.fov_y") + ": must be in (0, 180) degrees, got " + number_text(lens.fov_y_degrees));
  if (!(lens.near >= 0) || !(lens.far >= 0) || !std::isfinite(lens.far) || (lens.far > 0 && !(lens.far > lens.near)))
    fail(name, 0, paths.scene("camera.far") + ": near and far must be 0 (fitted) or 0 < near < far, got " +
                      number_text(lens.near) + ", " + number_text(lens.far));
  if (!(lens.orthographic_height >= 0) || !std::isfinite(lens.orthographic_height))
    fail(name, 0, paths.scene("camera.orthographic") + ": must be a height > 0 (world units)");
  require_colour(s.global_ambient, name, paths.scene("ambient"));
  require_colour(s.material.ambient, name, paths.scene("material.ambient"));
  require_colour(s.material.diffuse, name, paths.scene("material.diffuse"));
  require_colour(s.material.specular, name, paths.scene("material.specular"));
  require_colour(s.material.emission, name, paths.scene("material.emission"));
  require_non_negative(s.material.shininess, name, paths.scene("material.shininess"));
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    validate_light(s.lights[i], name, [&](const std::string& field) { return paths.light(i, field); });
}

}  // namespace shadetool
