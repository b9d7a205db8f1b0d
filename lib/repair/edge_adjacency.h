// edge_adjacency.h: which corners (half-edges) lie on each undirected edge, as flat arrays.
//
// A half-edge is named by its corner: corner c of face f runs from corner_vertex[c] to the vertex
// of the next corner of f (cyclically). Half-edges whose two ends are the same vertex (a repeated
// index, e.g. face (a, a, b)) are not edges and get kNoEdge.
//
// Inputs:  mesh   faces (face_start #F+1, corner_vertex #C), polygons of any size; positions unused
//          skip   #F flags or empty: faces whose flag is nonzero contribute no half-edges (repair
//                 leaves out faces with a repeated index: their (a, b), (b, a) pair would make a
//                 false non-manifold edge out of a manifold one)
// Outputs: EdgeAdjacency with
//   corner_face    #C   face of each corner
//   edge_start     #E+1 edge e's half-edges are edge_corner[edge_start[e] .. edge_start[e+1])
//   edge_corner    #H   (H = number of half-edges that are edges) corners grouped by edge, each
//                       group in increasing corner order
//   corner_across  #C   the face adjacency: for a half-edge on a manifold edge (exactly two
//                       half-edges, from two different faces g and f), (g << 1) | s with s = 1
//                       when both faces run the edge the same way; else kNoEdge. Packed so that
//                       the BFS of consistent_winding reads one array per face. (#F < 2^31.)
//   non_manifold_edges  edges with 3 or more half-edges
// Edges are numbered in increasing (low vertex, high vertex) order: the numbering depends only on
// the faces' vertex sets, not on their winding. edge_ends(mesh, adj, e) gives (low, high).
//
// Method: counts, offsets, data in two passes over the half-edges (bucketed by their lower
// vertex), then each small bucket is sorted by (higher vertex, corner); equal higher vertices
// form one edge (meshoptimizer's adjacency layout). O(C log d) for vertex degree d, no maps.
// Parallel over chunks of faces and blocks of vertices (TBB), with the same output for any
// number of threads. Throws Error if a face refers to a vertex index >= #V.
// An edge with 1 half-edge is a boundary edge, 2 a manifold edge, 3 or more non-manifold.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace shadetool {

struct EdgeAdjacency {
  static constexpr std::uint32_t kNoEdge = std::numeric_limits<std::uint32_t>::max();

  std::vector<std::uint32_t> corner_face;
  std::vector<std::uint32_t> corner_across;
  std::vector<std::uint32_t> edge_start{0};
  std::vector<std::uint32_t> edge_corner;
  std::size_t non_manifold_edges = 0;

  std::size_t num_edges() const { return edge_start.size() - 1; }
  std::uint32_t edge_valence(std::size_t e) const { return edge_start[e + 1] - edge_start[e]; }
};

EdgeAdjacency edge_adjacency(const Mesh& mesh, const std::vector<std::uint8_t>& skip = {});

// The vertex following corner c in its face (the head of c's half-edge).
inline std::uint32_t head_vertex(const Mesh& mesh, const EdgeAdjacency& adj, std::uint32_t c) {
  const std::uint32_t f = adj.corner_face[c];
  return mesh.corner_vertex[c + 1 < mesh.face_start[f + 1] ? c + 1 : mesh.face_start[f]];
}

// (lower, higher) vertex of edge e.
inline std::pair<std::uint32_t, std::uint32_t> edge_ends(const Mesh& mesh, const EdgeAdjacency& adj, std::size_t e) {
  const std::uint32_t c = adj.edge_corner[adj.edge_start[e]];
  const std::uint32_t a = mesh.corner_vertex[c], b = head_vertex(mesh, adj, c);
  return {a < b ? a : b, a < b ? b : a};
}

}  // namespace shadetool
