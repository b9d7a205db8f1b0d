// edge_adjacency.cpp: half-edges paired by a counting sort on their lower vertex (see the header).
#include "topology/edge_adjacency.h"

#include <algorithm>

#include "core/error.h"
#include "io/bulk_reserve.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

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
  // Large fresh arrays: huge pages first (io/bulk_reserve.h); page faults are much of the cost.
  io::reserve_bulk(adj.corner_mate, C);
  adj.corner_mate.resize(C);
  std::uint32_t* mate = adj.corner_mate.data();

  // Whether face f contributes half-edges.
  auto takes_part = [&](std::size_t f, std::uint32_t b, std::uint32_t e) {
    if (!skip.empty() && skip[f]) return false;
    return !options.skip_unwound_faces || !unwound(cv + b, e - b);
  };

  // Chunks of faces for passes 1 and 2, each with its own counts (no atomics); blocks of vertices
  // for pass 3. Two chunks when a second thread is there and the mesh is large enough to pay for
  // the second count array; the output is the same for any number of chunks and threads.
  const std::size_t threads = std::min<std::size_t>(
      std::size_t(tbb::this_task_arena::max_concurrency()),
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  const std::size_t chunks = F >= kParallelFaces && threads >= 2 ? 2 : 1;
  auto chunk_begin = [&](std::size_t k) { return F * k / chunks; };
  auto for_each_chunk = [&](auto&& body) {
    if (chunks == 1) return body(std::size_t(0));
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t k) { body(k); });
  };

  // Pass 1: range check; half-edges of chunk k per lower vertex, counted at count[k][lo].
  std::vector<std::vector<std::uint32_t>> count(chunks);
  std::vector<std::uint8_t> out_of_range(chunks, 0);
  for_each_chunk([&](std::size_t k) {
    io::reserve_bulk(count[k], V + 1);
    count[k].assign(V + 1, 0);
    std::uint32_t* n = count[k].data();
    for (std::size_t f = chunk_begin(k); f < chunk_begin(k + 1); ++f) {
      const std::uint32_t b = triangles ? std::uint32_t(3 * f) : fs[f], e = triangles ? b + 3 : fs[f + 1];
      std::uint32_t highest = 0;
      for (std::uint32_t c = b; c < e; ++c) highest = std::max(highest, cv[c]);
      if (highest >= V && e > b) {
        out_of_range[k] = 1;
        return;
      }
      if (!takes_part(f, b, e)) continue;
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
        if (t != h) ++n[std::min(t, h)];
      }
    }
  });
  for (std::uint8_t bad : out_of_range)
    if (bad) fail("edge_adjacency", 0, "a face refers to a vertex index beyond the vertex count");

  // Prefix sum: count[k][v] becomes chunk k's cursor into bucket v, after the half-edges of
  // buckets < v and of chunks < k in bucket v (so a bucket holds its half-edges in corner order).
  std::size_t H = 0;
  for (std::size_t v = 0; v < V; ++v)
    for (std::size_t k = 0; k < chunks; ++k) {
      const std::uint32_t n = count[k][v];
      count[k][v] = std::uint32_t(H);
      H += n;
    }

  // Pass 2: scatter (higher vertex << 32 | corner << 1 | tail is the lower vertex); corners that
  // are no half-edge get kUnpaired now. The last chunk's cursor ends at the end of each bucket.
  std::vector<std::uint64_t> slot;
  io::reserve_bulk(slot, H);
  slot.resize(H);
  for_each_chunk([&](std::size_t k) {
    std::uint32_t* cursor = count[k].data();
    for (std::size_t f = chunk_begin(k); f < chunk_begin(k + 1); ++f) {
      const std::uint32_t b = triangles ? std::uint32_t(3 * f) : fs[f], e = triangles ? b + 3 : fs[f + 1];
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
        slot[cursor[lo]++] = (std::uint64_t(hi) << 32) | (std::uint64_t(c) << 1) | std::uint64_t(t == lo);
      }
    }
  });
  const std::uint32_t* end = count[chunks - 1].data();

  // Pass 3: sort each bucket by (higher vertex, corner); pair the edges of valence 2, list the
  // rest. Blocks of vertices in parallel, each with its own list; joined in block order.
  struct Odd {
    std::vector<std::uint32_t> start, corner;
    std::size_t pairs = 0, boundary = 0, non_manifold = 0;
  };
  const std::size_t blocks = chunks == 1 ? 1 : std::max<std::size_t>(1, std::min<std::size_t>(16, V / 4096));
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
