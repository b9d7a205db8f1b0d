// edge_adjacency.cpp: half-edges grouped by undirected edge in flat arrays (see the header).
#include "repair/edge_adjacency.h"

#include <algorithm>
#include <cstddef>

#include "core/error.h"

namespace shadetool {

EdgeAdjacency edge_adjacency(const Mesh& mesh, const std::vector<std::uint8_t>& skip) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners(), V = mesh.num_vertices();
  const std::vector<std::uint32_t>& cv = mesh.corner_vertex;
  EdgeAdjacency adj;
  adj.corner_face.resize(C);
  adj.corner_next.resize(C);
  adj.corner_edge.assign(C, EdgeAdjacency::kNoEdge);

  // Vertex indices beyond #V would be a reader bug; size the buckets to cover them anyway.
  std::uint32_t max_vertex = 0;
  for (std::uint32_t v : cv) max_vertex = std::max(max_vertex, v);
  const std::size_t buckets = std::max<std::size_t>(V, C > 0 ? std::size_t(max_vertex) + 1 : 0);

  // A half-edge takes part when its face is not skipped and its ends differ.
  std::vector<std::uint8_t> live(C, 0);
  if (!skip.empty() && skip.size() != F) fail("edge_adjacency", 0, "skip flags size differs from the face count");
  const bool use_skip = !skip.empty();
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    const bool skipped = use_skip && skip[f];
    for (std::uint32_t c = b; c < e; ++c) {
      adj.corner_face[c] = std::uint32_t(f);
      adj.corner_next[c] = c + 1 < e ? c + 1 : b;
      live[c] = !skipped && cv[c] != cv[adj.corner_next[c]];
    }
  }

  // Pass 1: count half-edges per lower vertex.
  std::vector<std::uint32_t> offset(buckets + 1, 0);
  for (std::size_t c = 0; c < C; ++c)
    if (live[c]) ++offset[std::min(cv[c], cv[adj.corner_next[c]]) + 1];
  for (std::size_t v = 0; v < buckets; ++v) offset[v + 1] += offset[v];
  const std::size_t H = offset[buckets];

  // Pass 2: fill each bucket with (higher vertex, corner) packed so that sorting orders by both.
  std::vector<std::uint64_t> slot(H);
  std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
  for (std::size_t c = 0; c < C; ++c) {
    if (!live[c]) continue;
    const std::uint32_t a = cv[c], b = cv[adj.corner_next[c]];
    slot[fill[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | std::uint64_t(c);
  }

  adj.edge_corner.resize(H);
  adj.edge_start.clear();
  adj.edge_start.reserve(H / 2 + 2);
  adj.edge_vertices.reserve(H + 2);
  for (std::size_t v = 0; v < buckets; ++v) {
    const std::uint32_t b = offset[v], e = offset[v + 1];
    if (e - b > 32) {
      std::sort(slot.begin() + b, slot.begin() + e);  // a high-degree vertex (a fan's hub)
    } else if (e - b > 1) {
      // Buckets hold about half the vertex degree: insertion sort beats std::sort here.
      for (std::uint32_t i = b + 1; i < e; ++i) {
        const std::uint64_t x = slot[i];
        std::uint32_t j = i;
        for (; j > b && slot[j - 1] > x; --j) slot[j] = slot[j - 1];
        slot[j] = x;
      }
    }
    for (std::uint32_t i = b; i < e; ++i) {
      const std::uint32_t high = std::uint32_t(slot[i] >> 32), c = std::uint32_t(slot[i]);
      if (i == b || std::uint32_t(slot[i - 1] >> 32) != high) {
        adj.edge_start.push_back(i);
        adj.edge_vertices.push_back(std::uint32_t(v));
        adj.edge_vertices.push_back(high);
      }
      adj.edge_corner[i] = c;
      adj.corner_edge[c] = std::uint32_t(adj.edge_start.size() - 1);
    }
  }
  adj.edge_start.push_back(std::uint32_t(H));
  return adj;
}

}  // namespace shadetool
