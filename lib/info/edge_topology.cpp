// edge_topology.cpp
#include "info/edge_topology.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "info/union_find.h"

namespace shadetool::info {

EdgeTopology edge_topology(const Mesh& mesh) {
  EdgeTopology t;
  const std::size_t nf = mesh.num_faces();
  const std::size_t nc = mesh.num_corners();

  // next corner within the face, for every corner
  std::vector<std::uint32_t> next(nc);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    for (std::uint32_t c = b; c < e; ++c) next[c] = c + 1 < e ? c + 1 : b;
  }
  // Half-edge c runs corner_vertex[c] -> corner_vertex[next[c]]; keyed by its undirected edge.
  struct Half {
    std::uint64_t key;
    std::uint32_t corner;
  };
  std::vector<Half> halves;
  halves.reserve(nc);
  for (std::uint32_t c = 0; c < nc; ++c) {
    const std::uint32_t a = mesh.corner_vertex[c], b = mesh.corner_vertex[next[c]];
    if (a == b) continue;
    const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
    halves.push_back({(lo << 32) | hi, c});
  }
  std::sort(halves.begin(), halves.end(),
            [](const Half& x, const Half& y) { return x.key != y.key ? x.key < y.key : x.corner < y.corner; });

  UnionFind fans(nc);
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while (j < halves.size() && halves[j].key == halves[i].key) ++j;
    const std::size_t sides = j - i;
    ++t.edges;
    if (sides == 1) ++t.boundary_edges;
    if (sides > 2) ++t.non_manifold_edges;
    if (sides == 2) {
      const std::uint32_t c1 = halves[i].corner, c2 = halves[i + 1].corner;
      const bool same_direction = mesh.corner_vertex[c1] == mesh.corner_vertex[c2];
      if (same_direction) {
        ++t.inconsistent_edges;
        fans.unite(c1, c2);              // both start at the same vertex
        fans.unite(next[c1], next[c2]);  // and end at the same vertex
      } else {
        fans.unite(c1, next[c2]);
        fans.unite(next[c1], c2);
      }
    }
    i = j;
  }

  // A referenced vertex is manifold when all its corners are in one fan.
  const std::size_t nv = mesh.num_vertices();
  const std::uint32_t none = UINT32_MAX;
  std::vector<std::uint32_t> root(nv, none);
  std::vector<std::uint8_t> bad(nv, 0);
  for (std::uint32_t c = 0; c < nc; ++c) {
    const std::uint32_t v = mesh.corner_vertex[c];
    const std::uint32_t r = fans.find(c);
    if (root[v] == none) root[v] = r;
    else if (root[v] != r) bad[v] = 1;
  }
  for (std::size_t v = 0; v < nv; ++v) t.non_manifold_vertices += bad[v];
  return t;
}

}  // namespace shadetool::info
