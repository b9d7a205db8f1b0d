// connected_components.cpp
#include <shadetool/info/connected_components.h>

#include <cstdint>
#include <vector>

#include <shadetool/geometry/union_find.h>

namespace shadetool::info {

std::size_t connected_components(const Mesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  UnionFind sets(nv);
  std::vector<std::uint8_t> used(nv, 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    used[mesh.corner_vertex[b]] = 1;
    for (std::uint32_t c = b + 1; c < e; ++c) {
      used[mesh.corner_vertex[c]] = 1;
      sets.unite(mesh.corner_vertex[b], mesh.corner_vertex[c]);
    }
  }
  std::size_t count = 0;
  for (std::uint32_t v = 0; v < nv; ++v) count += used[v] && sets.find(v) == v;
  return count;
}

}  // namespace shadetool::info
