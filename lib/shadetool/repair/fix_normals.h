// fix_normals.h: stored normals that are broken, or point against their (re-oriented) faces, are
// recomputed; valid ones are kept bit for bit; a mesh without normals gets vertex normals.
//
// Inputs:  mesh       positions #V by 3, faces #F (with their final winding), optional
//                     vertex_normals #V by 3, corner_normals pool (#N by 3) with
//                     corner_normal_index #C, face_normals #F by 3
//          weighting  how face normals are weighted into vertex and corner normals
// Output:  mesh modified in place, and NormalsFix counting the normals replaced, by reason:
//   nan      a component is NaN
//   inf      a component is +-Inf (and none is NaN)
//   zero     all components are zero
//   flipped  finite and nonzero, but dot(stored, reference) < 0, where the reference is
//              vertex normal   the vertex normal recomputed from the repaired faces
//                              (normals/vertex_normals.h, `weighting`)
//              corner normal   the normal of the group of corners that reference this pool
//                              entry (normals/corner_normals.h, corner_group_normals): a
//                              flat-shaded cube's shared `vn` and a smooth vertex's `vn` alike
//              face normal     the face's own unit normal (normals/face_normals.h)
//            A vertex with no valid face (isolated, or only degenerate faces) has no reference:
//            its stored normal is never called flipped.
//   missing  normals computed because the mesh had neither vertex nor corner normals (#V)
// A replaced normal is the reference normalised (the vertex normal for vertices; for a corner
// entry whose corners all lie on degenerate faces, the recomputed normal of its first corner's
// vertex; for faces, the face normal, (0, 0, 0) for a degenerate face): never NaN. A replacement
// that leaves the stored bits unchanged (a degenerate face's zero face normal) is not counted,
// so a repaired mesh reports zero. Corner normal entries no corner references are left alone.
// Precision: double (the stored arrays are double).
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct NormalsFix {
  std::size_t nan = 0, inf = 0, zero = 0, flipped = 0, missing = 0;
  std::size_t vertex = 0, corner = 0, face = 0;  // the same replacements, by kind of normal
  std::size_t total() const { return nan + inf + zero + flipped + missing; }
};

NormalsFix fix_normals(Mesh& mesh, Weighting weighting = Weighting::Angle);

}  // namespace shadetool
#pragma GCC visibility pop
