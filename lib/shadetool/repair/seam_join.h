// seam_join.h: vertices at exactly the same position, joined for the orientation decision only.
//
// Exporters split a closed model at its texture seams (every UV island gets vertices of its own),
// so its faces meet across a seam only through coincident positions, not shared indices; winding
// and outward orientation then see a patchwork of open islands. Orientation is decided on the
// connectivity of exactly coincident positions instead (the output's vertices are not changed:
// that is `--weld`'s job, on request).
//
// Inputs:  mesh  positions #V by 3, faces #F
//          adj   edge_adjacency(mesh, ...): its boundary edges (valence 1)
// Output:  SeamJoin with
//   corner_vertex  #C: the mesh's corner_vertex with each boundary vertex replaced by the lowest
//                  boundary vertex at exactly the same position (== comparison of x, y and z:
//                  -0 equals +0; NaN equals nothing); empty when no two boundary vertices coincide
//   joined         vertices replaced (boundary vertices at an earlier vertex's position)
// Only vertices on boundary edges are candidates: an edge can pair with another only when both
// are boundary edges now (joining an interior edge would make a non-manifold edge, which does not
// propagate winding). A closed mesh has none: the check costs nothing there.
// Cost: O(B log B) for B boundary vertices (a sort of their positions).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/edge_adjacency.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct SeamJoin {
  std::vector<std::uint32_t> corner_vertex;
  std::size_t joined = 0;
};

SeamJoin seam_join(const Mesh& mesh, const EdgeAdjacency& adj);

}  // namespace shadetool
#pragma GCC visibility pop
