// edge_topology.h: the undirected edges of a polygon mesh and how many faces meet at each.
//
// Inputs:  mesh  face_start (F+1), corner_vertex (C); positions are not used
// Outputs: EdgeTopology
//   edges                  #E  distinct undirected edges {a, b}, a < b
//   boundary_edges         edges used by exactly one face side
//   non_manifold_edges     edges used by three or more face sides
//   inconsistent_edges     edges with exactly two sides that run the same direction (a->b twice):
//                          the two faces are wound inconsistently
//   non_manifold_vertices  referenced vertices whose incident faces do not form one fan, i.e. are
//                          not connected through the manifold edges around the vertex (a bow-tie,
//                          or a vertex on a non-manifold edge whose sheets meet only there)
// What an edge, a boundary / manifold / non-manifold edge is, and what a face repeating a vertex
// gives, are the rules of core/edge_adjacency.h (info counts every face side: the default there).
// Method: that half-edge pairing (a counting sort on the lower vertex, flat arrays, no maps),
// shared with repair; for the fans, a union-find over corners joins the two corners at each end of
// every manifold edge, and a vertex is non-manifold when its corners fall into more than one set.
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::info {

struct EdgeTopology {
  std::size_t edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t inconsistent_edges = 0;
  std::size_t non_manifold_vertices = 0;
};

EdgeTopology edge_topology(const Mesh& mesh);

}  // namespace shadetool::info
#pragma GCC visibility pop
