// tangent_vertices.cpp: see tangent_vertices.h.
#include <shadetool/normals/tangent_vertices.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <cstdint>

#include <shadetool/core/error.h>
#include <shadetool/normals/tangents.h>

namespace shadetool {

const char* const kTangentPropertyNames[4] = {"tx", "ty", "tz", "tw"};

std::array<MeshProperty*, 4> tangent_properties(Mesh& mesh) {
  std::array<MeshProperty*, 4> props{};
  for (std::size_t k = 0; k < 4; ++k)
    for (MeshProperty& p : mesh.vertex_properties)
      if (p.name == kTangentPropertyNames[k]) props[k] = &p;
  return props;
}

std::size_t remove_tangent_properties(Mesh& mesh) {
  auto& props = mesh.vertex_properties;
  const std::size_t before = props.size();
  props.erase(std::remove_if(props.begin(), props.end(),
                             [](const MeshProperty& p) {
                               return std::any_of(std::begin(kTangentPropertyNames), std::end(kTangentPropertyNames),
                                                  [&](const char* n) { return p.name == n; });
                             }),
              props.end());
  return before - props.size();
}

std::size_t store_tangents_per_vertex(Mesh& mesh, const std::vector<double>& tangents) {
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners();
  if (tangents.size() != 4 * C) throw Error("store_tangents_per_vertex: not 4 values per corner");
  const bool corner_normals = mesh.has_corner_normals();
  auto same = [&](std::uint32_t a, std::uint32_t b) {
    if (corner_normals && mesh.corner_normal_index[a] != mesh.corner_normal_index[b]) return false;
    return std::equal(&tangents[4 * std::size_t(a)], &tangents[4 * std::size_t(a)] + 4, &tangents[4 * std::size_t(b)]);
  };
  std::vector<std::uint32_t> offset(V + 1, 0), corners(C);
  for (std::size_t c = 0; c < C; ++c) ++offset[mesh.corner_vertex[c] + 1];
  for (std::size_t v = 0; v < V; ++v) offset[v + 1] += offset[v];
  std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
  for (std::size_t c = 0; c < C; ++c) corners[fill[mesh.corner_vertex[c]]++] = std::uint32_t(c);

  std::vector<std::uint32_t> new_vertex(C), source;  // corner -> its vertex; appended vertex -> copied from
  std::vector<std::uint32_t> reps, rep_vertex;          // at one vertex: each distinct frame's corner and vertex
  for (std::size_t v = 0; v < V; ++v) {
    reps.clear();
    rep_vertex.clear();
    for (std::uint32_t i = offset[v]; i < offset[v + 1]; ++i) {
      const std::uint32_t c = corners[i];
      std::size_t k = 0;
      while (k < reps.size() && !same(reps[k], c)) ++k;
      if (k == reps.size()) {  // the first frame keeps v, each further one is a new vertex
        reps.push_back(c);
        rep_vertex.push_back(k == 0 ? std::uint32_t(v) : std::uint32_t(V + source.size()));
        if (k > 0) source.push_back(std::uint32_t(v));
      }
      new_vertex[c] = rep_vertex[k];
    }
  }
  std::vector<std::uint32_t> frame_corner(V + source.size(), ~0u);
  for (std::size_t c = 0; c < C; ++c) frame_corner[new_vertex[c]] = std::uint32_t(c);
  mesh.for_each_vertex_array([&](auto& a, std::size_t width) {
    a.reserve(a.size() + width * source.size());
    for (std::uint32_t v : source)
      for (std::size_t k = 0; k < width; ++k) a.push_back(a[width * v + k]);
  });
  for (std::uint32_t v : source)
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(mesh.positions[3 * std::size_t(v) + k]);
  mesh.corner_vertex = new_vertex;

  const std::size_t V2 = mesh.num_vertices();
  for (const char* name : kTangentPropertyNames) {
    auto it = std::find_if(mesh.vertex_properties.begin(), mesh.vertex_properties.end(),
                           [&](const MeshProperty& p) { return p.name == name; });
    if (it == mesh.vertex_properties.end()) {
      mesh.vertex_properties.push_back({name, "float", {}});
      it = mesh.vertex_properties.end() - 1;
    }
    it->type = "float";
    it->values.assign(V2, 0.0);
  }
  const std::array<MeshProperty*, 4> props = tangent_properties(mesh);
  for (std::size_t v = 0; v < V2; ++v) {
    double t[4] = {1.0, 0.0, 0.0, 1.0};
    if (frame_corner[v] != ~0u) {
      std::copy(&tangents[4 * std::size_t(frame_corner[v])], &tangents[4 * std::size_t(frame_corner[v])] + 4, t);
    } else {
      const Vec3d p = perpendicular_unit(mesh.has_vertex_normals() ? get3(mesh.vertex_normals, v) : Vec3d{0, 0, 1});
      t[0] = p.x; t[1] = p.y; t[2] = p.z; t[3] = 1.0;
    }
    for (int k = 0; k < 4; ++k) props[std::size_t(k)]->values[v] = t[k];
  }
  return source.size();
}

}  // namespace shadetool
