// split_face_colors.h: face colours carried as vertex colours, for formats that store colours
// only per vertex (OBJ `v x y z r g b [a]`): flat shading by splitting vertices, as a renderer's
// vertex buffer does.
//
// Inputs:  mesh  with face_colors (F * color_channels floats)
// Outputs: a mesh whose vertex_colors (V' * color_channels) hold, for each distinct (vertex, face
//          colour) pair used by a corner, one vertex; face_colors removed; `added` = V' - V.
//          Every corner's vertex carries its face's colour; faces keep their order, size and corner
//          order; per-corner attributes (corner normals, texcoords) are untouched (indexed by corner).
// The first colour met for vertex v (in corner order) keeps index v, so vertex order is kept and
// vertices shared by faces of one colour are not split; each further colour becomes a new vertex
// appended after the originals, copying the position and the vertex normal (if any).
// Colours are compared bitwise (identical floats, channel by channel): two faces of one colour
// share the vertex, and a NaN colour equals the same NaN.
// Vertices no face uses keep their vertex colour if the mesh had vertex colours, else white
// (what the readers give an uncoloured vertex); `unreferenced` counts them. Vertex colours of
// referenced vertices are replaced by the face colours (one colour per vertex is all such formats hold).
// Flat arrays, two passes (count corners per vertex, then bucket): O(C * distinct colours per vertex).
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

Mesh split_face_colors(const Mesh& mesh, std::size_t& added, std::size_t& unreferenced);

}  // namespace shadetool::io
#pragma GCC visibility pop
