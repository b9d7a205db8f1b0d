// Tests of duplicate_faces, and of repair with duplicated and two-sided faces.
#include <catch2/catch.hpp>

#include <shadetool/repair/duplicate_faces.h>
#include <shadetool/repair/repair_mesh.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

TEST_CASE("duplicates are found in any vertex order; the lowest face is the original", "[repair][duplicates]") {
  Mesh m = icosphere(1).mesh;  // 80 faces
  const std::uint32_t a = m.corner_vertex[30], b = m.corner_vertex[31], c = m.corner_vertex[32];  // face 10
  m.add_face({b, c, a});  // 80: same winding, rotated
  m.add_face({a, c, b});  // 81: opposite winding
  m.add_face({c, b, a});  // 82: opposite winding, rotated
  const DuplicateFaces d = duplicate_faces(m, edge_adjacency(m));
  CHECK(d.count == 3);
  CHECK(d.original[80] == 10);
  CHECK(d.original[81] == 10);
  CHECK(d.original[82] == 10);
  CHECK(d.original[10] == DuplicateFaces::kNone);
  CHECK(d.original[0] == DuplicateFaces::kNone);
}

TEST_CASE("a closed mesh with a duplicated face and a two-sided face is restored exactly", "[repair][duplicates]") {
  Mesh truth = icosphere(2).mesh;
  const std::size_t F = truth.num_faces();
  auto corner = [&](std::size_t f, int k) { return truth.corner_vertex[3 * f + k]; };
  truth.add_face({corner(7, 0), corner(7, 1), corner(7, 2)});  // exported twice
  truth.add_face({corner(9, 0), corner(9, 2), corner(9, 1)});  // the back side of face 9
  Mesh m = truth;
  invert_all(m);
  flip_random_faces(m, 0.3, 53);
  // The duplicates keep their relation to their originals as damaged: make that the truth's.
  const bool seven_same = m.corner_vertex[3 * 7 + 1] == m.corner_vertex[3 * F + 1];
  const bool nine_opposite = m.corner_vertex[3 * 9 + 1] == m.corner_vertex[3 * (F + 1) + 2];
  const RepairReport r = repair_mesh(m);
  CHECK(r.duplicate_faces == 2);
  CHECK(r.non_manifold_edges == 0);  // once the duplicates are set aside
  CHECK(r.components == 1);
  CHECK(r.closed_components == 1);
  CHECK(std::vector<std::uint32_t>(m.corner_vertex.begin(), m.corner_vertex.begin() + 3 * F) ==
        std::vector<std::uint32_t>(truth.corner_vertex.begin(), truth.corner_vertex.begin() + 3 * F));
  // Face 80 ends wound like face 7 exactly when it came in wound like it.
  CHECK((m.corner_vertex[3 * 7 + 1] == m.corner_vertex[3 * F + 1]) == seven_same);
  CHECK((m.corner_vertex[3 * 9 + 1] == m.corner_vertex[3 * (F + 1) + 2]) == nine_opposite);
  Mesh again = m;
  CHECK(repair_mesh(again).changes() == 0);
}

TEST_CASE("a lone pair of faces on the same vertices is a duplicate, not a closed surface", "[repair][duplicates]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 1, 2});
  const Mesh before = m;
  const RepairReport r = repair_mesh(m);
  CHECK(r.duplicate_faces == 1);
  CHECK(r.faces_flipped == 0);
  CHECK(r.components == 1);
  CHECK(r.open_components == 1);
  CHECK(m.corner_vertex == before.corner_vertex);
}
