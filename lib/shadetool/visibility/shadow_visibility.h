// shadow_visibility.h: whether points see a light, for bake-lighting --shadows (and a renderer).
//
// Hard shadows, one ray per point, 0 or 1:
//   shadow_visibility_directional: the ray from p toward the light, direction `to_light` (world;
//       need not be unit), unbounded: 1 when nothing of the mesh is in the way.
//   shadow_visibility_point: the segment from p to the light's position (point and spot lights):
//       1 when no triangle meets it (a triangle through the light's position itself counts).
//       A point at the light's position sees it (1).
// Sampled lights (area, sky, environment), N rays per point, a fraction in [0, 1]:
//   shadow_visibility_sampled: for k < N, (u, v) = point i's scrambled Sobol point k
//       (sample_sequence.h; seed from ids[i] and options.seed), and the caller's sampler returns
//       a LightSample: a target point on the light (or a direction, at_infinity) and a weight
//       w_k >= 0 (its share of the unoccluded closed form, e.g. cos/pdf). The result is
//
//           sum_k w_k V_k / sum_k w_k
//
//       so with nothing in the way it is exactly 1 (numerator and denominator add the same
//       numbers in the same order), and the caller multiplies the closed form by it. When every
//       w_k is 0 (the light wholly below the horizon) the result is 1: no sample says otherwise,
//       and the closed form is 0 there anyway. Samples with w_k = 0 cast no ray.
//       The sampler is called concurrently from several threads: it must be a pure function.
// Origins: moved off the surface by ray_offset.h along n on the side the ray leaves (-n when the
// light is below the surface); a point whose normal is zero or not finite is moved along the
// ray's own direction instead.
//
// Inputs:  scene   the mesh's VisibilityScene
//          points, normals  #P by 3 each, world space
//          ids     #P ids for the seeds (empty: the point's index); sampled lights only
// Output:  #P values (uint8 0/1, or double fractions)
// Precision: double geometry rounded to float in the scene's frame; weights summed in double.
// Threads: any count; same bits (each point's rays depend on its own seed only).
// Errors:  throws Error for mismatched sizes, non-finite points or light, samples = 0, a zero
//          direction, or a negative or non-finite weight.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <shadetool/core/progress.h>
#include <shadetool/core/vec3.h>
#include <shadetool/visibility/visibility_scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::vector<std::uint8_t> shadow_visibility_directional(const VisibilityScene& scene, const std::vector<double>& points,
                                                        const std::vector<double>& normals, const Vec3d& to_light);

std::vector<std::uint8_t> shadow_visibility_point(const VisibilityScene& scene, const std::vector<double>& points,
                                                  const std::vector<double>& normals, const Vec3d& light_position);

struct LightSample {
  Vec3d target{};           // world point on the light, or (at_infinity) the direction toward it
  bool at_infinity = false;
  double weight = 0;        // >= 0
};

// sampler(point index, point position (world), u, v) -> LightSample.
using LightSampler = std::function<LightSample(std::size_t, const Vec3d&, double, double)>;

struct ShadowSampleOptions {
  std::uint32_t samples = 16;
  std::uint32_t seed = 0;  // e.g. the light's index, so that two lights do not share directions
  // Told samples units per point, a block of points per call (core/progress.h); the caller
  // begins the stage. Null: nobody listens. Never changes a result.
  ProgressSink* progress = nullptr;
};

std::vector<double> shadow_visibility_sampled(const VisibilityScene& scene, const std::vector<double>& points,
                                              const std::vector<double>& normals,
                                              const std::vector<std::uint64_t>& ids, const LightSampler& sampler,
                                              const ShadowSampleOptions& options = {});

}  // namespace shadetool
#pragma GCC visibility pop
