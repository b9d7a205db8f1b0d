// light_visibility.cpp: see light_visibility.h.
#include <shadetool/lighting/light_visibility.h>

#include <atomic>
#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/environment_map.h>
#include <shadetool/visibility/sample_sequence.h>
#include <shadetool/visibility/shadow_visibility.h>

namespace shadetool {

namespace {

// Two unit vectors completing unit n to a right-handed basis: the visibility module's (Duff et al.
// 2017), the one the ambient-occlusion rays use.
using visibility::orthonormal_basis;

Vec3d unit_normal(const std::vector<double>& normals, std::size_t i) {
  const Vec3d n{normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
  return normalized_or(n, Vec3d{0, 0, 0});
}

// A polygon light: uniform on its area. Fan (v0, v_k, v_k+1) with cumulative areas.
struct PolygonSampler {
  std::vector<Vec3d> v;
  std::vector<double> cumulative;  // normalised to end at 1
  Vec3d emit{0, 0, 0};
  bool two_sided = false;

  explicit PolygonSampler(const Light& light) : v(light.vertices), two_sided(light.two_sided) {
    Vec3d newell{0, 0, 0};
    for (std::size_t k = 0; k < v.size(); ++k) newell += cross(v[k], v[(k + 1) % v.size()]);
    emit = normalized_or(newell, Vec3d{0, 0, 0});
    double total = 0;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      total += length(cross(v[k] - v[0], v[k + 1] - v[0]));
      cumulative.push_back(total);
    }
    for (double& c : cumulative) c = total > 0 ? c / total : 1.0;  // zero area: read as valid, P = 0
  }

  LightSample operator()(const Vec3d& p, const Vec3d& n, double u, double w) const {
    std::size_t k = 0;
    while (k + 1 < cumulative.size() && u >= cumulative[k]) ++k;
    const double lo = k == 0 ? 0.0 : cumulative[k - 1];
    const double width = cumulative[k] - lo;
    double s = width > 0 ? (u - lo) / width : 0.5;  // u re-used within the chosen triangle
    s = s < 0 ? 0 : (s > 1 ? 1 : s);
    const double r = std::sqrt(s);  // uniform on a triangle: (1 - r) a + r (1 - w) b + r w c
    const Vec3d x = v[0] * (1 - r) + v[k + 1] * (r * (1 - w)) + v[k + 2] * (r * w);
    LightSample out;
    out.target = x;
    const Vec3d to = x - p;
    const double d = length(to);
    if (!(d > 0) || n == Vec3d{0, 0, 0}) return out;  // weight 0
    const Vec3d dir = to * (1.0 / d);  // d > 0 checked
    const double cos_p = dot(n, dir);
    double cos_l = -dot(emit, dir);
    if (two_sided) cos_l = std::fabs(cos_l);
    if (!(cos_p > 0) || !(cos_l > 0)) return out;
    out.weight = cos_p * cos_l / d / d;  // divided twice: d^2 could underflow for a tiny light
    if (!std::isfinite(out.weight)) out.weight = 0;
    return out;
  }
};

// A sphere light: directions uniform in the subtended cone, cast to the near surface.
LightSample sample_sphere(const Light& light, const Vec3d& p, const Vec3d& n, double u, double v) {
  LightSample out;
  out.target = light.center;
  const Vec3d to = light.center - p;
  const double d = length(to);
  if (!(d > light.radius) || n == Vec3d{0, 0, 0}) return out;  // inside or on it: P = 0 there
  const Vec3d axis = to * (1.0 / d);                           // d > radius > 0
  const double s = light.radius / d;
  const double cos_max = std::sqrt(std::fmax(0.0, (1 - s) * (1 + s)));
  const double cos_t = 1 - u * (1 - cos_max);
  const double sin_t = std::sqrt(std::fmax(0.0, (1 - cos_t) * (1 + cos_t)));
  const double phi = kTwoPi * v;
  Vec3d t1, t2;
  orthonormal_basis(axis, t1, t2);
  const Vec3d dir = t1 * (sin_t * std::cos(phi)) + t2 * (sin_t * std::sin(phi)) + axis * cos_t;
  // Near intersection of p + t dir with the sphere: t = b - sqrt(r^2 - (d^2 - b^2)), b = dir.to;
  // d^2 - b^2 = d^2 sin_t^2 (no cancellation).
  const double b = d * cos_t;
  const double h = d * sin_t;
  const double t = b - std::sqrt(std::fmax(0.0, (light.radius - h) * (light.radius + h)));
  out.target = p + dir * t;
  out.weight = std::fmax(0.0, dot(n, dir));
  return out;
}

// A direction about unit n with density (n.w)/pi: Malley's method on the polar map of the disc
// (radius sqrt(u), angle 2 pi v), shared by the sky and the environment.
Vec3d cosine_direction(const Vec3d& n, double u, double v) {
  Vec3d t1, t2;
  orthonormal_basis(n, t1, t2);
  const double r = std::sqrt(u), phi = kTwoPi * v;
  return t1 * (r * std::cos(phi)) + t2 * (r * std::sin(phi)) + n * std::sqrt(std::fmax(0.0, 1 - u));
}

// Sky: cosine-weighted directions about n; `sky` picks the sky's (up.w > 0) or the ground's.
LightSample sample_sky(const Light& light, const Vec3d& n, double u, double v, bool sky) {
  LightSample out;
  out.at_infinity = true;
  out.target = light.up;
  if (n == Vec3d{0, 0, 0}) return out;
  const Vec3d dir = cosine_direction(n, u, v);
  out.target = dir;
  const Vec3d up = normalized_or(light.up, Vec3d{0, 0, 1});
  out.weight = (dot(up, dir) > 0) == sky ? 1.0 : 0.0;
  return out;
}

// Environment: cosine-weighted directions about n (as the sky), weighted by the map's luminance
// there (Rec. 709), so that the fraction sum w V / sum w estimates the visible share of P.
LightSample sample_environment(const Light& light, const Vec3d& n, double u, double v) {
  LightSample out;
  out.at_infinity = true;
  out.target = n;
  if (n == Vec3d{0, 0, 0}) return out;
  const Vec3d dir = cosine_direction(n, u, v);
  out.target = dir;
  const Vec3d L = environment_radiance(*light.environment, transpose(light.world_from_map) * dir);
  out.weight = 0.2126 * L.x + 0.7152 * L.y + 0.0722 * L.z;
  return out;
}

}  // namespace

namespace {

// The units of the stage "shadows": rays per point, summed over the kept lights (a sampled ray
// whose weight is 0 is counted though not cast: the fraction is of the work planned).
std::uint64_t shadow_progress_units(const Scene& lighting, const LightingPlan& plan, std::size_t P, std::uint32_t samples) {
  std::uint64_t per_point = 0;
  for (const std::size_t index : plan.lights) {
    switch (lighting.lights[index].type) {
      case LightType::Ambient: break;
      case LightType::Directional:
      case LightType::Point:
      case LightType::Spot: per_point += 1; break;
      case LightType::Area:
      case LightType::Environment: per_point += samples; break;
      case LightType::Sky: per_point += 2ull * samples; break;
    }
  }
  return per_point * P;
}

}  // namespace

void check_shadow_options(const ShadowOptions& shadows, const std::string& what) {
  if (shadows.enabled && (shadows.samples < 1 || shadows.samples > kMaxShadowSamples))
    throw Error(what + " must be 1.." + std::to_string(kMaxShadowSamples) + ", got " + std::to_string(shadows.samples));
}

std::vector<double> light_visibility(const VisibilityScene& scene, const Scene& lighting, const LightingPlan& plan,
                                     const std::vector<double>& points, const std::vector<double>& normals,
                                     const std::vector<std::uint64_t>& ids, std::uint32_t samples,
                                     ShadowStats* stats, ProgressSink* progress) {
  if (points.size() % 3 != 0 || normals.size() != points.size())
    throw Error("light_visibility: points and normals must both be #P by 3");
  if (samples == 0) throw Error("light_visibility: samples must be at least 1");
  const std::size_t P = points.size() / 3;
  const std::size_t L = plan.lights.size();
  const std::size_t row = 2 * L;
  std::vector<double> vis(row * P, 1.0);
  report_begin(progress, "shadows", shadow_progress_units(lighting, plan, P, samples));
  ShadowStats st;
  st.bvh_bytes = scene.stats().bvh_bytes + scene.stats().buffer_bytes;
  st.build_ms = scene.stats().build_ms;

  auto store_hard = [&](std::size_t j, const std::vector<std::uint8_t>& v) {
    for (std::size_t i = 0; i < P; ++i) {
      vis[row * i + 2 * j] = v[i];
      st.occluded_terms += v[i] == 0;
    }
  };
  std::atomic<std::size_t> sampled_rays{0};
  auto store_sampled = [&](std::size_t j, std::size_t slot, const std::vector<double>& v) {
    for (std::size_t i = 0; i < P; ++i) vis[row * i + 2 * j + slot] = v[i];
  };
  // A light's sampler at point i (normal unit_normal(normals, i)) that counts the rays it asks for.
  auto counting = [&sampled_rays](auto sample) -> LightSampler {
    return [sample, &sampled_rays](std::size_t i, const Vec3d& p, double u, double v) {
      const LightSample s = sample(i, p, u, v);
      if (s.weight > 0) sampled_rays.fetch_add(1, std::memory_order_relaxed);
      return s;
    };
  };
  // One sampled part per light (area, environment): visibility in slot 0, partly hidden points counted.
  auto sample_one_part = [&](std::size_t j, const LightSampler& sampler, const ShadowSampleOptions& so) {
    const std::vector<double> v = shadow_visibility_sampled(scene, points, normals, ids, sampler, so);
    store_sampled(j, 0, v);
    for (std::size_t i = 0; i < P; ++i) st.occluded_terms += v[i] < 1;
  };
  for (std::size_t j = 0; j < L; ++j) {
    const Light& light = lighting.lights[plan.lights[j]];
    ShadowSampleOptions so;
    so.samples = samples;
    so.progress = progress;
    so.seed = std::uint32_t(2 * j);
    switch (light.type) {
      case LightType::Ambient:  // never in plan.lights
        break;
      case LightType::Directional:
        ++st.hard_lights;
        st.shadow_rays += P;
        store_hard(j, shadow_visibility_directional(scene, points, normals, -light.direction));
        report_advance(progress, P);
        break;
      case LightType::Point:
      case LightType::Spot:
        ++st.hard_lights;
        st.shadow_rays += P;
        store_hard(j, shadow_visibility_point(scene, points, normals, light.position));
        report_advance(progress, P);
        break;
      case LightType::Area: {
        ++st.sampled_lights;
        LightSampler sampler;
        if (light.shape == AreaShape::Polygon) {
          const PolygonSampler polygon(light);
          sampler = counting([polygon, &normals](std::size_t i, const Vec3d& p, double u, double v) {
            return polygon(p, unit_normal(normals, i), u, v);
          });
        } else {
          sampler = counting([&light, &normals](std::size_t i, const Vec3d& p, double u, double v) {
            return sample_sphere(light, p, unit_normal(normals, i), u, v);
          });
        }
        sample_one_part(j, sampler, so);
        break;
      }
      case LightType::Sky: {
        ++st.sampled_lights;
        std::vector<double> parts[2];
        for (int slot = 0; slot < 2; ++slot) {
          const bool sky = slot == 0;
          so.seed = std::uint32_t(2 * j + slot);
          const LightSampler sampler = counting([&light, &normals, sky](std::size_t i, const Vec3d&, double u, double v) {
            return sample_sky(light, unit_normal(normals, i), u, v, sky);
          });
          parts[slot] = shadow_visibility_sampled(scene, points, normals, ids, sampler, so);
          store_sampled(j, slot, parts[slot]);
        }
        for (std::size_t i = 0; i < P; ++i) st.occluded_terms += parts[0][i] < 1 || parts[1][i] < 1;
        break;
      }
      case LightType::Environment: {
        ++st.sampled_lights;
        sample_one_part(j, counting([&light, &normals](std::size_t i, const Vec3d&, double u, double v) {
                          return sample_environment(light, unit_normal(normals, i), u, v);
                        }),
                        so);
        break;
      }
    }
  }
  st.shadow_rays += sampled_rays.load();
  if (stats) *stats = st;
  return vis;
}

}  // namespace shadetool
