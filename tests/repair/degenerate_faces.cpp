// Tests of degenerate_faces and remove_faces.
#include <catch2/catch.hpp>

#include <limits>

#include "repair/degenerate_faces.h"

using namespace shadetool;

TEST_CASE("each kind of degenerate face is named; a tiny but well-shaped face is not one", "[repair][degenerate]") {
  Mesh m;
  m.add_vertex({0, 0, 0});                  // 0
  m.add_vertex({1, 0, 0});                  // 1
  m.add_vertex({0, 1, 0});                  // 2
  m.add_vertex({2, 0, 0});                  // 3: collinear with 0 and 1
  m.add_vertex({1e-20, 0, 0});              // 4
  m.add_vertex({0, 1e-20, 0});              // 5
  m.add_vertex({std::numeric_limits<double>::quiet_NaN(), 0, 0});  // 6
  m.add_vertex({1, 1e-15, 0});              // 7: 1e-15 off the line: sin(angle) ~ 5e-16, below 1.4e-14
  m.add_vertex({1, 1e-9, 0});               // 8: clearly off the line
  m.add_face({0, 1, 2});     // fine
  m.add_face({0, 1});        // too few corners
  m.add_face({0, 1, 1});     // repeated index
  m.add_face({0, 1, 3});     // collinear: zero area
  m.add_face({0, 4, 5});     // 1e-20 wide, right-angled: fine
  m.add_face({0, 1, 6});     // NaN corner
  m.add_face({0, 3, 7});     // numerically collinear
  m.add_face({0, 3, 8});     // thin but real
  m.add_face({0, 1, 8, 2});  // a quad: fine
  m.add_face({0, 1, 3, 1});  // quad with a repeated index
  const DegenerateFaces d = degenerate_faces(m);
  using K = DegenerateKind;
  CHECK(d.kind == std::vector<K>{K::None, K::TooFewCorners, K::RepeatedIndex, K::ZeroArea, K::None, K::NonFinite,
                                 K::ZeroArea, K::None, K::None, K::RepeatedIndex});
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
