// consistent_winding.h: connected components and a winding for every face such that each
// manifold edge is traversed in opposite directions by its two faces.
//
// Inputs:  mesh      faces #F (polygons of any size)
//          adj       edge_adjacency(mesh, left_out) (core/edge_adjacency.h)
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
// Method: each manifold edge (adj.corner_mate) between faces f and g says that after reversal g
// must run the edge opposite to f: reverse[f] XOR reverse[g] = (both run it the same way).
//   1. Union-find with parity over the faces, the edges taken in corner order (one streaming pass
//      over corner_mate): union by lower index, so each set's root is its lowest face, the seed;
//      path halving. Each node keeps its reversal relative to its parent; an edge inside one set
//      with the wrong parity is a conflict. On 2+ threads (32768+ faces) two halves of the faces
//      are united in parallel, each only through edges inside it; the edges across the cut are
//      united afterwards on one thread (sets, roots and orientable parities do not depend on the
//      order of union). A second pass in face order gives every face its component (numbered by
//      seed) and its reversal relative to the seed.
//      On an orientable component the consistent labelling with the seed unreversed is unique,
//      so the result does not depend on the order the edges were taken in, nor on the input
//      winding (repair is idempotent).
//   2. A component with a conflict is non-orientable (no labelling satisfies every edge). It is
//      labelled again by a depth-first search from its seed (explicit stack, faces labelled when
//      pushed) that visits a face's neighbours in increasing (face, edge's vertex pair) order,
//      which does not depend on the winding: the search tree, and so the result, is the same for
//      a mesh and any re-wound copy of it. The inconsistent edges are where the search closes a
//      cycle of the wrong parity (one cut across a Möbius strip); each is counted once, from its
//      lower-numbered face.
// Edges a face uses twice and non-manifold edges neither propagate nor count as inconsistent.
// Why union-find: it reads corner_mate in order and touches the face array near the faces being
// joined (with the vertex order coherent, as exporters write it), where a graph search jumps
// along its front; the fastest of the three in bench/repair (figures: bench/repair/results.md).
// Cost: O(C alpha(F)); the labelling pass is serial. At most 2^31 - 1 faces (a face index and a parity share 32 bits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/mesh.h>
#include <shadetool/core/edge_adjacency.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct ConsistentWinding {
  static constexpr std::uint32_t kNoComponent = std::numeric_limits<std::uint32_t>::max();

  BulkVector<std::uint32_t> face_component;  // std::vector, not zeroed on resize (core/bulk_reserve.h)
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
#pragma GCC visibility pop
