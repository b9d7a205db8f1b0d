// Tests of outward_orientation: the basis chosen for each kind of component in one scene.
#include <catch2/catch.hpp>

#include <shadetool/repair/outward_orientation.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("one scene: closed, nested, open with and without evidence, non-orientable", "[repair][outward]") {
  Mesh outer = icosphere(2).mesh, inner = icosphere(1).mesh, hemi = hemisphere(24, 12), terrain = bumpy_terrain(8),
       strip = mobius_strip(20);
  invert_all(outer);                        // component 0: closed, inverted
  transform_positions(inner, 0.5, {});      // component 1: inside 0, wound outward
  transform_positions(hemi, 1.0, {4, 0, 0});
  invert_all(hemi);                         // component 2: open, facing in
  transform_positions(terrain, 1.0, {0, 4, 0});  // component 3: open, no evidence
  transform_positions(strip, 1.0, {0, -4, 0});   // component 4: Möbius
  Mesh m = outer;
  for (const Mesh* p : {&inner, &hemi, &terrain, &strip}) append(m, *p);

  const EdgeAdjacency adj = edge_adjacency(m);
  const ConsistentWinding w = consistent_winding(m, adj);
  REQUIRE(w.num_components == 5);
  const OutwardOrientation o = outward_orientation(m, w, component_boundaries(m, adj, w));
  CHECK(o.component_basis[0] == OrientationBasis::Volume);
  CHECK(o.component_invert[0] == 1);
  CHECK(o.component_basis[1] == OrientationBasis::NestedShell);
  CHECK(o.component_invert[1] == 1);  // wound outward, must face the cavity
  CHECK(o.component_basis[2] == OrientationBasis::SurfaceVote);
  CHECK(o.component_invert[2] == 1);
  CHECK(o.component_basis[3] == OrientationBasis::Majority);
  CHECK(o.component_invert[3] == 0);
  CHECK(o.component_basis[4] == OrientationBasis::Majority);
  CHECK(o.nested_shells == 1);
  CHECK(o.majority_components == 2);
}

TEST_CASE("majority: the winding most input faces had wins, a tie keeps the seed's", "[repair][outward]") {
  Mesh m = bumpy_terrain(4);  // 32 faces
  for (std::size_t f = 0; f < 20; ++f) swap_corners_1_2(m, f);  // 20 of 32 flipped, seed included
  const EdgeAdjacency adj = edge_adjacency(m);
  const ConsistentWinding w = consistent_winding(m, adj);
  REQUIRE(w.component_reverse_count[0] == 12);  // relative to the (flipped) seed
  OutwardOrientation o = outward_orientation(m, w, component_boundaries(m, adj, w));
  CHECK(o.component_invert[0] == 0);  // the 20 agree with the seed: keep
  for (std::size_t f = 0; f < 4; ++f) swap_corners_1_2(m, f);  // now 16 / 16
  const EdgeAdjacency adj2 = edge_adjacency(m);
  const ConsistentWinding w2 = consistent_winding(m, adj2);
  REQUIRE(w2.component_reverse_count[0] == 16);
  o = outward_orientation(m, w2, component_boundaries(m, adj2, w2));
  CHECK(o.component_invert[0] == 0);
}
