// degenerate_faces.h: faces that have no area or no well-defined winding, and their removal.
//
// Inputs:  mesh  positions #V by 3, faces #F (polygons of any size)
// Output:  DegenerateFaces with
//   kind  #F  per face: None, TooFewCorners (fewer than 3), RepeatedIndex (a vertex used twice:
//             (a, a, b) has no winding of its own), ZeroArea (all corners distinct but the area
//             vector vanishes to rounding), NonFinite (a corner has a NaN or Inf coordinate)
//   counts by kind, and count() = all degenerate faces
//
// What counts as degenerate, and the tolerance, is the one rule of geometry/degenerate_face.h
// (also used by info and normals): zero area means |N| <= 64 eps |a| |b| for a triangle's two
// shortest edges a, b (sin of its largest angle <= 1.4e-14: collinear to double precision, in any
// corner order), |N| <= 64 eps sum |p_i - p_0| |p_{i+1} - p_0| for a polygon. Scale-free.
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
#include <shadetool/geometry/degenerate_face.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct DegenerateFaces {
  std::vector<DegenerateKind> kind;
  std::size_t too_few_corners = 0, repeated_index = 0, zero_area = 0, non_finite = 0;
  std::size_t count() const { return too_few_corners + repeated_index + zero_area + non_finite; }
};

DegenerateFaces degenerate_faces(const Mesh& mesh);

// The kind of one face (geometry/degenerate_face.h's face_degenerate_kind).
inline DegenerateKind degenerate_kind(const Mesh& mesh, std::size_t f) { return face_degenerate_kind(mesh, f); }

// Fills the counts of `d` from d.kind.
void count_degenerate_kinds(DegenerateFaces& d);

// Returns the number of faces removed.
std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove);

}  // namespace shadetool
#pragma GCC visibility pop
