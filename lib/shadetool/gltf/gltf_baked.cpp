// gltf_baked.cpp: normals for a baked glTF output (see gltf_baked.h).
#include <shadetool/gltf/gltf_baked.h>

#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

std::string add_baked_normals(Mesh& mesh, bool per_face) {
  if (mesh.has_vertex_normals() || mesh.has_corner_normals() || mesh.has_face_normals()) return std::string();
  if (!per_face) {
    mesh.vertex_normals = vertex_normals(mesh, Weighting::Angle, Precision::Double).normals;
    return "the vertex normals the colours were computed with (angle-weighted) written as NORMAL";
  }
  std::vector<double> n = face_normals(mesh, Precision::Double);
  for (std::size_t i = 0; i + 2 < n.size(); i += 3)
    if (n[i] == 0 && n[i + 1] == 0 && n[i + 2] == 0)
      return "no NORMAL written: a degenerate face has no normal (a glTF viewer computes flat normals itself)";
  mesh.face_normals = std::move(n);
  return "the face normals the colours were computed with written as NORMAL";
}

}  // namespace shadetool
