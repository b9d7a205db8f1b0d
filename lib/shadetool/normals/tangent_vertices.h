// tangent_vertices.h: per-corner tangent frames carried as per-vertex properties `tx ty tz tw`
// (the names Blender's and Assimp's PLY tools read), for formats that store values per vertex.
//
// Inputs:  mesh      positions, faces, any per-vertex arrays, corner normals or not
//          tangents  #C by 4 (normals/tangents.h: xyz, w = +-1)
// Output:  mesh      vertices split so that the corners of each vertex share one tangent frame and
//                    one corner normal: the first (normal, tangent) met at vertex v keeps index v,
//                    each further one becomes a new vertex appended after the originals, a copy of
//                    v in every per-vertex array (Mesh::for_each_vertex_array); corner_vertex
//                    renumbered; vertex properties tx, ty, tz, tw (float) set (replacing any read).
//                    A vertex no corner uses gets a unit vector perpendicular to its vertex normal
//                    (or (1, 0, 0)), w = +1.
//          returns   the number of vertices added.
// Linear: corners bucketed by vertex (count, fill), a short linear search per vertex.
#pragma once

#include <cstddef>
#include <array>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::size_t store_tangents_per_vertex(Mesh& mesh, const std::vector<double>& tangents);

// The four properties' names, in order: tx, ty, tz, tw (the one place they are spelled).
extern const char* const kTangentPropertyNames[4];
// The mesh's tangent properties in that order, null where one is absent (transform maps them).
std::array<MeshProperty*, 4> tangent_properties(Mesh& mesh);
// Removes every tangent property (their frames no longer belong to the normals); returns how many.
std::size_t remove_tangent_properties(Mesh& mesh);

}  // namespace shadetool
#pragma GCC visibility pop
