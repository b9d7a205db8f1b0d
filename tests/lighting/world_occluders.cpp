// Tests of lighting/world_occluders.h: the one builder of the world-space occluders shadows are
// cast by (bake-lighting's own mesh, a glTF document's scene, render's Phong shadows).
#include <catch2/catch.hpp>

#include <shadetool/lighting/world_occluders.h>

using namespace shadetool;

TEST_CASE("world_occluders: positions M p, the mesh's faces, and a BVH over them", "[lighting][shadows]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({5, 5, 5});  // unreferenced: placed, casts nothing
  m.add_face({0, 1, 2});
  Affine3d M;  // x' = 2 x + (0, 0, 3)
  for (int i = 0; i < 3; ++i) M.A.m[i][i] = 2;
  M.t = {0, 0, 3};
  const std::vector<double> world = world_positions(m, M);
  CHECK(world == std::vector<double>{0, 0, 3, 2, 0, 3, 0, 2, 3, 10, 10, 13});
  const auto occluders = world_occluders(world, m);
  CHECK(occluders->world.positions == world);
  CHECK(occluders->world.face_start == m.face_start);
  CHECK(occluders->world.corner_vertex == m.corner_vertex);
  REQUIRE(occluders->bvh != nullptr);
  CHECK(occluders->bvh->stats().triangles == 1);
  CHECK(occluders->bvh->stats().faces_used == 1);
}
