// recompute_normals.cpp: see recompute_normals.h.
#include <shadetool/transform/recompute_normals.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {

// Recomputes the corner-normal pool within the input's smoothing groups; returns the groups that
// fell back to their vertex normal.
std::size_t recompute_corner_groups(Mesh& mesh, const std::vector<double>& vertex_n) {
  const std::size_t C = mesh.num_corners();
  // Group = (vertex, old pool index), numbered in order of first use.
  std::unordered_map<std::uint64_t, std::uint32_t> group_of;
  group_of.reserve(C);
  std::vector<std::uint32_t> corner_group(C);
  std::vector<std::uint32_t> group_vertex;
  for (std::size_t c = 0; c < C; ++c) {
    const std::uint64_t key = (std::uint64_t(mesh.corner_vertex[c]) << 32) | mesh.corner_normal_index[c];
    auto [it, inserted] = group_of.try_emplace(key, std::uint32_t(group_vertex.size()));
    if (inserted) group_vertex.push_back(mesh.corner_vertex[c]);
    corner_group[c] = it->second;
  }
  GroupNormals groups = corner_group_normals(mesh, corner_group, group_vertex.size(), Weighting::Angle);
  for (std::uint32_t g : groups.failed) set3(groups.normals, g, get3(vertex_n, group_vertex[g]));
  mesh.corner_normals.swap(groups.normals);
  mesh.corner_normal_index.swap(corner_group);
  return groups.failed.size();
}

}  // namespace

std::size_t recompute_normals(Mesh& mesh) {
  const bool want_faces = mesh.has_face_normals(), want_vertices = mesh.has_vertex_normals(),
             want_corners = mesh.has_corner_normals();
  if (!want_faces && !want_vertices && !want_corners) return 0;
  std::size_t fallbacks = 0;
  std::vector<double> face_n;
  if (want_faces) face_n = face_normals(mesh);
  std::vector<double> vertex_n;
  if (want_vertices || want_corners) {
    VertexNormals vn = vertex_normals(mesh);
    if (want_vertices) fallbacks += vn.fallback_vertices;
    vertex_n = std::move(vn.normals);
  }
  if (want_corners) fallbacks += recompute_corner_groups(mesh, vertex_n);
  if (want_vertices) mesh.vertex_normals = std::move(vertex_n);
  if (want_faces) mesh.face_normals = std::move(face_n);
  return fallbacks;
}

}  // namespace shadetool
