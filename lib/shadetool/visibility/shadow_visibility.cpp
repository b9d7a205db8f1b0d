// shadow_visibility.cpp
#include <shadetool/visibility/shadow_visibility.h>

#include <cmath>
#include <limits>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/engine/point_ranges.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool {

namespace {

constexpr std::uint32_t kShadowSalt = 2;
constexpr float kInf = std::numeric_limits<float>::infinity();

struct LocalPoints {
  std::vector<Vec3f> p;  // scene frame
  std::vector<Vec3f> n;  // unit, or (0,0,0) when the given normal is unusable
};

LocalPoints to_local(const VisibilityScene& scene, const std::vector<double>& points, const std::vector<double>& normals) {
  if (points.size() % 3 != 0 || normals.size() != points.size())
    throw Error("shadow visibility: points and normals differ in size");
  LocalPoints l;
  const std::size_t n = points.size() / 3;
  l.p.resize(n);
  l.n.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_finite(get3(points, i))) throw Error("shadow visibility: point " + std::to_string(i) + " is not finite");
    l.p[i] = scene.to_local(get3(points, i));
    l.n[i] = Vec3f(normalized_or(get3(normals, i), Vec3d{0, 0, 0}));
  }
  return l;
}

// The origin for a ray from p in direction d: offset along the normal on d's side, or along d
// itself when there is no normal.
Vec3f leave_surface(const Vec3f& p, const Vec3f& n, const Vec3f& d) {
  if (n == Vec3f{0, 0, 0}) return visibility::offset_ray_origin(p, Vec3f(normalized_or(Vec3d(d), Vec3d{0, 0, 0})));
  return visibility::offset_ray_origin(p, dot(n, d) >= 0 ? n : -n);
}

// One ray toward a light sample from local point p: true when it is blocked.
bool blocked(RTCScene rtc, const VisibilityScene& scene, const Vec3f& p, const Vec3f& n, const Vec3d& target,
             bool at_infinity) {
  if (at_infinity) {
    const Vec3f d(normalized_or(target, Vec3d{0, 0, 0}));
    if (d == Vec3f{0, 0, 0}) throw Error("shadow visibility: a light direction is zero or not finite");
    return visibility_engine::occluded(rtc, leave_surface(p, n, d), d, kInf);
  }
  const Vec3f t = scene.to_local(target);
  if (t == p) return false;  // at the light
  const Vec3f o = leave_surface(p, n, t - p);
  return visibility_engine::occluded(rtc, o, t - o, 1.0f);  // the segment o -> t, t = 1 at the light
}

}  // namespace

std::vector<std::uint8_t> shadow_visibility_directional(const VisibilityScene& scene, const std::vector<double>& points,
                                                        const std::vector<double>& normals, const Vec3d& to_light) {
  const LocalPoints l = to_local(scene, points, normals);
  if (!is_finite(to_light) || to_light == Vec3d{0, 0, 0})
    throw Error("shadow visibility: the light's direction is zero or not finite");
  std::vector<std::uint8_t> out(l.p.size(), 1);
  RTCScene rtc = scene.impl().scene;
  visibility_engine::parallel_point_ranges(l.p.size(), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) out[i] = blocked(rtc, scene, l.p[i], l.n[i], to_light, true) ? 0 : 1;
  });
  return out;
}

std::vector<std::uint8_t> shadow_visibility_point(const VisibilityScene& scene, const std::vector<double>& points,
                                                  const std::vector<double>& normals, const Vec3d& light_position) {
  const LocalPoints l = to_local(scene, points, normals);
  if (!is_finite(light_position)) throw Error("shadow visibility: the light's position is not finite");
  std::vector<std::uint8_t> out(l.p.size(), 1);
  RTCScene rtc = scene.impl().scene;
  visibility_engine::parallel_point_ranges(l.p.size(), 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) out[i] = blocked(rtc, scene, l.p[i], l.n[i], light_position, false) ? 0 : 1;
  });
  return out;
}

std::vector<double> shadow_visibility_sampled(const VisibilityScene& scene, const std::vector<double>& points,
                                              const std::vector<double>& normals,
                                              const std::vector<std::uint64_t>& ids, const LightSampler& sampler,
                                              const ShadowSampleOptions& options) {
  const LocalPoints l = to_local(scene, points, normals);
  if (!ids.empty() && ids.size() != l.p.size()) throw Error("shadow visibility: ids and points differ in size");
  if (options.samples == 0) throw Error("shadow visibility: samples must be at least 1");
  const std::uint32_t salt_seed = visibility::hash_combine(kShadowSalt, options.seed);
  std::vector<double> out(l.p.size(), 1.0);
  RTCScene rtc = scene.impl().scene;
  visibility_engine::parallel_point_ranges(l.p.size(), options.samples, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const std::uint32_t seed = visibility::point_seed(ids.empty() ? i : ids[i], salt_seed);
      const Vec3d p_world = get3(points, i);
      double seen = 0, total = 0;
      for (std::uint32_t k = 0; k < options.samples; ++k) {
        const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(k, seed);
        const LightSample ls = sampler(i, p_world, s.u, s.v);
        if (!(ls.weight >= 0) || !std::isfinite(ls.weight))
          throw Error("shadow visibility: a light sample's weight is negative or not finite");
        if (ls.weight == 0) continue;
        total += ls.weight;
        if (!blocked(rtc, scene, l.p[i], l.n[i], ls.target, ls.at_infinity)) seen += ls.weight;
      }
      out[i] = total > 0 ? seen / total : 1.0;  // divisor checked; equal sums give exactly 1
    }
    report_advance(options.progress, std::uint64_t(e - b) * options.samples);
  });
  return out;
}

}  // namespace shadetool
