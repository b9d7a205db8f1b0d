// occlusion_to_error.cpp: see occlusion_to_error.h.
#include <shadetool/visibility/occlusion_to_error.h>

#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/engine/cosine_rays.h>
#include <shadetool/visibility/engine/point_ranges.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool {

namespace {

constexpr std::uint32_t kErrorSalt = 2;  // fixed-count occlusion uses 0 (vertices) and 1 (faces)
// The rate assumed from the pilot to N rays: below the N^(-3/4) of sample_sequence.h, for margin.
constexpr double kRate = 0.7;

struct PointResult {
  float open = 1, se = 0;
  std::uint32_t rays = 0, hits = 0;
  bool capped = false;
};

// The standard error of the replicates' mean (occlusion_to_error.h), hits[r] of n rays each.
double replicate_standard_error(const std::uint32_t* hits, std::uint32_t R, std::uint32_t n) {
  double mean = 0;
  std::uint64_t total = 0;
  for (std::uint32_t r = 0; r < R; ++r) {
    mean += 1.0 - double(hits[r]) / n;  // divisor: n >= 4
    total += hits[r];
  }
  mean /= R;
  double ss = 0;
  for (std::uint32_t r = 0; r < R; ++r) {
    const double d = (1.0 - double(hits[r]) / n) - mean;
    ss += d * d;
  }
  if (ss > 0) return std::sqrt(ss / (double(R) * (R - 1)));  // divisor: R = 8
  const double N = double(R) * n;
  const double p = (double(total) + 0.5) / (N + 1);
  return std::sqrt(p * (1 - p) / N);
}

PointResult trace_point(RTCScene rtc, const Vec3f& p, const Vec3d& axis, std::uint32_t point_seed,
                        const OcclusionToErrorOptions& o, float tfar) {
  constexpr std::uint32_t R = kOcclusionReplicates, n0 = kOcclusionFirstBatch;
  std::uint32_t hits[R] = {};
  PointResult out;
  // Pilot: R scrambles of n0 rays; sigma = the spread of one replicate's estimate.
  for (std::uint32_t r = 0; r < R; ++r)
    hits[r] = visibility_engine::count_cosine_hits(rtc, p, axis, visibility::hash_combine(point_seed, r), 0, n0, tfar);
  const double sigma = replicate_standard_error(hits, R, n0) * std::sqrt(double(R));
  std::uint32_t pilot_hits = 0;
  for (std::uint32_t r = 0; r < R; ++r) pilot_hits += hits[r];
  const double pilot_open = 1.0 - double(pilot_hits) / double(R * n0);  // divisor: R n0 = 32
  if (sigma / std::sqrt(double(R)) <= o.target_error) {
    out.rays = R * n0;
    out.hits = pilot_hits;
    out.open = float(pilot_open);
    out.se = float(sigma / std::sqrt(double(R)));
    return out;
  }
  // Main: replicate 0 extended to N rays, N the least power of two whose predicted error
  // sigma (N / n0)^(-3/4) is at most E, within the cap.
  const std::uint32_t room = o.max_samples - (R - 1) * n0;  // >= n0 (checked by the caller)
  std::uint32_t N = 2 * n0;
  while (N < room && sigma * std::pow(double(N) / n0, -kRate) > o.target_error && N <= (1u << 30)) N *= 2;
  if (N > room) N = room;
  const std::uint32_t main_hits =
      hits[0] + visibility_engine::count_cosine_hits(rtc, p, axis, visibility::hash_combine(point_seed, 0), n0, N - n0, tfar);
  // Inverse-variance combination of the main estimate and the other R - 1 pilots.
  const double var_main = sigma * sigma * std::pow(double(N) / n0, -2 * kRate), var_pilot = sigma * sigma;
  const double w_main = 1.0 / var_main, w_pilot = 1.0 / var_pilot;  // divisors: sigma > E > 0 here
  double sum = w_main * (1.0 - double(main_hits) / N);
  for (std::uint32_t r = 1; r < R; ++r) sum += w_pilot * (1.0 - double(hits[r]) / n0);
  const double w = w_main + (R - 1) * w_pilot;
  out.open = float(sum / w);
  out.se = float(std::sqrt(1.0 / w));
  out.rays = N + (R - 1) * n0;
  out.hits = main_hits;
  for (std::uint32_t r = 1; r < R; ++r) out.hits += hits[r];
  out.capped = out.se > o.target_error;
  return out;
}

}  // namespace

OcclusionToError occlusion_to_error_at_points(const VisibilityScene& scene, const std::vector<double>& points,
                                              const std::vector<double>& normals, const std::vector<std::uint64_t>& ids,
                                              const OcclusionToErrorOptions& options) {
  const std::size_t n = points.size() / 3;
  if (points.size() % 3 != 0 || normals.size() != points.size() || (!ids.empty() && ids.size() != n))
    throw Error("occlusion to an error: points, normals and ids differ in size");
  if (!(options.target_error > 0) || !std::isfinite(options.target_error))
    throw Error("occlusion to an error: the target standard error must be positive");
  if (options.max_samples < kOcclusionReplicates * kOcclusionFirstBatch)
    throw Error("occlusion to an error: the ray cap must be at least " +
                std::to_string(kOcclusionReplicates * kOcclusionFirstBatch) + " (one round of every replicate)");
  if (!(options.max_distance > 0)) throw Error("occlusion to an error: max_distance must be positive");
  OcclusionToError out;
  out.open_fraction.assign(n, 1.0f);
  out.standard_error.assign(n, 0.0f);
  out.rays.assign(n, 0);
  std::vector<std::uint32_t> hits(n, 0);
  std::vector<char> capped(n, 0), skipped(n, 0);
  const float tfar = std::isinf(options.max_distance) ? std::numeric_limits<float>::infinity()
                                                      : float(options.max_distance * scene.scale());
  const std::uint32_t salt_seed = visibility::hash_combine(kErrorSalt, options.seed);
  RTCScene rtc = scene.impl().scene;
  visibility_engine::parallel_point_ranges(n, 64, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const Vec3d raw = get3(normals, i), p = get3(points, i);
      const double l = length(raw);
      if (!(l > 0) || !std::isfinite(l) || !is_finite(p)) {
        skipped[i] = 1;
        continue;
      }
      const Vec3d axis = raw * (1.0 / l);  // divisor checked
      const std::uint64_t id = ids.empty() ? i : ids[i];
      const PointResult r = trace_point(rtc, scene.to_local(p), axis, visibility::point_seed(id, salt_seed), options, tfar);
      out.open_fraction[i] = r.open;
      out.standard_error[i] = r.se;
      out.rays[i] = r.rays;
      hits[i] = r.hits;
      capped[i] = r.capped;
    }
  });
  for (std::size_t i = 0; i < n; ++i) {
    out.total_rays += out.rays[i];
    out.hits += hits[i];
    out.capped += std::size_t(capped[i]);
    out.skipped += std::size_t(skipped[i]);
  }
  return out;
}

OcclusionToError mesh_occlusion_to_error(const Mesh& mesh, bool per_face, const OcclusionToErrorOptions& options,
                                         const std::string& source, bool& normals_computed) {
  const VisibilityScene scene(mesh);
  OcclusionToError out = mesh_occlusion_to_error(scene, mesh, per_face, options, source, normals_computed);
  out.scene = scene.stats();
  return out;
}

OcclusionToError mesh_occlusion_to_error(const VisibilityScene& scene, const Mesh& mesh, bool per_face,
                                         const OcclusionToErrorOptions& options, const std::string& source,
                                         bool& normals_computed) {
  normals_computed = false;
  if (!per_face) {
    const std::vector<double> axes = occlusion_vertex_axes(mesh, source, normals_computed);
    return occlusion_to_error_at_points(scene, mesh.positions, axes, {}, options);
  }
  const std::size_t F = mesh.num_faces();
  std::vector<double> normals = face_normals(mesh, Precision::Double), centres(3 * F, 0.0);
  for (std::size_t f = 0; f < F; ++f) {
    const std::size_t size = mesh.face_size(f);
    if (size < 3) {
      set3(normals, f, {0, 0, 0});  // no area: skipped
      continue;
    }
    Vec3d sum{0, 0, 0};
    for (std::size_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) sum += mesh.position(mesh.corner_vertex[c]);
    set3(centres, f, sum * (1.0 / double(size)));  // divisor: size >= 3
  }
  return occlusion_to_error_at_points(scene, centres, normals, {}, options);
}

std::map<std::uint32_t, std::size_t> ray_histogram(const std::vector<std::uint32_t>& rays) {
  std::map<std::uint32_t, std::size_t> h;
  for (std::uint32_t r : rays) ++h[r];
  return h;
}

}  // namespace shadetool
