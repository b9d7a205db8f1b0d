// duplicate_faces.h: faces that use exactly the vertices of an earlier face (in any order, with
// either winding), found among the faces on non-manifold edges.
//
// A duplicated face (an export writing a triangle twice, or a two-sided leaf modelled as two
// opposite faces on the same vertices) makes each of its edges non-manifold, so it would stop
// orientation from propagating across them and cut itself and its twin out of their surface.
// Repair sets duplicates aside: the first face of each group takes part in orientation, and each
// later one keeps its input relation to it (same winding stays same, opposite stays opposite).
//
// Inputs:  mesh     faces #F
//          adj      edge_adjacency(mesh, left_out) (core/edge_adjacency.h)
//          winding  consistent_winding(mesh, adj, left_out): its components
// Output:  DuplicateFaces with
//   original  #F  for a duplicate, the lowest-numbered face with the same vertex set; else kNone
//                 (empty when no face was a candidate: then count is 0)
//   count         number of duplicates (faces with original != kNone)
// Candidates: faces on edges with 3 or more half-edges (every duplicate that shares its edges
// with anything else), and the faces of components of exactly two faces (a lone pair, all of
// whose edges the two faces share with each other, is one: its edges are manifold). Cost O(K)
// plus O(F) only when a two-face component exists, plus O(n log n) for n candidates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/core/edge_adjacency.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct DuplicateFaces {
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> original;
  std::size_t count = 0;
};

DuplicateFaces duplicate_faces(const Mesh& mesh, const EdgeAdjacency& adj, const ConsistentWinding& winding);
// The same, with the winding computed here (consistent_winding(mesh, adj)).
DuplicateFaces duplicate_faces(const Mesh& mesh, const EdgeAdjacency& adj);

}  // namespace shadetool
#pragma GCC visibility pop
