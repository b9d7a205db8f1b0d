// ambient_occlusion.h: how open the sky is from points of a mesh.
//
// For a point p with unit normal n, the open fraction is the cosine-weighted part of the
// hemisphere about n from which a ray leaves without meeting the mesh within distance D:
//
//   open(p) = (1/pi) * integral over the hemisphere of  V(p, w, D) (n.w) dw,    in [0, 1]
//
// (1 under an open sky, 0 fully enclosed; ambient occlusion = 1 - open). It is estimated with N
// rays in directions drawn with density (n.w)/pi (sample_sequence.h's cosine_hemisphere), so the
// estimate is the fraction of rays that escape: open = (N - hits) / N, exactly 1 with no hit.
// Directions come from point i's own scrambled Sobol sequence, seeded from its id (vertex id or
// face id, and options.seed), so the result is the same bits for any thread count and any run.
// RMS error over seeds falls as N^(-3/4) (sample_sequence.h). Ray origins are moved off the
// surface by ray_offset.h (Wächter & Binder), in the scene's float frame (visibility_scene.h).
//
// Inputs:  scene    the mesh's VisibilityScene
//          mesh     the same mesh (per vertex / per face)
//          vertex_normals  #V by 3, the hemisphere's axis (need not be unit; normalised here in
//                   double), as doubles or as floats (12 B per vertex instead of 24 for a caller that
//                   holds them only for this). A float axis is a different axis in its last bits, so
//                   some rays' float directions, and with them a few hits, differ from the double
//                   axis's.
//          points, normals  #P by 3 each, world space (ambient_occlusion_at_points)
//          ids      #P seeds' ids (empty: the point's index)
//          options  samples N >= 1; max_distance D > 0 in world units (default +inf: any hit
//                   counts); seed mixed into every point's scramble; progress (optional) told
//                   the points traced
// Output:  AmbientOcclusion: open_fraction #P (float), rays cast and hits, and `skipped`: points
//          whose normal is zero or not finite (an isolated vertex, a degenerate face): open = 1,
//          no ray cast.
// Per vertex: the point is the vertex itself (its float copy in the BVH, exactly). Per face: the
// point is the mean of the face's corners and the axis the face normal (normals/face_normals.h,
// made 8192 faces at a time just before their rays: the same bits without holding 24 B per face;
// engine/face_normal_blocks.h); degenerate faces are skipped.
// Precision: directions in double, rounded to float for Embree; counts in integers; the fraction
// (N - hits)/N in double, rounded once to float.
// Errors: throws Error for samples outside 1..kMaxOcclusionSamples, D <= 0 or NaN
// (check_occlusion_options), mismatched sizes, non-finite points.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/progress.h>
#include <shadetool/visibility/visibility_scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct AmbientOcclusionOptions {
  std::uint32_t samples = 64;
  double max_distance = std::numeric_limits<double>::infinity();  // world units
  std::uint32_t seed = 0;
  // Reports the rays' stage "occlusion" in points (vertices, faces or points), a block of points
  // per call (core/progress.h); null: nobody listens. Never changes a result.
  ProgressSink* progress = nullptr;
};

// The limits of AmbientOcclusionOptions, checked once here (every entry point below calls it; the
// CLI and Python call it before reading anything and relay the message): Error "WHAT: samples
// must be 1..1048576, got N" or "WHAT: distance must be > 0 (default: unlimited)" (NaN included).
constexpr std::uint32_t kMaxOcclusionSamples = 1u << 20;
void check_occlusion_options(const AmbientOcclusionOptions& options, const std::string& what);

struct AmbientOcclusion {
  std::vector<float> open_fraction;
  std::uint64_t rays = 0;
  std::uint64_t hits = 0;
  std::size_t skipped = 0;
};

AmbientOcclusion ambient_occlusion_per_vertex(const VisibilityScene& scene, const Mesh& mesh,
                                              const std::vector<double>& vertex_normals,
                                              const AmbientOcclusionOptions& options = {});

AmbientOcclusion ambient_occlusion_per_vertex(const VisibilityScene& scene, const Mesh& mesh,
                                              const std::vector<float>& vertex_normals,
                                              const AmbientOcclusionOptions& options = {});

AmbientOcclusion ambient_occlusion_per_face(const VisibilityScene& scene, const Mesh& mesh,
                                            const AmbientOcclusionOptions& options = {});

AmbientOcclusion ambient_occlusion_at_points(const VisibilityScene& scene, const std::vector<double>& points,
                                             const std::vector<double>& normals,
                                             const std::vector<std::uint64_t>& ids,
                                             const AmbientOcclusionOptions& options = {});

// The whole job of `shadetool occlusion` and Python's `shadetool.occlusion`, in one place. Per face;
// or per vertex about the mesh's own vertex normals (Error "SOURCE: K of V vertex normals are
// invalid ..." when any is NaN, Inf or zero: they are the hemispheres' axes) or, when it has none,
// the library's angle-weighted normals (normals/vertex_normals.h, in double). Peak memory
// (bench/visibility/results.md, Memory): computed normals are never held for the whole mesh but
// made 4096 vertices at a time just before those vertices' rays (engine/vertex_normal_blocks.h:
// the same bits as computing them all at once), and per vertex the rays' hits are kept as 1, 2 or
// 4-byte counts (N <= 255, <= 65535, more) and turned into the float open fractions only after the
// BVH is freed (per face too). So the result is bit for bit ambient_occlusion_per_vertex's with
// the same normals in double, or ambient_occlusion_per_face's. The BVH is freed before it returns.
struct MeshOcclusion {
  AmbientOcclusion ao;
  VisibilitySceneStats scene;    // the BVH's size; faces left out of it
  bool normals_computed = false;  // per vertex, without vertex normals in the mesh
};

MeshOcclusion mesh_occlusion(const Mesh& mesh, bool per_face, const AmbientOcclusionOptions& options,
                             const std::string& source);

// The same job for `mesh` against a scene built from another mesh (a glTF document's whole scene,
// gltf/gltf_occlusion.h): the same axes and errors; normals_computed as MeshOcclusion's.
AmbientOcclusion mesh_occlusion(const VisibilityScene& scene, const Mesh& mesh, bool per_face,
                                const AmbientOcclusionOptions& options, const std::string& source, bool& normals_computed);

// The hemispheres' axes per vertex, #V by 3: the mesh's vertex normals (the same Error as
// mesh_occlusion when any is invalid), else the library's angle-weighted ones in double
// (computed = true). For callers that hold them all (occlusion_to_error.h, fit_occlusion.h).
std::vector<double> occlusion_vertex_axes(const Mesh& mesh, const std::string& source, bool& computed);

}  // namespace shadetool
#pragma GCC visibility pop
