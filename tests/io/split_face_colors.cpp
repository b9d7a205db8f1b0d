// Tests of io/split_face_colors: a cube with one colour per side (flat shading) needs 3 vertices
// per corner of the cube (each touches 3 sides): 8 become 24, 16 added.
#include <shadetool/io/split_face_colors.h>
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {
std::vector<float> color_of(const std::vector<float>& a, std::size_t i, int ch) {
  return {a.begin() + std::ptrdiff_t(i) * ch, a.begin() + std::ptrdiff_t(i + 1) * ch};
}
}  // namespace

TEST_CASE("split colours: flat-coloured cube becomes 24 vertices, each corner with its face's colour", "[split]") {
  Mesh m = read_mesh(data_path("cube.obj"));
  REQUIRE(m.num_vertices() == 8);
  REQUIRE(m.num_faces() == 12);
  // one colour per side: the two triangles of a side share it (sides in the file's face order)
  const float C[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  for (std::size_t f = 0; f < 12; ++f) m.face_colors.insert(m.face_colors.end(), C[f / 2], C[f / 2] + 3);
  std::size_t added = 0, unreferenced = 9;
  const Mesh s = io::split_face_colors(m, added, unreferenced);
  CHECK(added == 16);
  CHECK(unreferenced == 0);
  CHECK(s.num_vertices() == 24);
  CHECK(!s.has_face_colors());
  REQUIRE(s.vertex_colors.size() == 24 * 3);
  CHECK(s.face_start == m.face_start);
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
      CHECK(s.position(s.corner_vertex[c]) == m.position(m.corner_vertex[c]));
      CHECK(color_of(s.vertex_colors, s.corner_vertex[c], 3) == std::vector<float>(C[f / 2], C[f / 2] + 3));
    }
  // each original vertex keeps its index for its first colour
  for (std::size_t c = 0; c < m.num_corners(); ++c)
    if (s.corner_vertex[c] < 8) CHECK(s.corner_vertex[c] == m.corner_vertex[c]);
}

TEST_CASE("split colours: faces of one colour share vertices; unreferenced vertices white or as they were", "[split]") {
  Mesh m;
  for (int i = 0; i < 5; ++i) m.add_vertex({double(i), double(i * i), 0});  // vertex 4 used by no face
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.face_colors = {0.25f, 0.5f, 0.75f, 0.25f, 0.5f, 0.75f};
  std::size_t added = 7, unreferenced = 0;
  Mesh s = io::split_face_colors(m, added, unreferenced);
  CHECK(added == 0);
  CHECK(unreferenced == 1);
  CHECK(s.corner_vertex == m.corner_vertex);
  CHECK(s.vertex_colors == std::vector<float>{0.25f, 0.5f, 0.75f, 0.25f, 0.5f, 0.75f, 0.25f, 0.5f, 0.75f,
                                              0.25f, 0.5f, 0.75f, 1, 1, 1});
  // with vertex colours, the face colours replace them where faces use the vertex
  m.vertex_colors = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.125f, 0.125f, 0.125f};
  s = io::split_face_colors(m, added, unreferenced);
  CHECK(color_of(s.vertex_colors, 0, 3) == std::vector<float>{0.25f, 0.5f, 0.75f});
  CHECK(color_of(s.vertex_colors, 4, 3) == std::vector<float>{0.125f, 0.125f, 0.125f});
}

TEST_CASE("split colours: rgba, vertex normals copied, texcoords and corner normals untouched", "[split]") {
  Mesh m;  // two triangles of a square, two colours: the diagonal 0-2 is split
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({1, 1, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.color_channels = 4;
  m.face_colors = {1, 0, 0, 0.5f, 0, 0, 1, 1};
  m.vertex_normals = {0, 0, 1, 0, 0.6, 0.8, 0.6, 0, 0.8, 0, -0.6, 0.8};
  m.texcoords = {0, 0, 1, 0, 1, 1, 0, 1};
  m.corner_texcoord_index = {0, 1, 2, 0, 2, 3};
  std::size_t added = 0, unreferenced = 0;
  const Mesh s = io::split_face_colors(m, added, unreferenced);
  CHECK(added == 2);  // vertex 0 and vertex 2 are in both faces
  CHECK(s.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 4, 5, 3});  // new ones in vertex order
  CHECK(s.vertex_colors == std::vector<float>{1, 0, 0, 0.5f, 1, 0, 0, 0.5f, 1, 0, 0, 0.5f, 0, 0, 1, 1,
                                              0, 0, 1, 1, 0, 0, 1, 1});
  CHECK(s.vertex_normals == std::vector<double>{0, 0, 1, 0, 0.6, 0.8, 0.6, 0, 0.8, 0, -0.6, 0.8,  //
                                                0, 0, 1, 0.6, 0, 0.8});
  CHECK(s.corner_texcoord_index == m.corner_texcoord_index);
  CHECK(s.texcoords == m.texcoords);
}
