// shade_point.cpp: see shade_point.h.
#include <shadetool/lighting/shade_point.h>

#include <shadetool/lighting/engine/shade_point.h>

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

}  // namespace shadetool
