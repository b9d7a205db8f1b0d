// reverse_faces.cpp: winding reversal keeping the first corner (see the header).
#include "repair/reverse_faces.h"

#include <algorithm>

#include "core/error.h"

namespace shadetool {

std::size_t reverse_faces(Mesh& mesh, const std::vector<std::uint8_t>& reverse) {
  const std::size_t F = mesh.num_faces();
  if (reverse.size() != F) fail("reverse_faces", 0, "flag array size differs from the face count");
  const bool normals = mesh.has_corner_normals(), texcoords = mesh.has_texcoords();
  std::size_t count = 0;
  if (mesh.all_triangles() && !normals && !texcoords) {
    // Triangles with nothing else per corner: swap corners 1 and 2 by selection, not by a branch
    // (the flags of a damaged mesh are as good as random; a mispredicted branch per face cost
    // more than writing every face back).
    std::uint32_t* cv = mesh.corner_vertex.data();
    const std::uint8_t* flag = reverse.data();
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t r = flag[f] != 0;
      const std::uint32_t a = cv[3 * f + 1], b = cv[3 * f + 2];
      cv[3 * f + 1] = r ? b : a;
      cv[3 * f + 2] = r ? a : b;
      count += r;
    }
    return count;
  }
  for (std::size_t f = 0; f < F; ++f) {
    if (!reverse[f]) continue;
    ++count;
    const std::uint32_t b = mesh.face_start[f] + 1, e = mesh.face_start[f + 1];
    if (e <= b) continue;  // an empty face has nothing to reverse
    std::reverse(mesh.corner_vertex.begin() + b, mesh.corner_vertex.begin() + e);
    if (normals) std::reverse(mesh.corner_normal_index.begin() + b, mesh.corner_normal_index.begin() + e);
    if (texcoords) std::reverse(mesh.corner_texcoord_index.begin() + b, mesh.corner_texcoord_index.begin() + e);
  }
  return count;
}

}  // namespace shadetool
