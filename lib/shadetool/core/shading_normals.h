// shading_normals.h: which of a mesh's stored normals shade its corners when it holds more than
// one kind (an STL's facet normals beside the vertex normals `shadetool normals` computed, a PLY
// with vertex nx ny nz and face nx ny nz): its corner normals, else its vertex normals, else its
// face normals. The rule of the tangent frames (normals/tangents.h) and of every writer that holds
// one normal per corner (OBJ vn, glTF NORMAL), so that a file shades in a viewer as our own render
// shades it. The lighting (lighting/lit_normals.h) needs one normal per vertex and agrees with it
// for the cases above (vertex normals before face normals); it differs only for a mesh holding both
// vertex and corner normals, where it takes the vertex normals (not yet one rule: see its header).
// PLY holds vertex and face normals side by side and writes both; OFF holds vertex normals only.
//
// Input:  mesh  any normals it stores (vertex #V by 3, corner pool + #C indices, face #F by 3)
// Output: the kind that shades (None: no normals stored), and the note a one-normal-per-corner
//         writer gives when the mesh also has face normals it does not write ("" otherwise).
#pragma once

#include <string>

#include <shadetool/core/mesh.h>

namespace shadetool {

enum class ShadingNormals { None, Corner, Vertex, Face };

inline ShadingNormals shading_normals(const Mesh& mesh) {
  if (mesh.has_corner_normals()) return ShadingNormals::Corner;
  if (mesh.has_vertex_normals()) return ShadingNormals::Vertex;
  if (mesh.has_face_normals()) return ShadingNormals::Face;
  return ShadingNormals::None;
}

// FORMAT: the writer's name as users see it ("OBJ", "glTF").
inline std::string face_normals_not_written_note(const Mesh& mesh, const std::string& format) {
  switch (shading_normals(mesh)) {
    case ShadingNormals::Corner:
    case ShadingNormals::Vertex:
      if (!mesh.has_face_normals()) return std::string();
      return "face normals not written: " + format + " holds one normal per corner, and the " +
             (mesh.has_corner_normals() ? "corner" : "vertex") +
             " normals shade it (as in shadetool render; PLY writes both)";
    case ShadingNormals::Face:
    case ShadingNormals::None:
      return std::string();
  }
  return std::string();
}

}  // namespace shadetool
