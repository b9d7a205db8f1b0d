// vertex_normals.cpp: one unit normal per vertex, the normalised sum of its corners'
// contributions (normals/weighting.h gives the formula and source of each weighting; the sums'
// machinery, memory and threads are in engine/vertex_sums.h).
//
// Precision: every contribution is computed in double (engine/corner_contributions.h). Double accumulates
// in double (default: a vertex of high valence sums hundreds of terms, and double keeps the
// result exact to ~1e-15 rad); Float rounds each contribution once to float (Area and Max after
// one power-of-two scale per mesh, so meshes at 1e-30 or 1e30 neither under- nor overflow) and
// accumulates in float: half the accumulator memory and traffic. Positions far from unit size
// (largest sampled coordinate outside [2^-32, 2^32)) are first scaled exactly by one power of two per mesh
// (engine/mesh_scale.h; the float scale of contributions then follows the same rule). Error against Double: each term
// carries a relative error <= 2^-24 and the float sum of k terms <= (k-1) 2^-24 of the sum of
// their magnitudes, so the angle to the double normal is <= ~k 2^-24 (|terms| / |sum|) rad, which
// for any vertex whose terms do not cancel is < 1e-5 deg for k < 100; measured max 2e-5 deg on
// the benchmark meshes (tests assert 1e-3 deg).
// Fallback (never NaN): a vertex whose sum is zero or not finite takes the unit normal of its
// first valid face (by face index) when it has one (contributions cancelled, e.g. a two-sided
// sheet), else kFallbackNormal = (0, 0, 1) (isolated vertex, or only degenerate faces). Both are
// counted in fallback_vertices.
#include <shadetool/normals/vertex_normals.h>

#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/normals/engine/mesh_scale.h>
#include <shadetool/normals/engine/vertex_sums.h>
#include <shadetool/normals/vertex_fallback.h>

namespace shadetool {
namespace {

using namespace normals_detail;

// n_v = normalise( sum over the corners c of v of contribution_W(c) ) (normals/weighting.h),
// summed in T; a vertex whose sum is zero or not finite takes the fallback.
template <class T, Weighting W>
void compute(const MeshView& mesh, const ChunkPlan* cached_plan, Precision precision, VertexNormals& result) {
  std::vector<float> float_sum;  // the sums for T = float (for double: result.normals itself)
  result.degenerate_faces = sum_by_vertex<T, W>(mesh, cached_plan, result.normals, float_sum);
  const T* sum;
  if constexpr (std::is_same_v<T, double>) sum = result.normals.data();
  else sum = float_sum.data();
  const std::vector<std::uint32_t> failed = normalise_by_vertex(sum, mesh.num_vertices(), result.normals);
  result.fallback_vertices = failed.size();
  if (!failed.empty()) apply_vertex_fallback(mesh, failed, precision, result.normals);
}

}  // namespace

void vertex_normals(const MeshView& mesh, Weighting weighting, Precision precision, VertexNormals& out) {
  std::vector<double> storage;  // exactly scaled positions for a mesh outside the kernels' range (engine/mesh_scale.h)
  const MeshView in_range = in_kernel_range(mesh, storage);
  dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    compute<T, W>(in_range, nullptr, precision, out);
    return 0;
  });
}

void vertex_normals(const MeshView& mesh, const VertexNormalsPlan& plan, Weighting weighting, Precision precision,
                    VertexNormals& out) {
  if (!plan.fits(mesh))
    throw Error("vertex_normals: the plan was built for a mesh with other vertex, face or corner counts");
  std::vector<double> storage;  // as above; the scaled view has the same faces, so the plan fits it
  const MeshView in_range = in_kernel_range(mesh, storage);
  dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    compute<T, W>(in_range, &plan.chunks(), precision, out);
    return 0;
  });
}

VertexNormals vertex_normals(const MeshView& mesh, Weighting weighting, Precision precision) {
  VertexNormals result;
  vertex_normals(mesh, weighting, precision, result);
  return result;
}

// A Mesh is computed through its view: one code path.
VertexNormals vertex_normals(const Mesh& mesh, Weighting weighting, Precision precision) {
  return vertex_normals(MeshView(mesh), weighting, precision);
}

void vertex_normals(const Mesh& mesh, Weighting weighting, Precision precision, VertexNormals& out) {
  vertex_normals(MeshView(mesh), weighting, precision, out);
}

void vertex_normals(const Mesh& mesh, const VertexNormalsPlan& plan, Weighting weighting, Precision precision,
                    VertexNormals& out) {
  vertex_normals(MeshView(mesh), plan, weighting, precision, out);
}

}  // namespace shadetool
