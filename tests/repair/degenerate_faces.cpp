// Tests of degenerate_faces and remove_faces.
#include <catch2/catch.hpp>

#include <limits>

#include "repair_test_meshes.h"
#include <shadetool/repair/degenerate_faces.h>

using namespace shadetool;

TEST_CASE("each kind of degenerate face is named; a tiny but well-shaped face is not one", "[repair][degenerate]") {
  // Vertices and faces, each with its expected kind, in repair_test_meshes.h.
  Mesh m = testing::degenerate_triangles_mesh();
  testing::add_degenerate_polygons(m);
  const DegenerateFaces d = degenerate_faces(m);
  using K = DegenerateKind;
  CHECK(d.kind == std::vector<K>{K::None, K::RepeatedIndex, K::ZeroArea, K::None, K::NonFinite, K::ZeroArea, K::None,
                                 K::TooFewCorners, K::None, K::RepeatedIndex});
  CHECK(d.count() == 6);
  CHECK(d.zero_area == 2);
  CHECK(d.repeated_index == 2);
}

TEST_CASE("remove_faces keeps the other faces in order with all their attributes", "[repair][degenerate]") {
  Mesh m;
  for (int i = 0; i < 5; ++i) m.add_vertex({double(i), double(i * i), 0});
  m.add_face({0, 1, 2});
  m.add_face({1, 2, 3, 4});
  m.add_face({2, 3, 4});
  m.corner_normal_index = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  m.corner_texcoord_index = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
  m.face_normals = {1, 1, 1, 2, 2, 2, 3, 3, 3};
  m.face_colors = {0.1f, 0.1f, 0.1f, 0.2f, 0.2f, 0.2f, 0.3f, 0.3f, 0.3f};
  CHECK(remove_faces(m, {0, 1, 0}) == 1);
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 6});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 2, 3, 4});
  CHECK(m.corner_normal_index == std::vector<std::uint32_t>{0, 1, 2, 7, 8, 9});
  CHECK(m.corner_texcoord_index == std::vector<std::uint32_t>{10, 11, 12, 17, 18, 19});
  CHECK(m.face_normals == std::vector<double>{1, 1, 1, 3, 3, 3});
  CHECK(m.face_colors == std::vector<float>{0.1f, 0.1f, 0.1f, 0.3f, 0.3f, 0.3f});
  CHECK(m.num_vertices() == 5);
}
