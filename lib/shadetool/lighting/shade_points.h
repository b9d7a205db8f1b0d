// shade_points.h: lit colours of many points of one object, in a chosen shading space.
//
// Inputs:  scene           lights, material, camera, world_from_object M (lighting/scene.h)
//          points_object   #P by 3 flat doubles, object space
//          normals_object  #P by 3 flat doubles, object space, any length (outward); a zero or
//                          non-finite normal leaves only the emission and ambient terms
//          options         model (default: the scene's), space (default auto), threads
// Output:  #P by 3 flat doubles, linear RGB, unclamped (the equation of lighting_equation.h)
//          report (optional): model and space used, what was skipped, counters
//
// Steps: plan_lighting (which terms are needed) -> choose_space (auto) -> make_frame (lights and
// eye into the space, once) -> per point: map p and n into the space unless the map is the
// identity or nothing reads them, then the equation with the space's metric.
//
// Precision: double. Parallel over points (TBB) when options.parallel; every point is computed
// independently, so the result is bitwise the same for any number of threads.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/shading_space.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// What the per-point loop (engine/shade_point.h) did and skipped, summed over points.
struct ShadeCounters {
  std::size_t points = 0;
  std::size_t vertex_light_evaluations = 0;  // (point, light) pairs entered
  std::size_t back_facing = 0;               // pairs stopped before the square root: n.L <= 0, no ambient
  std::size_t outside_cone = 0;              // pairs stopped at the spot-cone test
  std::size_t at_light = 0;                  // point exactly at a light's position
  std::size_t zero_normals = 0;              // points with a zero or non-finite normal
  std::size_t below_horizon = 0;             // area lights wholly below the point's horizon: skipped
  std::size_t inside_light = 0;              // point on an area light's plane or inside a sphere light
  std::size_t shadowed = 0;                  // shadows: pairs with visibility < 1 that the light would
                                             // light (n.L > 0; area and sky lights: any)

  ShadeCounters& operator+=(const ShadeCounters& o) {
    points += o.points;
    vertex_light_evaluations += o.vertex_light_evaluations;
    back_facing += o.back_facing;
    outside_cone += o.outside_cone;
    at_light += o.at_light;
    zero_normals += o.zero_normals;
    below_horizon += o.below_horizon;
    inside_light += o.inside_light;
    shadowed += o.shadowed;
    return *this;
  }
};

struct ShadeOptions {
  std::optional<ShadingModel> model;  // overrides scene.model
  ShadingSpace space = ShadingSpace::Auto;
  bool parallel = true;
  // Shadows (lighting/light_visibility.h computes it): null = no shadows. Otherwise #P rows of
  // 2 * plan.lights.size() values in [0, 1]: per kept light (plan order) its visible fraction,
  // then (sky lights) the ground's, 1 where unused. Multiplies each light's diffuse and specular
  // terms (ambient is not shadowed). The caller owns it for the duration of the call.
  const std::vector<double>* visibility = nullptr;
};

struct ShadeReport {
  ShadingModel model = ShadingModel::BlinnPhong;
  ShadingSpace space = ShadingSpace::World;
  std::string space_reason;            // why (auto), or "requested"
  LightingPlan plan;
  bool transforms_skipped = false;     // no per-point matrix work (object space or identity map)
  ShadeCounters counters;
  std::vector<std::string> skipped;    // names: dark_lights, specular, view_vector, positions, transforms
};

std::vector<double> shade_points(const Scene& scene, const std::vector<double>& points_object,
                                 const std::vector<double>& normals_object, const ShadeOptions& options = {},
                                 ShadeReport* report = nullptr);

}  // namespace shadetool
#pragma GCC visibility pop
