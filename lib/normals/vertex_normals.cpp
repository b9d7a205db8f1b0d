// vertex_normals.cpp: one unit normal per vertex, the normalised sum of its corners'
// contributions (corner_contributions.h gives the formula and source of each weighting).
//
// Precision: Double accumulates in double (default: a vertex of high valence sums hundreds of
// terms, and double keeps the result exact to ~1e-15 rad); Float forms edge vectors in double,
// rounds them once to float and computes and accumulates in float (half the accumulator memory and
// traffic; error ~1e-5 deg against double, measured in tests and the benchmark).
// Fallback (never NaN): a vertex whose sum is zero or not finite takes the unit normal of its
// first valid face (by face index) when it has one (contributions cancelled, e.g. a two-sided
// sheet), else kFallbackNormal = (0, 0, 1) (isolated vertex, or only degenerate faces). Both are
// counted in fallback_vertices.
#include "normals/vertex_normals.h"

#include "normals/corner_contributions.h"
#include "normals/vertex_fallback.h"

namespace shadetool {
namespace {

using namespace normals_detail;

template <class T, Weighting W>
VertexNormals compute(const Mesh& mesh, Precision precision) {
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces();
  std::vector<T> sum(3 * V, T(0));
  auto add = [s = sum.data()](std::size_t, std::uint32_t v, const Vec3<T>& n) {
    T* o = s + 3 * std::size_t(v);
    o[0] += n.x; o[1] += n.y; o[2] += n.z;
  };
  if (mesh.all_triangles()) triangle_contributions<T, W>(mesh, 0, F, add);
  else polygon_contributions<T, W>(mesh, 0, F, add);

  VertexNormals result;
  result.normals.resize(3 * V);
  std::vector<std::uint32_t> needs_fallback;
  for (std::size_t v = 0; v < V; ++v) {
    const Vec3<T> s{sum[3 * v], sum[3 * v + 1], sum[3 * v + 2]};
    const T len = checked_length(s);
    if (len > T(0)) {  // divisor checked
      const T inv = T(1) / len;
      result.normals[3 * v] = double(s.x * inv);
      result.normals[3 * v + 1] = double(s.y * inv);
      result.normals[3 * v + 2] = double(s.z * inv);
    } else {
      needs_fallback.push_back(std::uint32_t(v));
    }
  }
  result.fallback_vertices = needs_fallback.size();
  if (!needs_fallback.empty()) apply_vertex_fallback(mesh, needs_fallback, precision, result.normals);
  return result;
}

}  // namespace

VertexNormals vertex_normals(const Mesh& mesh, Weighting weighting, Precision precision) {
  return dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    return compute<T, W>(mesh, precision);
  });
}

}  // namespace shadetool
