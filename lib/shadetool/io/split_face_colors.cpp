// split_face_colors.cpp
#include <shadetool/io/split_face_colors.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>

namespace shadetool::io {

Mesh split_face_colors(const Mesh& mesh, std::size_t& added, std::size_t& unreferenced) {
  added = 0;
  unreferenced = 0;
  Mesh out = mesh;
  if (!mesh.has_face_colors()) return out;
  const std::size_t nv = mesh.num_vertices();
  const std::size_t nf = mesh.num_faces();
  const std::size_t nc = mesh.num_corners();
  const std::size_t ch = std::size_t(mesh.color_channels);

  // Face of each corner, and corners bucketed by vertex (CSR): start[v]..start[v+1] in `bucket`.
  std::vector<std::uint32_t> corner_face(nc);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) corner_face[c] = std::uint32_t(f);
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (std::uint32_t v : mesh.corner_vertex) ++start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> bucket(nc), fill(start.begin(), start.end() - 1);
  for (std::uint32_t c = 0; c < nc; ++c) bucket[fill[mesh.corner_vertex[c]]++] = c;

  const float* fc = mesh.face_colors.data();
  auto same_color = [&](std::uint32_t f, std::uint32_t g) {
    return f == g || std::memcmp(fc + ch * f, fc + ch * g, ch * sizeof(float)) == 0;
  };

  // Unreferenced vertices keep their vertex colour, or get white.
  const bool had_vertex_colors = mesh.vertex_colors.size() == nv * ch;
  if (!had_vertex_colors) out.vertex_colors.assign(nv * ch, 1.0f);
  const bool normals = mesh.has_vertex_normals();
  std::vector<std::uint32_t> seen_face, seen_vertex;  // distinct colours of the current vertex
  for (std::size_t v = 0; v < nv; ++v) {
    if (start[v] == start[v + 1]) {
      ++unreferenced;
      continue;
    }
    seen_face.clear();
    seen_vertex.clear();
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      const std::uint32_t c = bucket[k];
      const std::uint32_t f = corner_face[c];
      std::uint32_t target = UINT32_MAX;
      for (std::size_t i = 0; i < seen_face.size() && target == UINT32_MAX; ++i)
        if (same_color(seen_face[i], f)) target = seen_vertex[i];
      if (target == UINT32_MAX) {
        if (seen_face.empty()) {
          target = static_cast<std::uint32_t>(v);
        } else {
          if (out.num_vertices() >= std::numeric_limits<std::uint32_t>::max())
            fail("<output>", 0, "too many vertices after splitting them for face colours (more than 2^32)");
          target = static_cast<std::uint32_t>(out.num_vertices());
          out.positions.insert(out.positions.end(), &mesh.positions[3 * v], &mesh.positions[3 * v] + 3);
          out.vertex_colors.resize(out.vertex_colors.size() + ch);
          if (normals)
            out.vertex_normals.insert(out.vertex_normals.end(), &mesh.vertex_normals[3 * v], &mesh.vertex_normals[3 * v] + 3);
          ++added;
        }
        std::memcpy(&out.vertex_colors[ch * target], fc + ch * f, ch * sizeof(float));
        seen_face.push_back(f);
        seen_vertex.push_back(target);
      }
      out.corner_vertex[c] = target;
    }
  }
  out.face_colors.clear();
  return out;
}

}  // namespace shadetool::io
