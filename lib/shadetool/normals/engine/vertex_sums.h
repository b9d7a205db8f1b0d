// vertex_sums.h: the machinery behind vertex_normals (internal to lib/normals): where the
// per-vertex sums live, how they are zeroed and split over threads, and how they are normalised.
// The formulas are elsewhere (normals/weighting.h; the loops that call them: corner_contributions.h).
//
// sum_by_vertex<T, W>   per-vertex sums of the corners' contributions of weighting W, accumulated
//                       in T. Returns the number of degenerate faces (they contribute nothing).
//   Storage: for T = double the output array itself (#V by 3) holds the sums and is normalised in
//   place (no second array to allocate, zero and copy); for float, a float accumulator padded to 4
//   per vertex (16 bytes: one SSE addition per corner, accumulate_by_vertex.h add_to_row). An
//   output array that already has the capacity (a caller reusing its result) is reused; a fresh
//   one is reserved in huge pages (core/bulk_reserve.h: a one-shot caller otherwise pays a
//   page fault per 4 KiB of it).
//   Threads: with a cached plan (VertexNormalsPlan) the zeroing and the sum are split over the
//   threads; without one, the angle and Max kernels plan the chunks beside the serial zeroing
//   (one bitmap pass over the corners per thread), while the cheap area and uniform kernels sum
//   serially (the plan would cost half the area kernel). Figures: bench/normals/results/notes.md.
//   Results are bitwise the same either way and for any thread count (accumulate_by_vertex.h).
// normalise_by_vertex   out[v] = sum[v] / |sum[v]| in fixed blocks of vertices (independent of the
//                       thread count); returns the vertices whose sum is zero or not finite,
//                       ascending (the caller gives them its fallback).
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <tbb/parallel_invoke.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/core/engine/usable_threads.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/engine/accumulate_by_vertex.h>
#include <shadetool/normals/engine/corner_contributions.h>
#include <shadetool/normals/engine/normalise_sums.h>

namespace shadetool::normals_detail {

// Values per vertex of the sums in T (float sums are padded to 4).
template <class T>
constexpr std::size_t kSumStride = std::is_same_v<T, double> ? 3 : 4;

// The sums: `out` (#V by 3) for double, `float_sum` (#V by 4) for float. cached: the caller's
// chunk plan, or null.
template <class T, Weighting W>
std::size_t sum_by_vertex(const MeshView& mesh, const ChunkPlan* cached, std::vector<double>& out,
                          std::vector<float>& float_sum) {
  constexpr std::size_t S = kSumStride<T>;
  const std::size_t V = mesh.num_vertices();
  const bool big = mesh.num_faces() >= kSerialBelow;
  ChunkPlan own_plan;
  reserve_bulk(out, 3 * V);
  if (cached) {
    out.resize(3 * V);
    if constexpr (!std::is_same_v<T, double>) float_sum.resize(S * V);
    constexpr std::size_t kZeroBlock = std::size_t(1) << 16;  // values
    const std::size_t n = S * V, blocks = (n + kZeroBlock - 1) / kZeroBlock;
    auto zero = [&](std::size_t b) {
      const std::size_t begin = b * kZeroBlock, end = std::min(n, begin + kZeroBlock);
      if constexpr (std::is_same_v<T, double>)
        std::fill(out.begin() + std::ptrdiff_t(begin), out.begin() + std::ptrdiff_t(end), 0.0);
      else
        std::fill(float_sum.begin() + std::ptrdiff_t(begin), float_sum.begin() + std::ptrdiff_t(end), 0.0f);
    };
    if (big && cached->K > 0) parallel_blocks(blocks, zero);
    else for (std::size_t b = 0; b < blocks; ++b) zero(b);
  } else {
    // float: the output is not a sum, and every entry is written (normalised or fallback).
    auto zero = [&] {
      if constexpr (std::is_same_v<T, double>) {
        out.assign(3 * V, 0.0);
      } else {
        out.resize(3 * V);
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
  if constexpr (std::is_same_v<T, double>) sum = out.data();
  else sum = float_sum.data();
  const bool triangles = mesh.all_triangles();
  // float Area/Max: one power of two for the whole mesh (corner_contributions.h). A vertex whose
  // float sum still overflows (a face ~2^100 times larger than the sampled ones) cannot be
  // normalised and takes the caller's fallback.
  const double scale = contribution_scale<T, W>(mesh);
  const RowHint rows{reinterpret_cast<const char*>(sum), S * sizeof(T)};
  return accumulate_by_target<false, T, S>(mesh, plan, nullptr,
      [&](std::size_t f_begin, std::size_t f_end, auto&& sink) {
        return triangles ? triangle_contributions<T, W>(mesh, f_begin, f_end, sink, scale, rows)
                         : polygon_contributions<T, W>(mesh, f_begin, f_end, sink, scale);
      }, sum);
}

template <class T>
std::vector<std::uint32_t> normalise_by_vertex(const T* sum, std::size_t V, std::vector<double>& out) {
  constexpr std::size_t kBlock = 1 << 14;
  const std::size_t blocks = (V + kBlock - 1) / kBlock;
  std::vector<std::vector<std::uint32_t>> failed(blocks);
  parallel_blocks(blocks, [&](std::size_t b) {
    normalise_range<T, kSumStride<T>>(sum, out.data(), b * kBlock, std::min(V, (b + 1) * kBlock), failed[b]);
  });
  std::vector<std::uint32_t> all;  // blocks in order: ascending
  for (auto& list : failed) all.insert(all.end(), list.begin(), list.end());
  return all;
}

}  // namespace shadetool::normals_detail
