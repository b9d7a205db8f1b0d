// shade_point.h: the lit colour of one point at a time, for callers that make their points
// themselves (a renderer, per pixel). The same equation and the same bits as shade_points.h in
// world space: lighting_equation.h for the formulas, engine/shade_point.h for the loop.
//
// Inputs:  scene           lighting/scene.h, validated (read_scene.h's ranges)
//          model           the scene's unless given
//          position_world  the point, world space
//          normal_world    its normal, world space, any length (a zero or non-finite normal leaves
//                          only the emission and ambient terms)
// Output:  linear RGB, unclamped. V = normalize(eye - p) with the scene's eye (eye_world).
//
// Usage:   const PointLighting lit = prepare_point_lighting(scene);
//          for each pixel: Vec3d c = shade_point(lit, p_world, n_world);
// prepare_point_lighting does the per-scene work once (plan_lighting, the lights brought into
// world space); shade_point only reads it, so any number of threads may call it at once.
#pragma once

#include <cstddef>
#include <optional>

#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/shade_points.h>
#include <shadetool/lighting/shading_space.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct PointLighting {
  ShadingModel model = ShadingModel::BlinnPhong;
  LightingPlan plan;
  ShadingFrame frame;  // world space (metric: identity)
  bool two_sided = false;
  double shininess = 0;
};

PointLighting prepare_point_lighting(const Scene& scene, std::optional<ShadingModel> model = std::nullopt);

// counters, when given, are added to (points, light evaluations, skips; shade_points.h).
Vec3d shade_point(const PointLighting& lighting, const Vec3d& position_world, const Vec3d& normal_world,
                  ShadeCounters* counters = nullptr);

// With shadows: visibility is this point's row of light_visibility.h's output for lighting.plan
// (2 values per kept light: its visible fraction, then a sky's ground's), multiplying each light's
// diffuse and specular terms as shade_points' ShadeOptions::visibility does. All ones give
// shade_point's bits.
Vec3d shade_point_shadowed(const PointLighting& lighting, const Vec3d& position_world, const Vec3d& normal_world,
                           const double* visibility, ShadeCounters* counters = nullptr);

// count points at once, as structure of arrays (world space; each pointer #count).
struct PointBlock {
  std::size_t count = 0;
  const double *px = nullptr, *py = nullptr, *pz = nullptr;
  const double *nx = nullptr, *ny = nullptr, *nz = nullptr;
};

// shade_point for every point of block, into rgb_out (#count by 3). Where the CPU has AVX2 and FMA
// and every light is directional, point or spot, four points at a time (engine/shade_point_lanes.h):
// the same bits as shade_point, powers included (lighting_equation.h's lighting_power, whose
// four-wide form the lanes compute; tested in tests/lighting/shade_point.cpp); otherwise
// shade_point point by point.
void shade_point_block(const PointLighting& lighting, const PointBlock& block, double* rgb_out,
                       ShadeCounters* counters = nullptr);

}  // namespace shadetool
#pragma GCC visibility pop
