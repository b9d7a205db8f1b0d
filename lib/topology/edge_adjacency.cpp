// edge_adjacency.cpp: half-edges paired by a counting sort on their lower vertex (see the header).
#include "topology/edge_adjacency.h"

#include <algorithm>

#include "core/error.h"
#include "io/bulk_reserve.h"

namespace shadetool {

namespace {

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

  // Pass 1: range check; half-edges per lower vertex, counted at pos[lo + 1].
  std::vector<std::uint32_t> pos;
  io::reserve_bulk(pos, V + 1);
  pos.assign(V + 1, 0);
  {
    std::uint32_t* n = pos.data() + 1;
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t b = triangles ? std::uint32_t(3 * f) : fs[f], e = triangles ? b + 3 : fs[f + 1];
      std::uint32_t highest = 0;
      for (std::uint32_t c = b; c < e; ++c) highest = std::max(highest, cv[c]);
      if (highest >= V && e > b) fail("edge_adjacency", 0, "a face refers to a vertex index beyond the vertex count");
      if (!takes_part(f, b, e)) continue;
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
        if (t != h) ++n[std::min(t, h)];
      }
    }
  }
  // Prefix sum: pos[v] = start of bucket v; pos[V] = number of half-edges H.
  for (std::size_t v = 0; v < V; ++v) pos[v + 1] += pos[v];
  const std::size_t H = pos[V];

  // Pass 2: scatter (higher vertex << 32 | corner << 1 | tail is the lower vertex) in corner order;
  // corners that are no half-edge get kUnpaired now. pos[v] becomes the end of bucket v.
  std::vector<std::uint64_t> slot;
  io::reserve_bulk(slot, H);
  slot.resize(H);
  for (std::size_t f = 0; f < F; ++f) {
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
      slot[pos[lo]++] = (std::uint64_t(hi) << 32) | (std::uint64_t(c) << 1) | std::uint64_t(t == lo);
    }
  }

  // Pass 3: sort each bucket by (higher vertex, corner); pair the edges of valence 2, list the rest.
  std::size_t pairs = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const std::uint32_t b = v == 0 ? 0 : pos[v - 1], e = pos[v];
    std::uint64_t* s = slot.data() + b;
    const std::uint32_t n = e - b;
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
        ++pairs;
      } else {
        for (std::uint32_t k = i; k < j; ++k) {
          mate[std::uint32_t(s[k]) >> 1] = kUnpaired;
          adj.odd_edge_corner.push_back(std::uint32_t(s[k]) >> 1);
        }
        adj.odd_edge_start.push_back(std::uint32_t(adj.odd_edge_corner.size()));
        (j - i == 1 ? adj.boundary_edges : adj.non_manifold_edges) += 1;
      }
      i = j;
    }
  }
  adj.num_edges = pairs + adj.num_odd_edges();
  return adj;
}

}  // namespace shadetool
