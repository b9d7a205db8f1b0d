// gltf_morph_normals.cpp: morph-target NORMAL deltas from displaced positions (see the header).
#include <shadetool/gltf/gltf_morph_normals.h>

namespace shadetool {

std::size_t recompute_morph_normal_deltas(GltfPrimitive& p, const std::function<void(Mesh&)>& compute) {
  const Mesh& base = p.mesh;
  if (!base.has_vertex_normals() || base.has_corner_normals() || base.has_face_normals()) return 0;
  std::size_t done = 0;
  for (GltfMorphTarget& target : p.targets) {
    if (target.position_deltas.size() != base.positions.size()) continue;
    Mesh displaced;
    displaced.positions = base.positions;
    for (std::size_t k = 0; k < displaced.positions.size(); ++k) displaced.positions[k] += target.position_deltas[k];
    displaced.face_start = base.face_start;
    displaced.corner_vertex = base.corner_vertex;
    compute(displaced);
    if (displaced.vertex_normals.size() != base.vertex_normals.size()) continue;
    target.normal_deltas.resize(base.vertex_normals.size());
    for (std::size_t k = 0; k < base.vertex_normals.size(); ++k)
      target.normal_deltas[k] = displaced.vertex_normals[k] - base.vertex_normals[k];
    ++done;
  }
  return done;
}

}  // namespace shadetool
