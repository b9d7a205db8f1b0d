// Tests of info/connected_components.
#include <catch2/catch.hpp>

#include <shadetool/info/connected_components.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

TEST_CASE("components: pieces joined only through a vertex are one; isolated vertices are none", "[components]") {
  Mesh m = testing::icosphere(1).mesh;
  CHECK(info::connected_components(m) == 1);
  const std::uint32_t a = m.add_vertex({5, 0, 0}), b = m.add_vertex({6, 0, 0}), c = m.add_vertex({5, 1, 0});
  m.add_face({a, b, c});
  CHECK(info::connected_components(m) == 2);
  m.add_vertex({9, 9, 9});  // isolated
  CHECK(info::connected_components(m) == 2);
  const std::uint32_t d = m.add_vertex({7, 0, 0}), e = m.add_vertex({7, 1, 0});
  m.add_face({b, d, e});  // touches the triangle only at b: same component
  CHECK(info::connected_components(m) == 2);
  CHECK(info::connected_components(Mesh{}) == 0);
}
