// shade_point.cpp: see shade_point.h.
#include <shadetool/lighting/shade_point.h>

#include <shadetool/lighting/engine/shade_point.h>
#include <shadetool/lighting/engine/shade_point_lanes.h>

namespace shadetool {

PointLighting prepare_point_lighting(const Scene& scene, std::optional<ShadingModel> model) {
  PointLighting lit;
  lit.model = model ? *model : scene.model;
  lit.plan = plan_lighting(scene, lit.model);
  lit.frame = make_frame(scene, lit.plan, ShadingSpace::World);
  lit.two_sided = scene.two_sided;
  lit.shininess = scene.material.shininess;
  return lit;
}

namespace {

lighting_engine::EquationSetup equation_setup(const PointLighting& lighting) {
  lighting_engine::EquationSetup eq;
  eq.model = lighting.model;
  eq.specular = lighting.plan.specular;
  eq.view = lighting.plan.view;
  eq.two_sided = lighting.two_sided;
  eq.shininess = lighting.shininess;
  eq.base = lighting.plan.base;
  return eq;
}

}  // namespace

Vec3d shade_point(const PointLighting& lighting, const Vec3d& position_world, const Vec3d& normal_world,
                  ShadeCounters* counters) {
  const lighting_engine::EquationSetup eq = equation_setup(lighting);
  ShadeCounters local;
  const Vec3d c = lighting_engine::shade_point_in_space<true, false>(lighting_engine::IdentityMetric{}, lighting.frame, eq,
                                                              position_world, normal_world, counters ? *counters : local);
  return c;
}

Vec3d shade_point_shadowed(const PointLighting& lighting, const Vec3d& position_world, const Vec3d& normal_world,
                           const double* visibility, ShadeCounters* counters) {
  const lighting_engine::EquationSetup eq = equation_setup(lighting);
  ShadeCounters local;
  return lighting_engine::shade_point_in_space<true, true>(lighting_engine::IdentityMetric{}, lighting.frame, eq,
                                                          position_world, normal_world, counters ? *counters : local,
                                                          visibility);
}

void shade_point_block(const PointLighting& lighting, const PointBlock& block, double* rgb_out, ShadeCounters* counters) {
  ShadeCounters local;
  ShadeCounters& count = counters ? *counters : local;
  auto scalar_point = [&](std::size_t i) {
    const Vec3d c = shade_point(lighting, {block.px[i], block.py[i], block.pz[i]}, {block.nx[i], block.ny[i], block.nz[i]},
                                &count);
    rgb_out[3 * i] = c.x, rgb_out[3 * i + 1] = c.y, rgb_out[3 * i + 2] = c.z;
  };
  if (!lighting_engine::point_lanes_available() || !lighting_engine::point_lanes_support(lighting)) {
    for (std::size_t i = 0; i < block.count; ++i) scalar_point(i);
    return;
  }
  lighting_engine::shade_point_lanes(lighting, block, rgb_out, count);
}

}  // namespace shadetool
