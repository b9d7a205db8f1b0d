// Tests of topology/edge_adjacency: pairs and odd edges counted by hand on small meshes, by
// Euler's formula on closed ones, and against known flips on a re-wound torus.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <tbb/task_arena.h>

#include "repair/repair_test_meshes.h"
#include <shadetool/topology/edge_adjacency.h>

using namespace shadetool;
using namespace shadetool::testing;

namespace {
constexpr std::uint32_t kU = EdgeAdjacency::kUnpaired;

// The odd edges as (lo, hi, valence), in the order listed.
std::vector<std::array<std::uint32_t, 3>> odd_edges(const Mesh& m, const EdgeAdjacency& adj) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (std::size_t e = 0; e < adj.num_odd_edges(); ++e) {
    const auto [lo, hi] = half_edge_ends(m, adj.odd_edge_corner[adj.odd_edge_start[e]]);
    out.push_back({lo, hi, adj.odd_edge_valence(e)});
  }
  return out;
}
}  // namespace

TEST_CASE("two triangles of a square: four boundary edges and one shared diagonal", "[topology][adjacency]") {
  Mesh m;
  for (int i = 0; i < 4; ++i) m.add_vertex({double(i & 1), double(i >> 1), 0});
  m.add_face({0, 1, 3});
  m.add_face({0, 3, 2});
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 5);
  CHECK(adj.boundary_edges == 4);
  CHECK(adj.non_manifold_edges == 0);
  // Boundary edges listed by (low, high): (0,1) (0,2) (1,3) (2,3); each is corner... of one face.
  using E = std::array<std::uint32_t, 3>;
  CHECK(odd_edges(m, adj) == std::vector<E>{{0, 1, 1}, {0, 2, 1}, {1, 3, 1}, {2, 3, 1}});
  // (0,1) is corner 0, (0,2) corner 5 (2 -> 0), (1,3) corner 1, (2,3) corner 4 (3 -> 2).
  CHECK(adj.odd_edge_corner == std::vector<std::uint32_t>{0, 5, 1, 4});
  // The diagonal: face 0's corner 2 (3 -> 0) and face 1's corner 3 (0 -> 3), opposite ways (bit 0).
  CHECK(std::vector<std::uint32_t>(adj.corner_mate.begin(), adj.corner_mate.end()) ==
        std::vector<std::uint32_t>{kU, kU, (3u << 1) | 0u, (2u << 1) | 0u, kU, kU});
}

TEST_CASE("two faces running their shared edge the same way are paired with the same-direction bit", "[topology][adjacency]") {
  Mesh m;
  for (int i = 0; i < 4; ++i) m.add_vertex({double(i & 1), double(i >> 1), 0});
  m.add_face({0, 1, 3});  // corner 2: 3 -> 0
  m.add_face({0, 2, 3});  // corner 5: 3 -> 0 as well
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.corner_mate[2] == ((5u << 1) | 1u));
  CHECK(adj.corner_mate[5] == ((2u << 1) | 1u));
}

TEST_CASE("a closed triangle mesh: every edge is a pair, E = 3F/2, V - E + F = 2", "[topology][adjacency]") {
  const Mesh m = icosphere(3).mesh;
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges * 2 == 3 * m.num_faces());
  CHECK(adj.num_odd_edges() == 0);
  CHECK(long(m.num_vertices()) - long(adj.num_edges) + long(m.num_faces()) == 2);
  for (std::uint32_t c = 0; c < m.num_corners(); ++c) {
    REQUIRE(adj.corner_mate[c] != kU);
    CHECK(adj.corner_mate[adj.corner_mate[c] >> 1] >> 1 == c);  // mates are mutual
  }
}

TEST_CASE("on a torus with random flips the same-direction bit is exactly where one face of two was flipped", "[topology][adjacency]") {
  Mesh m = testing::torus(40, 20).mesh;
  const std::vector<std::size_t> list = flip_random_faces(m, 0.3, 7);
  std::vector<int> flipped(m.num_faces(), 0);
  for (std::size_t f : list) flipped[f] = 1;
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 3 * m.num_faces() / 2);
  for (std::uint32_t c = 0; c < m.num_corners(); ++c) {
    const std::uint32_t mate = adj.corner_mate[c];
    REQUIRE(mate != kU);
    CHECK(int(mate & 1u) == (flipped[c / 3] ^ flipped[(mate >> 1) / 3]));
  }
}

TEST_CASE("three triangles on one edge: valence 3, nothing paired there", "[topology][adjacency]") {
  const Mesh m = three_triangles_on_one_edge();
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 7);  // (0,1) plus two edges to each of vertices 2, 3, 4
  CHECK(adj.non_manifold_edges == 1);
  CHECK(adj.boundary_edges == 6);
  for (const auto& e : odd_edges(m, adj))
    CHECK(e[2] == ((e[0] == 0 && e[1] == 1) ? 3u : 1u));
  for (std::uint32_t a : adj.corner_mate) CHECK(a == kU);
}

TEST_CASE("repeated indices, unwound and skipped faces", "[topology][adjacency]") {
  Mesh m;
  for (int i = 0; i < 3; ++i) m.add_vertex({double(i), 0, 0});
  m.add_face({0, 0, 1});
  m.add_face({0, 1, 2});
  EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 3);  // 0 -> 0 is no edge
  CHECK(adj.non_manifold_edges == 1);  // (0,0,1) runs 0->1 and 1->0, face 1 runs 0->1
  CHECK(odd_edges(m, adj)[0] == std::array<std::uint32_t, 3>{0, 1, 3});
  EdgeAdjacencyOptions skip_first;
  skip_first.skip = {1, 0};
  EdgeAdjacencyOptions unwound;
  unwound.skip_unwound_faces = true;
  for (const EdgeAdjacencyOptions& o : {skip_first, unwound}) {
    adj = edge_adjacency(m, o);
    CHECK(adj.num_edges == 3);
    CHECK(adj.boundary_edges == 3);
    CHECK(odd_edges(m, adj)[0] == std::array<std::uint32_t, 3>{0, 1, 1});
    for (int c = 0; c < 3; ++c) CHECK(adj.corner_mate[c] == kU);
  }
  CHECK(face_is_unwound(m, 0));
  CHECK(!face_is_unwound(m, 1));
}

TEST_CASE("quads: a 2 x 1 strip has one interior edge and six boundary edges", "[topology][adjacency]") {
  Mesh m;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) m.add_vertex({double(i), double(j), 0});
  m.add_face({0, 1, 4, 3});
  m.add_face({1, 2, 5, 4});
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 7);
  CHECK(adj.boundary_edges == 6);
  // Interior edge (1,4): face 0's corner 1 (1 -> 4) and face 1's corner 7 (4 -> 1).
  CHECK(adj.corner_mate[1] == (7u << 1));
  CHECK(adj.corner_mate[7] == (1u << 1));
  CHECK(corner_face(m, 7) == 1);
  CHECK(corner_face(m, 3) == 0);
}

TEST_CASE("a vertex index beyond the vertex count is refused", "[topology][adjacency]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.corner_vertex = {0, 1, 7};
  m.face_start = {0, 3};
  CHECK_THROWS(edge_adjacency(m));
}

TEST_CASE("counts and odd edges do not depend on the winding", "[topology][adjacency]") {
  Mesh m = testing::torus(20, 10).mesh;
  m.face_start.resize(m.face_start.size() - 40);  // cut a strip off: a boundary to compare
  m.corner_vertex.resize(m.face_start.back());
  Mesh flipped = m;
  flip_random_faces(flipped, 0.5, 3);
  const EdgeAdjacency a = edge_adjacency(m), b = edge_adjacency(flipped);
  CHECK(a.boundary_edges == 40);
  CHECK(a.num_edges == b.num_edges);
  CHECK(odd_edges(m, a) == odd_edges(flipped, b));
}

TEST_CASE("a hub vertex of high degree (a fan of 1000 triangles)", "[topology][adjacency]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  const int n = 1000;
  for (int i = 0; i < n; ++i) m.add_vertex({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0});
  for (int i = 0; i < n; ++i) m.add_face({0u, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % n)});
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == std::size_t(2 * n));
  CHECK(adj.boundary_edges == std::size_t(n));  // the rim
  // Spoke (0, 1 + i): face i's corner 3i (0 -> 1+i) and face i-1's corner 3(i-1)+2 (1+i -> 0).
  for (int i = 0; i < n; ++i) CHECK(adj.corner_mate[3 * i] == std::uint32_t(3 * ((i + n - 1) % n) + 2) << 1);
}

TEST_CASE("same output for 1 and 2 threads (vertex blocks above 32768 faces)", "[topology][adjacency]") {
  Mesh m = testing::torus(300, 150).mesh;  // 90000 faces
  flip_random_faces(m, 0.3, 5);
  m.face_start.resize(m.face_start.size() - 600);  // one ring of quads off: two boundary loops of 300
  m.corner_vertex.resize(m.face_start.back());
  const EdgeAdjacency serial = tbb::task_arena(1).execute([&] { return edge_adjacency(m); });
  const EdgeAdjacency two = tbb::task_arena(2).execute([&] { return edge_adjacency(m); });
  CHECK(serial.boundary_edges == 600);
  CHECK(serial.corner_mate == two.corner_mate);
  CHECK(serial.odd_edge_start == two.odd_edge_start);
  CHECK(serial.odd_edge_corner == two.odd_edge_corner);
  CHECK(serial.num_edges == two.num_edges);
}

TEST_CASE("agrees with a map-based pairing on a random soup of triangles and polygons", "[topology][adjacency]") {
  // Faces of 1 to 6 corners (or triangles only: that path reads the higher vertex from the
  // corner) on 3000 vertices (the same vertex may repeat): boundary, manifold and non-manifold
  // edges in every bucket size, same-direction pairs, edges a face uses twice. 40000 faces, so
  // the counting and matching run in parts and blocks on 2 threads.
  const bool triangles_only = GENERATE(true, false);
  std::mt19937 rng(11);
  Mesh m;
  for (int v = 0; v < 3000; ++v) m.add_vertex({double(v), 0, 0});
  for (int f = 0; f < 40000; ++f) {
    const int n = triangles_only ? 3 : 1 + int(rng() % 6);
    const std::uint32_t base = rng() % 2990;
    std::vector<std::uint32_t> face;
    for (int i = 0; i < n; ++i) face.push_back(base + rng() % 10);  // local: valence 1 to many
    m.add_face(face);
  }
  // Reference: every half-edge (t != h) under its (lo, hi) key, in corner order.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
      const std::uint32_t t = m.corner_vertex[c], h = m.corner_vertex[next_corner(m, std::uint32_t(f), c)];
      if (t != h) edges[{std::min(t, h), std::max(t, h)}].push_back(c);
    }
  std::vector<std::uint32_t> mate(m.num_corners(), kU), odd_start{0}, odd_corner;
  std::size_t boundary = 0, non_manifold = 0;
  for (const auto& [key, corners] : edges) {
    if (corners.size() == 2) {
      const std::uint32_t x = corners[0], y = corners[1];
      const bool same = m.corner_vertex[x] == m.corner_vertex[y];  // both leave the same vertex
      mate[x] = (y << 1) | std::uint32_t(same);
      mate[y] = (x << 1) | std::uint32_t(same);
    } else {
      odd_corner.insert(odd_corner.end(), corners.begin(), corners.end());
      odd_start.push_back(std::uint32_t(odd_corner.size()));
      (corners.size() == 1 ? boundary : non_manifold) += 1;
    }
  }
  for (int threads : {1, 2}) {
    const EdgeAdjacency adj = tbb::task_arena(threads).execute([&] { return edge_adjacency(m); });
    CHECK(std::vector<std::uint32_t>(adj.corner_mate.begin(), adj.corner_mate.end()) == mate);
    CHECK(adj.odd_edge_start == odd_start);
    CHECK(adj.odd_edge_corner == odd_corner);
    CHECK(adj.boundary_edges == boundary);
    CHECK(adj.non_manifold_edges == non_manifold);
    CHECK(adj.num_edges == edges.size());
  }
  CHECK(boundary > 1000);  // the soup really has every kind
  CHECK(non_manifold > 1000);
  CHECK(std::count_if(mate.begin(), mate.end(), [](std::uint32_t x) { return x != kU; }) > 1000);
}
