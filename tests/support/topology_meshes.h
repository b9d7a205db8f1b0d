// topology_meshes.h: small meshes whose edges are counted by hand in their comments, for the tests
// of core/edge_adjacency and info/edge_topology (truth that the code did not produce).
#pragma once

#include <cmath>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/mesh.h>

namespace shadetool::testing {

// The unit cube: vertex i at (i & 1, (i >> 1) & 1, (i >> 2) & 1); six quads wound outward.
inline Mesh cube_quads() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.add_face({0, 2, 3, 1});  // z = 0   corners 0..3
  m.add_face({4, 5, 7, 6});  // z = 1   corners 4..7
  m.add_face({0, 1, 5, 4});  // y = 0   corners 8..11
  m.add_face({2, 6, 7, 3});  // y = 1   corners 12..15
  m.add_face({0, 4, 6, 2});  // x = 0   corners 16..19
  m.add_face({1, 3, 7, 5});  // x = 1   corners 20..23
  return m;
}

// Three quads closed into a ring with half a twist: top vertices t_i = 2i, bottom b_i = 2i + 1.
//   Q0 = (t0, b0, b1, t1)   Q1 = (t1, b1, b2, t2)   Q2 = (t2, b2, t0, b0)   <- the twist: t0, b0 swap
// Rungs {t_i, b_i} are interior (3); rails t0-t1, t1-t2, b0-b1, b1-b2 and the crossed t2-b0,
// b2-t0 are the boundary (6): one loop t0 t1 t2 b0 b1 b2. V - E + F = 6 - 9 + 3 = 0.
// Rung {t0, b0} is run t0 -> b0 by both Q0 and Q2: the one same-direction pair; the rungs
// {t1, b1} and {t2, b2} are run opposite ways. An odd number around the ring: no winding is
// consistent (that is what non-orientable means here).
inline Mesh moebius_three_quads() {
  Mesh m;
  for (int i = 0; i < 3; ++i) {
    const double u = 2 * kPi * i / 3;
    m.add_vertex({std::cos(u), std::sin(u), 0.3});
    m.add_vertex({std::cos(u), std::sin(u), -0.3});
  }
  m.add_face({0, 1, 3, 2});  // corners 0..3:  0->1, 1->3, 3->2, 2->0
  m.add_face({2, 3, 5, 4});  // corners 4..7:  2->3, 3->5, 5->4, 4->2
  m.add_face({4, 5, 0, 1});  // corners 8..11: 4->5, 5->0, 0->1, 1->4
  return m;
}

// A bow-tie: two triangles (0, 2, 1) and (0, 3, 4) that meet only at vertex 0. Six boundary edges,
// no shared edge; vertex 0's faces form two fans (a non-manifold vertex).
inline Mesh bow_tie() {
  Mesh m;
  for (auto p : {Vec3d{0, 0, 0}, Vec3d{1, 1, 0}, Vec3d{1, -1, 0}, Vec3d{-1, 1, 0}, Vec3d{-1, -1, 0}}) m.add_vertex(p);
  m.add_face({0, 2, 1});
  m.add_face({0, 3, 4});
  return m;
}

}  // namespace shadetool::testing
