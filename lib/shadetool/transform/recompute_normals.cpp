// recompute_normals.cpp: see recompute_normals.h.
#include <shadetool/transform/recompute_normals.h>

#include <algorithm>
#include <cstdint>
#include <utility>
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
  // Group = (vertex, old pool index), numbered in order of first use: sort the corners by
  // (key, corner), so each group is a run whose first entry is its first corner; then number the
  // runs by first corner (flat arrays, two sorts).
  std::vector<std::pair<std::uint64_t, std::uint32_t>> by_key(C);
  for (std::size_t c = 0; c < C; ++c)
    by_key[c] = {(std::uint64_t(mesh.corner_vertex[c]) << 32) | mesh.corner_normal_index[c], std::uint32_t(c)};
  std::sort(by_key.begin(), by_key.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;  // (first corner, start in by_key)
  for (std::size_t i = 0; i < C; ++i)
    if (i == 0 || by_key[i].first != by_key[i - 1].first) runs.emplace_back(by_key[i].second, std::uint32_t(i));
  std::sort(runs.begin(), runs.end());
  std::vector<std::uint32_t> corner_group(C), group_vertex(runs.size());
  for (std::size_t g = 0; g < runs.size(); ++g) {  // group g = the run with the g-th first corner
    group_vertex[g] = mesh.corner_vertex[runs[g].first];
    const std::uint64_t key = by_key[runs[g].second].first;
    for (std::size_t i = runs[g].second; i < C && by_key[i].first == key; ++i) corner_group[by_key[i].second] = std::uint32_t(g);
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
