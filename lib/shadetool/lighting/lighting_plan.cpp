// lighting_plan.cpp: see lighting_plan.h.
#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/engine/skip_options.h>

namespace shadetool {

LightingPlan plan_lighting(const Scene& scene, ShadingModel model) { return plan_lighting(scene, model, SkipOptions{}); }

LightingPlan plan_lighting(const Scene& scene, ShadingModel model, const SkipOptions& skips) {
  const Material& m = scene.material;
  LightingPlan plan;
  plan.model = model;

  // Ambient lights add ka * a_i everywhere: folded into the constant base.
  Vec3d ambient = scene.global_ambient;
  for (const Light& L : scene.lights)
    if (L.type == LightType::Ambient) ambient += L.ambient;
  plan.base = m.emission + mul(m.ambient, ambient);

  // Specular at all? Decided on the model and material first, then on the lights that remain.
  const bool model_has_specular = model != ShadingModel::Lambert;
  bool specular_possible = model_has_specular && !(skips.specular && is_zero(m.specular));

  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& L = scene.lights[i];
    bool positional = false, area = false;
    Vec3d diffuse = L.diffuse, specular = L.specular;  // the light's radiances that kd and ks meet
    switch (L.type) {  // exhaustive: a new kind must say where it goes
      case LightType::Ambient: continue;  // in plan.base
      case LightType::Directional: break;
      case LightType::Point:
      case LightType::Spot: positional = true; break;
      case LightType::Area: area = positional = true; break;
      case LightType::Environment: area = true; break;  // intensity in diffuse and specular
      case LightType::Sky:
        area = true;
        diffuse += L.ground;
        specular += L.ground;
        break;
    }
    const bool dark = is_zero(mul(m.ambient, L.ambient)) && is_zero(mul(m.diffuse, diffuse)) &&
                      (!specular_possible || is_zero(mul(m.specular, specular)));
    if (dark && skips.dark_lights) {
      ++plan.dark_lights_dropped;
      continue;
    }
    plan.lights.push_back(i);
    if (positional) ++plan.positional_lights;
    if (area) ++plan.area_lights;
  }

  bool any_light_specular = false;
  for (std::size_t i : plan.lights)
    if (!is_zero(mul(m.specular, scene.lights[i].specular)) || !is_zero(mul(m.specular, scene.lights[i].ground)))
      any_light_specular = true;

  if (!model_has_specular) {
    plan.specular_skip_reason = "model is lambert";
  } else if (skips.specular && is_zero(m.specular)) {
    plan.specular_skip_reason = "material specular is zero";
  } else if (skips.specular && !any_light_specular) {
    plan.specular_skip_reason = plan.lights.empty() ? "no lights" : "every light's specular is zero";
  } else {
    plan.specular = true;
  }
  plan.view = plan.specular || scene.two_sided || !skips.view_vector;
  plan.positions = plan.view || plan.positional_lights > 0 || !skips.unused_positions;
  return plan;
}

}  // namespace shadetool
