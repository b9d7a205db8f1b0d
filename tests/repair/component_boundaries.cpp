// Tests of component_boundaries: closedness and loop counts against the topology of known shapes.
#include <catch2/catch.hpp>

#include <shadetool/repair/component_boundaries.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
ComponentBoundaries bounds(const Mesh& m) {
  const EdgeAdjacency adj = edge_adjacency(m);
  return component_boundaries(m, adj, consistent_winding(m, adj));
}
}  // namespace

TEST_CASE("closed surfaces have no boundary", "[repair][boundaries]") {
  for (const Mesh& m : {icosphere(2).mesh, testing::torus(20, 8).mesh, genus3_slab()}) {
    const ComponentBoundaries b = bounds(m);
    CHECK(b.component_closed == std::vector<std::uint8_t>{1});
    CHECK(b.boundary_loops == 0);
  }
}

TEST_CASE("loops: disk 1, annulus 2, Möbius strip 1, terrain 1", "[repair][boundaries]") {
  CHECK(bounds(hemisphere(24, 12)).boundary_loops == 1);
  // A band around a sphere's equator (|z| < 0.5): an annulus.
  const Mesh band = keep_faces(uv_sphere(24, 12).mesh, [](const Vec3d& c) { return std::abs(c.z) < 0.5; });
  CHECK(bounds(band).boundary_loops == 2);
  const ComponentBoundaries mob = bounds(mobius_strip(30));
  CHECK(mob.boundary_loops == 1);
  CHECK(mob.component_boundary_edges[0] == 60);
  CHECK(bounds(bumpy_terrain(10)).boundary_loops == 1);
}

TEST_CASE("three triangles on one edge: each has a 3-edge loop including the shared edge", "[repair][boundaries]") {
  const ComponentBoundaries b = bounds(three_triangles_on_one_edge());
  CHECK(b.component_closed == std::vector<std::uint8_t>{0, 0, 0});
  CHECK(b.component_boundary_edges == std::vector<std::uint32_t>{3, 3, 3});
  CHECK(b.boundary_loops == 3);
}

TEST_CASE("two holes touching at one vertex count as two loops", "[repair][boundaries]") {
  // A 4x4 grid of unit squares with the cells (1,1) and (2,2) removed: the holes share the
  // vertex (2,2). One component; boundary = outer square + two holes = 3 loops.
  Mesh m;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) m.add_vertex({double(i), double(j), 0});
  auto id = [](int i, int j) { return std::uint32_t(j * 5 + i); };
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      if ((i == 1 && j == 1) || (i == 2 && j == 2)) continue;
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  const ComponentBoundaries b = bounds(m);
  CHECK(b.component_loops.size() == 1);
  CHECK(b.boundary_loops == 3);
}
