// engine/area_point.cpp: see area_point.h.
#include <shadetool/lighting/engine/area_point.h>

#include <shadetool/lighting/engine/lambert_lanes.h>
#include <shadetool/lighting/engine/metric.h>
#include <shadetool/lighting/environment_map.h>

#include <new>

namespace shadetool {
namespace lighting_engine {

namespace {

// Unit vector by engine/metric.h's rule (a power-of-two pre-scale only outside [2^-500, 2^500],
// one division): core's normalized_or divides six times and calls fmax twice, a visible part of a
// rect light's per-point time (bench/lighting/results.md). Zero (or unrepresentable) gives zero.
Vec3d unit(const Vec3d& v) { return metric_normalize(IdentityMetric{}, v).unit; }

}  // namespace

void world_point(const ShadingFrame& frame, ShadingModel model, bool specular, double shininess, const Vec3d& p,
                 const Vec3d& n, bool zero_normal, WorldPoint& w, double world_unit_scale) {
  w.p = frame.space_is_world ? p : transform_point(frame.world_from_space, p);
  w.has_lobe = false;
  if (zero_normal) {
    w.n = {0, 0, 0};
    return;
  }
  if (world_unit_scale > 0 && frame.space_is_world)
    w.n = n * world_unit_scale;  // = unit(n), bit for bit (area_point.h)
  else
    w.n = unit(frame.space_is_world ? n : Vec3d(transform_normal(frame.normal_to_world, Normal3d(n))));
  if (!specular) return;
  const Vec3d V = unit(frame.eye_world - w.p);  // 0 at the eye
  new (&w.lobe) SpecularLobe();
  w.has_lobe = true;
  w.lobe.shininess = shininess;
  switch (model) {
    case ShadingModel::Lambert: break;
    case ShadingModel::Phong:
      w.lobe.kind = LobeKind::Phong;
      w.lobe.reflected = V == Vec3d{0, 0, 0} ? V : unit(w.n * (2 * dot(w.n, V)) - V);
      break;
    case ShadingModel::BlinnPhong:
      w.lobe.kind = LobeKind::BlinnPhong;
      w.lobe.view = V;
      w.lobe.normal = w.n;
      break;
  }
}

void add_area_light(Vec3d& color, const SpaceLight& light, const WorldPoint& point, ShadeCounters& count,
                    double visibility, double visibility_ground) {
  const bool with_specular = light.has_specular && point.has_lobe && point.lobe.kind != LobeKind::None;
  if (point.n == Vec3d{0, 0, 0}) {  // zero normal: the ambient term only
    if (light.has_ambient) color += light.products.ambient;
    return;
  }
  static const SpecularLobe no_lobe;  // kind None: P only (not copied per point)
  const SpecularLobe& lobe = with_specular ? point.lobe : no_lobe;
  switch (light.type) {
    case LightType::Area: {
      const AreaTerms t =
          light.shape == AreaShape::Polygon
              ? polygon_light_terms(light.vertices.data(), int(light.vertices.size()), light.emit_normal,
                                    light.two_sided, point.p, point.n, lobe)
              : sphere_light_terms(light.center, light.radius, point.p, point.n, lobe);
      add_area_terms(color, light, point, t, with_specular, count, visibility);
      return;
    }
    case LightType::Sky: {
      const SkyTerms t = sky_light_terms(light.up, point.n, lobe);
      add_light_term(color, light.products, 1.0, t.P_sky, t.S_sky, light.has_ambient, with_specular, visibility);
      add_light_term(color, light.ground_products, 1.0, t.P_ground, t.S_ground, false, with_specular,
                     visibility_ground);
      return;
    }
    case LightType::Environment: {
      // In the map's frame: n (and the lobe) rotated by the inverse of the light's rotation.
      const EnvironmentMap& map = *light.environment;
      const Mat3d& R = light.map_from_world;
      const Vec3d n_map = R * point.n;
      const Vec3d sh = environment_irradiance_sh(map, n_map);
      // The nine-term approximation of max(cos, 0) dips to -0.04 of a single texel's peak behind
      // it: clamped at 0 (the true P is >= 0).
      const Vec3d P{positive_part(sh.x), positive_part(sh.y), positive_part(sh.z)};
      Vec3d S{0, 0, 0};
      if (with_specular) {
        SpecularLobe m = lobe;
        m.reflected = R * lobe.reflected;
        m.view = R * lobe.view;
        m.normal = R * lobe.normal;
        S = environment_specular_sum(map, n_map, m, environment_specular_level(map, lobe.shininess));
      }
      add_light_term_rgb(color, light.products, P, S, light.has_ambient, with_specular, visibility);
      return;
    }
    case LightType::Ambient:
    case LightType::Directional:
    case LightType::Point:
    case LightType::Spot:
      return;  // not area lights: engine/shade_point.h's own branches
  }
}

bool batched_polygon_light(const SpaceLight& light, ShadingModel model, bool specular) {
  // add_area_light's with_specular: light.has_specular, a lobe (specular scenes) of a kind other
  // than None (not Lambert).
  const bool with_specular = light.has_specular && specular && model != ShadingModel::Lambert;
  const std::size_t count = light.vertices.size();  // read_scene: [3, kMaxAreaVertices]; else as before
  return light.type == LightType::Area && light.shape == AreaShape::Polygon && !with_specular && count >= 3 &&
         count <= std::size_t(kMaxAreaVertices);
}

void polygon_terms_batch(const SpaceLight& light, const WorldPoint* points, int count, AreaTerms* terms,
                         std::size_t stride) {
  PointLanes lanes;
  for (int k = 0; k < kPointLanes; ++k) {
    const WorldPoint& w = points[k < count ? k : 0];  // spare lanes: the first point again (not read)
    lanes.px[k] = w.p.x, lanes.py[k] = w.p.y, lanes.pz[k] = w.p.z;
    lanes.nx[k] = w.n.x, lanes.ny[k] = w.n.y, lanes.nz[k] = w.n.z;
  }
  PolygonLaneTerms lane_terms;
  const int n_vertices = int(light.vertices.size());
  polygon_diffuse_lanes(light.vertices.data(), n_vertices, light.emit_normal, light.two_sided, lanes, lane_terms);
  static const SpecularLobe no_lobe;  // kind None: P only
  for (int k = 0; k < count; ++k) {
    AreaTerms& t = terms[k * stride];
    t = AreaTerms{};
    if (points[k].n == Vec3d{0, 0, 0}) continue;  // ambient only (add_area_light)
    if (lane_terms.scalar[k]) {
      t = polygon_light_terms(light.vertices.data(), n_vertices, light.emit_normal, light.two_sided, points[k].p,
                              points[k].n, no_lobe);
      continue;
    }
    t.P = lane_terms.P[k];
    t.below_horizon = lane_terms.below_horizon[k];
    t.inside = lane_terms.inside[k];
  }
}

}  // namespace lighting_engine
}  // namespace shadetool
