// component_boundaries.h: which components are closed, and how many boundary loops each has.
//
// Inputs:  mesh     faces #F
//          adj      edge_adjacency(mesh, left_out) (core/edge_adjacency.h)
//          winding  consistent_winding(mesh, adj, skip): face_component, num_components (K)
// Outputs: ComponentBoundaries with
//   component_boundary_edges #K  edges on which the component has an odd number of half-edges
//                                (usually one: a boundary edge; also a non-manifold edge it meets
//                                once, e.g. each of three triangles on one edge)
//   component_loops          #K  boundary loops of the component
//   component_closed         #K  1 when the component has no boundary edge
//   boundary_loops               sum of component_loops
//
// Loops are counted as the cycle rank of the component's boundary graph, E_b - V_b + C_b (edges,
// vertices, connected pieces). Every boundary vertex of an oriented surface has as many boundary
// half-edges in as out, so the boundary graph is a union of edge-disjoint cycles and its cycle
// rank is the number of simple loops when each vertex the boundary passes k times is split k
// ways: a disk has 1, an annulus 2, a Möbius strip 1, two holes touching at a vertex 2.
// Integer counting only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/core/edge_adjacency.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct ComponentBoundaries {
  std::vector<std::uint32_t> component_boundary_edges;
  std::vector<std::uint32_t> component_loops;
  std::vector<std::uint8_t> component_closed;
  std::size_t boundary_loops = 0;
};

ComponentBoundaries component_boundaries(const Mesh& mesh, const EdgeAdjacency& adj, const ConsistentWinding& winding);

}  // namespace shadetool
#pragma GCC visibility pop
