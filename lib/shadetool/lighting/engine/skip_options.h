// engine/skip_options.h (internal: not installed): the switches that turn each of lighting_plan.h's
// skips off, and the entry points that take them. Every skip drops a term that is exactly zero, so
// turning one off (everything computed, zeros added) changes no bit: bench/lighting times what each
// saves, and tests/lighting checks that the result is the same. The public entry points
// (plan_lighting, choose_space, make_frame, shade_points without a SkipOptions) are these with
// every skip on; a library user has no switch to turn, so none is in the public ShadeOptions.
#pragma once

#include <vector>

#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/shade_points.h>
#include <shadetool/lighting/shading_space.h>

namespace shadetool {

struct SkipOptions {
  bool dark_lights = true;     // drop lights with a zero product with the material
  bool specular = true;        // no specular work when it is zero
  bool view_vector = true;     // no V when nothing reads it
  bool early_tests = true;     // back-facing and spot-cone tests before attenuation, pow, specular
  bool identity_transform = true;  // an exactly-identity object-to-space map is not applied
  bool unused_positions = true;    // points are not transformed when nothing reads them

  static SkipOptions none() { return {false, false, false, false, false, false}; }
};

LightingPlan plan_lighting(const Scene& scene, ShadingModel model, const SkipOptions& skips);
SpaceChoice choose_space(const Scene& scene, const LightingPlan& plan, const SkipOptions& skips);
ShadingFrame make_frame(const Scene& scene, const LightingPlan& plan, ShadingSpace space, const SkipOptions& skips);
std::vector<double> shade_points(const Scene& scene, const std::vector<double>& points_object,
                                 const std::vector<double>& normals_object, const ShadeOptions& options,
                                 const SkipOptions& skips, ShadeReport* report = nullptr);

}  // namespace shadetool
