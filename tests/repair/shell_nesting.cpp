// Tests of shell_nesting_depth: nested, side-by-side, intersecting and duplicated shells.
#include <catch2/catch.hpp>

#include <algorithm>

#include <shadetool/repair/shell_nesting.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
// Depth of every component of m, all components taken as shells facing as wound.
std::vector<std::uint32_t> depths(const Mesh& m, std::vector<std::uint8_t> invert = {}) {
  const EdgeAdjacency adj = edge_adjacency(m);
  const ConsistentWinding w = consistent_winding(m, adj);
  std::vector<std::uint32_t> shells(w.num_components);
  for (std::uint32_t k = 0; k < shells.size(); ++k) shells[k] = k;
  if (invert.empty()) invert.assign(w.num_components, 0);
  return shell_nesting_depth(m, w, faces_by_component(w), shells, invert);
}
Mesh sphere_at(double r, const Vec3d& c) {
  Mesh m = icosphere(2).mesh;
  transform_positions(m, r, c);
  return m;
}
}  // namespace

TEST_CASE("three concentric spheres: depths 0, 1, 2", "[repair][nesting]") {
  Mesh m = sphere_at(1, {});
  append(m, sphere_at(0.6, {0.1, 0, 0}));
  append(m, sphere_at(0.3, {0.2, 0, 0}));
  CHECK(depths(m) == std::vector<std::uint32_t>{0, 1, 2});
}

TEST_CASE("the shells' winding is taken from shell_invert: an inverted outer shell still contains", "[repair][nesting]") {
  Mesh outer = sphere_at(1, {});
  invert_all(outer);
  Mesh m = outer;
  append(m, sphere_at(0.5, {}));
  CHECK(depths(m, {1, 0}) == std::vector<std::uint32_t>{0, 1});
}

TEST_CASE("side by side, intersecting, and duplicated shells are not nested", "[repair][nesting]") {
  Mesh side = sphere_at(1, {});
  append(side, sphere_at(1, {3, 0, 0}));
  CHECK(depths(side) == std::vector<std::uint32_t>{0, 0});
  Mesh cross = sphere_at(1, {});
  append(cross, sphere_at(0.5, {0.75, 0, 0}));  // inside the box, half out of the sphere
  CHECK(depths(cross) == std::vector<std::uint32_t>{0, 0});
  Mesh twice = sphere_at(1, {});
  append(twice, sphere_at(1, {}));
  CHECK(depths(twice) == std::vector<std::uint32_t>{0, 0});
}

TEST_CASE("many small shells: side by side depth 0, inside one container depth 1", "[repair][nesting]") {
  // 10 x 10 x 10 small spheres on a grid, then the same inside one large sphere.
  Mesh grid;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) append(grid, sphere_at(0.2, {double(i) - 4.5, double(j) - 4.5, double(k) - 4.5}));
  std::vector<std::uint32_t> d = depths(grid);
  CHECK(std::count(d.begin(), d.end(), 0u) == 1000);
  Mesh boxed = grid;
  append(boxed, sphere_at(20, {}));
  d = depths(boxed);
  CHECK(std::count(d.begin(), d.end(), 1u) == 1000);
  CHECK(d.back() == 0);
}
