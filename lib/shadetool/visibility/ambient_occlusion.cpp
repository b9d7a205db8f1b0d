// ambient_occlusion.cpp
#include <shadetool/visibility/ambient_occlusion.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/normals/invalid_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/engine/cosine_rays.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/engine/face_normal_blocks.h>
#include <shadetool/visibility/engine/point_ranges.h>
#include <shadetool/visibility/engine/vertex_normal_blocks.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>

namespace shadetool {

void check_occlusion_options(const AmbientOcclusionOptions& o, const std::string& what) {
  if (o.samples < 1 || o.samples > kMaxOcclusionSamples)
    throw Error(what + ": samples must be 1.." + std::to_string(kMaxOcclusionSamples) + ", got " + std::to_string(o.samples));
  if (!(o.max_distance > 0)) throw Error(what + ": distance must be > 0 (default: unlimited)");
}

namespace {

constexpr std::uint32_t kVertexSalt = 0, kFaceSalt = 1;

void check_options(const AmbientOcclusionOptions& o) { check_occlusion_options(o, "ambient occlusion"); }

// Unit n from a stored normal, or false when it has zero or non-finite length.
bool unit_axis(const Vec3d& raw, Vec3d& n) {
  const double l = length(raw);
  if (!(l > 0) || !std::isfinite(l)) return false;
  n = raw * (1.0 / l);  // divisor checked
  return true;
}

// The estimate open = (N - hits) / N, in double, rounded once to float (exactly 1 with no hit).
float open_fraction(std::uint32_t hits, std::uint32_t samples) {
  return float(double(samples - hits) / double(samples));  // divisor: samples >= 1 (check_options)
}

struct Totals {
  std::uint64_t hits = 0, skipped = 0;
};

// Traces the rays of points [begin, end): point(i, p_local, n, id) fills point i's query or
// returns false (skipped: nothing stored), store(i, hits) keeps a traced point's hits. Each TBB
// range's points go into Embree streams of up to 2048 rays (engine/cosine_rays.h's CosineRayBatch:
// a point's rays depend only on its own seed and axis, so the split changes no answer). Totals are
// summed per range, then added atomically: integer sums, the same for any split.
template <class PointFn, class StoreFn>
Totals trace(const VisibilityScene& scene, std::size_t begin, std::size_t end, std::uint32_t salt,
             const AmbientOcclusionOptions& options, const PointFn& point, const StoreFn& store) {
  std::uint64_t total_hits = 0, total_skipped = 0;
  const float tfar = std::isinf(options.max_distance)
                         ? std::numeric_limits<float>::infinity()
                         : float(options.max_distance * scene.scale());
  const std::uint32_t salt_seed = visibility::hash_combine(salt, options.seed);
  RTCScene rtc = scene.impl().scene;
  visibility_engine::parallel_point_ranges(end - begin, options.samples, [&](std::size_t b, std::size_t e) {
    std::uint64_t range_hits = 0, range_skipped = 0;
    visibility_engine::CosineRayBatch batch(rtc, tfar, (e - b) * std::size_t(options.samples));
    const auto done = [&](std::size_t i, std::uint32_t hits) {
      range_hits += hits;
      store(i, hits);
    };
    for (std::size_t i = begin + b; i < begin + e; ++i) {
      Vec3f p;
      Vec3d n;
      std::uint64_t id = i;
      if (!point(i, p, n, id)) {
        ++range_skipped;
        continue;
      }
      batch.add(i, p, n, visibility::point_seed(id, salt_seed), options.samples, done);
    }
    batch.finish(done);  // every point of the range is stored: the end of one block of work
    __atomic_add_fetch(&total_hits, range_hits, __ATOMIC_RELAXED);
    __atomic_add_fetch(&total_skipped, range_skipped, __ATOMIC_RELAXED);
    report_advance(options.progress, e - b);
  });
  return {total_hits, total_skipped};
}

AmbientOcclusion totals(Totals t, std::size_t count, std::uint32_t samples) {
  AmbientOcclusion out;
  out.hits = t.hits;
  out.skipped = std::size_t(t.skipped);
  out.rays = std::uint64_t(count - out.skipped) * samples;
  return out;
}

// All P points at once, each open fraction stored as it is made (float, 4 B per point).
template <class PointFn>
AmbientOcclusion run(const VisibilityScene& scene, std::size_t count, std::uint32_t salt,
                     const AmbientOcclusionOptions& options, const PointFn& point) {
  check_options(options);
  report_begin(options.progress, "occlusion", count);
  std::vector<float> open(count, 1.0f);
  AmbientOcclusion out = totals(trace(scene, 0, count, salt, options, point,
                                      [&](std::size_t i, std::uint32_t hits) { open[i] = open_fraction(hits, options.samples); }),
                                count, options.samples);
  out.open_fraction = std::move(open);
  return out;
}

// Row i of a #V by 3 array, widened to double.
template <class Real>
Vec3d row(const std::vector<Real>& a, std::size_t i) {
  return {double(a[3 * i]), double(a[3 * i + 1]), double(a[3 * i + 2])};
}

// Vertex v's query: its BVH vertex and its unit axis; false when the axis is zero or not finite,
// or the vertex is not finite or lies too far to be a float in the scene's frame (isolated).
bool vertex_query(const VisibilityScene& scene, const Mesh& mesh, std::size_t v, const Vec3d& axis, Vec3f& p,
                  Vec3d& n) {
  const std::vector<float>& local = scene.impl().vertices;
  if (!is_finite(mesh.position(v)) || !unit_axis(axis, n)) return false;
  p = {local[3 * v], local[3 * v + 1], local[3 * v + 2]};  // the BVH's own vertex
  return is_finite(Vec3f((mesh.position(v) - scene.centre()) * scene.scale()));  // else: far isolated
}

// Faces are traced a block at a time, each block's normals made just before its rays
// (engine/face_normal_blocks.h: face_normals' bits without its #F rows; 2^13 faces = 192 KB).
constexpr std::size_t kFaceBlock = std::size_t(1) << 13;

// Face f's query: the mean of its corners (scene frame) and its unit normal; false for a face
// without area (normal (0, 0, 0)).
bool face_query(const VisibilityScene& scene, const Mesh& mesh, std::size_t f, const Vec3d& normal, Vec3f& p,
                Vec3d& n) {
  if (!unit_axis(normal, n)) return false;
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  Vec3d sum{};
  for (std::uint32_t c = b; c < e; ++c) sum += mesh.position(mesh.corner_vertex[c]) - scene.centre();
  p = Vec3f(sum * (scene.scale() / double(e - b)));  // divisor: a face with area has >= 3 corners
  return true;
}

template <class StoreFn>
Totals trace_faces(const VisibilityScene& scene, const Mesh& mesh, const AmbientOcclusionOptions& options,
                   const StoreFn& store) {
  Totals sum;
  report_begin(options.progress, "occlusion", mesh.num_faces());
  std::vector<std::uint32_t> starts;
  for (std::size_t first = 0; first < mesh.num_faces(); first += kFaceBlock) {
    const std::size_t last = std::min(mesh.num_faces(), first + kFaceBlock);
    const std::vector<double> normals = visibility_engine::face_normal_block(mesh, first, last, starts);
    const Totals block = trace(scene, first, last, kFaceSalt, options,
                               [&](std::size_t f, Vec3f& p, Vec3d& n, std::uint64_t&) {
                                 return face_query(scene, mesh, f, get3(normals, f - first), p, n);
                               }, store);
    sum.hits += block.hits;
    sum.skipped += block.skipped;
  }
  return sum;
}

template <class Real>
AmbientOcclusion per_vertex(const VisibilityScene& scene, const Mesh& mesh, const std::vector<Real>& vertex_normals,
                            const AmbientOcclusionOptions& options) {
  const std::size_t nv = mesh.num_vertices();
  if (vertex_normals.size() != 3 * nv)
    throw Error("ambient occlusion: " + std::to_string(vertex_normals.size() / 3) + " normals for " +
                std::to_string(nv) + " vertices");
  if (scene.impl().vertices.size() != 3 * nv + 1) throw Error("ambient occlusion: the scene was built from another mesh");
  return run(scene, nv, kVertexSalt, options, [&](std::size_t v, Vec3f& p, Vec3d& n, std::uint64_t&) {
    return vertex_query(scene, mesh, v, row(vertex_normals, v), p, n);
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
  check_options(options);
  const std::size_t nf = mesh.num_faces();
  std::vector<float> open(nf, 1.0f);
  AmbientOcclusion out = totals(trace_faces(scene, mesh, options, [&](std::size_t f, std::uint32_t hits) {
                                  open[f] = open_fraction(hits, options.samples);
                                }),
                                nf, options.samples);
  out.open_fraction = std::move(open);
  return out;
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

// Computed normals are made 2^12 = 4096 vertices at a time (engine/vertex_normal_blocks.h: about
// 0.45 MB while a block is alive, against 12 MB in double or 6 MB in float for all of them at 1M
// triangles).
constexpr unsigned kNormalBlockLog2 = 12;

// mesh_occlusion's rays: per face (normals made a block at a time, as ambient_occlusion_per_face),
// or per vertex about the mesh's normals or (computed) the library's, made block by block just
// before their rays. Each point's hits are kept as a Count (1, 2 or 4 B, wide enough for N) and
// turned into the float open fractions once the BVH is freed, so the rays' peak holds neither #V
// normals nor #V floats. The same bits as ambient_occlusion_per_face / _per_vertex (normals in
// double).
template <class Count>
AmbientOcclusion mesh_counts(const Mesh& mesh, bool per_face, bool computed, const AmbientOcclusionOptions& options,
                             VisibilitySceneStats& stats) {
  check_options(options);
  const std::size_t count = per_face ? mesh.num_faces() : mesh.num_vertices();
  std::vector<Count> hits(count, 0);  // a skipped point keeps 0: open fraction 1
  const auto store = [&](std::size_t i, std::uint32_t h) { hits[i] = Count(h); };  // h <= N fits Count
  Totals sum;
  {
    const VisibilityScene scene(mesh);
    if (per_face) {
      sum = trace_faces(scene, mesh, options, store);
    } else if (!computed) {
      report_begin(options.progress, "occlusion", count);
      sum = trace(scene, 0, count, kVertexSalt, options, [&](std::size_t v, Vec3f& p, Vec3d& n, std::uint64_t&) {
        return vertex_query(scene, mesh, v, get3(mesh.vertex_normals, v), p, n);
      }, store);
    } else {
      visibility_engine::VertexNormalBlocks blocks(mesh, kNormalBlockLog2);
      VertexNormals normals;
      report_begin(options.progress, "occlusion", count);
      for (std::size_t k = 0; k < blocks.blocks(); ++k) {
        blocks.compute(k, normals);
        const std::size_t first = blocks.begin(k);
        const Totals block = trace(scene, first, blocks.end(k), kVertexSalt, options,
                                   [&](std::size_t v, Vec3f& p, Vec3d& n, std::uint64_t&) {
                                     return vertex_query(scene, mesh, v, get3(normals.normals, v - first), p, n);
                                   }, store);
        sum.hits += block.hits;
        sum.skipped += block.skipped;
      }
    }
    stats = scene.stats();
  }  // the BVH and the last block's normals are freed here
  AmbientOcclusion out = totals(sum, count, options.samples);
  out.open_fraction.resize(count);
  for (std::size_t i = 0; i < count; ++i) out.open_fraction[i] = open_fraction(hits[i], options.samples);
  return out;
}

}  // namespace

namespace {

// The hemispheres' axes are the mesh's own vertex normals when it has them: one per vertex, every
// one usable (else Error: an axis cannot be made up).
void require_axis_normals(const Mesh& mesh, const std::string& source) {
  if (mesh.vertex_normals.size() != 3 * mesh.num_vertices())
    throw Error("ambient occlusion: " + std::to_string(mesh.vertex_normals.size() / 3) + " normals for " +
                std::to_string(mesh.num_vertices()) + " vertices");
  const std::size_t invalid = count_invalid_normals(mesh.vertex_normals);
  if (invalid > 0)
    throw Error(located(source, 0,
                        std::to_string(invalid) + " of " + std::to_string(mesh.num_vertices()) +
                            " vertex normals are invalid (NaN, Inf or zero length); they give the hemisphere's "
                            "axis: recompute them first (`shadetool normals --recompute`, or normals/vertex_normals.h)"));
}

}  // namespace

std::vector<double> occlusion_vertex_axes(const Mesh& mesh, const std::string& source, bool& computed) {
  if (mesh.has_vertex_normals()) require_axis_normals(mesh, source);
  computed = !mesh.has_vertex_normals();
  return computed ? vertex_normals(mesh).normals : mesh.vertex_normals;
}

MeshOcclusion mesh_occlusion(const Mesh& mesh, bool per_face, const AmbientOcclusionOptions& options,
                             const std::string& source) {
  MeshOcclusion out;
  if (!per_face && mesh.has_vertex_normals()) require_axis_normals(mesh, source);
  out.normals_computed = !per_face && !mesh.has_vertex_normals();
  if (options.samples <= 0xffu)
    out.ao = mesh_counts<std::uint8_t>(mesh, per_face, out.normals_computed, options, out.scene);
  else if (options.samples <= 0xffffu)
    out.ao = mesh_counts<std::uint16_t>(mesh, per_face, out.normals_computed, options, out.scene);
  else
    out.ao = mesh_counts<std::uint32_t>(mesh, per_face, out.normals_computed, options, out.scene);
  return out;
}

AmbientOcclusion mesh_occlusion(const VisibilityScene& scene, const Mesh& mesh, bool per_face,
                                const AmbientOcclusionOptions& options, const std::string& source, bool& normals_computed) {
  normals_computed = false;
  if (per_face) return ambient_occlusion_per_face(scene, mesh, options);
  // The axes: the mesh's normals, or the library's angle-weighted ones in double (the bits
  // mesh_occlusion's blocks give). The scene's vertices are another mesh's: the vertices go in as
  // points (to_local rounds them as the BVH's copy of the same world positions was rounded), each
  // with its index as its id.
  if (mesh.has_vertex_normals()) require_axis_normals(mesh, source);
  normals_computed = !mesh.has_vertex_normals();
  const std::vector<double> axes = normals_computed ? vertex_normals(mesh).normals : mesh.vertex_normals;
  std::vector<std::uint64_t> ids(mesh.num_vertices());
  for (std::size_t v = 0; v < ids.size(); ++v) ids[v] = v;
  return ambient_occlusion_at_points(scene, mesh.positions, axes, ids, options);
}

}  // namespace shadetool
