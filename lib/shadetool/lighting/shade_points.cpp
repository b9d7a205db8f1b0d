// shade_points.cpp: see shade_points.h.
#include <shadetool/lighting/shade_points.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/lighting/engine/shade_batched.h>
#include <shadetool/lighting/engine/shade_point.h>
#include <shadetool/lighting/engine/skip_options.h>

#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace shadetool {

namespace {

using lighting_engine::EquationSetup;
using lighting_engine::GeneralMetric;
using lighting_engine::IdentityMetric;
using lighting_engine::ScaledMetric;

// Points [begin, end): into the space (when needed), then the equation.
template <bool kEarlyTests, bool kShadows, class Metric>
ShadeCounters shade_range(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq, bool map_points,
                          const double* points, const double* normals, const double* visibility, double* out,
                          std::size_t begin, std::size_t end) {
  const std::size_t row = 2 * frame.lights.size();
  ShadeCounters count;
  for (std::size_t i = begin; i < end; ++i) {
    Vec3d p{points[3 * i], points[3 * i + 1], points[3 * i + 2]};
    Vec3d n{normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
    if (frame.transform) {
      if (map_points) p = transform_point(frame.space_from_object, p);
      n = transform_normal(frame.normal_to_space, Normal3d(n));
    }
    const Vec3d c = lighting_engine::shade_point_in_space<kEarlyTests, kShadows>(
        g, frame, eq, p, n, count, kShadows ? visibility + row * i : nullptr);
    out[3 * i] = c.x;
    out[3 * i + 1] = c.y;
    out[3 * i + 2] = c.z;
  }
  return count;
}

template <bool kEarlyTests, bool kShadows, class Metric>
ShadeCounters shade_range_any(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq, bool map_points,
                              const double* points, const double* normals, const double* visibility, double* out,
                              std::size_t begin, std::size_t end, bool batch) {
  if (batch)
    return lighting_engine::shade_range_batched<kEarlyTests, kShadows>(g, frame, eq, map_points, points, normals,
                                                                       visibility, out, begin, end);
  return shade_range<kEarlyTests, kShadows>(g, frame, eq, map_points, points, normals, visibility, out, begin, end);
}

template <bool kEarlyTests, bool kShadows, class Metric>
ShadeCounters shade_all(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq, bool map_points,
                        const double* points, const double* normals, const double* visibility, double* out,
                        std::size_t n, bool parallel) {
  bool batch = false;  // any polygon light whose terms the lanes compute for blocks of points
  for (const SpaceLight& light : frame.lights)
    batch = batch || lighting_engine::batched_polygon_light(light, eq.model, eq.specular);
  if (!parallel || n < 4096)
    return shade_range_any<kEarlyTests, kShadows>(g, frame, eq, map_points, points, normals, visibility, out, 0, n,
                                                  batch);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 2048), ShadeCounters{},
      [&](const tbb::blocked_range<std::size_t>& r, ShadeCounters acc) {
        acc += shade_range_any<kEarlyTests, kShadows>(g, frame, eq, map_points, points, normals, visibility, out,
                                                      r.begin(), r.end(), batch);
        return acc;
      },
      [](ShadeCounters a, const ShadeCounters& b) { return a += b; });
}

// SkipOptions::early_tests and shadows (visibility non-null) pick the loop at compile time: the
// equation itself has no switch, and the loop without shadows reads no visibility.
template <class Metric>
ShadeCounters shade_all_points(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq, bool early_tests,
                        bool map_points, const double* points, const double* normals, const double* visibility,
                        double* out, std::size_t n, bool parallel) {
  if (visibility)
    return early_tests ? shade_all<true, true>(g, frame, eq, map_points, points, normals, visibility, out, n, parallel)
                       : shade_all<false, true>(g, frame, eq, map_points, points, normals, visibility, out, n, parallel);
  return early_tests ? shade_all<true, false>(g, frame, eq, map_points, points, normals, nullptr, out, n, parallel)
                     : shade_all<false, false>(g, frame, eq, map_points, points, normals, nullptr, out, n, parallel);
}

}  // namespace

std::vector<double> shade_points(const Scene& scene, const std::vector<double>& points_object,
                                 const std::vector<double>& normals_object, const ShadeOptions& options,
                                 ShadeReport* report) {
  return shade_points(scene, points_object, normals_object, options, SkipOptions{}, report);
}

std::vector<double> shade_points(const Scene& scene, const std::vector<double>& points_object,
                                 const std::vector<double>& normals_object, const ShadeOptions& options,
                                 const SkipOptions& skips, ShadeReport* report) {
  if (points_object.size() % 3 != 0 || normals_object.size() != points_object.size())
    throw std::invalid_argument("shade_points: points and normals must both be #P by 3");
  const std::size_t n = points_object.size() / 3;
  ShadeReport r;
  r.model = options.model ? *options.model : scene.model;
  r.plan = plan_lighting(scene, r.model, skips);
  if (options.space == ShadingSpace::Auto) {
    const SpaceChoice choice = choose_space(scene, r.plan, skips);
    r.space = choice.space;
    r.space_reason = choice.reason;
  } else {
    r.space = options.space;
    r.space_reason = std::string(shading_space_name(r.space)) + " (requested)";
  }
  const ShadingFrame frame = make_frame(scene, r.plan, r.space, skips);
  const bool map_points = r.plan.positions;

  EquationSetup eq;
  eq.model = r.model;
  eq.specular = r.plan.specular;
  eq.view = r.plan.view;
  eq.two_sided = scene.two_sided;
  const bool early = skips.early_tests;
  eq.shininess = scene.material.shininess;
  eq.base = r.plan.base;

  std::vector<double> out;  // on huge pages from 4 MiB (core/bulk_reserve.h)
  reserve_bulk(out, 3 * n);
  out.resize(3 * n);
  const double* P = points_object.data();
  const double* N = normals_object.data();
  const double* V = nullptr;
  if (options.visibility) {
    if (options.visibility->size() != 2 * frame.lights.size() * n)
      throw std::invalid_argument("shade_points: visibility has " + std::to_string(options.visibility->size()) +
                                  " values, expected 2 per kept light per point (" +
                                  std::to_string(2 * frame.lights.size() * n) + ")");
    V = options.visibility->data();
  }
  switch (frame.metric.kind) {
    case MetricKind::Identity:
      r.counters = shade_all_points(IdentityMetric{}, frame, eq, early, map_points, P, N, V, out.data(), n, options.parallel);
      break;
    case MetricKind::Scaled:
      r.counters = shade_all_points(ScaledMetric{frame.metric.scale2, 1.0 / frame.metric.scale2}, frame, eq, early, map_points,
                             P, N, V, out.data(), n, options.parallel);
      break;
    case MetricKind::General:
      r.counters = shade_all_points(GeneralMetric{frame.metric.B, transpose(frame.metric.B), frame.metric.B_inverse_transpose},
                             frame, eq, early, map_points, P, N, V, out.data(), n, options.parallel);
      break;
  }

  r.transforms_skipped = !frame.transform;
  if (r.plan.dark_lights_dropped > 0) r.skipped.push_back("dark_lights");
  if (!r.plan.specular) r.skipped.push_back("specular");
  if (!r.plan.view) r.skipped.push_back("view_vector");
  if (frame.transform && !map_points) r.skipped.push_back("positions");
  if (!frame.transform) r.skipped.push_back("transforms");
  if (report) *report = std::move(r);
  return out;
}

}  // namespace shadetool
