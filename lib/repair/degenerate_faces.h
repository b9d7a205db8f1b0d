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

#include <shadetool/core/mesh.h>

namespace shadetool {

enum class DegenerateKind : std::uint8_t { None = 0, TooFewCorners, RepeatedIndex, ZeroArea, NonFinite };

struct DegenerateFaces {
  std::vector<DegenerateKind> kind;
  std::size_t too_few_corners = 0, repeated_index = 0, zero_area = 0, non_finite = 0;
  std::size_t count() const { return too_few_corners + repeated_index + zero_area + non_finite; }
};

DegenerateFaces degenerate_faces(const Mesh& mesh);

// The kind of one face (the per-face test of degenerate_faces).
DegenerateKind degenerate_kind(const Mesh& mesh, std::size_t f);

// The triangle test on squares, for a caller that has the edge vectors e1 = p1 - p0, e2 = p2 - p0
// at hand: l1 = |e1|^2, l2 = |e2|^2, a2 = |e1 x e2|^2. Sets `kind` (None or ZeroArea) and returns
// true while the squares can neither overflow nor underflow; else returns false (NaN included):
// use degenerate_kind.
inline bool triangle_kind_by_squares(double l1, double l2, double a2, DegenerateKind& kind) {
  constexpr double kTolerance = 64 * 2.220446049250313e-16;  // 64 eps
  if (!(l1 > 1e-100 && l1 < 1e100 && l2 > 1e-100 && l2 < 1e100)) return false;
  kind = a2 <= kTolerance * kTolerance * l1 * l2 ? DegenerateKind::ZeroArea : DegenerateKind::None;
  return true;
}

// Fills the counts of `d` from d.kind.
void count_degenerate_kinds(DegenerateFaces& d);

// Returns the number of faces removed.
std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove);

}  // namespace shadetool
