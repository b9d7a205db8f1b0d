// Tests of io/split_corner_normals: a cube with one normal per side (the flat-shaded cube) needs
// 3 vertices per corner of the cube: 8 become 24.
#include <shadetool/io/split_corner_normals.h>
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

TEST_CASE("split: flat-shaded cube becomes 24 vertices, each with its side's normal", "[split]") {
  Mesh m = read_mesh(data_path("cube.obj"));
  REQUIRE(m.num_vertices() == 8);
  // one normal per side: the two triangles of a side share it
  const double N[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (auto& n : N) m.corner_normals.insert(m.corner_normals.end(), n, n + 3);
  for (std::size_t f = 0; f < 12; ++f)
    for (int k = 0; k < 3; ++k) m.corner_normal_index.push_back(std::uint32_t(f / 2));
  std::size_t added = 0;
  const Mesh s = io::split_corner_normals(m, added);
  CHECK(added == 16);
  CHECK(s.num_vertices() == 24);
  CHECK(!s.has_corner_normals());
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    CHECK(s.position(s.corner_vertex[c]) == m.position(m.corner_vertex[c]));
    CHECK(get3(s.vertex_normals, s.corner_vertex[c]) == get3(m.corner_normals, m.corner_normal_index[c]));
  }
  // each original vertex keeps its index for its first normal
  for (std::size_t c = 0; c < m.num_corners(); ++c)
    if (s.corner_vertex[c] < 8) CHECK(s.corner_vertex[c] == m.corner_vertex[c]);
}

TEST_CASE("split: smooth normals (one per vertex) add nothing; unreferenced vertices are kept", "[split]") {
  Mesh m;
  for (int i = 0; i < 4; ++i) m.add_vertex({double(i), double(i * i), 0});
  m.add_face({0, 1, 2});
  m.corner_normals = {0, 0, 1, 0, 0, -1, 1, 0, 0};
  m.corner_normal_index = {0, 1, 2};
  std::size_t added = 7;
  const Mesh s = io::split_corner_normals(m, added);
  CHECK(added == 0);
  CHECK(s.num_vertices() == 4);
  // Vertex 3 is used by no face: the documented fallback (0, 0, 1), never (0, 0, 0) (issue 27 item 4).
  CHECK(s.vertex_normals == std::vector<double>{0, 0, 1, 0, 0, -1, 1, 0, 0, 0, 0, 1});
}

TEST_CASE("split: an unreferenced vertex keeps a valid vertex normal it had; an invalid one gets the fallback "
          "(issue 27 item 4: no written normal is zero)", "[split]") {
  Mesh m;
  for (int i = 0; i < 5; ++i) m.add_vertex({double(i), double(i * i), 0});
  m.add_face({0, 1, 2});
  m.vertex_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0.6, 0.8, 0, 0, 0, 0};  // 3: valid, 4: zero
  m.corner_normals = {0, 0, 1, 0, 0, -1, 1, 0, 0};
  m.corner_normal_index = {0, 1, 2};
  std::size_t added = 0;
  const Mesh s = io::split_corner_normals(m, added);
  CHECK(added == 0);
  CHECK(get3(s.vertex_normals, 3) == Vec3d{0.6, 0.8, 0});
  CHECK(get3(s.vertex_normals, 4) == Vec3d{0, 0, 1});
}

TEST_CASE("split: a vertex with 50000 distinct normals gets one copy per normal; a normal index shared by other vertices stays theirs",
          "[split]") {
  // A fan of k triangles (0, r, r+1) around vertex 0 (rim vertices 1..k, closed ring). At the
  // centre, triangles 2i and 2i+1 use normal i: k/2 distinct normals, so the centre keeps normal 0
  // and gets k/2 - 1 copies. Every rim corner uses normal 0 too, which is the only normal of each
  // rim vertex: rim vertices are not copied and keep their own index (normal 0 of vertex r is not
  // the centre's normal 0). Expected: added = k/2 - 1.
  const std::uint32_t k = 100000;
  Mesh m;
  m.add_vertex({0, 0, 0});
  for (std::uint32_t r = 0; r < k; ++r) m.add_vertex({std::cos(r * 1e-4), std::sin(r * 1e-4), 0});
  for (std::uint32_t i = 0; i < k / 2; ++i) m.corner_normals.insert(m.corner_normals.end(), {double(i), 1.0, 0.5});
  for (std::uint32_t t = 0; t < k; ++t) {
    m.add_face({0, 1 + t, 1 + (t + 1) % k});
    m.corner_normal_index.insert(m.corner_normal_index.end(), {t / 2, 0, 0});
  }
  std::size_t added = 0;
  const Mesh s = io::split_corner_normals(m, added);
  REQUIRE(added == k / 2 - 1);
  REQUIRE(s.num_vertices() == 1 + k + k / 2 - 1);
  bool all_match = true;
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    all_match &= s.position(s.corner_vertex[c]) == m.position(m.corner_vertex[c]);
    all_match &= get3(s.vertex_normals, s.corner_vertex[c]) == get3(m.corner_normals, m.corner_normal_index[c]);
  }
  CHECK(all_match);
  for (std::uint32_t t = 0; t < k; ++t) {
    const std::uint32_t centre = s.corner_vertex[3 * t];
    CHECK((t < 2 ? centre == 0 : centre == 1 + k + t / 2 - 1));  // first normal on 0, then copies in order
    CHECK(s.corner_vertex[3 * t + 1] == 1 + t);                    // rim vertices keep their index
    if (!(t < 2 ? centre == 0 : centre == 1 + k + t / 2 - 1)) break;
  }
}
