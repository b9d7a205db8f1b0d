// vertex_fallback.cpp: see vertex_fallback.h.
#include <shadetool/normals/vertex_fallback.h>

#include <shadetool/normals/face_normals.h>

namespace shadetool {

void apply_vertex_fallback(const MeshView& mesh, const std::vector<std::uint32_t>& vertices, Precision precision,
                           std::vector<double>& normals) {
  if (vertices.empty()) return;
  const std::size_t V = mesh.num_vertices();
  std::vector<char> pending(V, 0);
  for (auto v : vertices) {
    pending[v] = 1;
    for (int k = 0; k < 3; ++k) normals[3 * std::size_t(v) + k] = kFallbackNormal[k];
  }
  const std::vector<double> fn = face_normals(mesh, precision);
  std::size_t left = vertices.size();
  for (std::size_t f = 0; f < mesh.num_faces() && left > 0; ++f) {
    const double* n = &fn[3 * f];
    if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0) continue;  // degenerate face
    for (std::uint32_t c = mesh.face_begin(f), end = mesh.face_end(f); c < end; ++c) {
      const std::uint32_t v = mesh.corner_vertex[c];
      if (!pending[v]) continue;
      pending[v] = 0;
      --left;
      for (int k = 0; k < 3; ++k) normals[3 * std::size_t(v) + k] = n[k];
    }
  }
}

}  // namespace shadetool
