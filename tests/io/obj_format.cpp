// Tests of io/obj_format: every index form, relative indices, what is accepted and skipped, the
// precision hint (values never rounded), shortest text output and the error messages (FILE:LINE: what).
#include <cmath>
#include <cstring>

#include <tbb/task_arena.h>

#include <shadetool/io/obj_format.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

TEST_CASE("OBJ: all four face index forms resolve to the same 0-based corners", "[obj]") {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 1\n";
  // i
  Mesh a = read_text(text + "f 1 2 3 4\n", Format::Obj);
  CHECK(a.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 3});
  CHECK(!a.has_texcoords());
  CHECK(!a.has_corner_normals());
  // i/j
  Mesh b = read_text(text + "f 1/4 2/3 3/2 4/1\n", Format::Obj);
  CHECK(b.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 3});
  CHECK(b.corner_texcoord_index == std::vector<std::uint32_t>{3, 2, 1, 0});
  CHECK(b.texcoords == std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1});
  // i//k
  Mesh c = read_text(text + "f 1//1 2//1 3//1 4//1\n", Format::Obj);
  CHECK(c.corner_normal_index == std::vector<std::uint32_t>{0, 0, 0, 0});
  CHECK(c.corner_normals == std::vector<double>{0, 0, 1});
  CHECK(!c.has_texcoords());
  // i/j/k
  Mesh d = read_text(text + "f 1/1/1 2/2/1 3/3/1 4/4/1\n", Format::Obj);
  CHECK(d.corner_texcoord_index == std::vector<std::uint32_t>{0, 1, 2, 3});
  CHECK(d.corner_normal_index == std::vector<std::uint32_t>{0, 0, 0, 0});
  CHECK(d.face_start == std::vector<std::uint32_t>{0, 4});
}

TEST_CASE("OBJ: negative indices count back from the last element defined so far", "[obj]") {
  // After 4 vertices, -1 is vertex 4 (index 3); after the 5th, -1 is index 4.
  Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf -4//-1 -3//-1 -2//-1\nv 2 2 0\nf -1 -2 -3\n", Format::Obj);
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 4, 3, 2});
  // the second face has no normal: it gets its face's normal, the first keeps vn 1 (issue 21, item 5)
  REQUIRE(m.has_corner_normals());
  CHECK(m.corner_normal_index[0] == 0);
}

TEST_CASE("OBJ: polygons, duplicate faces and isolated vertices are kept in order", "[obj]") {
  Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\nv 9 9 9\n"
                     "f 1 2 3 5 4\nf 1 2 3\nf 1 2 3\n",
                     Format::Obj);
  CHECK(m.num_vertices() == 6);
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 5, 8, 11});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 4, 3, 0, 1, 2, 0, 1, 2});
}

TEST_CASE("OBJ: comments, groups, materials, CRLF, tabs, blank lines and trailing spaces are accepted", "[obj]") {
  const std::string text =
      "# a comment\r\n"
      "mtllib a.mtl\r\n"
      "o thing\r\n"
      "\r\n"
      "g group one\r\n"
      "   \t\r\n"
      "v\t0 0 0   \r\n"
      "v 1 0 0 # trailing comment\r\n"
      "v  1  1  0\t\r\n"
      "usemtl red\r\n"
      "s 1\r\n"
      "s off\r\n"
      "f 1 2 3   \r\n"
      "f 3 2 1";  // no final newline
  ReadInfo info;
  Mesh m = read_text(text, Format::Obj, &info);
  CHECK(m.num_vertices() == 3);
  CHECK(m.num_faces() == 2);
  CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 2, 1, 0});
  CHECK(info.notes.empty());
}

TEST_CASE("OBJ: unknown keywords are skipped with one note", "[obj]") {
  ReadInfo info;
  Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 1\nf 1 2 3\n", Format::Obj, &info);
  CHECK(m.num_faces() == 1);
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0].find("skipped 2 lines") != std::string::npos);
  CHECK(info.notes[0].find("1 `l` (polyline), 1 `p` (point)") != std::string::npos);
}

TEST_CASE("OBJ: vertex colours after xyz, w ignored", "[obj]") {
  Mesh m = read_text("v 0 0 0 1 0.5 0.25\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n", Format::Obj);
  REQUIRE(m.has_vertex_colors());
  CHECK(m.color_channels == 3);
  CHECK(m.colors_are_float);
  CHECK(m.vertex_colors == std::vector<float>{1, 0.5f, 0.25f, 0, 1, 0, 0, 0, 1});
  Mesh w = read_text("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n", Format::Obj);
  CHECK(!w.has_vertex_colors());
  CHECK(w.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
}

TEST_CASE("OBJ: values kept as parsed; precision hint follows the digits (<= 9 significant: Float)", "[obj]") {
  Mesh f = read_text("v 0.1 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", Format::Obj);
  CHECK(f.precision == ValuePrecision::Float);
  CHECK(f.positions[0] == 0.1);  // the double nearest to the text, not narrowed to 0.1f
  CHECK(f.positions[0] != double(0.1f));
  Mesh d = read_text("v 0.10000000000000001 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", Format::Obj);
  CHECK(d.precision == ValuePrecision::Double);
  CHECK(d.positions[0] == 0.1);  // the double nearest to the text
  CHECK(d.positions[1] == 0.2);
  // trailing zeros do not count as digits
  Mesh z = read_text("v 0.500000000000000 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", Format::Obj);
  CHECK(z.precision == ValuePrecision::Float);
}

TEST_CASE("OBJ: NaN and Inf coordinates are read (info reports them)", "[obj]") {
  Mesh m = read_text("v nan 0 0\nv inf 0 0\nv 0 -inf 0\nf 1 2 3\n", Format::Obj);
  CHECK(std::isnan(m.positions[0]));
  CHECK(std::isinf(m.positions[3]));
  CHECK(m.positions[7] == -INFINITY);
}

TEST_CASE("OBJ writer: shortest text that reads back exactly", "[obj]") {
  Mesh m;
  m.add_vertex({double(0.1f), double(1.0f / 3.0f), -2.5});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.precision = ValuePrecision::Float;
  WriteOptions o;
  o.format = Format::Obj;
  const std::string text = write_mesh_to_memory(m, o);
  CHECK(text.find("v 0.1 0.33333334 -2.5\n") != std::string::npos);
  CHECK(text.find("f 1 2 3\n") != std::string::npos);
  // double data: 17 significant digits where needed, never more than needed
  m.positions[0] = 0.1;
  m.positions[1] = 1.0 / 3.0;
  m.precision = ValuePrecision::Double;
  const std::string dtext = write_mesh_to_memory(m, o);
  CHECK(dtext.find("v 0.1 0.3333333333333333 -2.5\n") != std::string::npos);
  Mesh back = read_text(dtext, Format::Obj);
  CHECK(back.precision == ValuePrecision::Double);
  CHECK(back.positions == m.positions);
  // the value decides the form, not the precision hint
  m.precision = ValuePrecision::Float;
  CHECK(write_mesh_to_memory(m, o) == dtext);
  m.positions[0] = double(0.1f);
  m.precision = ValuePrecision::Double;
  CHECK(write_mesh_to_memory(m, o).find("v 0.1 0.3333333333333333 -2.5\n") != std::string::npos);
}

TEST_CASE("OBJ: 9-digit values that are not floats are kept and written back as typed", "[obj][precision]") {
  // None of these is a float. The floats nearest to them (what the reader used to store) are
  // 123456.7890625 (float spacing 2^-7 in [2^16, 2^17)), 1 (spacing 2^-23 ~ 1.2e-7 above 1, so
  // 1.00000001 is within half a step of 1), 16777216 (2^24 + 1 needs 25 bits), -7.654321193695068,
  // 0.3333333432674408, 0.699999988079071 and 0.26726123690605164.
  const std::string text =
      "v 123456.789 0.1 -7.65432109\n"
      "v 1.00000001 0 0\n"
      "v 0 16777217 0\n"
      "vt 0.333333333 0.7\n"
      "vn 0.267261242 0.534522484 0.801783726\n"
      "f 1/1/1 2/1/1 3/1/1\n";
  const Mesh m = read_text(text, Format::Obj);
  CHECK(m.precision == ValuePrecision::Float);  // no number has more than 9 significant digits
  // the doubles nearest to the text (the compiler's own decimal conversion of the literals)
  CHECK(m.positions == std::vector<double>{123456.789, 0.1, -7.65432109, 1.00000001, 0, 0, 0, 16777217, 0});
  CHECK(m.positions[3] != 1.0);
  CHECK(m.texcoords == std::vector<double>{0.333333333, 0.7});
  CHECK(m.corner_normals == std::vector<double>{0.267261242, 0.534522484, 0.801783726});
  WriteOptions o;
  o.format = Format::Obj;
  const std::string out = write_mesh_to_memory(m, o);
  CHECK(out.find("v 123456.789 0.1 -7.65432109\n") != std::string::npos);
  CHECK(out.find("v 1.00000001 0 0\n") != std::string::npos);
  CHECK(out.find("v 0 16777217 0\n") != std::string::npos);
  CHECK(out.find("vt 0.333333333 0.7\n") != std::string::npos);
  CHECK(out.find("vn 0.267261242 0.534522484 0.801783726\n") != std::string::npos);
  const Mesh back = read_text(out, Format::Obj);
  CHECK(back.positions == m.positions);
  CHECK(back.texcoords == m.texcoords);
  CHECK(back.corner_normals == m.corner_normals);
  CHECK(back.precision == ValuePrecision::Float);
  CHECK(write_mesh_to_memory(back, o) == out);
}

TEST_CASE("OBJ from binary float PLY: floats print in their short form and read back as the same floats",
          "[obj][precision]") {
  // A binary PLY built by hand, in the host's byte order: positions and normals declared float.
  const std::uint16_t one = 1;
  char low_byte;
  std::memcpy(&low_byte, &one, 1);
  std::string ply = std::string("ply\nformat ") + (low_byte == 1 ? "binary_little_endian" : "binary_big_endian") +
      " 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float v[18] = {0.1f, 1.0f / 3.0f, 123456.789f, 0.6f, 0.0f, 0.8f,  //
                       1.0f, 0.0f,        -2.5f,       0.0f, 0.0f, 1.0f,  //
                       0.0f, 1e-40f,      3.4e38f,     0.0f, -1.0f, 0.0f};
  ply.append(reinterpret_cast<const char*>(v), sizeof v);
  const std::int32_t idx[3] = {0, 1, 2};
  ply += char(3);
  ply.append(reinterpret_cast<const char*>(idx), sizeof idx);
  const Mesh m = read_text(ply, Format::Ply);
  WriteOptions o;
  o.format = Format::Obj;
  const std::string out = write_mesh_to_memory(m, o);
  // shortest float forms: 1/3f = 0.3333333432674408 -> "0.33333334", 123456.789f = 123456.7890625
  // -> "123456.79" (not the 17-digit double forms)
  CHECK(out.find("v 0.1 0.33333334 123456.79\n") != std::string::npos);
  CHECK(out.find("v 1 0 -2.5\n") != std::string::npos);
  CHECK(out.find("v 0 1e-40 3.4e+38\n") != std::string::npos);
  CHECK(out.find("vn 0.6 0 0.8\n") != std::string::npos);
  const Mesh back = read_text(out, Format::Obj);
  REQUIRE(back.positions.size() == 9);
  for (std::size_t i = 0; i < 9; ++i) {
    const float f = float(back.positions[i]), want = v[6 * (i / 3) + i % 3];
    CHECK(std::memcmp(&f, &want, sizeof f) == 0);
  }
  // and on to binary PLY again: the very same floats, bitwise
  WriteOptions p;
  p.format = Format::Ply;
  const Mesh again = read_text(write_mesh_to_memory(back, p), Format::Ply);
  for (std::size_t i = 0; i < 9; ++i) CHECK(again.positions[i] == m.positions[i]);
}

TEST_CASE("OBJ writer: computed (double) normals print with up to 17 digits and read back exactly", "[obj][precision]") {
  Mesh m;  // the corner of a cube: the vertex normal along (1,1,1) is 1/sqrt(3) per component
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({0, 0, 1});
  m.add_face({0, 1, 2});
  const double c = 1.0 / std::sqrt(3.0);  // 0.57735026918962573 (17 digits); shortest "0.5773502691896258"
  m.vertex_normals = {c, c, c, c, c, c, c, c, c};
  WriteOptions o;
  o.format = Format::Obj;
  const std::string out = write_mesh_to_memory(m, o);
  CHECK(out.find("vn 0.5773502691896258 0.5773502691896258 0.5773502691896258\n") != std::string::npos);
  const Mesh back = read_text(out, Format::Obj);
  CHECK(back.corner_normals == std::vector<double>{c, c, c, c, c, c, c, c, c});
  CHECK(back.precision == ValuePrecision::Double);  // 16 digits: the hint follows
}

TEST_CASE("OBJ writer: normals as vn pool, per vertex or per face; texcoords as vt", "[obj]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  WriteOptions o;
  o.format = Format::Obj;
  m.face_normals = {0, 0, 1};
  std::string t = write_mesh_to_memory(m, o);
  CHECK(t.find("vn 0 0 1\n") != std::string::npos);
  CHECK(t.find("f 1//1 2//1 3//1\n") != std::string::npos);
  m.vertex_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  t = write_mesh_to_memory(m, o);
  CHECK(t.find("f 1//1 2//2 3//3\n") != std::string::npos);
  m.texcoords = {0, 0, 1, 0};
  m.corner_texcoord_index = {0, 1, 1};
  t = write_mesh_to_memory(m, o);
  CHECK(t.find("vt 1 0\n") != std::string::npos);
  CHECK(t.find("f 1/1/1 2/2/2 3/2/3\n") != std::string::npos);
}

TEST_CASE("OBJ writer: face colours split the vertices shared by faces of different colours", "[obj][colors]") {
  Mesh m;  // a square as two triangles, red and blue, sharing the diagonal 0-2
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({1, 1, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.face_colors = {1, 0, 0, 0, 0, 1};
  m.face_normals = {0, 0, 1, 0, 0, 1};
  WriteOptions o;
  o.format = Format::Obj;
  WriteInfo wi;
  const std::string text = write_mesh_to_memory(m, o, &wi);
  // vertices 0 and 2 keep red (their first face) and get a blue copy each, appended as 5 and 6
  CHECK(text ==
        "# written by shadetool\n"
        "v 0 0 0 1 0 0\n"
        "v 1 0 0 1 0 0\n"
        "v 1 1 0 1 0 0\n"
        "v 0 1 0 0 0 1\n"
        "v 0 0 0 0 0 1\n"
        "v 1 1 0 0 0 1\n"
        "vn 0 0 1\n"
        "vn 0 0 1\n"
        "f 1//1 2//1 3//1\n"
        "f 5//2 6//2 4//2\n");
  CHECK(wi.split_vertices == 2);
  REQUIRE(wi.notes.size() == 1);
  CHECK(wi.notes[0] == "face colours written as vertex colours (v x y z r g b): 2 vertices added so that every face's corners carry its colour");
  // one colour for both: nothing to split; an unused vertex is written white, with a note
  m.face_colors = {0.5f, 0.25f, 1, 0.5f, 0.25f, 1};
  m.add_vertex({5, 5, 5});
  wi = WriteInfo{};
  const std::string one = write_mesh_to_memory(m, o, &wi);
  CHECK(one.find("v 0 0 0 0.5 0.25 1\nv 1 0 0 0.5 0.25 1\nv 1 1 0 0.5 0.25 1\nv 0 1 0 0.5 0.25 1\nv 5 5 5 1 1 1\nvn") !=
        std::string::npos);
  CHECK(one.find("f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n") != std::string::npos);
  CHECK(wi.split_vertices == 0);
  REQUIRE(wi.notes.size() == 2);
  CHECK(wi.notes[1] == "1 vertex used by no face written white");
}

TEST_CASE("OBJ: errors name the file and line", "[obj][errors]") {
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Obj, nullptr, "m.obj"); }); };
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n") == "m.obj:4: vertex index 4 out of range (3 vertices defined so far)");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n") == "m.obj:4: vertex index -4 out of range (3 vertices defined so far)");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n") == "m.obj:4: vertex index 0 is invalid (OBJ indices start at 1)");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n") == "m.obj:5: texcoord index 2 out of range (1 texcoord defined so far)");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n") ==
        "m.obj:5: normal index 2 out of range (1 normal defined so far)");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n") == "m.obj:4: malformed face index '1/x'");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\ 2 3\n") == "m.obj:4: malformed face index '\\'");  // `\` not ending the line
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\x\n2 3\n") == "m.obj:4: malformed face index '\\x'");
  CHECK(err("v 0 0 \\\n0\nv 1 x 0\n") == "m.obj:3: malformed number 'x'");  // after a continued line
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n 2 \\\n 4\n") == "m.obj:6: vertex index 4 out of range (3 vertices defined so far)");
  CHECK(err("v 0 0\n") == "m.obj:1: v has 2 values (need x y z)");
  CHECK(err("v 0 0 0\nv 1 0x 0\n") == "m.obj:2: malformed number '0x'");
  CHECK(err("v 0 0 0\nv 1 0 1.5.2\n") == "m.obj:2: malformed number '1.5.2'");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n") == "m.obj:4: malformed face index 'x'");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3a\n") == "m.obj:4: malformed face index '3a'");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0\n") == "m.obj:5: vn has 2 values (need x y z)");
  CHECK(err("# nothing\r\n\r\nv 1 2 3\r\nv 1 2 e\r\n") == "m.obj:4: malformed number 'e'");
}

TEST_CASE("OBJ: partial vn and vt are kept per face (vt absent where absent, vn from the face) with one note", "[obj]") {
  // issue 21, item 5: `f 1/1/1 2/2/1 3/1/1` beside `f 1 2 3` keeps the first face's vt and vn.
  ReadInfo info;
  Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0.6 0.8\nvt 0.25 0.5\nvt 1 0\nf 1/1/1 2/2/1 3/1/1\nf 1 2 3\n",
                     Format::Obj, &info);
  REQUIRE(m.has_corner_normals());
  REQUIRE(m.has_texcoords());
  CHECK(m.corner_texcoord_index == std::vector<std::uint32_t>{0, 1, 0, kNoTexcoord, kNoTexcoord, kNoTexcoord});
  // the first face keeps vn 1 exactly; the second gets its own geometric normal, +z (counter-clockwise)
  for (int c = 0; c < 3; ++c) CHECK(get3(m.corner_normals, m.corner_normal_index[std::size_t(c)]) == Vec3d{0, 0.6, 0.8});
  for (int c = 3; c < 6; ++c) CHECK(get3(m.corner_normals, m.corner_normal_index[std::size_t(c)]) == Vec3d{0, 0, 1});
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "normals (vn): 3 of 6 face corners have none: given their face's normal");
  // Written back as OBJ, the face without vt has none again.
  WriteOptions o;
  o.format = Format::Obj;
  const std::string text = write_mesh_to_memory(m, o);
  CHECK(text.find("f 1/1/1 2/2/1 3/1/1\nf 1//2 2//2 3//2\n") != std::string::npos);
}

TEST_CASE("OBJ: vt and vn indices while the file has no vt or vn line are ignored with one counted note (as assimp)",
          "[obj][issue27]") {
  // issue 27, item 7: OpenSubdiv's shapes (tinyobjloader's test data) write `f v/vt/vn` and no vn
  // line; assimp reads the positions and faces and ignores the indices. This was refused before
  // ("normal index 1 out of range").
  ReadInfo info;
  Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1/1/1 2/2/2 3/3/3\nf 2//4 4//5 3//6\n", Format::Obj, &info, "m.obj");
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2});
  CHECK(!m.has_corner_normals());
  CHECK(!m.has_texcoords());
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "face corners name 6 normal (vn) and 3 texture (vt) indices but the file defines no vn or vt "
                         "line before them: those indices ignored (as assimp does)");
  // With vt lines present, only the dangling normal indices are ignored; the vt are kept.
  ReadInfo info2;
  Mesh t = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1/1 2/2/1 3/3/1\n", Format::Obj, &info2);
  CHECK(t.corner_texcoord_index == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(!t.has_corner_normals());
  REQUIRE(info2.notes.size() == 1);
  CHECK(info2.notes[0] == "face corners name 3 normal (vn) indices but the file defines no vn line before them: "
                          "those indices ignored (as assimp does)");
}

namespace {

// `text` with every `\` ending a line joined with the next line by one space (the spaces around
// the `\` and the line feed, and the next line's leading spaces, dropped): what the OBJ spec says
// a continued line means, written here by the test, not by the reader.
std::string joined_continuations(const std::string& text) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\') {
      std::size_t j = i + 1;
      while (j < text.size() && space(text[j])) ++j;
      if (j < text.size() && text[j] == '\n') {
        while (!out.empty() && space(out.back())) out.pop_back();
        out += ' ';
        i = j;
        while (i + 1 < text.size() && space(text[i + 1])) ++i;
        continue;
      }
    }
    out += text[i];
  }
  return out;
}

}  // namespace

TEST_CASE("OBJ: an empty vt or vn field (`1/`, `1//`, `1/1/`) is absent, as tinyobjloader, assimp and trimesh read it",
          "[obj][xcorpus]") {
  const std::string head = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  ReadInfo info;
  const Mesh m = read_text(head + "f 2/2/ 4/4/ 1/1/\nf 1// 2// 3//\nf 1/ 3/ 4/\nf 1/1/\t2/2/ 3/3/ # c\n", Format::Obj, &info);
  CHECK(info.notes.empty());
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 6, 9, 12});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{1, 3, 0, 0, 1, 2, 0, 2, 3, 0, 1, 2});
  const std::uint32_t no = kNoTexcoord;
  CHECK(m.corner_texcoord_index == std::vector<std::uint32_t>{1, 3, 0, no, no, no, no, no, no, 0, 1, 2});
  CHECK(!m.has_corner_normals());
  // The same faces written without the empty fields read to the same mesh, bit for bit.
  const Mesh plain = read_text(head + "f 2/2 4/4 1/1\nf 1 2 3\nf 1 3 4\nf 1/1 2/2 3/3\n", Format::Obj);
  require_same_mesh(m, plain);
  // A vn after an empty vt is still read; a field that is not a number is still an error.
  const Mesh n = read_text(head + "vn 0 0 1\nf 1//1 2/ 3/3/\n", Format::Obj);
  CHECK(n.corner_normal_index.size() == 3);
  CHECK(n.corner_normal_index[0] == 0);
}

TEST_CASE("OBJ: an `f` of 1 or 2 vertices is skipped with a count, leaving the mesh as if the line were absent",
          "[obj][xcorpus]") {
  // Around the short faces: the first vn and vt references of the file (lazily started per-corner
  // arrays), a dangling index and a relative index: all taken back with the line.
  const std::string head = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\n";
  const std::string tail = "f 1 2 3\nf -4/1/1 -3/1/1 -2/1/1 -1/1/1\n";
  ReadInfo info;
  const Mesh m = read_text(head + "f 1 2 3\nf 2/1/1 3/1/1\nf 4//1\nf 1//\n" + tail, Format::Obj, &info);
  ReadInfo without_info;
  const Mesh without = read_text(head + "f 1 2 3\n" + tail, Format::Obj, &without_info);
  require_same_mesh(m, without);
  REQUIRE(info.notes.size() == without_info.notes.size() + 1);
  CHECK(info.notes.back() == "skipped 3 lines: 3 `f` with fewer than 3 vertices (not a face)");
  // Counted beside the other skipped lines, in one note.
  ReadInfo both;
  read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\nf\nf 1 2\n", Format::Obj, &both);
  REQUIRE(both.notes.size() == 1);
  CHECK(both.notes[0] == "skipped 3 lines: 1 `l` (polyline), 1 `f` with no indices (no face), 1 `f` with fewer than 3 vertices (not a face)");
  // An index out of range is still an error, short face or not.
  CHECK(error_of([] { read_text("v 0 0 0\nf 1 5\n", Format::Obj, nullptr, "m.obj"); }) ==
        "m.obj:2: vertex index 5 out of range (1 vertex defined so far)");
}

TEST_CASE("OBJ: a line ending in `\\` continues its statement (v, vn, vt, f, grouping, comments); messages count the lines",
          "[obj][xcorpus]") {
  const std::string text =
      "# a comment \\\n"
      "  that goes on\n"
      "v 0 0 \\\n"
      "0\n"
      "v 1 \\ \t\n"
      "0 0\n"
      "v 1 1 0\nv 0 1 0\n"
      "vt 0.25 \\\n0.5\n"
      "vn 0 \\\n0 1\n"
      "g left \\\n  right\n"
      "f 1/1/1 \\\n2/1/1 \\\n\n"  // an empty continued line: the face ends there
      "f 1 3 \\\n 4\n"
      "s 1 \\\n"
      "f 1 2 4\n";  // a statement's words on a continued line are not a face of their own
  ReadInfo info;
  const Mesh m = read_text(text, Format::Obj, &info);
  ReadInfo joined_info;
  const Mesh joined = read_text(joined_continuations(text), Format::Obj, &joined_info);
  require_same_mesh(m, joined);
  CHECK(info.notes == joined_info.notes);
  CHECK(m.num_vertices() == 4);
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3});  // the 2-vertex face skipped, then `f 1 3 4`
  CHECK(m.group_statements == std::vector<std::string>{"g left right\n", "s 1 f 1 2 4\n"});
  // Messages name the line the bad token is on, every continued line counted.
  auto err = [](const std::string& t) { return error_of([&] { read_text(t, Format::Obj, nullptr, "m.obj"); }); };
  CHECK(err("# c \\\nx\nv 0 0 \\\n\\\n 0\nv 0 0 0\nv 0 0\n") == "m.obj:7: v has 2 values (need x y z)");
  CHECK(err("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 \\\n 3/9\n") ==
        "m.obj:6: texcoord index 9 out of range (1 texcoord defined so far)");
  // A `\` ending the text ends the statement.
  const Mesh last = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 \\", Format::Obj);
  CHECK(last.num_faces() == 1);
}

TEST_CASE("OBJ: vt or vn lines no face references are named in a note (not read); referenced ones read as before",
          "[obj][xcorpus]") {
  ReadInfo info;
  const Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1 2 3\n", Format::Obj, &info);
  CHECK(!m.has_texcoords());
  CHECK(!m.has_corner_normals());
  CHECK(info.notes == std::vector<std::string>{"3 texture coordinates (vt) no face references: not read",
                                               "1 normal (vn) no face references: not read"});
  ReadInfo some;
  const Mesh r = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/1 2/2 3/1\n", Format::Obj, &some);
  CHECK(some.notes.empty());
  CHECK(r.texcoords == std::vector<double>{0, 0, 1, 0});
}

TEST_CASE("OBJ: vn lines no corner names, beside ones that are named, are not read (a note); a zero one no longer "
          "stops the writers",
          "[obj][xcorpus3]") {
  // MeshLab writes `vn 0 0 0` for the vertices no face uses (draco's testdata/test_nm.obj: 17 of
  // 114). Truth: the same text without those vn lines, the corners renumbered by hand.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nvn 0 0 1\nvn 0 0 0\nvn 0 1 0\nvn 1 0 0\n"
                           "f 1//1 2//3 3//4\n";
  ReadInfo info;
  const Mesh m = read_text(text, Format::Obj, &info);
  CHECK(info.notes == std::vector<std::string>{"1 of 4 normals (vn) no face references: not read"});
  require_same_mesh(m, read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nvn 0 0 1\nvn 0 1 0\nvn 1 0 0\nf 1//1 2//2 3//3\n",
                                 Format::Obj));
  // Every format that holds normals writes the mesh (the zero vn is gone, not written).
  for (Format f : {Format::Obj, Format::Ply, Format::Off, Format::Gltf}) {
    WriteOptions o;
    o.format = f;
    CHECK(error_of([&] { write_mesh_to_memory(m, o); }).empty());
  }
  const std::string written = [&] {
    WriteOptions o;
    o.format = Format::Obj;
    return write_mesh_to_memory(m, o);
  }();
  CHECK(written.find("vn 0 0 0") == std::string::npos);
  // Face normals given to corners without vn are named by those corners: kept, no note about them
  // beyond the usual one.
  ReadInfo mixed;
  const Mesh x = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 0\nvn 0 0 1\nf 1//2 2//2 3//2\nf 1 2 4\n",
                           Format::Obj, &mixed);
  CHECK(x.corner_normals.size() == 6);  // vn 2 and the second face's normal
  CHECK(x.corner_normal_index == std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1});
  CHECK(mixed.notes.size() == 2);
  CHECK(mixed.notes[0] == "1 of 2 normals (vn) no face references: not read");
}

TEST_CASE("OBJ: an MNI surface .obj (BIC's format: `P` and numbers) is refused as that format, by name", "[obj][xcorpus]") {
  // The first lines of pyvista's mni-surface-mesh.obj.
  CHECK(error_of([] { read_text("P 0.3 0.3 0.4 10 1 4\n -18 -16.85 2.5\n -17.75 -16.6 2.5\n -18 -16.6 2.25\n", Format::Obj, nullptr, "m.obj"); }) ==
        "m.obj: not a Wavefront OBJ file: it starts as an MNI surface .obj does (`P` and numbers, no `v` line): MNI's format "
        "(BIC), which shadetool does not read");
  // Other keyword-less text keeps its message.
  CHECK(error_of([] { read_text("Q 1\n", Format::Obj, nullptr, "m.obj"); }) ==
        "m.obj: not an OBJ file: no vertices, 1 line with unknown keywords (first: 'Q')");
}

TEST_CASE("OBJ writer: normals of a mesh without faces (a point cloud) are written as vn lines and named in a note, "
          "since no reader ties them to a point",
          "[obj][xcorpus3]") {
  // draco's float_two_att_point_cloud.ply: 3 points with nx ny nz, written to OBJ.
  const Mesh points = read_text("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n"
                                "4.9 2.9 3.8 1 0 0\n4.7 2.9 7.7 0 1 0\n4.1 2.6 1.4 0 0 1\n",
                                Format::Ply);
  REQUIRE(points.num_faces() == 0);
  WriteOptions o;
  o.format = Format::Obj;
  WriteInfo info;
  const std::string text = write_mesh_to_memory(points, o, &info);
  CHECK(text.find("vn 1 0 0\nvn 0 1 0\nvn 0 0 1\n") != std::string::npos);
  CHECK(text.find("\nf ") == std::string::npos);
  CHECK(info.notes == std::vector<std::string>{"3 normals written as vn lines no face names: OBJ ties a normal to a face "
                                               "corner, so readers do not read them back for points"});
  // A mesh with faces gets no such note.
  WriteInfo tri;
  write_mesh_to_memory(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n", Format::Obj), o, &tri);
  CHECK(tri.notes.empty());
}

TEST_CASE("OBJ `v x y z w`: positions are x y z as written (as Blender 3.4 imports them), a w other than 1 counted in a note",
          "[obj][xcorpus6]") {
  // PDAL's test/data/obj/hyper_box.obj writes every vertex with a fourth value (0.5 and -0.5);
  // the mesh's truth is the same lines with w removed (Blender 3.4's importer gives exactly those
  // positions; assimp divides by w instead). w is not dropped silently: the note counts it.
  const std::string faces = "f 1 2 3\nf 1 3 4\n";
  const std::string with_w = "v 0 0 0 0.5\nv 1 0 0 0.5\nv 1 1 0 1\nv 0 1 0 -0.5\n" + faces;
  const std::string without_w = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + faces;
  for (std::size_t chunk : {std::size_t(0), std::size_t(12)}) {  // serial, and parallel chunks of a line or two
    ReadInfo info, plain_info;
    Mesh m, truth;
    tbb::task_arena(2).execute([&] {
      m = io::read_obj(with_w, "w.obj", info, io::ObjReadOptions{chunk});
      truth = io::read_obj(without_w, "p.obj", plain_info, io::ObjReadOptions{chunk});
    });
    require_same_mesh(m, truth);
    CHECK(plain_info.notes.empty());
    REQUIRE(info.notes.size() == 1);
    CHECK(info.notes[0] ==
          "3 of 4 vertices have a weight w other than 1 (v x y z w): not read, positions are x y z as written (as Blender "
          "reads them; assimp divides by w)");
  }
  ReadInfo ones;
  read_text("v 0 0 0 1\nv 1 0 0 1.0\nv 0 1 0 1\nf 1 2 3\n", Format::Obj, &ones);
  CHECK(ones.notes.empty());  // w = 1, the spec's default, changes nothing: no note
}
