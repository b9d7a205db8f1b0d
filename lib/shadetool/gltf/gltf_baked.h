// gltf_baked.h: what a baked glTF output (bake-lighting, occlusion) carries besides COLOR_0, so
// that a viewer shows the baked colours as computed (issue 28, 3):
//   - the normals the colours were computed with, when the mesh has none: per vertex the
//     angle-weighted vertex normals in double (normals/vertex_normals.h: what bake_lighting and
//     mesh_occlusion compute for a mesh without normals; isolated vertices get the documented
//     fallback, never zero), per face the face normals (normals/face_normals.h);
//   - a material with KHR_materials_unlit (GltfDocument::unlit_materials; gltf_write.cpp): the
//     baked colours are the lit result, and a viewer must not light them a second time.
//
// Inputs: mesh (positions, faces; its normals, if any, are kept), per_face (the colours are per
// face). Output: the mesh gains vertex_normals (#V by 3) or face_normals (#F by 3) when it had no
// normal of any kind; returns a note saying so, or "" when nothing was added. Per face, a
// degenerate face has no normal: then none are added (the note says why), never a zero one.
#pragma once

#include <string>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::string add_baked_normals(Mesh& mesh, bool per_face);

}  // namespace shadetool
#pragma GCC visibility pop
