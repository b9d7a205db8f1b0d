// validate_scene.h: the one check of a built Scene against the ranges scene.h lists, which every
// way of building a Scene passes through: the JSON scene reader (lighting/read_scene.h: files and
// Python's dicts), glTF's KHR_lights_punctual lights (gltf/gltf_lights.h), and code that fills a
// Scene by hand. After it, the lighting code may rely on every range below without re-checking.
//
// Inputs:  scene  the Scene to check (lighting/scene.h)
//          name   the source for messages (a file name, "scene", "<glTF>")
//          paths  where each part was read from, for messages: ScenePaths::json() names JSON
//                 scene paths ($.lights[2].diffuse); the glTF lights name their glTF JSON paths
//                 (extensions.KHR_lights_punctual.lights[2].intensity, nodes[4])
// Output:  nothing; throws shadetool::Error "NAME: PATH: what" at the first value out of range.
//
// The ranges (scene.h):
//   colours (global ambient, material ka kd ks e, each light's a_i d_i s_i, a sky's ground):
//            every channel finite and >= 0 (no upper bound: HDR); a colour that overflowed on
//            color x intensity is caught here as not finite
//   shininess, spot exponent: finite, >= 0;  spot cutoff: [0, 90] or 180
//   attenuation: finite, >= 0, not all zero;  positions: finite
//   directions (directional, spot), a sky's up: finite and non-zero
//   area polygon: 3..kMaxAreaVertices finite vertices (planarity and convexity are the reader's,
//   read_scene.cpp's polygon_shape); area sphere: finite centre, radius > 0 and finite
//   environment: a map; world_from_object: finite, 3x3 part invertible; camera_from_world (when
//   has_camera): invertible; lens: fov_y in (0, 180), near and far 0 (fitted) or 0 < near < far,
//   orthographic height >= 0.
// require_colour and require_non_negative are those rules for one value, for readers that check
// a source value before it is combined (a glTF light's colour and intensity before their product).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include <shadetool/core/vec3.h>
#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct ScenePaths {
  // The path of a top-level Scene field ("world_from_object", "camera", "ambient", "material.diffuse").
  std::function<std::string(const std::string& field)> scene;
  // The path of field `field` ("diffuse", "position", "attenuation", ...) of scene.lights[light].
  std::function<std::string(std::size_t light, const std::string& field)> light;

  static ScenePaths json();  // $.field, $.lights[i].field
};

void validate_scene(const Scene& scene, const std::string& name, const ScenePaths& paths = ScenePaths::json());

void require_colour(const Vec3d& colour, const std::string& name, const std::string& path);
void require_non_negative(double value, const std::string& name, const std::string& path);

}  // namespace shadetool
#pragma GCC visibility pop
