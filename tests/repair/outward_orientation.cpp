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

namespace {

// Unit vertex normals along the position from `centre` (a sphere's outward normals), times `sign`.
void radial_vertex_normals(Mesh& m, const Vec3d& centre, double sign) {
  m.vertex_normals.clear();
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d n = normalized_or(m.position(v) - centre, Vec3d{0, 0, 1}) * sign;
    m.vertex_normals.insert(m.vertex_normals.end(), {n.x, n.y, n.z});
  }
}

OutwardOrientation orient(const Mesh& m, ConsistentWinding* out_winding = nullptr) {
  const EdgeAdjacency adj = edge_adjacency(m);
  const ConsistentWinding w = consistent_winding(m, adj);
  if (out_winding) *out_winding = w;
  return outward_orientation(m, w, component_boundaries(m, adj, w));
}

}  // namespace

TEST_CASE("a bowl whose winding and normals both face in keeps them: the open-surface vote does not overrule "
          "agreeing authored normals (issue 27 item 1)", "[repair][outward][authored]") {
  // The inside of a hemisphere, as a valley terrain or a helmet's liner is authored: wound and
  // normalled towards the centre. The winding-number vote alone reverses it (checked first).
  Mesh bowl = hemisphere(24, 12);
  invert_all(bowl);
  OutwardOrientation o = orient(bowl);
  REQUIRE(o.component_basis[0] == OrientationBasis::SurfaceVote);
  REQUIRE(o.component_invert[0] == 1);
  radial_vertex_normals(bowl, {0, 0, 0}, -1.0);  // into the bowl, as its faces
  o = orient(bowl);
  CHECK(o.component_basis[0] == OrientationBasis::WindingAndNormals);
  CHECK(o.component_invert[0] == 0);
  CHECK(o.geometry_overruled == 1);
  CHECK(o.faces_agreeing == bowl.num_faces());
  // Normals that contradict the winding are not a statement: the geometry decides again.
  radial_vertex_normals(bowl, {0, 0, 0}, 1.0);
  o = orient(bowl);
  CHECK(o.component_basis[0] == OrientationBasis::SurfaceVote);
  CHECK(o.component_invert[0] == 1);
  CHECK(o.faces_disagreeing == bowl.num_faces());
}

TEST_CASE("a shell buried in another keeps its outward winding when its normals agree; nesting parity decides "
          "only without them (issue 27 item 2)", "[repair][outward][authored]") {
  Mesh outer = icosphere(2).mesh, inner = icosphere(1).mesh;
  transform_positions(inner, 0.3, {0.2, 0, 0});  // a tooth inside the body, both wound outward
  Mesh m = outer;
  append(m, inner);
  OutwardOrientation o = orient(m);
  REQUIRE(o.component_basis[1] == OrientationBasis::NestedShell);  // no normals: parity turns it in
  radial_vertex_normals(m, {0, 0, 0}, 1.0);
  for (std::size_t v = outer.num_vertices(); v < m.num_vertices(); ++v) {  // the inner shell's own centre
    const Vec3d n = normalized_or(m.position(v) - Vec3d{0.2, 0, 0}, Vec3d{0, 0, 1});
    set3(m.vertex_normals, v, n);
  }
  o = orient(m);
  CHECK(o.component_basis[0] == OrientationBasis::WindingAndNormals);
  CHECK(o.component_basis[1] == OrientationBasis::WindingAndNormals);
  CHECK(o.component_invert[0] == 0);
  CHECK(o.component_invert[1] == 0);
  CHECK(o.nested_shells == 0);
  CHECK(o.geometry_overruled == 1);  // parity would have turned the inner one
}

TEST_CASE("a part whose winding is inconsistent follows the majority of its normals' evidence",
          "[repair][outward][authored]") {
  // Terrain wound +z, normals +z; 20 of its 32 faces reversed: the input majority says -z, the
  // normals say +z for every face. The normals decide.
  Mesh m = bumpy_terrain(4);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.vertex_normals.insert(m.vertex_normals.end(), {0.0, 0.0, 1.0});
  for (std::size_t f = 0; f < 20; ++f) swap_corners_1_2(m, f);
  ConsistentWinding w;
  const OutwardOrientation o = orient(m, &w);
  CHECK(o.component_basis[0] == OrientationBasis::AuthoredNormals);
  CHECK(o.faces_agreeing == 12);
  CHECK(o.faces_disagreeing == 20);
  // Seed (face 0) is reversed in the input: the final winding of face 0 must be flipped back.
  CHECK((w.face_reverse[0] ^ o.component_invert[0]) == 1);
  CHECK((w.face_reverse[31] ^ o.component_invert[0]) == 0);  // face 31 was right: kept
}
