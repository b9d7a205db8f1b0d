// vertex_normals.cpp: one unit normal per vertex, the normalised sum of its corners'
// contributions (corner_contributions.h gives the formula and source of each weighting).
//
// Precision: every contribution is computed in double (corner_contributions.h). Double accumulates
// in double (default: a vertex of high valence sums hundreds of terms, and double keeps the
// result exact to ~1e-15 rad); Float rounds each contribution once to float (Area and Max after
// one power-of-two scale per mesh, so meshes at 1e-30 or 1e30 neither under- nor overflow) and
// accumulates in float: half the accumulator memory and traffic. Error against Double: each term
// carries a relative error <= 2^-24 and the float sum of k terms <= (k-1) 2^-24 of the sum of
// their magnitudes, so the angle to the double normal is <= ~k 2^-24 (|terms| / |sum|) rad, which
// for any vertex whose terms do not cancel is < 1e-5 deg for k < 100; measured max 2e-5 deg on
// the benchmark meshes (tests assert 1e-3 deg).
// Fallback (never NaN): a vertex whose sum is zero or not finite takes the unit normal of its
// first valid face (by face index) when it has one (contributions cancelled, e.g. a two-sided
// sheet), else kFallbackNormal = (0, 0, 1) (isolated vertex, or only degenerate faces). Both are
// counted in fallback_vertices.
#include <shadetool/normals/vertex_normals.h>

#include <algorithm>
#include <type_traits>

#include <tbb/parallel_invoke.h>

#include <shadetool/core/engine/bulk_reserve.h>
#include <shadetool/core/error.h>
#include <shadetool/normals/engine/accumulate_by_vertex.h>
#include <shadetool/normals/engine/corner_contributions.h>
#include <shadetool/normals/engine/normalise_sums.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/normals/vertex_fallback.h>

namespace shadetool {
namespace {

using namespace normals_detail;
using namespace engine;

// plan: the caller's cached chunk plan, or null (then made here, beside zeroing the sums).
template <class T, Weighting W>
void compute(const Mesh& mesh, const ChunkPlan* cached, Precision precision, VertexNormals& result) {
  const std::size_t V = mesh.num_vertices();
  result.fallback_vertices = result.degenerate_faces = 0;
  // In double the output array itself accumulates the sums (normalised in place afterwards): no
  // second #V by 3 array to allocate, zero and copy. In float a float accumulator is used. An
  // output array that already has the capacity (a caller reusing `result`) is reused, not
  // reallocated. With a cached plan the zeroing is split over the threads.
  // Float sums are padded to 4 per vertex (16 bytes): one SSE addition per corner instead of three
  // scalar ones (accumulate_by_vertex.h, add_to_row).
  constexpr std::size_t S = std::is_same_v<T, double> ? 3 : 4;
  std::vector<float> float_sum;
  ChunkPlan own_plan;
  const bool big = mesh.num_faces() >= kSerialBelow;
  // A fresh output array in huge pages (core/engine/bulk_reserve.h): a one-shot caller (the CLI, repair)
  // otherwise pays a page fault per 4 KiB of it (bench/repair: 16.1 -> 12.1 ms for the angle
  // normals of 1M triangles). No effect when `result` already has the capacity.
  reserve_bulk(result.normals, 3 * V);
  if (cached) {
    result.normals.resize(3 * V);
    if constexpr (!std::is_same_v<T, double>) float_sum.resize(S * V);
    constexpr std::size_t kZeroBlock = std::size_t(1) << 16;  // values
    const std::size_t n = S * V, blocks = (n + kZeroBlock - 1) / kZeroBlock;
    auto zero = [&](std::size_t b) {
      const std::size_t begin = b * kZeroBlock, end = std::min(n, begin + kZeroBlock);
      if constexpr (std::is_same_v<T, double>)
        std::fill(result.normals.begin() + std::ptrdiff_t(begin), result.normals.begin() + std::ptrdiff_t(end), 0.0);
      else
        std::fill(float_sum.begin() + std::ptrdiff_t(begin), float_sum.begin() + std::ptrdiff_t(end), 0.0f);
    };
    if (big && cached->K > 0) parallel_blocks(blocks, zero);
    else for (std::size_t b = 0; b < blocks; ++b) zero(b);
  } else {
    // Without a cached plan, the angle and Max kernels plan the chunks here, beside the (serial)
    // zeroing of the sums: one bitmap pass over the corners per thread (accumulate_by_vertex.h).
    // Measured on the 1M torus with both cores free: angle 12.1 -> 9.8 ms, Max 9.5 -> 8.4 ms on 2
    // threads, but area 5.8 -> 6.8 ms (the plan costs half the area kernel): the cheap kernels sum
    // serially. float: the output is not a sum, and every entry is written (normalised or
    // fallback).
    auto zero = [&] {
      if constexpr (std::is_same_v<T, double>) {
        result.normals.assign(3 * V, 0.0);
      } else {
        result.normals.resize(3 * V);
        float_sum.assign(S * V, 0.0f);
      }
    };
    constexpr bool kPlanPays = W == Weighting::Angle || W == Weighting::Max;
    if (kPlanPays && big && usable_threads() >= 2)
      tbb::parallel_invoke(zero, [&] { own_plan = plan_chunks<false>(mesh, nullptr, V); });
    else
      zero();
  }
  const ChunkPlan& plan = cached ? *cached : own_plan;
  T* sum;
  if constexpr (std::is_same_v<T, double>) sum = result.normals.data();
  else sum = float_sum.data();
  const bool triangles = mesh.all_triangles();
  // float Area/Max: one power of two for the whole mesh (corner_contributions.h). A vertex whose
  // float sum still overflows (a face ~2^100 times larger than the sampled ones) takes the
  // fallback below: a valid unit normal, counted.
  const double scale = contribution_scale<T, W>(mesh);
  const RowHint rows{reinterpret_cast<const char*>(sum), S * sizeof(T)};
  result.degenerate_faces = accumulate_by_target<false, T, S>(mesh, plan, nullptr,
      [&](std::size_t f_begin, std::size_t f_end, auto&& sink) {
        return triangles ? triangle_contributions<T, W>(mesh, f_begin, f_end, sink, scale, rows)
                         : polygon_contributions<T, W>(mesh, f_begin, f_end, sink, scale);
      }, sum);

  // Normalise in fixed blocks (independent of the thread count); failures listed per block and
  // concatenated in block order, so needs_fallback is ascending.
  constexpr std::size_t kBlock = 1 << 14;
  const std::size_t blocks = (V + kBlock - 1) / kBlock;
  std::vector<std::vector<std::uint32_t>> failed(blocks);
  parallel_blocks(blocks, [&](std::size_t b) {
    normalise_range<T, S>(sum, result.normals.data(), b * kBlock, std::min(V, (b + 1) * kBlock), failed[b]);
  });
  std::vector<std::uint32_t> needs_fallback;
  for (auto& list : failed) needs_fallback.insert(needs_fallback.end(), list.begin(), list.end());
  result.fallback_vertices = needs_fallback.size();
  if (!needs_fallback.empty()) apply_vertex_fallback(mesh, needs_fallback, precision, result.normals);
}

}  // namespace

void vertex_normals(const Mesh& mesh, Weighting weighting, Precision precision, VertexNormals& out) {
  dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    compute<T, W>(mesh, nullptr, precision, out);
    return 0;
  });
}

void vertex_normals(const Mesh& mesh, const VertexNormalsPlan& plan, Weighting weighting, Precision precision,
                    VertexNormals& out) {
  if (!plan.fits(mesh))
    throw Error("vertex_normals: the plan was built for a mesh with other vertex, face or corner counts");
  dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    compute<T, W>(mesh, &plan.chunks(), precision, out);
    return 0;
  });
}

VertexNormals vertex_normals(const Mesh& mesh, Weighting weighting, Precision precision) {
  VertexNormals result;
  vertex_normals(mesh, weighting, precision, result);
  return result;
}

}  // namespace shadetool
