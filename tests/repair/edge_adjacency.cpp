// Tests of edge_adjacency: counts checked by hand on small meshes and by Euler's formula on closed ones.
#include <catch2/catch.hpp>

#include <tbb/task_arena.h>

#include "repair/edge_adjacency.h"
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
// Edge id by brute force over the half-edges of each edge.
std::uint32_t edge_between(const Mesh& m, const EdgeAdjacency& adj, std::uint32_t a, std::uint32_t b) {
  for (std::size_t e = 0; e < adj.num_edges(); ++e)
    for (std::uint32_t i = adj.edge_start[e]; i < adj.edge_start[e + 1]; ++i) {
      const std::uint32_t c = adj.edge_corner[i], f = adj.corner_face[c];
      const std::uint32_t u = m.corner_vertex[c], v = m.corner_vertex[c + 1 < m.face_start[f + 1] ? c + 1 : m.face_start[f]];
      if (std::min(u, v) == std::min(a, b) && std::max(u, v) == std::max(a, b)) return std::uint32_t(e);
    }
  return EdgeAdjacency::kNoEdge;
}
}  // namespace

TEST_CASE("two triangles of a square: four boundary edges and one shared diagonal", "[repair][adjacency]") {
  Mesh m;
  for (int i = 0; i < 4; ++i) m.add_vertex({double(i & 1), double(i >> 1), 0});
  m.add_face({0, 1, 3});
  m.add_face({0, 3, 2});
  const EdgeAdjacency adj = edge_adjacency(m);
  REQUIRE(adj.num_edges() == 5);
  // Numbered by (low, high): (0,1) (0,2) (0,3) (1,3) (2,3).
  const std::uint32_t expected[5][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  for (int e = 0; e < 5; ++e) {
    CHECK(edge_ends(m, adj, e) == std::make_pair(expected[e][0], expected[e][1]));
  }
  const std::uint32_t diagonal = edge_between(m, adj, 0, 3);
  CHECK(adj.edge_valence(diagonal) == 2);
  // Face 0's corner 2 (3 -> 0) and face 1's corner 3 (0 -> 3) lie on it, in corner order.
  CHECK(adj.edge_corner[adj.edge_start[diagonal]] == 2);
  CHECK(adj.edge_corner[adj.edge_start[diagonal] + 1] == 3);
  for (std::uint32_t e : {edge_between(m, adj, 0, 1), edge_between(m, adj, 1, 3), edge_between(m, adj, 3, 2), edge_between(m, adj, 2, 0)})
    CHECK(adj.edge_valence(e) == 1);
  CHECK(adj.corner_face == std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1});
  const std::uint32_t k = EdgeAdjacency::kNoEdge;
  // Across the diagonal: face 1 from corner 2, face 0 from corner 3; opposite directions (bit 0).
  CHECK(adj.corner_across == std::vector<std::uint32_t>{k, k, (1u << 1) | 0u, (0u << 1) | 0u, k, k});
  CHECK(adj.non_manifold_edges == 0);
}

TEST_CASE("a closed triangle mesh: every edge has two half-edges, E = 3F/2, V - E + F = 2", "[repair][adjacency]") {
  const Mesh m = icosphere(3).mesh;
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges() * 2 == 3 * m.num_faces());
  for (std::size_t e = 0; e < adj.num_edges(); ++e) CHECK(adj.edge_valence(e) == 2);
  CHECK(long(m.num_vertices()) - long(adj.num_edges()) + long(m.num_faces()) == 2);
}

TEST_CASE("three triangles on one edge: valence 3", "[repair][adjacency]") {
  const Mesh m = three_triangles_on_one_edge();
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges() == 7);  // (0,1) plus two edges to each of vertices 2, 3, 4
  CHECK(adj.edge_valence(edge_between(m, adj, 0, 1)) == 3);
  CHECK(adj.non_manifold_edges == 1);
  for (std::uint32_t a : adj.corner_across) CHECK(a == EdgeAdjacency::kNoEdge);  // nothing propagates
}

TEST_CASE("repeated indices and skipped faces contribute no half-edges", "[repair][adjacency]") {
  Mesh m;
  for (int i = 0; i < 3; ++i) m.add_vertex({double(i), 0, 0});
  m.add_face({0, 0, 1});
  m.add_face({0, 1, 2});
  EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges() == 3);                           // 0 -> 0 is no edge
  CHECK(adj.edge_valence(edge_between(m, adj, 0, 1)) == 3);  // (0,0,1) runs 0->1 and 1->0
  CHECK(adj.non_manifold_edges == 1);
  adj = edge_adjacency(m, {1, 0});
  CHECK(adj.edge_valence(edge_between(m, adj, 0, 1)) == 1);
  CHECK(adj.num_edges() == 3);
  for (int c = 0; c < 3; ++c) CHECK(adj.corner_across[c] == EdgeAdjacency::kNoEdge);
}

TEST_CASE("same output for 1 and 2 threads (parallel above 32768 faces)", "[repair][adjacency]") {
  const Mesh m = testing::torus(300, 150).mesh;  // 90000 faces
  const EdgeAdjacency serial = tbb::task_arena(1).execute([&] { return edge_adjacency(m); });
  const EdgeAdjacency two = tbb::task_arena(2).execute([&] { return edge_adjacency(m); });
  CHECK(serial.edge_start == two.edge_start);
  CHECK(serial.edge_corner == two.edge_corner);
  CHECK(serial.corner_across == two.corner_across);
  CHECK(serial.corner_face == two.corner_face);
}

TEST_CASE("a vertex index beyond the vertex count is refused", "[repair][adjacency]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.corner_vertex = {0, 1, 7};
  m.face_start = {0, 3};
  CHECK_THROWS(edge_adjacency(m));
}

TEST_CASE("edge numbering does not depend on the winding", "[repair][adjacency]") {
  const Mesh m = testing::torus(20, 10).mesh;
  Mesh flipped = m;
  flip_random_faces(flipped, 0.5, 3);
  const EdgeAdjacency a = edge_adjacency(m), b = edge_adjacency(flipped);
  for (std::size_t e = 0; e < a.num_edges(); ++e) CHECK(edge_ends(m, a, e) == edge_ends(flipped, b, e));
  CHECK(a.edge_start == b.edge_start);
}

TEST_CASE("a hub vertex of high degree (a fan of 1000 triangles)", "[repair][adjacency]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  const int n = 1000;
  for (int i = 0; i < n; ++i) m.add_vertex({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0});
  for (int i = 0; i < n; ++i) m.add_face({0u, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % n)});
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges() == std::size_t(2 * n));
  for (int i = 0; i < n; ++i) CHECK(adj.edge_valence(edge_between(m, adj, 0, 1 + i)) == 2);
}
