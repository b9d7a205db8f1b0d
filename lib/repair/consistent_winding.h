// consistent_winding.h: connected components and a winding for every face such that each
// manifold edge is traversed in opposite directions by its two faces (breadth-first propagation).
//
// Inputs:  mesh  faces #F (polygons of any size)
//          adj       edge_adjacency(mesh, left_out) (topology/edge_adjacency.h)
//          left_out  the same options: faces flagged in skip, and with skip_unwound_faces faces
//                    of fewer than 3 corners or with a repeated index, take no part (no
//                    component, never reversed)
// Outputs: ConsistentWinding with
//   face_component   #F   component of each face (kNoComponent for skipped faces)
//   face_reverse     #F   1 if the face must be reversed to agree with its component's seed
//   num_components        components: faces joined through manifold edges (exactly two faces)
//   component_seed   #K   the lowest-index face of each component (its winding is kept)
//   component_faces  #K   faces per component
//   component_reverse_count #K  faces with face_reverse = 1 per component
//   component_non_orientable #K 1 if no winding makes every manifold edge consistent (Möbius)
//   inconsistent_edges    manifold edges still traversed in the same direction by both faces
//                         after the reversal (only in non-orientable components)
//   non_manifold_edges    edges with 3 or more half-edges (they do not propagate orientation)
//
// Method: for each unvisited face in index order, a graph search over manifold edges
// (adj.corner_mate), depth-first with an explicit stack (faces are labelled when pushed): the
// neighbour g across half-edge (a -> b) of face f must run (b -> a) after reversal, so
// reverse[g] = reverse[f] XOR (g runs a -> b too). A face's neighbours are labelled and pushed in
// increasing (face, edge's vertex pair) order, which does not depend on the winding: the search
// tree, and so the result, is the same for a mesh and any re-wound copy of it (repair is
// idempotent). Depth-first keeps the working set small (the stack stays near the face being
// expanded, where a breadth-first front spreads over the mesh); measured in bench/repair.
// A component is orientable iff the labels leave no edge inconsistent: on an orientable surface
// the labelling along any spanning tree is the unique consistent one up to a global flip. On a
// non-orientable one, the inconsistent edges are where the search closes a cycle of the wrong
// parity (one cut across a Möbius strip). Edges a face uses twice and non-manifold edges neither
// propagate nor count as inconsistent. Each inconsistent edge is counted once, from its
// lower-numbered face.
// Cost: O(F + C), serial (the search order is what makes the result winding-free).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/mesh.h"
#include "topology/edge_adjacency.h"

namespace shadetool {

struct ConsistentWinding {
  static constexpr std::uint32_t kNoComponent = std::numeric_limits<std::uint32_t>::max();

  std::vector<std::uint32_t> face_component;
  std::vector<std::uint8_t> face_reverse;
  std::size_t num_components = 0;
  std::vector<std::uint32_t> component_seed;
  std::vector<std::uint32_t> component_faces;
  std::vector<std::uint32_t> component_reverse_count;
  std::vector<std::uint8_t> component_non_orientable;
  std::size_t inconsistent_edges = 0;
  std::size_t non_manifold_edges = 0;
};

ConsistentWinding consistent_winding(const Mesh& mesh, const EdgeAdjacency& adj,
                                     const EdgeAdjacencyOptions& left_out = {});

// The faces of each component, in increasing face order, as flat arrays: component k's faces are
// faces[start[k] .. start[k+1]). Counting sort, O(F).
struct ComponentFaces {
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> faces;
};
ComponentFaces faces_by_component(const ConsistentWinding& winding);

}  // namespace shadetool
