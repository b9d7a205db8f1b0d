// Tests of info/edge_topology against counts known by hand or by Euler's formula.
#include <catch2/catch.hpp>

#include <shadetool/info/edge_topology.h>
#include "support/analytic_meshes.h"
#include "support/topology_meshes.h"

using namespace shadetool;
using namespace shadetool::info;

namespace {
Mesh grid(int n) {  // n x n quads on the unit square, wound counter-clockwise (+z)
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.add_vertex({double(i), double(j), 0});
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return m;
}
}  // namespace

TEST_CASE("edge topology: closed surfaces satisfy Euler's formula with no boundary", "[edge_topology]") {
  // icosphere with 2 subdivisions: F = 20 * 16 = 320, E = 3F/2 = 480, V = 2 - F + E = 162
  const Mesh ico = testing::icosphere(2).mesh;
  const EdgeTopology t = edge_topology(ico);
  CHECK(t.edges == 480);
  CHECK(ico.num_vertices() - t.edges + ico.num_faces() == 2);
  CHECK(t.boundary_edges == 0);
  CHECK(t.non_manifold_edges == 0);
  CHECK(t.non_manifold_vertices == 0);
  CHECK(t.inconsistent_edges == 0);
  // torus 12 x 8: V = 96, F = 192, E = 288, chi = 0
  const Mesh torus = testing::torus(12, 8).mesh;
  const EdgeTopology tt = edge_topology(torus);
  CHECK(tt.edges == 288);
  CHECK(torus.num_vertices() + torus.num_faces() == tt.edges);
}

TEST_CASE("edge topology: an n x n quad grid has 2n(n+1) edges, 4n on the boundary", "[edge_topology]") {
  const EdgeTopology t = edge_topology(grid(5));
  CHECK(t.edges == 60);
  CHECK(t.boundary_edges == 20);
  CHECK(t.non_manifold_vertices == 0);  // boundary vertices have one open fan: manifold
}

TEST_CASE("edge topology: a fin is one non-manifold edge, its two ends non-manifold vertices", "[edge_topology]") {
  Mesh m;
  for (auto p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0.5, 1, 0}, Vec3d{0.5, -1, 0}, Vec3d{0.5, 0, 1}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.add_face({1, 0, 3});
  m.add_face({0, 1, 4});
  const EdgeTopology t = edge_topology(m);
  CHECK(t.edges == 7);  // 0-1 plus two more per triangle
  CHECK(t.non_manifold_edges == 1);
  CHECK(t.boundary_edges == 6);
  CHECK(t.non_manifold_vertices == 2);
}

TEST_CASE("edge topology: a bow-tie is one non-manifold vertex and no non-manifold edge", "[edge_topology]") {
  const EdgeTopology t = edge_topology(testing::bow_tie());
  CHECK(t.non_manifold_vertices == 1);
  CHECK(t.non_manifold_edges == 0);
  CHECK(t.boundary_edges == 6);
}

TEST_CASE("edge topology: two faces running an edge the same way are inconsistent", "[edge_topology]") {
  Mesh m;
  for (auto p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, -1, 0}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.add_face({0, 1, 3});  // should be 1 0 3
  const EdgeTopology t = edge_topology(m);
  CHECK(t.inconsistent_edges == 1);
  CHECK(t.non_manifold_vertices == 0);  // the fan is still connected through edge 0-1
  m.corner_vertex[3] = 1;
  m.corner_vertex[4] = 0;
  CHECK(edge_topology(m).inconsistent_edges == 0);
}

TEST_CASE("edge topology: a repeated index makes no self-edge", "[edge_topology]") {
  Mesh m;
  for (auto p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}}) m.add_vertex(p);
  m.add_face({0, 1, 1});
  const EdgeTopology t = edge_topology(m);
  CHECK(t.edges == 1);  // 0-1, used by the sides 0->1 and 1->0 of the same face
}

TEST_CASE("edge topology: a Moebius strip of three quads has one inconsistent edge and a boundary of 6", "[edge_topology]") {
  // Counted by hand in support/topology_meshes.h: rung {t0, b0} is run the same way by Q0 and Q2.
  const EdgeTopology t = edge_topology(testing::moebius_three_quads());
  CHECK(t.edges == 9);
  CHECK(t.boundary_edges == 6);
  CHECK(t.non_manifold_edges == 0);
  CHECK(t.inconsistent_edges == 1);
  CHECK(t.non_manifold_vertices == 0);  // each vertex's two quads share its rung
}

TEST_CASE("edge topology: the cube of quads is closed and manifold; an isolated vertex changes nothing", "[edge_topology]") {
  Mesh m = testing::cube_quads();
  EdgeTopology t = edge_topology(m);
  CHECK(t.edges == 12);
  CHECK(t.boundary_edges == 0);
  CHECK(t.inconsistent_edges == 0);
  CHECK(t.non_manifold_vertices == 0);
  m.add_vertex({5, 5, 5});  // referenced by no face: on no edge, in no fan
  t = edge_topology(m);
  CHECK(t.edges == 12);
  CHECK(t.non_manifold_vertices == 0);
}
