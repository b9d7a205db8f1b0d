// occlusion_to_error.h: the open fraction (ambient_occlusion.h) per point with rays added in
// batches until its estimated standard error is at most a target E (`occlusion --error E`).
//
// Estimator (a pilot, then one sequence): R = 8 independent randomisations of the point's scrambled
// Sobol sequence (replicate r seeded hash_combine(point_seed(id, salt), r); sample_sequence.h), 4
// rays each. Their spread gives sigma, the standard deviation of one 4-ray estimate
// (sqrt(R) times the standard error sqrt(sum_r (m_r - mean)^2 / (R (R - 1))) of the replicates' mean;
// Owen 1997: the replicates of a randomised QMC rule are i.i.d. and unbiased). When all replicates
// agree (all 32 rays escaped, or all hit) the binomial bound sqrt(p (1 - p) / 4) with
// p = (hits + 1/2) / 33 is used instead, so a point does not stop on 32 rays that happened to miss
// a small occluder. If sigma / sqrt(R) <= E the pilot's mean is the result (32 rays). Otherwise
// replicate 0 is extended (its own sequence continued) to N rays, N the least power of two with
// sigma (N / 4)^(-0.7) <= E (the N^(-3/4) rate of sample_sequence.h, taken as 0.7 for margin), at
// most max_samples - 28, and the result is the inverse-variance mean of its estimate (variance
// sigma^2 (N/4)^(-1.4)) and the other 7 pilots (sigma^2); its standard error sqrt(1 / sum of weights).
// Points whose cap stops them above E are counted in `capped`. The model's coverage is measured by
// tests/visibility/occlusion_to_error.cpp on the analytic cases (within 2E of the truth at 97-99%
// of the points) and the rays against a fixed count of the same RMS error.
//
// Inputs:  scene, points, normals (#P by 3, the scene's frame), ids (#P seeds; empty: index)
//          options  target_error E > 0, max_samples >= 32 (per point, all replicates), max_distance,
//                   seed
// Output:  open_fraction #P, standard_error #P, rays #P (per point), totals; points with a zero or
//          non-finite normal: open 1, no ray (skipped).
// Threads: each point's rays depend only on its id: the same bits for any thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/visibility/visibility_scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct OcclusionToErrorOptions {
  double target_error = 0.01;
  std::uint32_t max_samples = 4096;
  double max_distance = std::numeric_limits<double>::infinity();
  std::uint32_t seed = 0;
};

struct OcclusionToError {
  std::vector<float> open_fraction;
  std::vector<float> standard_error;
  std::vector<std::uint32_t> rays;
  std::uint64_t total_rays = 0;
  std::uint64_t hits = 0;
  std::size_t skipped = 0;
  std::size_t capped = 0;  // stopped at max_samples with SE > E
  VisibilitySceneStats scene;  // mesh_occlusion_to_error: its BVH
};

constexpr std::uint32_t kOcclusionReplicates = 8;
constexpr std::uint32_t kOcclusionFirstBatch = 4;  // rays per replicate in the first round

OcclusionToError occlusion_to_error_at_points(const VisibilityScene& scene, const std::vector<double>& points,
                                              const std::vector<double>& normals, const std::vector<std::uint64_t>& ids,
                                              const OcclusionToErrorOptions& options);

// The whole mesh (per vertex about occlusion_vertex_axes, per face at the corners' mean about the
// face normal; the mesh's own BVH), as mesh_occlusion does with a fixed count.
OcclusionToError mesh_occlusion_to_error(const Mesh& mesh, bool per_face, const OcclusionToErrorOptions& options,
                                         const std::string& source, bool& normals_computed);
// The same job for `mesh` against a scene built from another mesh (a glTF document's whole scene,
// gltf/gltf_occlusion.h; the points are the mesh's own vertices or face centres, ids their
// indices, as above); `scene` in the result is left empty (the caller owns the BVH).
OcclusionToError mesh_occlusion_to_error(const VisibilityScene& scene, const Mesh& mesh, bool per_face,
                                         const OcclusionToErrorOptions& options, const std::string& source,
                                         bool& normals_computed);

// Points per ray count (32 for a point the pilot settled, N + 28 otherwise, 0 for skipped points).
std::map<std::uint32_t, std::size_t> ray_histogram(const std::vector<std::uint32_t>& rays);

}  // namespace shadetool
#pragma GCC visibility pop
