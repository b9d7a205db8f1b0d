// compact_vertices.h: removes the vertices a caller does not keep, moving every per-vertex array
// with the positions. The one home of that compaction: repair's remove_unreferenced_vertices
// (keep = used by a face) and glTF's world mesh (gltf/gltf_scene.h: keep = used by this primitive,
// or by no primitive sharing its accessor) both call it.
//
// Inputs:  mesh  positions #V by 3, faces, any per-vertex arrays (Mesh::for_each_vertex_array)
//          keep  #V flags; a vertex a face uses must be kept (the caller's rule: a face is never
//                left pointing at a removed vertex; corner indices >= #V are left as they are)
// Output:  old_to_new #V: the new index of each kept vertex, kRemovedVertex for the others; mesh
//          modified in place: kept vertices keep their order and every per-vertex value (normals,
//          colours, quality, properties), faces point at them. Per-corner and per-face arrays are
//          untouched. A per-vertex array of the wrong length (a caller's) is left as it is, for the
//          writer's note. Values of removed vertices are never read (NaN there is fine). Exact.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/mesh.h>

namespace shadetool {

constexpr std::uint32_t kRemovedVertex = std::numeric_limits<std::uint32_t>::max();

// Moves `a` (#V rows of `width`) to the kept rows; left as it is when not #V rows.
template <class Array>
void compact_vertex_rows(Array& a, std::size_t width, const std::vector<std::uint32_t>& old_to_new, std::size_t kept) {
  const std::size_t V = old_to_new.size();
  if (a.size() != width * V) return;
  for (std::size_t v = 0; v < V; ++v) {
    if (old_to_new[v] == kRemovedVertex) continue;
    const std::size_t n = old_to_new[v];
    for (std::size_t i = 0; i < width; ++i) a[width * n + i] = a[width * v + i];
  }
  a.resize(width * kept);
}

inline std::vector<std::uint32_t> compact_vertices(Mesh& mesh, const std::vector<bool>& keep) {
  const std::size_t V = mesh.num_vertices();
  std::vector<std::uint32_t> old_to_new(V, kRemovedVertex);
  std::size_t kept = 0;
  for (std::size_t v = 0; v < V; ++v)
    if (v < keep.size() && keep[v]) old_to_new[v] = std::uint32_t(kept++);
  if (kept == V) return old_to_new;
  compact_vertex_rows(mesh.positions, 3, old_to_new, kept);
  mesh.for_each_vertex_array([&](auto& a, std::size_t width) { compact_vertex_rows(a, width, old_to_new, kept); });
  for (auto& v : mesh.corner_vertex) v = v < V ? old_to_new[v] : v;
  return old_to_new;
}

}  // namespace shadetool
