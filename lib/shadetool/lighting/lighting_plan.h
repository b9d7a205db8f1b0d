// lighting_plan.h: which terms of the lighting equation a scene needs, decided once per mesh.
//
// Inputs:  scene  (lighting/scene.h), model (the scene's, or the CLI's --model)
// Output:  LightingPlan: the lights worth evaluating per point, the constant part of the colour,
//          and whether the specular term, the view vector V and the point positions are needed.
//
// What is skipped, and why the result cannot change (each is a term that is exactly zero):
//   dark lights     a light whose every term is zero against this material (ka*a_i = 0,
//                   kd*d_i = 0 and ks*s_i = 0 or no specular): it adds att*spot*0 = 0.
//   specular        model lambert (no specular term), material ks = 0, or every kept light's
//                   specular s_i times ks is zero.
//   view vector     V = normalize(eye - p) is used only by the specular term and by two_sided.
//   positions       p is used only by V and by point/spot lights (directional lights need only n).
// Ambient lights and the global ambient are folded into `base` (emission + ka * ambient), which
// does not depend on the point.
//
// Every skip is always on here; engine/skip_options.h (internal) turns each off (everything
// computed, zeros added) so that bench/lighting can time what each saves and tests can check that
// skipping changes no bit of the result.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct LightingPlan {
  ShadingModel model = ShadingModel::BlinnPhong;
  std::vector<std::size_t> lights;  // indices into scene.lights: every kind but ambient, kept
  std::size_t dark_lights_dropped = 0;
  Vec3d base{0, 0, 0};              // emission + ka * (global ambient + sum of ambient lights)
  bool specular = false;            // evaluate the specular term at all
  std::string specular_skip_reason; // why not ("" when evaluated)
  bool view = false;                // compute V per point
  bool positions = false;           // the per-point position is read
  std::size_t positional_lights = 0;  // point and spot lights among `lights`
  std::size_t area_lights = 0;        // area and sky lights among `lights` (evaluated in world space)
};

LightingPlan plan_lighting(const Scene& scene, ShadingModel model);

// Component-wise product (colour times colour).
inline Vec3d mul(const Vec3d& a, const Vec3d& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline bool is_zero(const Vec3d& a) { return a.x == 0 && a.y == 0 && a.z == 0; }

}  // namespace shadetool
#pragma GCC visibility pop
