// vertex_normals_plan.cpp: see vertex_normals_plan.h.
#include <shadetool/normals/vertex_normals_plan.h>

#include <shadetool/normals/engine/accumulate_by_vertex.h>

namespace shadetool {

VertexNormalsPlan::VertexNormalsPlan(const MeshView& mesh)
    : vertices_(mesh.num_vertices()), faces_(mesh.num_faces()), corners_(mesh.num_corners()) {
  auto plan = std::make_shared<normals_detail::ChunkPlan>(normals_detail::plan_chunks<false>(mesh, nullptr, vertices_));
  normals_detail::flag_border_faces<false>(mesh, nullptr, *plan);
  chunks_ = plan;
}

bool VertexNormalsPlan::fits(const MeshView& mesh) const {
  return chunks_ && mesh.num_vertices() == vertices_ && mesh.num_faces() == faces_ && mesh.num_corners() == corners_;
}

}  // namespace shadetool
