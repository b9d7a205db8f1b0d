// vertex_normals.cpp: one unit normal per vertex, the normalised sum of its corners'
// contributions (corner_contributions.h gives the formula and source of each weighting).
//
// Precision: Double accumulates in double (default: a vertex of high valence sums hundreds of
// terms, and double keeps the result exact to ~1e-15 rad); Float forms edge vectors in double,
// rounds them once to float and computes and accumulates in float, angles excepted (they cost the
// same in double; interior_angle.h): half the accumulator memory and traffic, error ~1e-5 deg
// against double, measured in tests and the benchmark.
// Fallback (never NaN): a vertex whose sum is zero or not finite takes the unit normal of its
// first valid face (by face index) when it has one (contributions cancelled, e.g. a two-sided
// sheet), else kFallbackNormal = (0, 0, 1) (isolated vertex, or only degenerate faces). Both are
// counted in fallback_vertices.
#include "normals/vertex_normals.h"

#include <algorithm>
#include <type_traits>

#include <tbb/parallel_invoke.h>

#include "normals/accumulate_by_vertex.h"
#include "normals/corner_contributions.h"
#include "normals/parallel.h"
#include "normals/vertex_fallback.h"

namespace shadetool {
namespace {

using namespace normals_detail;

// Normalises sum[v] (T) into out[v] (double) for v in [v_begin, v_end); appends the vertices whose
// sum cannot be normalised to `failed`. `sum` and `out` may be the same array (T = double).
template <class T>
void normalise_range(const T* sum, double* out, std::size_t v_begin, std::size_t v_end, std::vector<std::uint32_t>& failed) {
  for (std::size_t v = v_begin; v < v_end; ++v) {
    const Vec3<T> s{sum[3 * v], sum[3 * v + 1], sum[3 * v + 2]};
    const T len = checked_length(s);
    if (len > T(0)) {  // divisor checked; divide (not multiply by 1/len): one rounding per component
      out[3 * v] = double(s.x / len);
      out[3 * v + 1] = double(s.y / len);
      out[3 * v + 2] = double(s.z / len);
    } else {
      failed.push_back(std::uint32_t(v));
    }
  }
}

template <class T, Weighting W>
VertexNormals compute(const Mesh& mesh, Precision precision) {
  const std::size_t V = mesh.num_vertices();
  VertexNormals result;
  // In double the output array itself accumulates the sums (normalised in place afterwards): no
  // second #V by 3 array to allocate, zero and copy. In float a float accumulator is used.
  // Zeroing (and first-touching) the arrays is serial; it runs beside the chunk plan.
  std::vector<float> float_sum;
  ChunkPlan plan;
  auto allocate = [&] {
    result.normals.assign(3 * V, 0.0);
    if constexpr (!std::is_same_v<T, double>) float_sum.assign(3 * V, 0.0f);
  };
  auto make_plan = [&] { plan = plan_chunks<false>(mesh, nullptr, V); };
  if (mesh.num_faces() < kSerialBelow) {
    allocate();
    make_plan();
  } else {
    tbb::parallel_invoke(allocate, make_plan);
  }
  T* sum;
  if constexpr (std::is_same_v<T, double>) sum = result.normals.data();
  else sum = float_sum.data();
  const bool triangles = mesh.all_triangles();
  result.degenerate_faces = accumulate_by_target<false, T>(mesh, plan, nullptr,
      [&](std::size_t f_begin, std::size_t f_end, auto&& sink) {
        return triangles ? triangle_contributions<T, W>(mesh, f_begin, f_end, sink)
                         : polygon_contributions<T, W>(mesh, f_begin, f_end, sink);
      }, sum);

  // Normalise in fixed blocks (independent of the thread count); failures listed per block and
  // concatenated in block order, so needs_fallback is ascending.
  constexpr std::size_t kBlock = 1 << 14;
  const std::size_t blocks = (V + kBlock - 1) / kBlock;
  std::vector<std::vector<std::uint32_t>> failed(blocks);
  parallel_blocks(blocks, [&](std::size_t b) {
    normalise_range<T>(sum, result.normals.data(), b * kBlock, std::min(V, (b + 1) * kBlock), failed[b]);
  });
  std::vector<std::uint32_t> needs_fallback;
  for (auto& list : failed) needs_fallback.insert(needs_fallback.end(), list.begin(), list.end());
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
