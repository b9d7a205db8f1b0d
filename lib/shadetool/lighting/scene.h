// scene.h: what bake-lighting lights a mesh with: material, lights, camera, object placement.
//
// The quantities of OpenGL 2.1's fixed-function lighting (The OpenGL Graphics System 2.1,
// section 2.14.1, "Lighting"), with the same defaults where OpenGL has one. Every position and
// direction here is in WORLD space; the mesh is in OBJECT space and world_from_object places it.
// A scene is read from JSON by lighting/read_scene.h, which validates every field; every way of
// building a Scene (JSON, glTF lights, code) passes it through lighting/validate_scene.h, the one
// check of the ranges listed per field below.
//
// Colours are linear RGB, each channel >= 0 (no upper bound: HDR light intensities are allowed).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct EnvironmentMap;  // lighting/environment_map.h

enum class ShadingModel {
  Lambert,     // ambient + diffuse, no specular term
  Phong,       // specular max(R.V, 0)^shininess, R = 2 (n.L) n - L          (Phong 1975)
  BlinnPhong,  // specular max(n.H, 0)^shininess, H = normalize(L + V)       (Blinn 1977; OpenGL)
};
// Its vocabulary (core/vocabulary.h): "lambert", "phong", "blinn-phong". parse_shading_model
// throws Error "WHAT: 'x' is not one of lambert, phong, blinn-phong".
ShadingModel parse_shading_model(std::string_view text, const std::string& what);
const char* shading_model_name(ShadingModel model);
std::vector<std::string> shading_model_names();

enum class LightType {
  Ambient,      // adds material.ambient * ambient everywhere (no position, no attenuation)
  Directional,  // at infinity; `direction` is the way the light travels (toward the scene)
  Point,        // at `position`, attenuated with distance
  Spot,         // a point light restricted to a cone around `direction`
  Area,         // a surface of constant radiance: convex polygon (rect) or sphere (issue 16)
  Sky,          // radiance `sky` above the horizon of `up`, `ground` below it (issue 16)
  Environment,  // radiance from an equirectangular HDR image around the scene (issue 16)
};
// Every switch over LightType is exhaustive with no default: a new kind does not compile
// (-Werror=switch and -Werror=switch-enum in CMakeLists.txt) until each place that reads lights
// has said what the kind does there.

enum class AreaShape {
  Polygon,  // planar convex polygon; rect is stored as one (corners center -u -v, +u -v, +u +v, -u +v)
  Sphere,   // emits outward everywhere
};

struct Light {
  LightType type = LightType::Directional;
  Vec3d position{0, 0, 0};    // world; Point and Spot
  Vec3d direction{0, 0, -1};  // world, any non-zero length; Directional (travel) and Spot (axis)
  Vec3d ambient{0, 0, 0};     // a_i  (JSON default black, as OpenGL's lights)
  Vec3d diffuse{1, 1, 1};     // d_i  (JSON default color * intensity)
  Vec3d specular{1, 1, 1};    // s_i  (JSON default color * intensity)
  double cutoff_degrees = 180;  // Spot: cone half-angle, [0, 90] or 180 (= no cone, a point light)
  double exponent = 0;          // Spot: falloff max(cos, 0)^exponent, >= 0
  Vec3d attenuation{1, 0, 0};   // Point/Spot: kc kl kq >= 0, not all zero; att = 1/(kc+kl d+kq d^2)

  // Area and Sky: `diffuse` and `specular` hold the emitted radiance L = color * intensity (Sky:
  // the sky's), `ambient` the light's a_i (default black). The equation adds
  // ka*a_i + kd*L*P + ks*L*S (lighting/area_light.h).
  AreaShape shape = AreaShape::Polygon;
  std::vector<Vec3d> vertices;  // Area Polygon, world: planar, convex, >= 3, counter-clockwise seen
                                // from the emitting side
  Vec3d center{0, 0, 0};        // Area Sphere, world
  double radius = 0;            // Area Sphere, > 0
  bool two_sided = false;       // Area Polygon: emits on both sides
  Vec3d up{0, 1, 0};            // Sky, world, non-zero
  Vec3d ground{0, 0, 0};        // Sky: radiance below the horizon (ground * intensity)
  // Environment: the image's radiance (shared, read once) rotated by world_from_map; `diffuse`
  // and `specular` hold intensity in each channel (the image's colour is in the map).
  std::shared_ptr<const EnvironmentMap> environment;  // non-null for Environment
  Mat3d world_from_map;                               // a rotation (lighting/environment_map.h)
};

struct Material {  // OpenGL's defaults (glMaterial)
  Vec3d ambient{0.2, 0.2, 0.2};   // ka
  Vec3d diffuse{0.8, 0.8, 0.8};   // kd
  Vec3d specular{0, 0, 0};        // ks
  Vec3d emission{0, 0, 0};        // e
  double shininess = 0;           // >= 0 (OpenGL caps at 128; we do not)
};

// The camera's projection, for renderers (render/camera.h); bake-lighting does not read it.
// Read from the scene's "camera" object: fov_y, near, far, orthographic.
struct CameraLens {
  double fov_y_degrees = 45;       // perspective: full vertical field of view, (0, 180)
  double near = 0, far = 0;        // 0: fitted to the mesh's bounds; given: 0 < near < far
  double orthographic_height = 0;  // > 0: orthographic, this many world units tall (fov_y unused)
};

struct Scene {
  ShadingModel model = ShadingModel::BlinnPhong;
  bool model_given = false;                   // the file named a model (the CLI's --model wins)
  Affine3d world_from_object;                 // M; its 3x3 part must be invertible
  Affine3d camera_from_world;                 // V (view matrix); must be invertible
  bool has_camera = false;                    // false: OpenGL's default eye at the world origin
  CameraLens lens;                            // projection (renderers only)
  Vec3d global_ambient{0.2, 0.2, 0.2};        // OpenGL's LIGHT_MODEL_AMBIENT default
  bool two_sided = false;                     // where n.V < 0, light the back: n -> -n
  Material material;
  std::vector<Light> lights;
};

// The eye position in world space: V^-1 (0, 0, 0). Requires V invertible (validated on read).
Vec3d eye_world(const Scene& scene);

}  // namespace shadetool
#pragma GCC visibility pop
