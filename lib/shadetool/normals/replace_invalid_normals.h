// replace_invalid_normals.h: stored normals that carry no direction (a NaN or infinite component,
// or zero length) replaced by computed ones; every valid normal kept bit for bit.
//
// Why: a command that passes the input's normals through (transform, bake-lighting, occlusion)
// must not write a zero normal and must not refuse a whole file for one bad row (assimp's
// spider.obj has one zero `vn`). Only `normals` without --recompute refuses, as documented: it
// is asked to keep the input's normals.
//
// Inputs:  mesh       positions #V by 3, faces #F, and any of vertex_normals #V by 3, the corner
//                     normal pool #N by 3 with corner_normal_index #C, face_normals #F by 3
//          weighting  how face normals are weighted into vertex and corner normals
// Output:  mesh modified in place; InvalidNormalsReplaced counts the rows replaced, by kind.
//   vertex  the vertex's normal from its faces (normals/vertex_normals.h, whose fallback gives an
//           isolated vertex kFallbackNormal)
//   corner  the normal of the corners that reference the pool entry (corner_group_normals); when
//           those faces are all degenerate, the vertex normal of its first corner's vertex; an
//           entry no corner references, kFallbackNormal
//   face    the face's unit normal (normals/face_normals.h); kFallbackNormal for a degenerate face
// No row written is zero or NaN. Nothing is computed when every stored normal is valid.
// Precision: double.
#pragma once

#include <cstddef>
#include <string>

#include <shadetool/core/fallback_normal.h>
#include <shadetool/core/mesh.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct InvalidNormalsReplaced {
  std::size_t vertex = 0, corner = 0, face = 0;
  std::size_t total() const { return vertex + corner + face; }
};

InvalidNormalsReplaced replace_invalid_normals(Mesh& mesh, Weighting weighting = Weighting::Angle);

// "3 input normals had no direction (zero, NaN or Inf): replaced by computed ones (3 vertex)",
// the note every command writes; empty when nothing was replaced.
std::string invalid_normals_note(const InvalidNormalsReplaced& replaced);

}  // namespace shadetool
#pragma GCC visibility pop
