// world_occluders.h: what shadows are cast by: a mesh's faces at world-space positions and the
// visibility BVH over them (visibility/visibility_scene.h). The one builder for bake-lighting's
// own mesh, a glTF document's whole scene (cli bake-lighting) and render's Phong shadows.
//
// Inputs:  positions_world  #V by 3 doubles, world space (world_positions: p_world = M p_object)
//          topology         the mesh whose face_start and corner_vertex index them (its positions
//                           and every other array are not read)
// Output:  WorldOccluders: `world` holds the positions and faces, `bvh` is built over it (the
//          scene's own filtering: degenerate and non-finite faces cast nothing). Returned on the
//          heap because the BVH reads `world`'s arrays in place: the pair must not move apart.
// Precision: positions in double, as the rays (lighting/light_visibility.h).
#pragma once

#include <memory>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/core/mesh.h>
#include <shadetool/visibility/visibility_scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct WorldOccluders {
  Mesh world;
  std::unique_ptr<VisibilityScene> bvh;
};

// M p for every vertex p of the mesh: #V by 3 world positions.
std::vector<double> world_positions(const Mesh& mesh, const Affine3d& world_from_object);

std::unique_ptr<WorldOccluders> world_occluders(std::vector<double> positions_world, const Mesh& topology);

}  // namespace shadetool
#pragma GCC visibility pop
