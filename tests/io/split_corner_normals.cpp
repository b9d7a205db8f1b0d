// Tests of io/split_corner_normals: a cube with one normal per side (the flat-shaded cube) needs
// 3 vertices per corner of the cube: 8 become 24.
#include "io/split_corner_normals.h"
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
  CHECK(s.vertex_normals == std::vector<double>{0, 0, 1, 0, 0, -1, 1, 0, 0, 0, 0, 0});
}
