// reverse_winding.cpp: see reverse_winding.h.
#include <shadetool/transform/reverse_winding.h>

#include <algorithm>
#include <string>

#include <shadetool/core/error.h>

namespace shadetool {

void reverse_winding(Mesh& mesh) {
  const std::size_t C = mesh.num_corners();
  const bool normals = mesh.corner_normal_index.size() == C && C > 0;
  const bool texcoords = mesh.corner_texcoord_index.size() == C && C > 0;
  if ((!mesh.corner_normal_index.empty() && !normals) || (!mesh.corner_texcoord_index.empty() && !texcoords))
    throw Error("reverse_winding: per-corner attributes do not match the number of corners (" + std::to_string(C) + ")");
  if (mesh.face_start.empty() || mesh.face_start.back() != C)
    throw Error("reverse_winding: face offsets do not match the number of corners");
  const std::size_t F = mesh.num_faces();
  for (std::size_t f = 0; f < F; ++f) {
    const std::size_t s = mesh.face_start[f] + 1, e = mesh.face_start[f + 1];  // keep the first corner
    if (e <= s) continue;
    std::reverse(mesh.corner_vertex.begin() + s, mesh.corner_vertex.begin() + e);
    if (normals) std::reverse(mesh.corner_normal_index.begin() + s, mesh.corner_normal_index.begin() + e);
    if (texcoords) std::reverse(mesh.corner_texcoord_index.begin() + s, mesh.corner_texcoord_index.begin() + e);
  }
}

}  // namespace shadetool
