// remove_unreferenced.h: removes the vertices that no face uses.
//
// Inputs:  mesh  positions #V by 3, faces, any per-vertex arrays (Mesh::for_each_vertex_array)
// Output:  the number of vertices removed; mesh modified in place: the kept vertices keep their
//          order and every per-vertex value (normals, colours, quality, properties), faces point at
//          them. Per-corner arrays (corner normals, texture coordinates) and per-face arrays are
//          untouched: corners and faces are not removed. A per-vertex array of the wrong length (a
//          caller's) is left as it is, for the writer's note.
// Why: Open3D writes NaN positions for vertices its subdivision left unused; such a file is
// refused by every command that computes with positions (core/validate.h), and this step is the
// way out (`shadetool repair --remove-unreferenced`). Values of removed vertices are never read,
// so NaN or Inf there is fine. No division; exact.
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::size_t remove_unreferenced_vertices(Mesh& mesh);

}  // namespace shadetool
#pragma GCC visibility pop
