// degenerate_faces.h: faces that have no area or no well-defined winding, and their removal.
//
// Inputs:  mesh  positions #V by 3, faces #F (polygons of any size)
// Output:  DegenerateFaces with
//   kind  #F  per face: None, TooFewCorners (fewer than 3), RepeatedIndex (a vertex used twice:
//             (a, a, b) has no winding of its own), ZeroArea (all corners distinct but the area
//             vector vanishes to rounding), NonFinite (a corner has a NaN or Inf coordinate)
//   counts by kind, and count() = all degenerate faces
//
// Zero area: N = sum over the fan (p0, pi, pi+1) of (pi - p0) x (pi+1 - p0) (twice the area
// vector, Newell's sum for planar polygons) against the bound B = sum |pi - p0| |pi+1 - p0| that
// its rounding error scales with: |N| <= 64 eps B, i.e. for a triangle sin(angle) <= 1.4e-14,
// collinear to double precision. The test is scale-free (a face 1e-20 wide is not degenerate if
// its shape is fine). Triangles whose squared edge lengths lie in (1e-100, 1e100) compare the
// squares instead, |N|^2 <= (64 eps)^2 |e1|^2 |e2|^2: the same test without square roots.
// Precision: double. Faces are classified in parallel (TBB); the result does not depend on the
// number of threads.
//
// remove_faces: deletes the flagged faces, keeping the order of the others and every per-face and
// per-corner attribute (face normals and colours, corner normal and texcoord indices). Vertices
// are kept, even when no face uses them any more.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace shadetool {

enum class DegenerateKind : std::uint8_t { None = 0, TooFewCorners, RepeatedIndex, ZeroArea, NonFinite };

struct DegenerateFaces {
  std::vector<DegenerateKind> kind;
  std::size_t too_few_corners = 0, repeated_index = 0, zero_area = 0, non_finite = 0;
  std::size_t count() const { return too_few_corners + repeated_index + zero_area + non_finite; }
};

DegenerateFaces degenerate_faces(const Mesh& mesh);

// Returns the number of faces removed.
std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove);

}  // namespace shadetool
