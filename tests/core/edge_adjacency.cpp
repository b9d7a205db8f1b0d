// Tests of core/edge_adjacency: pairs and odd edges counted by hand on small meshes (a cube, a
// Moebius strip, non-manifold fans, repeated indices, an isolated vertex), by Euler's formula on
// closed ones, against known flips on a re-wound torus, and against a map-based pairing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <tbb/task_arena.h>

#include "repair/repair_test_meshes.h"
#include "support/topology_meshes.h"
#include <shadetool/core/edge_adjacency.h>

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

TEST_CASE("two triangles of a square: four boundary edges and one shared diagonal", "[core][adjacency]") {
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

TEST_CASE("two faces running their shared edge the same way are paired with the same-direction bit", "[core][adjacency]") {
  Mesh m;
  for (int i = 0; i < 4; ++i) m.add_vertex({double(i & 1), double(i >> 1), 0});
  m.add_face({0, 1, 3});  // corner 2: 3 -> 0
  m.add_face({0, 2, 3});  // corner 5: 3 -> 0 as well
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.corner_mate[2] == ((5u << 1) | 1u));
  CHECK(adj.corner_mate[5] == ((2u << 1) | 1u));
}

TEST_CASE("a closed triangle mesh: every edge is a pair, E = 3F/2, V - E + F = 2", "[core][adjacency]") {
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

TEST_CASE("on a torus with random flips the same-direction bit is exactly where one face of two was flipped", "[core][adjacency]") {
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

TEST_CASE("three triangles on one edge: valence 3, nothing paired there", "[core][adjacency]") {
  const Mesh m = three_triangles_on_one_edge();
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 7);  // (0,1) plus two edges to each of vertices 2, 3, 4
  CHECK(adj.non_manifold_edges == 1);
  CHECK(adj.boundary_edges == 6);
  for (const auto& e : odd_edges(m, adj))
    CHECK(e[2] == ((e[0] == 0 && e[1] == 1) ? 3u : 1u));
  for (std::uint32_t a : adj.corner_mate) CHECK(a == kU);
}

TEST_CASE("repeated indices, unwound and skipped faces", "[core][adjacency]") {
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

TEST_CASE("quads: a 2 x 1 strip has one interior edge and six boundary edges", "[core][adjacency]") {
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

TEST_CASE("a vertex index beyond the vertex count is refused", "[core][adjacency]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.corner_vertex = {0, 1, 7};
  m.face_start = {0, 3};
  CHECK_THROWS(edge_adjacency(m));
}

TEST_CASE("counts and odd edges do not depend on the winding", "[core][adjacency]") {
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

TEST_CASE("a hub vertex of high degree (a fan of 1000 triangles)", "[core][adjacency]") {
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

TEST_CASE("same output for 1 and 2 threads (vertex blocks above 32768 faces)", "[core][adjacency]") {
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

TEST_CASE("agrees with a map-based pairing on a random soup of triangles and polygons", "[core][adjacency]") {
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

// ---- Hand-counted truth: the cube, a Moebius strip, non-manifold fans, repeated indices, an
// isolated vertex. Every count below is read off a figure (in the comment, or beside the mesh in
// support/topology_meshes.h), not from the code.

namespace {
using Odd = std::array<std::uint32_t, 3>;
using Counts = std::array<std::size_t, 3>;  // edges, boundary edges, non-manifold edges

Counts counts(const EdgeAdjacency& adj) { return {adj.num_edges, adj.boundary_edges, adj.non_manifold_edges}; }

}  // namespace

TEST_CASE("cube of six quads: 12 edges, every side paired, all pairs opposite, V - E + F = 2", "[core][adjacency][truth]") {
  const Mesh m = cube_quads();
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(counts(adj) == Counts{12, 0, 0});
  CHECK(adj.num_odd_edges() == 0);
  for (std::uint32_t c = 0; c < 24; ++c) {
    REQUIRE(adj.corner_mate[c] != kU);
    CHECK((adj.corner_mate[c] & 1u) == 0u);                   // wound outward: opposite ways
    CHECK(corner_face(m, adj.corner_mate[c] >> 1) != corner_face(m, c));
  }
  // Edge {0, 1}: the bottom's side 1 -> 0 (corner 3) and the front's 0 -> 1 (corner 8).
  CHECK(adj.corner_mate[3] == (8u << 1));
  CHECK(adj.corner_mate[8] == (3u << 1));
  // Edge {0, 2}: the bottom's 0 -> 2 (corner 0) and the left side's 2 -> 0 (corner 19).
  CHECK(adj.corner_mate[0] == (19u << 1));
  // Turning one face inside out makes its four edges same-direction pairs, nothing else.
  Mesh flipped = m;
  std::reverse(flipped.corner_vertex.begin() + 4, flipped.corner_vertex.begin() + 8);  // (6, 7, 5, 4)
  const EdgeAdjacency f = edge_adjacency(flipped);
  CHECK(f.num_edges == 12);
  int same = 0;
  for (std::uint32_t c = 0; c < 24; ++c) same += int(f.corner_mate[c] & 1u);
  CHECK(same == 8);  // 4 edges, counted from both sides
}

TEST_CASE("cube of twelve triangles: 18 edges (12 sides and 6 diagonals), V - E + F = 2", "[core][adjacency][truth]") {
  const Mesh q = cube_quads();
  Mesh m;
  m.positions = q.positions;
  for (std::size_t f = 0; f < 6; ++f) {
    const std::uint32_t* v = q.corner_vertex.data() + 4 * f;
    m.add_face({v[0], v[1], v[2]});
    m.add_face({v[0], v[2], v[3]});
  }
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 18);
  CHECK(adj.num_odd_edges() == 0);
  CHECK(long(m.num_vertices()) - long(adj.num_edges) + long(m.num_faces()) == 2);
  // The bottom's diagonal {0, 3}: triangle 0 = (0, 2, 3) runs 3 -> 0 at corner 2, triangle 1 =
  // (0, 3, 1) runs 0 -> 3 at corner 3.
  CHECK(adj.corner_mate[2] == (3u << 1));
}

TEST_CASE("Moebius strip of three quads: 9 edges, 6 on the boundary, one same-direction rung", "[core][adjacency][truth]") {
  const Mesh m = moebius_three_quads();
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(counts(adj) == Counts{9, 6, 0});
  CHECK(long(m.num_vertices()) - long(adj.num_edges) + long(m.num_faces()) == 0);
  // The boundary in (lo, hi) order: t0-t1 (0,2), b2-t0 (0,5), b0-b1 (1,3), t2-b0 (1,4), t1-t2 (2,4), b1-b2 (3,5).
  CHECK(odd_edges(m, adj) == std::vector<Odd>{{0, 2, 1}, {0, 5, 1}, {1, 3, 1}, {1, 4, 1}, {2, 4, 1}, {3, 5, 1}});
  // Rung {t0, b0} = {0, 1}: corner 0 (Q0, 0 -> 1) and corner 10 (Q2, 0 -> 1), the same way.
  CHECK(adj.corner_mate[0] == ((10u << 1) | 1u));
  CHECK(adj.corner_mate[10] == ((0u << 1) | 1u));
  // Rung {2, 3}: corner 4 (Q1, 2 -> 3) and corner 2 (Q0, 3 -> 2); rung {4, 5}: corners 8 and 6.
  CHECK(adj.corner_mate[4] == (2u << 1));
  CHECK(adj.corner_mate[8] == (6u << 1));
  int same = 0;
  for (std::uint32_t c = 0; c < m.num_corners(); ++c)
    if (adj.corner_mate[c] != kU) same += int(adj.corner_mate[c] & 1u);
  CHECK(same == 2);  // one edge, seen from both sides
}

TEST_CASE("Moebius strip of 2n triangles: 4n edges, 2n on the boundary, an odd number of same-direction edges", "[core][adjacency][truth]") {
  for (int n : {3, 8, 33}) {
    const Mesh m = mobius_strip(n);  // n rungs, n diagonals inside; 2n rail edges on the boundary
    const EdgeAdjacency adj = edge_adjacency(m);
    CHECK(counts(adj) == Counts{std::size_t(4 * n), std::size_t(2 * n), 0});
    std::size_t same = 0;
    for (std::uint32_t c = 0; c < m.num_corners(); ++c)
      if (adj.corner_mate[c] != kU && (adj.corner_mate[c] >> 1) > c) same += adj.corner_mate[c] & 1u;
    CHECK(same % 2 == 1);  // the faces form one ring through 2n interior edges: its parity is odd
  }
}

TEST_CASE("non-manifold fans: four faces on one edge are one edge of valence 4, not two pairs", "[core][adjacency][truth]") {
  // A book of four pages on the spine {0, 1}: triangles (0, 1, a) for a = 2..5.
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  for (int a = 0; a < 4; ++a) m.add_vertex({0.5, std::cos(a * 1.5), std::sin(a * 1.5)});
  for (std::uint32_t a = 2; a < 6; ++a) m.add_face({0, 1, a});
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(counts(adj) == Counts{9, 8, 1});  // the spine (valence 4) and two boundary edges per page
  const std::vector<Odd> odd = odd_edges(m, adj);
  REQUIRE(odd.size() == 9);
  CHECK(odd[0] == Odd{0, 1, 4});
  // The spine's four sides, one per page, in corner order.
  CHECK(std::vector<std::uint32_t>(adj.odd_edge_corner.begin(), adj.odd_edge_corner.begin() + 4) ==
        std::vector<std::uint32_t>{0, 3, 6, 9});
  for (std::uint32_t a : adj.corner_mate) CHECK(a == kU);

  // A bow-tie: two fans meeting only at vertex 0. Six boundary edges; the vertex is no matter of
  // edges (info/edge_topology counts it as a non-manifold vertex).
  const EdgeAdjacency b = edge_adjacency(bow_tie());
  CHECK(counts(b) == Counts{6, 6, 0});
}

TEST_CASE("repeated indices: a self side is no edge; one face may pair with itself; repair's rule leaves it out", "[core][adjacency][truth]") {
  // Face (0, 1, 2, 1) goes out to 2 and back: sides 0 -> 1, 1 -> 2, 2 -> 1, 1 -> 0.
  Mesh m;
  for (int i = 0; i < 3; ++i) m.add_vertex({double(i), 0, 0});
  m.add_face({0, 1, 2, 1});
  EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 2);  // {0, 1} and {1, 2}, each run both ways by the one face
  CHECK(adj.num_odd_edges() == 0);
  CHECK(adj.corner_mate[0] == (3u << 1));
  CHECK(adj.corner_mate[1] == (2u << 1));
  CHECK(face_is_unwound(m, 0));
  EdgeAdjacencyOptions unwound;
  unwound.skip_unwound_faces = true;
  adj = edge_adjacency(m, unwound);
  CHECK(adj.num_edges == 0);
  for (std::uint32_t a : adj.corner_mate) CHECK(a == kU);

  // Face (3, 3, 3): every side is a self side. Face (3, 4): two corners, the sides 3 -> 4, 4 -> 3.
  Mesh d;
  for (int i = 0; i < 5; ++i) d.add_vertex({double(i), 0, 0});
  d.add_face({3, 3, 3});
  d.add_face({3, 4});
  adj = edge_adjacency(d);
  CHECK(adj.num_edges == 1);
  CHECK(adj.corner_mate[0] == kU);
  CHECK(adj.corner_mate[3] == (4u << 1));
  CHECK(face_is_unwound(d, 0));
  CHECK(face_is_unwound(d, 1));
  CHECK(edge_adjacency(d, unwound).num_edges == 0);
}

TEST_CASE("an isolated vertex is on no edge; a mesh without faces has none", "[core][adjacency][truth]") {
  Mesh m;
  for (int i = 0; i < 4; ++i) m.add_vertex({double(i & 1), double(i >> 1), 0});
  m.add_face({0, 2, 3});  // vertex 1 is referenced by no face
  const EdgeAdjacency adj = edge_adjacency(m);
  CHECK(adj.num_edges == 3);
  CHECK(adj.boundary_edges == 3);
  CHECK(odd_edges(m, adj) == std::vector<Odd>{{0, 2, 1}, {0, 3, 1}, {2, 3, 1}});

  Mesh points;
  for (int i = 0; i < 3; ++i) points.add_vertex({double(i), 0, 0});
  const EdgeAdjacency none = edge_adjacency(points);
  CHECK(none.num_edges == 0);
  CHECK(none.corner_mate.empty());
  CHECK(none.odd_edge_start == std::vector<std::uint32_t>{0});
}
