// weld_vertices.h: merges vertices that lie within a distance of each other.
//
// Inputs:  mesh  positions #V by 3, faces, optional vertex normals / colours
//          eps   distance, >= 0: a vertex within eps (inclusive; eps = 0 merges exact
//                duplicates only) of an earlier kept vertex is merged into the nearest such one
// Output:  WeldResult with
//   removed      vertices merged away (#V before - #V after)
//   old_to_new   #V(before) index of each old vertex in the welded mesh
//   mesh modified in place: kept vertices keep their order, position, normal and colour (the
//   first vertex of a cluster represents it); faces point at the kept vertices. Faces that now
//   repeat a vertex are left for degenerate_faces to report.
//
// Method: one pass in vertex order over a uniform grid (cell h >= eps, so every vertex within eps
// of a point lies in its cell or one of the 26 around it), stored in an open-addressing hash of
// packed cell coordinates: O(V) expected, no O(V^2) pair test. Greedy and order-dependent by
// design: kept vertices are pairwise farther apart than eps and every merged vertex is within eps
// of its representative, so chains (a ~ b ~ c with a far from c) never collapse a whole region,
// which transitive merging (union-find over all close pairs) would. The grid has at most 2^21
// cells per axis: when eps is tiny for the mesh's extent, h grows beyond eps (still correct,
// cells just hold more vertices). Vertices with NaN or Inf coordinates are never merged.
// Precision: distances in double, compared unsquared (core/vec3.h length: no underflow, so
// eps = 0 merges only bitwise-equal positions, up to the sign of zero).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct WeldResult {
  std::size_t removed = 0;
  std::vector<std::uint32_t> old_to_new;
};

WeldResult weld_vertices(Mesh& mesh, double eps);

}  // namespace shadetool
#pragma GCC visibility pop
