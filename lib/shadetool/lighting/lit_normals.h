// lit_normals.h: the vertex normals a mesh's vertices are lit with, by bake-lighting per vertex and
// by render's Gouraud and Phong shading (render/lighting_adapter.h), so that Phong at a vertex
// equals the baked colour there. The one home of that choice.
//
// Input:   mesh  positions #V by 3, faces; vertex or corner normals if it has them
// Output:  normals  #V by 3 object space, in the first of these that applies:
//            1. the mesh's vertex normals (as given: not normalised);
//            2. its corner normals, when every corner of each vertex carries the same normal
//               value (a vertex without corners gets (0, 0, 0));
//            3. normals/vertex_normals.h, angle-weighted, accumulated in double (a vertex with no
//               valid face gets the normals module's fallback, counted in fallback_vertices).
//          source  which, for notes: "input vertex normals", "input corner normals (one per
//                  vertex)", "computed (angle-weighted)[: the input's corner normals differ at
//                  some vertices]"
// Degenerate input: a corner normal index out of range counts as a crease (case 3).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct LitVertexNormals {
  std::vector<double> normals;
  std::string source;
  std::size_t fallback_vertices = 0;
};

LitVertexNormals lit_vertex_normals(const Mesh& mesh);

}  // namespace shadetool
#pragma GCC visibility pop
