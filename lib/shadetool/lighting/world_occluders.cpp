// world_occluders.cpp: see world_occluders.h.
#include <shadetool/lighting/world_occluders.h>

namespace shadetool {

std::vector<double> world_positions(const Mesh& mesh, const Affine3d& world_from_object) {
  std::vector<double> out(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) set3(out, v, transform_point(world_from_object, mesh.position(v)));
  return out;
}

std::unique_ptr<WorldOccluders> world_occluders(std::vector<double> positions_world, const Mesh& topology) {
  auto occluders = std::make_unique<WorldOccluders>();
  occluders->world.positions = std::move(positions_world);
  occluders->world.face_start = topology.face_start;
  occluders->world.corner_vertex = topology.corner_vertex;
  occluders->bvh = std::make_unique<VisibilityScene>(occluders->world);
  return occluders;
}

}  // namespace shadetool
