// Tests of reverse_faces: the first corner stays, the rest reverse, attributes travel with corners.
#include <catch2/catch.hpp>

#include <shadetool/repair/reverse_faces.h>

using namespace shadetool;

TEST_CASE("a triangle becomes (a, c, b), a quad (a, d, c, b); twice is the identity", "[repair][reverse]") {
  Mesh m;
  for (int i = 0; i < 7; ++i) m.add_vertex({double(i), 0, 0});
  m.add_face({0, 1, 2});
  m.add_face({3, 4, 5, 6});
  m.add_face({6, 5, 4});
  m.corner_normal_index = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
  m.corner_texcoord_index = {20, 21, 22, 23, 24, 25, 26, 27, 28, 29};
  const Mesh before = m;
  CHECK(reverse_faces(m, {1, 1, 0}) == 2);
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 2, 1, 3, 6, 5, 4, 6, 5, 4});
  CHECK(m.corner_normal_index == std::vector<std::uint32_t>{10, 12, 11, 13, 16, 15, 14, 17, 18, 19});
  CHECK(m.corner_texcoord_index == std::vector<std::uint32_t>{20, 22, 21, 23, 26, 25, 24, 27, 28, 29});
  CHECK(m.face_start == before.face_start);
  reverse_faces(m, {1, 1, 0});
  CHECK(m.corner_vertex == before.corner_vertex);
  CHECK(m.corner_normal_index == before.corner_normal_index);
}

TEST_CASE("a flag array of the wrong size is refused", "[repair][reverse]") {
  Mesh m;
  m.corner_vertex = {0, 1, 2};  // (add_face on a fresh mesh trips GCC 12's bogus -Wstringop-overflow)
  m.face_start = {0, 3};
  CHECK_THROWS(reverse_faces(m, {1, 1}));
}
