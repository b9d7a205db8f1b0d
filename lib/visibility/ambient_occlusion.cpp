// ambient_occlusion.cpp
#include <shadetool/visibility/ambient_occlusion.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/invalid_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/engine/point_ranges.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool {

namespace {

constexpr std::uint32_t kVertexSalt = 0, kFaceSalt = 1;

// One point: p_local on the surface (scene frame), n unit (directions are the same in both frames:
// the scale is uniform and positive). Returns the number of rays that hit.
std::uint32_t count_hits(RTCScene scene, const Vec3f& p_local, const Vec3d& n, std::uint32_t seed,
                         std::uint32_t samples, float tfar_local) {
  Vec3d t, b;
  visibility::orthonormal_basis(n, t, b);
  const Vec3f origin = visibility::offset_ray_origin(p_local, Vec3f(n));
  constexpr std::uint32_t kStream = 64;  // rays made, then traced together
  RTCRay rays[kStream];
  std::uint32_t hits = 0;
  for (std::uint32_t first = 0; first < samples; first += kStream) {
    const std::uint32_t count = std::min(kStream, samples - first);
    for (std::uint32_t j = 0; j < count; ++j) {
      const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(first + j, seed);
      const Vec3d w = visibility::cosine_hemisphere(s.u, s.v);
      rays[j] = visibility_engine::make_ray(origin, Vec3f(t * w.x + b * w.y + n * w.z), tfar_local);
    }
    hits += visibility_engine::count_occluded(scene, rays, count);
  }
  return hits;
}

void check_options(const AmbientOcclusionOptions& o) {
  if (o.samples == 0) throw Error("ambient occlusion: samples must be at least 1");
  if (!(o.max_distance > 0)) throw Error("ambient occlusion: max_distance must be positive");
}

// Unit n from a stored normal, or false when it has zero or non-finite length.
bool unit_axis(const Vec3d& raw, Vec3d& n) {
  const double l = length(raw);
  if (!(l > 0) || !std::isfinite(l)) return false;
  n = raw * (1.0 / l);  // divisor checked
  return true;
}

// Runs count_hits over P points: point(i, p_local, n, id) fills point i's query or returns false
// (skipped).
template <class PointFn>
AmbientOcclusion run(const VisibilityScene& scene, std::size_t count, std::uint32_t salt,
                     const AmbientOcclusionOptions& options, const PointFn& point) {
  check_options(options);
  AmbientOcclusion out;
  out.open_fraction.assign(count, 1.0f);
  // Totals summed per range, then added atomically: integer sums, the same for any split (no
  // per-point arrays: at 1M triangles they were 2.5 MB of the command's peak).
  std::uint64_t total_hits = 0, total_skipped = 0;
  const float tfar = std::isinf(options.max_distance)
                         ? std::numeric_limits<float>::infinity()
                         : float(options.max_distance * scene.scale());
  const std::uint32_t salt_seed = visibility::hash_combine(salt, options.seed);
  RTCScene rtc = scene.impl().scene;
  visibility_engine::parallel_point_ranges(count, options.samples, [&](std::size_t begin, std::size_t end) {
    std::uint64_t range_hits = 0, range_skipped = 0;
    for (std::size_t i = begin; i < end; ++i) {
      Vec3f p;
      Vec3d n;
      std::uint64_t id = i;
      if (!point(i, p, n, id)) {
        ++range_skipped;
        continue;
      }
      const std::uint32_t hits = count_hits(rtc, p, n, visibility::point_seed(id, salt_seed), options.samples, tfar);
      range_hits += hits;
      out.open_fraction[i] = float(double(options.samples - hits) / double(options.samples));  // divisor >= 1
    }
    __atomic_add_fetch(&total_hits, range_hits, __ATOMIC_RELAXED);
    __atomic_add_fetch(&total_skipped, range_skipped, __ATOMIC_RELAXED);
  });
  out.hits = total_hits;
  out.skipped = std::size_t(total_skipped);
  out.rays = std::uint64_t(count - out.skipped) * options.samples;
  return out;
}

}  // namespace

namespace {

template <class Real>
AmbientOcclusion per_vertex(const VisibilityScene& scene, const Mesh& mesh, const std::vector<Real>& vertex_normals,
                            const AmbientOcclusionOptions& options) {
  const std::size_t nv = mesh.num_vertices();
  if (vertex_normals.size() != 3 * nv)
    throw Error("ambient occlusion: " + std::to_string(vertex_normals.size() / 3) + " normals for " +
                std::to_string(nv) + " vertices");
  const std::vector<float>& local = scene.impl().vertices;
  if (local.size() != 3 * nv + 1) throw Error("ambient occlusion: the scene was built from another mesh");
  return run(scene, nv, kVertexSalt, options, [&](std::size_t v, Vec3f& p, Vec3d& n, std::uint64_t&) {
    const Vec3d axis{double(vertex_normals[3 * v]), double(vertex_normals[3 * v + 1]), double(vertex_normals[3 * v + 2])};
    if (!is_finite(mesh.position(v)) || !unit_axis(axis, n)) return false;
    p = {local[3 * v], local[3 * v + 1], local[3 * v + 2]};  // the BVH's own vertex
    return is_finite(Vec3f((mesh.position(v) - scene.centre()) * scene.scale()));  // else: far isolated
  });
}

}  // namespace

AmbientOcclusion ambient_occlusion_per_vertex(const VisibilityScene& scene, const Mesh& mesh,
                                              const std::vector<double>& vertex_normals,
                                              const AmbientOcclusionOptions& options) {
  return per_vertex(scene, mesh, vertex_normals, options);
}

AmbientOcclusion ambient_occlusion_per_vertex(const VisibilityScene& scene, const Mesh& mesh,
                                              const std::vector<float>& vertex_normals,
                                              const AmbientOcclusionOptions& options) {
  return per_vertex(scene, mesh, vertex_normals, options);
}

AmbientOcclusion ambient_occlusion_per_face(const VisibilityScene& scene, const Mesh& mesh,
                                            const AmbientOcclusionOptions& options) {
  const std::vector<double> normals = face_normals(mesh);
  return run(scene, mesh.num_faces(), kFaceSalt, options, [&](std::size_t f, Vec3f& p, Vec3d& n, std::uint64_t&) {
    if (!unit_axis(get3(normals, f), n)) return false;  // degenerate face: normal (0,0,0)
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    Vec3d sum{};
    for (std::uint32_t c = b; c < e; ++c) sum += mesh.position(mesh.corner_vertex[c]) - scene.centre();
    p = Vec3f(sum * (scene.scale() / double(e - b)));  // divisor: a non-degenerate face has >= 3 corners
    return true;
  });
}

AmbientOcclusion ambient_occlusion_at_points(const VisibilityScene& scene, const std::vector<double>& points,
                                             const std::vector<double>& normals,
                                             const std::vector<std::uint64_t>& ids,
                                             const AmbientOcclusionOptions& options) {
  const std::size_t n = points.size() / 3;
  if (points.size() % 3 != 0 || normals.size() != points.size() || (!ids.empty() && ids.size() != n))
    throw Error("ambient occlusion: points, normals and ids differ in size");
  for (std::size_t i = 0; i < n; ++i)
    if (!is_finite(get3(points, i))) throw Error("ambient occlusion: point " + std::to_string(i) + " is not finite");
  std::vector<Vec3f> local(n);
  for (std::size_t i = 0; i < n; ++i) local[i] = scene.to_local(get3(points, i));
  return run(scene, n, kVertexSalt, options, [&](std::size_t i, Vec3f& p, Vec3d& axis, std::uint64_t& id) {
    if (!ids.empty()) id = ids[i];
    p = local[i];
    return unit_axis(get3(normals, i), axis);
  });
}

namespace {

// The hemispheres' axes of the occlusion job, per vertex: the mesh's own vertex normals (every one
// valid, else Error: they are the axes), or when it has none the library's angle-weighted normals
// rounded once to float (returned; their double copy is freed on return). Empty: use the mesh's.
std::vector<float> job_axes(const Mesh& mesh, const std::string& source, bool& computed) {
  computed = false;
  if (mesh.has_vertex_normals()) {
    const std::size_t invalid = count_invalid_normals(mesh.vertex_normals);
    if (invalid > 0)
      throw Error(located(source, 0,
                          std::to_string(invalid) + " of " + std::to_string(mesh.num_vertices()) +
                              " vertex normals are invalid (NaN, Inf or zero length); they give the hemisphere's "
                              "axis: recompute them first (`shadetool normals --recompute`, or normals/vertex_normals.h)"));
    return {};
  }
  const std::vector<double> normals = vertex_normals(mesh).normals;
  computed = true;
  return std::vector<float>(normals.begin(), normals.end());  // unit, rounded once to float
}

AmbientOcclusion job_occlusion(const VisibilityScene& scene, const Mesh& mesh, bool per_face, const std::vector<float>& computed,
                               const AmbientOcclusionOptions& options) {
  if (per_face) return ambient_occlusion_per_face(scene, mesh, options);
  if (!computed.empty() || !mesh.has_vertex_normals()) return ambient_occlusion_per_vertex(scene, mesh, computed, options);
  return ambient_occlusion_per_vertex(scene, mesh, mesh.vertex_normals, options);
}

}  // namespace

MeshOcclusion mesh_occlusion(const Mesh& mesh, bool per_face, const AmbientOcclusionOptions& options,
                             const std::string& source) {
  MeshOcclusion out;
  // The axes first, their double copy freed before the BVH is built (peak memory).
  const std::vector<float> computed = per_face ? std::vector<float>() : job_axes(mesh, source, out.normals_computed);
  const VisibilityScene scene(mesh);
  out.ao = job_occlusion(scene, mesh, per_face, computed, options);
  out.scene = scene.stats();
  return out;
}

AmbientOcclusion mesh_occlusion(const VisibilityScene& scene, const Mesh& mesh, bool per_face,
                                const AmbientOcclusionOptions& options, const std::string& source, bool& normals_computed) {
  normals_computed = false;
  if (per_face) return ambient_occlusion_per_face(scene, mesh, options);
  // The scene's vertices are another mesh's: the vertices as points (to_local rounds them as the
  // BVH's copy of the same world positions was rounded), each with its index as its id.
  const std::vector<float> computed = job_axes(mesh, source, normals_computed);
  const std::vector<double> axes = normals_computed ? std::vector<double>(computed.begin(), computed.end()) : mesh.vertex_normals;
  std::vector<std::uint64_t> ids(mesh.num_vertices());
  for (std::size_t v = 0; v < ids.size(); ++v) ids[v] = v;
  return ambient_occlusion_at_points(scene, mesh.positions, axes, ids, options);
}

}  // namespace shadetool
