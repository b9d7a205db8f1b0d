// engine/shade_batched.cpp: see shade_batched.h.
#include <shadetool/lighting/engine/shade_batched.h>

#include <memory>
#include <vector>

#include <shadetool/lighting/engine/lambert_lanes.h>

namespace shadetool {
namespace lighting_engine {

template <bool kEarlyTests, bool kShadows, class Metric>
ShadeCounters shade_range_batched(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq, bool map_points,
                                  const double* points, const double* normals, const double* visibility, double* out,
                                  std::size_t begin, std::size_t end) {
  const std::size_t n_lights = frame.lights.size();
  const std::size_t row = 2 * n_lights;
  std::unique_ptr<bool[]> batched(new bool[n_lights]);
  std::vector<std::size_t> batch_lights;
  for (std::size_t j = 0; j < n_lights; ++j) {
    batched[j] = batched_polygon_light(frame.lights[j], eq.model, eq.specular);
    if (batched[j]) batch_lights.push_back(j);
  }
  std::vector<AreaTerms> terms(kPointLanes * n_lights);  // point k, light j: terms[k * n_lights + j]
  Vec3d p[kPointLanes];
  PreparedPoint prepared[kPointLanes];
  WorldPoint world[kPointLanes];
  ShadeCounters count;
  for (std::size_t first = begin; first < end; first += kPointLanes) {
    const int m = int(end - first < std::size_t(kPointLanes) ? end - first : kPointLanes);
    for (int k = 0; k < m; ++k) {
      const std::size_t i = first + k;
      p[k] = {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
      Vec3d n{normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
      if (frame.transform) {
        if (map_points) p[k] = transform_point(frame.space_from_object, p[k]);
        n = transform_normal(frame.normal_to_space, Normal3d(n));
      }
      shade_point_in_space<kEarlyTests, kShadows, Metric, true>(g, frame, eq, p[k], n, count, nullptr, nullptr,
                                                                &prepared[k], &world[k]);
    }
    for (std::size_t j : batch_lights) polygon_terms_batch(frame.lights[j], world, m, &terms[j], n_lights);
    for (int k = 0; k < m; ++k) {
      const std::size_t i = first + k;
      const PointBatch batch{&prepared[k], &world[k], batched.get(), &terms[k * n_lights]};
      const Vec3d c = shade_point_in_space<kEarlyTests, kShadows>(g, frame, eq, p[k], prepared[k].n, count,
                                                                  kShadows ? visibility + row * i : nullptr, &batch);
      out[3 * i] = c.x;
      out[3 * i + 1] = c.y;
      out[3 * i + 2] = c.z;
    }
  }
  return count;
}

#define SHADETOOL_SHADE_RANGE_BATCHED(E, S, M)                                                                   \
  template ShadeCounters shade_range_batched<E, S, M>(const M&, const ShadingFrame&, const EquationSetup&, bool, \
                                                      const double*, const double*, const double*, double*,    \
                                                      std::size_t, std::size_t);
#define SHADETOOL_SHADE_RANGE_BATCHED_ALL(M)       \
  SHADETOOL_SHADE_RANGE_BATCHED(true, true, M)     \
  SHADETOOL_SHADE_RANGE_BATCHED(true, false, M)    \
  SHADETOOL_SHADE_RANGE_BATCHED(false, true, M)    \
  SHADETOOL_SHADE_RANGE_BATCHED(false, false, M)
SHADETOOL_SHADE_RANGE_BATCHED_ALL(IdentityMetric)
SHADETOOL_SHADE_RANGE_BATCHED_ALL(ScaledMetric)
SHADETOOL_SHADE_RANGE_BATCHED_ALL(GeneralMetric)

}  // namespace lighting_engine
}  // namespace shadetool
