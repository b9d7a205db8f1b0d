// shading_space.cpp: see shading_space.h.
#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/shading_space.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <shadetool/core/affine.h>
#include <shadetool/core/vocabulary.h>
#include <shadetool/lighting/engine/metric.h>
#include <shadetool/lighting/engine/skip_options.h>

namespace shadetool {

namespace {
const NamedValue<ShadingSpace> kShadingSpaces[] = {
    {ShadingSpace::Auto, "auto"},
    {ShadingSpace::World, "world"},
    {ShadingSpace::Camera, "camera"},
    {ShadingSpace::Object, "object"},
};
}  // namespace

ShadingSpace parse_shading_space(std::string_view text, const std::string& what) {
  return parse_named(kShadingSpaces, text, what);
}
const char* shading_space_name(ShadingSpace space) { return name_of(kShadingSpaces, space); }
std::vector<std::string> shading_space_names() { return names_of(kShadingSpaces); }

double cos_degrees(double degrees) {
  if (degrees == 0) return 1;
  if (degrees == 90) return 0;
  if (degrees == 180) return -1;
  return std::cos(degrees * kRadiansPerDegree);
}

SpaceMetric metric_of(const Mat3d& B) {
  SpaceMetric metric;
  const Mat3d G = transpose(B) * B;
  const double s2 = (G.m[0][0] + G.m[1][1] + G.m[2][2]) / 3.0;
  double deviation = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) deviation = std::max(deviation, std::fabs(G.m[i][j] - (i == j ? s2 : 0.0)));
  if (s2 > 0 && std::isfinite(s2) && deviation <= 1e-12 * s2) {
    if (std::fabs(s2 - 1) <= 1e-12) return metric;  // Identity: B is a rotation (or mirror)
    metric.kind = MetricKind::Scaled;
    metric.scale2 = s2;
    return metric;
  }
  metric.kind = MetricKind::General;
  metric.B = B;
  Affine3d b{B, {0, 0, 0}}, b_inv;
  invert_affine(b, b_inv);  // B invertible: validated when the scene was read
  metric.B_inverse_transpose = transpose(b_inv.A);
  return metric;
}

namespace {

Vec3d lower(const SpaceMetric& g, const Vec3d& v) {
  switch (g.kind) {
    case MetricKind::Identity: return v;
    case MetricKind::Scaled: return v * g.scale2;
    case MetricKind::General: return transpose(g.B) * (g.B * v);
  }
  return v;
}

// Unit length in the metric, by engine/metric.h's one scaled-normalise rule (the per-point loop's);
// v is non-zero (scene directions are validated non-zero).
Vec3d unit_in(const SpaceMetric& g, const Vec3d& v) {
  switch (g.kind) {
    case MetricKind::Identity: return lighting_engine::metric_normalize(lighting_engine::IdentityMetric{}, v).unit;
    case MetricKind::Scaled:
      return lighting_engine::metric_normalize(lighting_engine::ScaledMetric{g.scale2, 1.0 / g.scale2}, v).unit;
    case MetricKind::General: {
      const lighting_engine::GeneralMetric general{g.B, transpose(g.B), g.B_inverse_transpose};
      return lighting_engine::metric_normalize(general, v).unit;
    }
  }
  return {0, 0, 0};
}

// Unit normal of a planar polygon by Newell's method, sign by the vertex order (counter-clockwise
// seen from the side it points to); the polygon was validated non-degenerate.
Vec3d polygon_unit_normal(const std::vector<Vec3d>& v) {
  Vec3d sum{0, 0, 0};
  const Vec3d& o = v[0];  // relative to a vertex: no cancellation far from the origin
  for (std::size_t i = 1; i + 1 < v.size(); ++i) sum += cross(v[i] - o, v[i + 1] - o);
  return normalized_or(sum, Vec3d{0, 0, 0});
}

struct SpaceMaps {
  Affine3d world_from_space, space_from_world, space_from_object;
};

SpaceMaps maps_for(const Scene& scene, ShadingSpace space) {
  SpaceMaps m;
  const Affine3d& M = scene.world_from_object;
  switch (space) {
    case ShadingSpace::Camera: {
      m.space_from_world = scene.camera_from_world;  // identity without a camera (OpenGL default)
      invert_affine(m.space_from_world, m.world_from_space);
      m.space_from_object = compose(m.space_from_world, M);
      break;
    }
    case ShadingSpace::Object:
      m.world_from_space = M;
      invert_affine(M, m.space_from_world);
      break;  // space_from_object = identity
    case ShadingSpace::Auto:  // never reaches here: make_frame resolves Auto to World first
    case ShadingSpace::World:
      m.space_from_object = M;
      break;
  }
  return m;
}

}  // namespace

ShadingFrame make_frame(const Scene& scene, const LightingPlan& plan, ShadingSpace space) {
  return make_frame(scene, plan, space, SkipOptions{});
}

ShadingFrame make_frame(const Scene& scene, const LightingPlan& plan, ShadingSpace space, const SkipOptions& skips) {
  ShadingFrame frame;
  frame.space = space == ShadingSpace::Auto ? ShadingSpace::World : space;
  const SpaceMaps maps = maps_for(scene, frame.space);
  frame.space_from_object = maps.space_from_object;
  frame.normal_to_space = signed_cofactor(maps.space_from_object.A);
  frame.transform = frame.space != ShadingSpace::Object &&
                    !(skips.identity_transform && is_identity(maps.space_from_object));
  frame.metric = metric_of(maps.world_from_space.A);
  frame.eye = frame.space == ShadingSpace::Camera ? Vec3d{0, 0, 0}  // the eye is the camera's origin
                                                  : transform_point(maps.space_from_world, eye_world(scene));

  frame.world_from_space = maps.world_from_space;
  frame.space_is_world = is_identity(maps.world_from_space);
  frame.normal_to_world = signed_cofactor(maps.world_from_space.A);
  frame.eye_world = eye_world(scene);

  const Material& mat = scene.material;
  for (std::size_t index : plan.lights) {
    const Light& L = scene.lights[index];
    SpaceLight s;
    s.type = L.type;
    s.products.ambient = mul(mat.ambient, L.ambient);
    s.products.diffuse = mul(mat.diffuse, L.diffuse);
    s.products.specular = plan.specular ? mul(mat.specular, L.specular) : Vec3d{0, 0, 0};
    s.has_ambient = !is_zero(s.products.ambient);
    s.has_specular = plan.specular && (!is_zero(s.products.specular) || !skips.specular);
    switch (L.type) {
      case LightType::Ambient:  // folded into plan.base; plan.lights never holds one
        continue;
      case LightType::Directional:
        // Travels along `direction`; the unit vector toward the light is -direction.
        s.to_light = unit_in(frame.metric, transform_vector(maps.space_from_world, -L.direction));
        break;
      case LightType::Point:
      case LightType::Spot:
        s.position = transform_point(maps.space_from_world, L.position);
        s.kc = L.attenuation.x;
        s.kl = L.attenuation.y;
        s.kq = L.attenuation.z;
        if (L.type == LightType::Spot && L.cutoff_degrees != 180) {  // 180: OpenGL's "no cone", spot = 1
          s.cone = true;
          s.cos_cutoff = cos_degrees(L.cutoff_degrees);
          s.exponent = L.exponent;
          s.axis_lowered = lower(frame.metric, unit_in(frame.metric, transform_vector(maps.space_from_world, L.direction)));
        }
        break;
      case LightType::Area:
        s.shape = L.shape;
        s.vertices = L.vertices;
        s.two_sided = L.two_sided;
        s.center = L.center;
        s.radius = L.radius;
        if (L.shape == AreaShape::Polygon) s.emit_normal = polygon_unit_normal(L.vertices);
        break;
      case LightType::Sky:
        s.up = normalized_or(L.up, Vec3d{0, 1, 0});  // validated non-zero
        s.to_light = unit_in(frame.metric, transform_vector(maps.space_from_world, L.up));  // up in S (diffuse path)
        s.ground_products.diffuse = mul(mat.diffuse, L.ground);
        s.ground_products.specular = plan.specular ? mul(mat.specular, L.ground) : Vec3d{0, 0, 0};
        s.has_specular = s.has_specular || (plan.specular && !is_zero(s.ground_products.specular));
        break;
      case LightType::Environment:
        s.environment = L.environment;
        s.map_from_world = transpose(L.world_from_map);  // a rotation: its inverse is its transpose
        break;
    }
    frame.lights.push_back(s);
  }
  return frame;
}

SpaceChoice choose_space(const Scene& scene, const LightingPlan& plan) { return choose_space(scene, plan, SkipOptions{}); }

SpaceChoice choose_space(const Scene& scene, const LightingPlan& plan, const SkipOptions& skips) {
  const ShadingSpace order[3] = {ShadingSpace::Object, ShadingSpace::World, ShadingSpace::Camera};
  SpaceChoice choice;
  double best = 0;
  for (int k = 0; k < 3; ++k) {
    const ShadingSpace space = order[k];
    const SpaceMaps maps = maps_for(scene, space);
    const bool transforms = space != ShadingSpace::Object &&
                            !(skips.identity_transform && is_identity(maps.space_from_object));
    const SpaceMetric metric = metric_of(maps.world_from_space.A);
    double cost = 0;
    if (transforms) cost += 15 + (plan.positions ? 18 : 0);
    if (metric.kind == MetricKind::General)
      cost += 15 + (plan.view ? 45 : 0) + 15.0 * double(plan.positional_lights);
    if (plan.area_lights > 0 && !is_identity(maps.world_from_space)) cost += 18 + 15;  // p, n back to world
    const int slot = space == ShadingSpace::World ? 0 : space == ShadingSpace::Camera ? 1 : 2;
    choice.cost[slot] = cost;
    if (k == 0 || cost < best) {
      best = cost;
      choice.space = space;
    }
  }
  char line[160];
  std::snprintf(line, sizeof line, "%s (estimated flops per point beyond the equation: object %g, world %g, camera %g)",
                shading_space_name(choice.space), choice.cost[2], choice.cost[0], choice.cost[1]);
  choice.reason = line;
  return choice;
}

}  // namespace shadetool
