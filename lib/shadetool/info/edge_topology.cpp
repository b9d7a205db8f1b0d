// edge_topology.cpp: edge counts and fans from the shared half-edge pairing (see the header).
#include <shadetool/info/edge_topology.h>

#include <cstdint>
#include <vector>

#include <shadetool/geometry/union_find.h>
#include <shadetool/core/edge_adjacency.h>

namespace shadetool::info {

EdgeTopology edge_topology(const Mesh& mesh) {
  EdgeTopology t;
  const std::size_t nf = mesh.num_faces();
  const std::size_t nc = mesh.num_corners();

  // Every half-edge counts here, also those of faces that repeat a vertex.
  const EdgeAdjacency adj = edge_adjacency(mesh);
  t.edges = adj.num_edges;
  t.boundary_edges = adj.boundary_edges;
  t.non_manifold_edges = adj.non_manifold_edges;

  // next corner within the face, for every corner
  std::vector<std::uint32_t> next(nc);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    for (std::uint32_t c = b; c < e; ++c) next[c] = c + 1 < e ? c + 1 : b;
  }
  // Edges with exactly two sides (each pair seen once, from its lower corner): the fans join there.
  UnionFind fans(nc);
  for (std::uint32_t c1 = 0; c1 < nc; ++c1) {
    const std::uint32_t m = adj.corner_mate[c1];
    if (m == EdgeAdjacency::kUnpaired || (m >> 1) < c1) continue;
    const std::uint32_t c2 = m >> 1;
    if (m & 1u) {  // both sides run the same direction
      ++t.inconsistent_edges;
      fans.unite(c1, c2);              // both start at the same vertex
      fans.unite(next[c1], next[c2]);  // and end at the same vertex
    } else {
      fans.unite(c1, next[c2]);
      fans.unite(next[c1], c2);
    }
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
