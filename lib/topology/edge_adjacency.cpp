// edge_adjacency.cpp: half-edges paired by a counting sort on their lower vertex (see the header).
#include "topology/edge_adjacency.h"

#include <algorithm>
#include <type_traits>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/bulk_reserve.h"

namespace shadetool {

namespace {

constexpr std::size_t kParallelFaces = 1 << 15;  // below this, a second thread costs more than it saves

// Whether a face of n corners has fewer than 3 corners or repeats a vertex index.
bool unwound(const std::uint32_t* v, std::uint32_t n) {
  if (n < 3) return true;
  if (n == 3) return v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
  if (n <= 16) {
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j)
        if (v[i] == v[j]) return true;
    return false;
  }
  std::vector<std::uint32_t> s(v, v + n);
  std::sort(s.begin(), s.end());
  return std::adjacent_find(s.begin(), s.end()) != s.end();
}

// Sorts slot keys (higher vertex << 32 | corner << 1 | direction) ascending.
void sort_bucket(std::uint64_t* s, std::uint32_t n) {
  if (n > 32) {
    std::sort(s, s + n);  // a high-degree vertex (a fan's hub)
    return;
  }
  for (std::uint32_t i = 1; i < n; ++i) {  // buckets hold ~half a vertex degree: insertion sort
    const std::uint64_t x = s[i];
    std::uint32_t j = i;
    for (; j > 0 && s[j - 1] > x; --j) s[j] = s[j - 1];
    s[j] = x;
  }
}

}  // namespace

bool face_is_unwound(const Mesh& mesh, std::size_t f) {
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  return unwound(mesh.corner_vertex.data() + b, e - b);
}

EdgeAdjacency edge_adjacency(const Mesh& mesh, const EdgeAdjacencyOptions& options) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners(), V = mesh.num_vertices();
  const std::vector<std::uint8_t>& skip = options.skip;
  if (!skip.empty() && skip.size() != F) fail("edge_adjacency", 0, "skip flags size differs from the face count");
  if (C >= (std::size_t(1) << 31) - 1) fail("edge_adjacency", 0, "2^31 - 1 corners or more");  // (m << 1) | s
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const std::uint32_t* fs = mesh.face_start.data();
  const bool triangles = mesh.all_triangles();
  constexpr std::uint32_t kUnpaired = EdgeAdjacency::kUnpaired;

  EdgeAdjacency adj;
  // Large fresh arrays: huge pages first (core/bulk_reserve.h); page faults are much of the cost.
  reserve_bulk(adj.corner_mate, C);
  adj.corner_mate.resize(C);
  std::uint32_t* mate = adj.corner_mate.data();

  // Whether face f contributes half-edges.
  auto takes_part = [&](std::size_t f, std::uint32_t b, std::uint32_t e) {
    if (!skip.empty() && skip[f]) return false;
    if (!options.skip_unwound_faces) return true;
    if (e - b == 3) return cv[b] != cv[b + 1] && cv[b + 1] != cv[b + 2] && cv[b] != cv[b + 2];  // inline for triangles
    return !unwound(cv + b, e - b);
  };

  // Pass 1: range check; half-edges per lower vertex, counted at pos[lo + 1].
  std::vector<std::uint32_t> pos;
  reserve_bulk(pos, V + 1);
  pos.assign(V + 1, 0);
  std::uint32_t* count = pos.data() + 1;
  // (Both face passes are compiled twice: for a triangle mesh the corner loops have a constant
  // trip count of 3 and unroll.)
  auto count_pass = [&](auto all_triangles) {
    constexpr bool kTriangles = decltype(all_triangles)::value;
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t b = kTriangles ? std::uint32_t(3 * f) : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
      std::uint32_t highest = 0;
      for (std::uint32_t c = b; c < e; ++c) highest = std::max(highest, cv[c]);
      if (highest >= V && e > b) fail("edge_adjacency", 0, "a face refers to a vertex index beyond the vertex count");
      if (!takes_part(f, b, e)) continue;
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
        if (t != h) ++count[std::min(t, h)];
      }
    }
  };
  if (triangles) count_pass(std::true_type{});
  else count_pass(std::false_type{});
  // Prefix sum: pos[v] = start of bucket v; pos[V] = number of half-edges H.
  for (std::size_t v = 0; v < V; ++v) pos[v + 1] += pos[v];
  const std::size_t H = pos[V];

  // Pass 2: scatter (higher vertex << 32 | corner << 1 | tail is the lower vertex) in corner order;
  // corners that are no half-edge get kUnpaired now. pos[v] becomes the end of bucket v.
  std::vector<std::uint64_t> slot;
  reserve_bulk(slot, H);
  slot.resize(H);
  auto scatter_pass = [&](auto all_triangles) {
    constexpr bool kTriangles = decltype(all_triangles)::value;
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t b = kTriangles ? std::uint32_t(3 * f) : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
      if (!takes_part(f, b, e)) {
        for (std::uint32_t c = b; c < e; ++c) mate[c] = kUnpaired;
        continue;
      }
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
        if (t == h) {
          mate[c] = kUnpaired;
          continue;
        }
        const std::uint32_t lo = std::min(t, h), hi = std::max(t, h);
        slot[pos[lo]++] = (std::uint64_t(hi) << 32) | (std::uint64_t(c) << 1) | std::uint64_t(t == lo);
      }
    }
  };
  if (triangles) scatter_pass(std::true_type{});
  else scatter_pass(std::false_type{});
  const std::uint32_t* end = pos.data();

  // Pass 3: sort each bucket by (higher vertex, corner); pair the edges of valence 2, list the
  // rest. Blocks of vertices on 2 threads when there are 2 (each block with its own list, joined in
  // block order, so the output is the same for any number of threads). Passes 1 and 2 stay
  // serial: split by faces they need a count array per chunk, which cost more than the second
  // thread saved whenever the other core was busy (bench/repair/results.md).
  struct Odd {
    std::vector<std::uint32_t> start, corner;
    std::size_t pairs = 0, boundary = 0, non_manifold = 0;
  };
  const std::size_t threads = std::min<std::size_t>(
      std::size_t(tbb::this_task_arena::max_concurrency()),
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  const std::size_t blocks = F >= kParallelFaces && threads >= 2 ? std::max<std::size_t>(1, std::min<std::size_t>(16, V / 4096)) : 1;
  std::vector<Odd> odd(blocks);
  auto match = [&](std::size_t blk) {
    Odd& o = odd[blk];
    for (std::size_t v = V * blk / blocks; v < V * (blk + 1) / blocks; ++v) {
      const std::uint32_t b = v == 0 ? 0 : end[v - 1], n = end[v] - b;
      std::uint64_t* s = slot.data() + b;
      sort_bucket(s, n);
      for (std::uint32_t i = 0; i < n;) {
        const std::uint32_t hi = std::uint32_t(s[i] >> 32);
        std::uint32_t j = i + 1;
        while (j < n && std::uint32_t(s[j] >> 32) == hi) ++j;
        if (j - i == 2) {
          const std::uint32_t x = std::uint32_t(s[i]), y = std::uint32_t(s[i + 1]);  // (c << 1) | dir
          const std::uint32_t same = (x ^ y ^ 1u) & 1u;
          mate[x >> 1] = (y & ~1u) | same;
          mate[y >> 1] = (x & ~1u) | same;
          ++o.pairs;
        } else {
          for (std::uint32_t k = i; k < j; ++k) {
            mate[std::uint32_t(s[k]) >> 1] = kUnpaired;
            o.corner.push_back(std::uint32_t(s[k]) >> 1);
          }
          o.start.push_back(std::uint32_t(o.corner.size()));
          (j - i == 1 ? o.boundary : o.non_manifold) += 1;
        }
        i = j;
      }
    }
  };
  if (blocks == 1) match(0);
  else tbb::parallel_for(std::size_t(0), blocks, match);
  std::size_t pairs = 0;
  for (const Odd& o : odd) {
    const std::uint32_t base = std::uint32_t(adj.odd_edge_corner.size());
    adj.odd_edge_corner.insert(adj.odd_edge_corner.end(), o.corner.begin(), o.corner.end());
    for (std::uint32_t x : o.start) adj.odd_edge_start.push_back(base + x);
    pairs += o.pairs;
    adj.boundary_edges += o.boundary;
    adj.non_manifold_edges += o.non_manifold;
  }
  adj.num_edges = pairs + adj.num_odd_edges();
  return adj;
}

}  // namespace shadetool
