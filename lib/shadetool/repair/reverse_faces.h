// reverse_faces.h: reverses the winding of chosen faces, carrying every per-corner attribute.
//
// Inputs:  mesh     faces #F (polygons of any size) with optional corner_normal_index and
//                   corner_texcoord_index (#C each)
//          reverse  #F flags, nonzero = reverse this face
// Output:  mesh modified in place: face (v0, v1, ..., vk) becomes (v0, vk, ..., v1). The first
//          corner stays first, so reversing twice restores the face exactly (an involution), and a
//          triangle (a, b, c) becomes (a, c, b), the usual "swap two corners" flip. Corner normal
//          and texcoord indices move with their corners; the normals themselves are not touched
//          (repair's normals step checks them against the new winding).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Returns how many faces were reversed.
std::size_t reverse_faces(Mesh& mesh, const std::vector<std::uint8_t>& reverse);

}  // namespace shadetool
#pragma GCC visibility pop
