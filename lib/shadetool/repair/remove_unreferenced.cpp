// remove_unreferenced.cpp: see remove_unreferenced.h.
#include <shadetool/repair/remove_unreferenced.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace shadetool {

std::size_t remove_unreferenced_vertices(Mesh& mesh) {
  const std::size_t V = mesh.num_vertices();
  constexpr std::uint32_t kRemoved = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> old_to_new(V, kRemoved);
  for (std::uint32_t v : mesh.corner_vertex)
    if (v < V) old_to_new[v] = 0;  // used; numbered below
  std::size_t kept = 0;
  for (std::size_t v = 0; v < V; ++v)
    if (old_to_new[v] != kRemoved) old_to_new[v] = std::uint32_t(kept++);
  const std::size_t removed = V - kept;
  if (removed == 0) return 0;
  auto compact = [&](auto& a, std::size_t width) {
    if (a.size() != width * V) return;
    for (std::size_t v = 0; v < V; ++v) {
      if (old_to_new[v] == kRemoved) continue;
      const std::size_t n = old_to_new[v];
      for (std::size_t i = 0; i < width; ++i) a[width * n + i] = a[width * v + i];
    }
    a.resize(width * kept);
  };
  compact(mesh.positions, 3);
  mesh.for_each_vertex_array(compact);
  for (auto& v : mesh.corner_vertex) v = v < V ? old_to_new[v] : v;
  return removed;
}

}  // namespace shadetool
