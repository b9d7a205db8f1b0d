// Tests of open_surface_vote: a shape that wraps a region is decided; a shape that does not is not.
#include <catch2/catch.hpp>

#include <shadetool/repair/open_surface_vote.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
OpenSurfaceVote vote(const Mesh& m) {
  const EdgeAdjacency adj = edge_adjacency(m);
  const ConsistentWinding w = consistent_winding(m, adj);
  const ComponentFaces g = faces_by_component(w);
  return open_surface_vote(m, w, g.faces);
}
}  // namespace

TEST_CASE("hemisphere facing out: decided, keep; facing in: decided, invert", "[repair][vote]") {
  Mesh m = hemisphere(48, 24);
  OpenSurfaceVote v = vote(m);
  CHECK(v.decided);
  CHECK(!v.invert);
  CHECK(v.samples == m.num_faces());
  // Every sample sees the rest of the hemisphere from behind: w > 0 everywhere, agreement 1.
  CHECK(v.vote == Approx(v.magnitude));
  invert_all(m);
  v = vote(m);
  CHECK(v.decided);
  CHECK(v.invert);
}

TEST_CASE("a shallow cap (30 degrees) is decided too: the vote is scale- and depth-free", "[repair][vote]") {
  Mesh cap = keep_faces(uv_sphere(96, 48).mesh, [](const Vec3d& c) { return c.z > std::cos(kPi / 6); });
  transform_positions(cap, 1e-3, {5, 5, 5});
  const OpenSurfaceVote v = vote(cap);
  CHECK(v.decided);
  CHECK(!v.invert);
}

TEST_CASE("a flat sheet and a symmetric terrain are undecided", "[repair][vote]") {
  Mesh flat = bumpy_terrain(20);
  for (std::size_t i = 2; i < flat.positions.size(); i += 3) flat.positions[i] = 0;
  OpenSurfaceVote v = vote(flat);
  CHECK(v.vote == 0.0);  // coplanar triangles subtend no solid angle
  CHECK(!v.decided);
  CHECK(!vote(bumpy_terrain(40)).decided);
}

TEST_CASE("a large component is sampled (2048 faces), not evaluated everywhere", "[repair][vote]") {
  const Mesh m = hemisphere(128, 64);
  REQUIRE(m.num_faces() > 4096);
  const OpenSurfaceVote v = vote(m);
  CHECK(v.samples == 2048);
  CHECK(v.decided);
  CHECK(!v.invert);
}
