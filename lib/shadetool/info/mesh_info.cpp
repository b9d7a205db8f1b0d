// mesh_info.cpp
#include <shadetool/info/mesh_info.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <shadetool/info/connected_components.h>

namespace shadetool::info {

namespace {

template <class T>
std::size_t count_nonfinite(const std::vector<T>& a) {
  std::size_t n = 0;
  for (T x : a) n += !std::isfinite(x);
  return n;
}

}  // namespace

MeshInfo mesh_info(const Mesh& mesh) {
  MeshInfo m;
  m.vertices = mesh.num_vertices();
  m.faces = mesh.num_faces();
  m.corners = mesh.num_corners();

  std::vector<std::size_t> by_size;  // by_size[k] = faces with k corners
  for (std::size_t f = 0; f < m.faces; ++f) {
    const std::size_t k = mesh.face_size(f);
    if (k >= by_size.size()) by_size.resize(k + 1, 0);
    ++by_size[k];
  }
  for (std::size_t k = 0; k < by_size.size(); ++k) {
    if (by_size[k] == 0) continue;
    m.faces_by_size.emplace_back(k, by_size[k]);
    if (k == 3) m.triangles = by_size[k];
    else if (k == 4) m.quads = by_size[k];
    else if (k > 4) m.polygons += by_size[k];
  }

  for (std::size_t v = 0; v < m.vertices; ++v) {
    const Vec3d p = mesh.position(v);
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
      ++m.nonfinite_vertices;
      continue;
    }
    if (!m.has_bbox) {
      m.bbox_min = m.bbox_max = p;
      m.has_bbox = true;
    }
    for (std::size_t k = 0; k < 3; ++k) {
      m.bbox_min[k] = std::min(m.bbox_min[k], p[k]);
      m.bbox_max[k] = std::max(m.bbox_max[k], p[k]);
    }
  }

  m.vertex_normals = mesh.has_vertex_normals();
  m.corner_normals = mesh.has_corner_normals();
  m.face_normals = mesh.has_face_normals();
  m.vertex_colors = mesh.has_vertex_colors();
  m.face_colors = mesh.has_face_colors();
  m.texcoords = mesh.has_texcoords();
  m.vertex_quality = mesh.has_vertex_quality();
  m.face_quality = mesh.has_face_quality();
  for (const MeshProperty& p : mesh.vertex_properties) m.vertex_properties.push_back(p.name);
  for (const MeshProperty& p : mesh.face_properties) m.face_properties.push_back(p.name);
  m.corner_normal_pool = mesh.corner_normals.size() / 3;
  m.texcoord_pool = mesh.texcoord_dims > 0 ? mesh.texcoords.size() / std::size_t(mesh.texcoord_dims) : 0;
  m.color_channels = (m.vertex_colors || m.face_colors) ? mesh.color_channels : 0;
  m.double_precision = mesh.precision == ValuePrecision::Double;
  m.nonfinite_values = count_nonfinite(mesh.vertex_normals) + count_nonfinite(mesh.corner_normals) +
                       count_nonfinite(mesh.face_normals) + count_nonfinite(mesh.texcoords) +
                       count_nonfinite(mesh.vertex_colors) + count_nonfinite(mesh.face_colors);

  std::vector<std::uint8_t> used(m.vertices, 0);
  for (std::uint32_t v : mesh.corner_vertex) used[v] = 1;
  for (std::uint8_t u : used) m.unreferenced_vertices += !u;
  for (std::size_t v = 0; v < m.vertices; ++v) {
    const Vec3d p = mesh.position(v);
    m.nonfinite_unreferenced_vertices += !used[v] && !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }

  m.topology = edge_topology(mesh);
  m.components = connected_components(mesh);
  m.degenerate = degenerate_faces(mesh);
  return m;
}

}  // namespace shadetool::info
