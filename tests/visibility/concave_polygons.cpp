// The BVH holds a concave polygon of 5+ corners or a concave quad inside its outline
// (geometry/polygon_triangles.h; a quad through its reflex corner, not on its 0-2 diagonal),
// as render draws it and the glTF/STL writers write it: a point under the notch of an L hexagon
// sees the sky straight above it, which the fan from corner 0 covered.
// Truth the code did not produce: a crossing-number point-in-polygon test, computed here, of
// where the roof is over each point.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

#include <shadetool/visibility/shadow_visibility.h>
#include <shadetool/visibility/visibility_scene.h>
#include "geometry/polygon_outlines.h"

using namespace shadetool;
using namespace shadetool_test;

namespace {


// The outline as a roof, one face at z = 1; points on a grid at z = 0 (cell centres, never under
// an edge of the integer outlines below), normal +z, asking for a light straight above.
// Returns how many points see the light where the roof is over them or not where it is not.
std::size_t wrong_shadows(const Outline& p, bool reversed) {
  Mesh m;
  std::vector<std::uint32_t> face;
  for (const auto& q : p) {
    face.push_back(std::uint32_t(m.num_vertices()));
    m.add_vertex({q[0], q[1], 1});
  }
  if (reversed) face = std::vector<std::uint32_t>(face.rbegin(), face.rend());  // both sides block rays
  m.add_face(face);
  std::vector<double> points, normals;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 60; ++i) {
      points.insert(points.end(), {-0.5 + (i + 0.5) / 10, -0.5 + (j + 0.5) / 10, 0});
      normals.insert(normals.end(), {0, 0, 1});
    }
  const VisibilityScene scene(m);
  const std::vector<std::uint8_t> lit = shadow_visibility_directional(scene, points, normals, {0, 0, 1});
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < lit.size(); ++k) wrong += (lit[k] == 1) == crossing_inside(p, points[3 * k], points[3 * k + 1]);
  return wrong;
}

}  // namespace

TEST_CASE("occlusion: a concave polygon shadows exactly its outline (open under the notch of an L)", "[visibility][polygon_triangles]") {
  // The L of three unit squares with the notch (1,1)-(2,2), corner 0 at (2,1): the fan from it
  // covers part of the notch (and turns a triangle over across it).
  const Outline L = l_hexagon();
  for (bool reversed : {false, true}) {
    CHECK(wrong_shadows(L, reversed) == 0);
    // The point above the notch itself, asked alone.
    Mesh m;
    for (const auto& q : L) m.add_vertex({q[0], q[1], 1});
    m.add_face({0, 1, 2, 3, 4, 5});
    const VisibilityScene scene(m);
    CHECK(scene.stats().triangles == 4);
    CHECK(shadow_visibility_directional(scene, {1.25, 1.25, 0}, {0, 0, 1}, {0, 0, 1}) == std::vector<std::uint8_t>{1});
    CHECK(shadow_visibility_directional(scene, {1.2, 1.55, 0}, {0, 0, 1}, {0, 0, 1}) == std::vector<std::uint8_t>{1});
    CHECK(shadow_visibility_directional(scene, {0.5, 1.5, 0}, {0, 0, 1}, {0, 0, 1}) == std::vector<std::uint8_t>{0});
  }
  // A comb (base 0..5 x 0..1, teeth 1 high at x in [0,1], [2,3], [4,5]) halved to fit the grid,
  // corner 0 at a reflex corner.
  Outline teeth;
  for (const auto& q : comb()) teeth.push_back({q[0] / 2, q[1] / 2});
  CHECK(wrong_shadows(teeth, false) == 0);
}

TEST_CASE("occlusion: a concave quad (a dart) shadows exactly its outline, from each of its corners", "[visibility][polygon_triangles]") {
  // Dart (0,0) (4,2) (0,4) (1.5,2), reflex at (1.5,2); no grid point (x, y = 0.05 mod 0.1) lies on
  // an edge (slopes +-1/2, +-4/3). On its 0-2 diagonal with the reflex corner at 1 or 3, the
  // triangle (0,1,2) roofs the notch between (1.5,2) and the diagonal x = 0 or its turned-over
  // twin: points there are shadowed though outside the outline.
  const Outline dart{{0, 0}, {4, 2}, {0, 4}, {1.5, 2}};
  REQUIRE(shoelace_area(dart) == 5.0);
  for (std::size_t r = 0; r < 4; ++r) {
    Outline q;
    for (std::size_t k = 0; k < 4; ++k) q.push_back(dart[(r + k) % 4]);
    INFO("reflex corner at " << (3 + 4 - r) % 4);
    for (bool reversed : {false, true}) CHECK(wrong_shadows(q, reversed) == 0);
  }
}
