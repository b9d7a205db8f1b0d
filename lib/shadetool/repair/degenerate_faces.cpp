// degenerate_faces.cpp: removal of flagged faces (see the header).
#include <shadetool/repair/degenerate_faces.h>

#include <shadetool/core/error.h>

namespace shadetool {

std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove) {
  const std::size_t F = mesh.num_faces();
  if (remove.size() != F) fail("remove_faces", 0, "flag array size differs from the face count");
  const bool cn = mesh.has_corner_normals(), ct = mesh.has_texcoords();
  const bool fg = mesh.face_group_run.size() == F;  // OBJ statements stay with the faces that remain
  std::size_t kept = 0, corner_out = 0;
  for (std::size_t f = 0; f < F; ++f) {
    if (remove[f]) continue;
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    for (std::uint32_t c = b; c < e; ++c, ++corner_out) {
      mesh.corner_vertex[corner_out] = mesh.corner_vertex[c];
      if (cn) mesh.corner_normal_index[corner_out] = mesh.corner_normal_index[c];
      if (ct) mesh.corner_texcoord_index[corner_out] = mesh.corner_texcoord_index[c];
    }
    if (fg) mesh.face_group_run[kept] = mesh.face_group_run[f];
    mesh.face_start[kept + 1] = std::uint32_t(corner_out);
    ++kept;
  }
  mesh.face_start.resize(kept + 1);
  mesh.corner_vertex.resize(corner_out);
  if (cn) mesh.corner_normal_index.resize(corner_out);
  if (ct) mesh.corner_texcoord_index.resize(corner_out);
  if (fg) mesh.face_group_run.resize(kept);
  // Every per-face array (normals, colours, quality, properties: Mesh's for_each_face_array)
  // follows its faces; one of the wrong length (a caller's) is left for the writer's note.
  mesh.for_each_face_array([&](auto& a, std::size_t width) {
    if (a.size() != width * F) return;
    std::size_t out = 0;
    for (std::size_t f = 0; f < F; ++f) {
      if (remove[f]) continue;
      for (std::size_t i = 0; i < width; ++i) a[width * out + i] = a[width * f + i];
      ++out;
    }
    a.resize(width * kept);
  });
  return F - kept;
}

}  // namespace shadetool
