// Tests of component_signed_volumes: exact values on a unit cube, far from the origin too.
#include <catch2/catch.hpp>

#include <limits>

#include <shadetool/repair/signed_volume.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {
Mesh unit_cube(const Vec3d& at) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex(at + Vec3d{double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& s : q) m.add_face({s[0], s[1], s[2], s[3]});  // quads: fan-triangulated inside
  return m;
}
ComponentVolumes volumes(const Mesh& m) {
  const EdgeAdjacency adj = edge_adjacency(m);
  return component_signed_volumes(m, consistent_winding(m, adj));
}
}  // namespace

TEST_CASE("a unit cube has volume exactly 1, also at 1e8 from the origin", "[repair][volume]") {
  for (double offset : {0.0, 1e8}) {
    const Mesh m = unit_cube({offset, -offset, offset});
    const ComponentVolumes v = volumes(m);
    // Integer corners and a centroid at .5: every difference and product is exact in double.
    CHECK(v.volume[0] == 1.0);
    CHECK(v.magnitude[0] == 1.0);  // the centroid is inside: all tetrahedra positive
    CHECK(v.centroid[0].x == offset + 0.5);
    CHECK(volume_has_sign(v.volume[0], v.magnitude[0]));
  }
}

TEST_CASE("the volume follows the consistent winding of the seed face", "[repair][volume]") {
  Mesh m = icosphere(3).mesh;
  const long double truth = volume_from_origin(m);
  invert_all(m);
  flip_random_faces(m, 0.3, 2);
  const EdgeAdjacency adj = edge_adjacency(m);
  const ConsistentWinding w = consistent_winding(m, adj);
  const ComponentVolumes v = component_signed_volumes(m, w);
  // The seed (face 0) was inverted, unless the random flips restored it.
  const double seed_sign = m.corner_vertex[1] == icosphere(3).mesh.corner_vertex[1] ? 1.0 : -1.0;
  CHECK(v.volume[0] == Approx(double(truth) * seed_sign).epsilon(1e-12));
}

TEST_CASE("a two-sided sheet (two faces on the same three vertices) encloses nothing", "[repair][volume]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 1});
  const ComponentVolumes v = volumes(m);
  CHECK(v.volume[0] == 0.0);
  CHECK(!volume_has_sign(v.volume[0], v.magnitude[0]));
}

TEST_CASE("the volume pass classifies degenerate faces exactly as degenerate_faces does", "[repair][volume][degenerate]") {
  // The mesh of the degenerate_faces test (repair_test_meshes.h), triangles only (the pass's
  // fast path), then with polygons and a face of two corners (the general path).
  Mesh m = testing::degenerate_triangles_mesh();
  using K = DegenerateKind;
  EdgeAdjacencyOptions left_out;
  left_out.skip_unwound_faces = true;
  auto classify = [&](const Mesh& mesh) {
    DegenerateFaces d;
    component_signed_volumes(mesh, consistent_winding(mesh, edge_adjacency(mesh, left_out), left_out), &d);
    return d;
  };
  DegenerateFaces d = classify(m);
  CHECK(d.kind == std::vector<K>{K::None, K::RepeatedIndex, K::ZeroArea, K::None, K::NonFinite, K::ZeroArea, K::None});
  CHECK(d.zero_area == 2);
  CHECK(d.repeated_index == 1);
  CHECK(d.non_finite == 1);
  testing::add_degenerate_polygons(m);
  d = classify(m);
  CHECK(d.kind == std::vector<K>{K::None, K::RepeatedIndex, K::ZeroArea, K::None, K::NonFinite, K::ZeroArea, K::None,
                                 K::TooFewCorners, K::None, K::RepeatedIndex});
  CHECK(d.count() == 6);
  CHECK(d.too_few_corners == 1);
}

TEST_CASE("volumes are spanned from the seed face's first vertex; the centroid is the corners' mean", "[repair][volume]") {
  // A tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1), wound outward: volume 1/6 from any apex.
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({0, 0, 1});
  m.add_face({1, 2, 3});  // the seed: r = vertex 1
  m.add_face({0, 2, 1});
  m.add_face({0, 1, 3});
  m.add_face({0, 3, 2});
  const ComponentVolumes v = volumes(m);
  CHECK(v.reference[0] == Vec3d{1, 0, 0});
  CHECK(v.volume[0] == Approx(1.0 / 6.0).epsilon(1e-15));
  // From vertex 1 only the face without it spans a tetrahedron, the whole one: |det| = 1.
  CHECK(v.magnitude[0] == Approx(1.0 / 6.0).epsilon(1e-15));
  // 12 corners: vertex 0 three times, 1, 2, 3 three times each: mean (3, 3, 3) / 12.
  CHECK(v.centroid[0].x == 0.25);
  CHECK(v.centroid[0].z == 0.25);
}
