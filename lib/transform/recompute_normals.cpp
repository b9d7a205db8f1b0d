// recompute_normals.cpp: see recompute_normals.h.
#include <shadetool/core/math_constants.h>
#include <shadetool/transform/recompute_normals.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {


// Interior angle at corner c of face f (unit normal n), in [0, 2 pi); 0 for a zero-length edge.
double corner_angle(const Mesh& mesh, std::size_t f, std::size_t c, const Vec3d& n) {
  const std::size_t begin = mesh.face_start[f], end = mesh.face_start[f + 1];
  const std::size_t next = c + 1 < end ? c + 1 : begin, prev = c > begin ? c - 1 : end - 1;
  const Vec3d p = mesh.position(mesh.corner_vertex[c]);
  const Vec3d a = mesh.position(mesh.corner_vertex[next]) - p, b = mesh.position(mesh.corner_vertex[prev]) - p;
  const Vec3d axb = cross(a, b);
  // Signed about the face normal: atan2 needs no division and is accurate near 0 and pi.
  const double s = end - begin == 3 ? length(axb) : dot(axb, n);
  double theta = std::atan2(s, dot(a, b));  // atan2(0, 0) = 0: a zero edge adds nothing
  if (theta < 0) theta += kTwoPi;
  return theta;
}

// Recomputes the corner-normal pool within the input's smoothing groups; returns the groups that
// fell back to their vertex normal.
std::size_t recompute_corner_groups(Mesh& mesh, const std::vector<double>& face_n, const std::vector<double>& vertex_n) {
  const std::size_t C = mesh.num_corners(), F = mesh.num_faces();
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
  std::vector<double> sum(3 * group_vertex.size(), 0.0);
  for (std::size_t f = 0; f < F; ++f) {
    const Vec3d n = get3(face_n, f);
    if (n.x == 0 && n.y == 0 && n.z == 0) continue;  // degenerate face: contributes nothing
    for (std::size_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      const double w = corner_angle(mesh, f, c, n);
      const std::size_t g = corner_group[c];
      sum[3 * g] += w * n.x;
      sum[3 * g + 1] += w * n.y;
      sum[3 * g + 2] += w * n.z;
    }
  }
  std::size_t fallbacks = 0;
  for (std::size_t g = 0; g < group_vertex.size(); ++g) {
    const Vec3d s = get3(sum, g);
    const double l = length(s);
    if (l > 0 && std::isfinite(l)) {
      set3(sum, g, Vec3d{s.x / l, s.y / l, s.z / l});
    } else {
      set3(sum, g, get3(vertex_n, group_vertex[g]));
      ++fallbacks;
    }
  }
  mesh.corner_normals.swap(sum);
  mesh.corner_normal_index.swap(corner_group);
  return fallbacks;
}

}  // namespace

std::size_t recompute_normals(Mesh& mesh) {
  const bool want_faces = mesh.has_face_normals(), want_vertices = mesh.has_vertex_normals(),
             want_corners = mesh.has_corner_normals();
  if (!want_faces && !want_vertices && !want_corners) return 0;
  std::size_t fallbacks = 0;
  std::vector<double> face_n;
  if (want_faces || want_corners) face_n = face_normals(mesh);
  std::vector<double> vertex_n;
  if (want_vertices || want_corners) {
    VertexNormals vn = vertex_normals(mesh);
    if (want_vertices) fallbacks += vn.fallback_vertices;
    vertex_n = std::move(vn.normals);
  }
  if (want_corners) fallbacks += recompute_corner_groups(mesh, face_n, vertex_n);
  if (want_vertices) mesh.vertex_normals = std::move(vertex_n);
  if (want_faces) mesh.face_normals = std::move(face_n);
  return fallbacks;
}

}  // namespace shadetool
