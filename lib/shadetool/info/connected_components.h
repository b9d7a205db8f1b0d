// connected_components.h: faces grouped into pieces that share vertices.
//
// Inputs:  mesh  face_start (F+1), corner_vertex (C)
// Outputs: number of connected components: two faces are in one component when a chain of faces,
//          each sharing at least one vertex with the next, joins them. Unreferenced vertices form
//          no component (count them with unreferenced_vertices); a mesh with no faces has 0.
// Method: union-find over vertices, joining each face's corners to its first corner.
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::info {

std::size_t connected_components(const Mesh& mesh);

}  // namespace shadetool::info
#pragma GCC visibility pop
