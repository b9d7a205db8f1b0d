// Tests of transform/reverse_winding: cyclic order reversed, first corner kept, and per-corner
// normal and texcoord indices following their corners.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/transform/reverse_winding.h>

using namespace shadetool;

TEST_CASE("reverse_winding: (v0 v1 ... vk) becomes (v0 vk ... v1), attributes follow", "[reverse_winding]") {
  Mesh m;
  for (int i = 0; i < 6; ++i) m.add_vertex({double(i), double(i * i), 0});
  m.add_face({0, 1, 2});
  m.add_face({2, 3, 4, 5});
  // Corner attributes chosen so that corner c carries normal 10 + c and texcoord 20 + c.
  for (std::uint32_t c = 0; c < 7; ++c) {
    m.corner_normal_index.push_back(10 + c);
    m.corner_texcoord_index.push_back(20 + c);
  }
  reverse_winding(m);
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 2, 1, 2, 5, 4, 3});
  // Corner that held vertex 2 in face 0 was corner 2: its normal 12 and texcoord 22 go with it.
  CHECK(m.corner_normal_index == std::vector<std::uint32_t>{10, 12, 11, 13, 16, 15, 14});
  CHECK(m.corner_texcoord_index == std::vector<std::uint32_t>{20, 22, 21, 23, 26, 25, 24});
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 7});
  // Twice is the identity.
  reverse_winding(m);
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 2, 3, 4, 5});
  CHECK(m.corner_normal_index == std::vector<std::uint32_t>{10, 11, 12, 13, 14, 15, 16});
}

TEST_CASE("reverse_winding: meshes without corner attributes, and inconsistent ones", "[reverse_winding]") {
  Mesh m;
  for (int i = 0; i < 3; ++i) m.add_vertex({double(i), 1, 0});
  m.add_face({0, 1, 2});
  reverse_winding(m);
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 2, 1});
  CHECK(m.corner_normal_index.empty());
  m.corner_normal_index = {0, 1};  // 2 entries for 3 corners
  CHECK_THROWS_AS(reverse_winding(m), Error);
}
