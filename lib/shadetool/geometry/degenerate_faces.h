// degenerate_faces.h: every face of a mesh classified and counted by the one degenerate rule
// (geometry/degenerate_face.h) — the one count, used by info (`shadetool info`) and repair
// (report, --remove-degenerate).
//
// Inputs:  mesh  positions #V by 3, faces #F (polygons of any size)
// Output:  DegenerateFaces with
//   kind  #F  per face: None, TooFewCorners (fewer than 3), RepeatedIndex (a vertex used twice:
//             (a, a, b) has no winding of its own), ZeroArea (all corners distinct but the area
//             vector vanishes to rounding), NonFinite (a corner has a NaN or Inf coordinate, or
//             the area vector overflows)
//   counts by kind, and count() = all degenerate faces (every kind but None: a face with a NaN
//   corner is degenerate, it has no area and no winding)
//
// The rule and its tolerance (64 eps, scale-free) are geometry/degenerate_face.h's; this file only
// applies it to every face. Precision: double. Faces are classified in parallel (TBB); the result
// does not depend on the number of threads.
#pragma once

#include <cstddef>
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

}  // namespace shadetool
#pragma GCC visibility pop
