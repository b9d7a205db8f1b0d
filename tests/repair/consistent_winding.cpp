// Tests of consistent_winding: BFS labels against the known flips, components, Möbius detection.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include <tbb/task_arena.h>

#include <shadetool/repair/consistent_winding.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
ConsistentWinding wind(const Mesh& m, const std::vector<std::uint8_t>& skip = {}) {
  EdgeAdjacencyOptions left_out;
  left_out.skip = skip;
  return consistent_winding(m, edge_adjacency(m, left_out), left_out);
}
}  // namespace

TEST_CASE("labels are exactly the flipped faces, relative to the seed face", "[repair][winding]") {
  Mesh m = testing::torus(30, 12).mesh;
  std::vector<std::size_t> flipped = flip_random_faces(m, 0.3, 5);
  const bool seed_flipped = std::find(flipped.begin(), flipped.end(), 0) != flipped.end();
  const ConsistentWinding w = wind(m);
  REQUIRE(w.num_components == 1);
  std::vector<std::uint8_t> expected(m.num_faces(), seed_flipped ? 1 : 0);
  for (std::size_t f : flipped) expected[f] ^= 1;
  CHECK(w.face_reverse == expected);
  CHECK(w.component_reverse_count[0] == std::size_t(std::count(expected.begin(), expected.end(), 1)));
  CHECK(w.component_faces[0] == m.num_faces());
  CHECK(w.component_non_orientable[0] == 0);
  CHECK(w.inconsistent_edges == 0);
}

TEST_CASE("components are joined through manifold edges only", "[repair][winding]") {
  SECTION("three triangles on one edge: three components, one non-manifold edge") {
    const ConsistentWinding w = wind(three_triangles_on_one_edge());
    CHECK(w.num_components == 3);
    CHECK(w.non_manifold_edges == 1);
    CHECK(w.face_reverse == std::vector<std::uint8_t>{0, 0, 0});
  }
  SECTION("two spheres: two components, seeds at their first faces") {
    Mesh m = icosphere(1).mesh;
    append(m, icosphere(1).mesh);
    const ConsistentWinding w = wind(m);
    CHECK(w.num_components == 2);
    CHECK(w.component_seed == std::vector<std::uint32_t>{0, 80});
    CHECK(w.component_faces == std::vector<std::uint32_t>{80, 80});
  }
  SECTION("skipped faces belong to no component") {
    Mesh m = icosphere(1).mesh;
    const ConsistentWinding w = wind(m, std::vector<std::uint8_t>(m.num_faces(), 1));
    CHECK(w.num_components == 0);
    CHECK(w.face_component[0] == ConsistentWinding::kNoComponent);
  }
}

TEST_CASE("a Möbius strip is non-orientable with one inconsistent edge", "[repair][winding]") {
  Mesh m = mobius_strip(40);
  flip_random_faces(m, 0.3, 9);
  const ConsistentWinding w = wind(m);
  CHECK(w.num_components == 1);
  CHECK(w.component_non_orientable[0] == 1);
  // The face adjacency of a one-triangle-wide strip is a cycle: exactly one non-tree edge.
  CHECK(w.inconsistent_edges == 1);
}

TEST_CASE("the result does not depend on the input winding (BFS order is winding-free)", "[repair][winding]") {
  Mesh a = mobius_strip(50);
  Mesh b = a;
  flip_random_faces(b, 0.5, 13);
  std::vector<std::uint8_t> ra = wind(a).face_reverse, rb = wind(b).face_reverse;
  // Apply each labelling; both must give the same final winding up to one global flip.
  Mesh fa = a, fb = b;
  for (std::size_t f = 0; f < a.num_faces(); ++f) {
    if (ra[f]) swap_corners_1_2(fa, f);
    if (rb[f]) swap_corners_1_2(fb, f);
  }
  if (fa.corner_vertex != fb.corner_vertex) invert_all(fb);
  CHECK(fa.corner_vertex == fb.corner_vertex);
}

TEST_CASE("faces_by_component lists each component's faces in order", "[repair][winding]") {
  Mesh m = icosphere(0).mesh;
  append(m, three_triangles_on_one_edge());
  const ConsistentWinding w = wind(m);
  const ComponentFaces g = faces_by_component(w);
  REQUIRE(g.start.size() == w.num_components + 1);
  CHECK(g.start[1] == 20);
  for (std::uint32_t i = 0; i < 20; ++i) CHECK(g.faces[i] == i);
  CHECK(g.faces.size() == 23);
}

TEST_CASE("an orientable and a non-orientable part in one mesh: each settled on its own", "[repair][winding]") {
  Mesh m = testing::torus(16, 8).mesh;  // faces 0 .. 255: orientable
  std::vector<std::size_t> flipped = flip_random_faces(m, 0.3, 21);
  const std::size_t torus_faces = m.num_faces();
  append(m, mobius_strip(30));  // the union-find finds a conflict here only
  const ConsistentWinding w = wind(m);
  REQUIRE(w.num_components == 2);
  CHECK(w.component_seed == std::vector<std::uint32_t>{0, std::uint32_t(torus_faces)});
  CHECK(w.component_non_orientable == std::vector<std::uint8_t>{0, 1});
  CHECK(w.inconsistent_edges == 1);
  const bool seed_flipped = std::find(flipped.begin(), flipped.end(), 0) != flipped.end();
  std::vector<std::uint8_t> expected(torus_faces, seed_flipped ? 1 : 0);
  for (std::size_t f : flipped) expected[f] ^= 1;
  CHECK(std::vector<std::uint8_t>(w.face_reverse.begin(), w.face_reverse.begin() + std::ptrdiff_t(torus_faces)) == expected);
  CHECK(w.component_faces == std::vector<std::uint32_t>{std::uint32_t(torus_faces), std::uint32_t(m.num_faces() - torus_faces)});
}

TEST_CASE("quads: labels are exactly the reversed faces", "[repair][winding]") {
  // A quad torus, 12 x 6, every 3rd face reversed (corners 1 .. 3 in reverse order).
  const int nu = 12, nv = 6;
  Mesh m;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) m.add_vertex({double(i), double(j), 0});  // positions unused here
  auto id = [&](int i, int j) { return std::uint32_t((j % nv) * nu + (i % nu)); };
  std::vector<std::uint8_t> expected;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const bool reversed = (j * nu + i) % 3 == 1;
      if (reversed) m.add_face({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
      else m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      expected.push_back(reversed ? 1 : 0);  // face 0 is not reversed: labels are relative to it
    }
  const ConsistentWinding w = wind(m);
  REQUIRE(w.num_components == 1);
  CHECK(w.face_reverse == expected);
  CHECK(w.component_reverse_count[0] == std::size_t(nu * nv / 3));
  CHECK(w.component_non_orientable[0] == 0);
}

TEST_CASE("the same winding on 1 and 2 threads, with components cut by the parts and faces out of order", "[repair][winding]") {
  // 2 parts above 32768 faces: the torus spans the cut between them (its edges across it are
  // deferred), the Möbius strip lies in the second part; then the same with every face shuffled,
  // so that half of all edges cross the cut.
  Mesh m = testing::torus(150, 120).mesh;  // 36000 faces
  const std::vector<std::size_t> flipped = flip_random_faces(m, 0.3, 4);
  const std::size_t torus_faces = m.num_faces();
  append(m, mobius_strip(2000));
  Mesh shuffled;
  shuffled.positions = m.positions;
  std::vector<std::uint32_t> order(m.num_faces());
  for (std::uint32_t f = 0; f < order.size(); ++f) order[f] = f;
  std::mt19937 rng(9);
  std::shuffle(order.begin(), order.end(), rng);
  for (std::uint32_t f : order)
    shuffled.add_face({m.corner_vertex[3 * f], m.corner_vertex[3 * f + 1], m.corner_vertex[3 * f + 2]});
  for (const Mesh* mesh : {&m, &shuffled}) {
    const ConsistentWinding one = tbb::task_arena(1).execute([&] { return wind(*mesh); });
    const ConsistentWinding two = tbb::task_arena(2).execute([&] { return wind(*mesh); });
    REQUIRE(one.num_components == 2);
    CHECK(std::equal(one.face_component.begin(), one.face_component.end(), two.face_component.begin(), two.face_component.end()));
    CHECK(one.face_reverse == two.face_reverse);
    CHECK(one.component_seed == two.component_seed);
    CHECK(one.component_faces == two.component_faces);
    CHECK(one.component_reverse_count == two.component_reverse_count);
    CHECK(one.component_non_orientable == two.component_non_orientable);
    CHECK(one.inconsistent_edges == 1);
    CHECK(two.inconsistent_edges == 1);
  }
  // In the ordered mesh the torus's labels are exactly its flips, relative to face 0.
  const ConsistentWinding w = tbb::task_arena(2).execute([&] { return wind(m); });
  const bool seed_flipped = std::find(flipped.begin(), flipped.end(), 0) != flipped.end();
  std::vector<std::uint8_t> expected(torus_faces, seed_flipped ? 1 : 0);
  for (std::size_t f : flipped) expected[f] ^= 1;
  CHECK(std::vector<std::uint8_t>(w.face_reverse.begin(), w.face_reverse.begin() + std::ptrdiff_t(torus_faces)) == expected);
  CHECK(w.component_non_orientable == std::vector<std::uint8_t>{0, 1});
}
