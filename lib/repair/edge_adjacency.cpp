// edge_adjacency.cpp: half-edges grouped by undirected edge in flat arrays (see the header).
//
// Parallel (TBB) and deterministic: the half-edges are counted and scattered per chunk of faces
// (each chunk with its own counts, so no atomics), and every bucket is then sorted by (higher
// vertex, corner), which erases any trace of the scatter order; buckets are processed in blocks
// of vertices, edge ids assigned after a prefix sum over the blocks. The output is the same for
// any number of threads.
#include "repair/edge_adjacency.h"

#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "io/bulk_reserve.h"

namespace shadetool {

namespace {

constexpr std::size_t kSerialBelow = 1 << 15;  // faces; below this, threads cost more than they save
constexpr std::size_t kVertexBlock = 1 << 14;

// Calls body(i) for i in [0, n), in parallel when `parallel`.
template <class Body>
void for_each_index(std::size_t n, bool parallel, const Body& body) {
  if (!parallel) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) body(i);
  });
}

// Sorts keys (higher vertex << 32 | corner) ascending.
void sort_keys(std::uint64_t* s, std::uint32_t n) {
  if (n > 32) {
    std::sort(s, s + n);  // a high-degree vertex (a fan's hub)
    return;
  }
  // Buckets hold about half the vertex degree: insertion sort beats std::sort here.
  for (std::uint32_t i = 1; i < n; ++i) {
    const std::uint64_t x = s[i];
    std::uint32_t j = i;
    for (; j > 0 && s[j - 1] > x; --j) s[j] = s[j - 1];
    s[j] = x;
  }
}

}  // namespace

EdgeAdjacency edge_adjacency(const Mesh& mesh, const std::vector<std::uint8_t>& skip) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners(), V = mesh.num_vertices();
  if (!skip.empty() && skip.size() != F) fail("edge_adjacency", 0, "skip flags size differs from the face count");
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const std::uint32_t* fs = mesh.face_start.data();
  constexpr std::uint32_t kNone = EdgeAdjacency::kNoEdge;
  const bool parallel = F >= kSerialBelow;
  const bool triangles = mesh.all_triangles();

  // Large fresh arrays: ask for huge pages first (io/bulk_reserve.h), page faults are much of
  // the cost of filling fresh memory.
  EdgeAdjacency adj;
  io::reserve_bulk(adj.corner_face, C);
  adj.corner_face.resize(C);
  io::reserve_bulk(adj.corner_across, C);
  adj.corner_across.assign(C, kNone);
  if (F >= (std::size_t(1) << 31)) fail("edge_adjacency", 0, "more than 2^31 - 1 faces");  // corner_across packing

  // Chunks of faces: each counts and scatters its own half-edges.
  const std::size_t chunks = parallel ? std::size_t(std::min(8, std::max(1, tbb::this_task_arena::max_concurrency()))) : 1;
  auto chunk_begin = [&](std::size_t k) { return F * k / chunks; };

  // Calls visit(corner, tail, head) for each half-edge of faces [f0, f1) that takes part: its
  // face is not skipped and its ends differ.
  auto for_each_half_edge = [&](std::size_t f0, std::size_t f1, auto&& visit) {
    for (std::size_t f = f0; f < f1; ++f) {
      if (!skip.empty() && skip[f]) continue;
      const std::uint32_t b = triangles ? std::uint32_t(3 * f) : fs[f], e = triangles ? b + 3 : fs[f + 1];
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t a = cv[c], h = cv[c + 1 < e ? c + 1 : b];
        if (a != h) visit(c, a, h);
      }
    }
  };

  // Pass 1: corner -> face, vertex range check, half-edges per lower vertex and chunk.
  std::vector<std::vector<std::uint32_t>> count(chunks);
  for (auto& n : count) {
    io::reserve_bulk(n, V + 1);
    n.assign(V + 1, 0);
  }
  std::vector<std::uint8_t> out_of_range(chunks, 0);
  for_each_index(chunks, parallel, [&](std::size_t k) {
    std::uint32_t* n = count[k].data();
    for (std::size_t f = chunk_begin(k); f < chunk_begin(k + 1); ++f)
      for (std::uint32_t c = fs[f]; c < fs[f + 1]; ++c) {
        adj.corner_face[c] = std::uint32_t(f);
        if (cv[c] >= V) out_of_range[k] = 1;
      }
    if (out_of_range[k]) return;
    for_each_half_edge(chunk_begin(k), chunk_begin(k + 1), [&](std::uint32_t, std::uint32_t a, std::uint32_t h) { ++n[std::min(a, h)]; });
  });
  for (std::uint8_t bad : out_of_range)
    if (bad) fail("edge_adjacency", 0, "a face refers to a vertex index beyond the vertex count");

  // Offsets: bucket v of chunk k starts after all of bucket v's half-edges from chunks < k.
  std::vector<std::uint32_t> offset;
  io::reserve_bulk(offset, V + 1);
  offset.assign(V + 1, 0);
  {
    std::uint32_t sum = 0;
    for (std::size_t v = 0; v < V; ++v) {
      offset[v] = sum;
      for (std::size_t k = 0; k < chunks; ++k) {
        const std::uint32_t n = count[k][v];
        count[k][v] = sum;  // becomes chunk k's cursor into bucket v
        sum += n;
      }
    }
    offset[V] = sum;
  }
  const std::size_t H = offset[V];

  // Pass 2: scatter (higher vertex << 32 | corner) into the buckets, so that sorting a bucket
  // orders it by both.
  std::vector<std::uint64_t> slot;
  io::reserve_bulk(slot, H);
  slot.resize(H);
  for_each_index(chunks, parallel, [&](std::size_t k) {
    std::uint32_t* cursor = count[k].data();
    for_each_half_edge(chunk_begin(k), chunk_begin(k + 1), [&](std::uint32_t c, std::uint32_t a, std::uint32_t h) {
      slot[cursor[std::min(a, h)]++] = (std::uint64_t(std::max(a, h)) << 32) | std::uint64_t(c);
    });
  });
  count.clear();
  count.shrink_to_fit();

  // Sort each bucket; count edges per block of vertices.
  const std::size_t blocks = (V + kVertexBlock - 1) / kVertexBlock;
  std::vector<std::uint32_t> block_edges(blocks + 1, 0);
  for_each_index(blocks, parallel, [&](std::size_t blk) {
    std::uint32_t edges = 0;
    for (std::size_t v = blk * kVertexBlock; v < std::min(V, (blk + 1) * kVertexBlock); ++v) {
      const std::uint32_t b = offset[v], e = offset[v + 1];
      sort_keys(slot.data() + b, e - b);
      for (std::uint32_t i = b; i < e; ++i) edges += i == b || (slot[i] >> 32) != (slot[i - 1] >> 32);
    }
    block_edges[blk + 1] = edges;
  });
  for (std::size_t blk = 0; blk < blocks; ++blk) block_edges[blk + 1] += block_edges[blk];
  const std::size_t E = block_edges[blocks];

  // Assign edge ids in (low, high) order; fill the edge arrays and the face adjacency.
  io::reserve_bulk(adj.edge_start, E + 1);
  adj.edge_start.resize(E + 1);
  io::reserve_bulk(adj.edge_corner, H);
  adj.edge_corner.resize(H);
  std::vector<std::size_t> block_non_manifold(blocks, 0);
  for_each_index(blocks, parallel, [&](std::size_t blk) {
    std::uint32_t edge = block_edges[blk];
    for (std::size_t v = blk * kVertexBlock; v < std::min(V, (blk + 1) * kVertexBlock); ++v) {
      const std::uint32_t b = offset[v], e = offset[v + 1];
      for (std::uint32_t i = b; i < e;) {
        const std::uint64_t high = slot[i] >> 32;
        std::uint32_t j = i + 1;
        while (j < e && (slot[j] >> 32) == high) ++j;
        adj.edge_start[edge] = i;
        for (std::uint32_t k = i; k < j; ++k) adj.edge_corner[k] = std::uint32_t(slot[k]);
        if (j - i == 2) {
          const std::uint32_t c0 = adj.edge_corner[i], c1 = adj.edge_corner[i + 1];
          const std::uint32_t f0 = adj.corner_face[c0], f1 = adj.corner_face[c1];
          if (f0 != f1) {  // a face using an edge twice is no bridge
            const std::uint32_t same = cv[c0] == cv[c1];
            adj.corner_across[c0] = (f1 << 1) | same;
            adj.corner_across[c1] = (f0 << 1) | same;
          }
        } else if (j - i >= 3) {
          ++block_non_manifold[blk];
        }
        ++edge;
        i = j;
      }
    }
  });
  adj.edge_start[E] = std::uint32_t(H);
  for (std::size_t n : block_non_manifold) adj.non_manifold_edges += n;
  return adj;
}

}  // namespace shadetool
