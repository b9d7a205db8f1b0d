// remove_unreferenced.cpp: see remove_unreferenced.h.
#include <shadetool/repair/remove_unreferenced.h>

#include <vector>

#include <shadetool/core/compact_vertices.h>

namespace shadetool {

std::size_t remove_unreferenced_vertices(Mesh& mesh) {
  const std::size_t V = mesh.num_vertices();
  std::vector<bool> used(V, false);
  for (std::uint32_t v : mesh.corner_vertex)
    if (v < V) used[v] = true;
  std::size_t removed = 0;
  for (std::uint32_t n : compact_vertices(mesh, used)) removed += n == kRemovedVertex;
  return removed;
}

}  // namespace shadetool
