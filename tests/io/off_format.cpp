// Tests of io/off_format: header variants, counts placement, comments, colours (integers and
// floats), polygons, and the error messages.
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

TEST_CASE("OFF: plain, with comments, counts on the keyword line, polygons", "[off]") {
  Mesh m = read_text("# comment\nOFF 4 2 0\n\n0 0 0\n1 0 0 # c\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 2 1\n", Format::Off);
  CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 4, 7});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 3, 0, 2, 1});
  CHECK(m.precision == ValuePrecision::Float);
  Mesh n = read_text("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Format::Off);  // keyword is optional
  CHECK(n.num_faces() == 1);
}

TEST_CASE("OFF: a digit right after the keyword starts the counts (`OFF8 6 12`), after leading spaces and before a comment",
          "[off][xcorpus]") {
  // trimesh's whitespace.off opens with a tab and spaces, then `OFF8 6 12 # or nah`. The truth: the
  // same text with a space between keyword and counts, which every OFF reader reads.
  const std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 0.5 0.25 0 0.75\n";
  ReadInfo info;
  const Mesh glued = read_text("\t      OFF4 1 4 # or nah\n" + body, Format::Off, &info);
  const Mesh spaced = read_text("OFF 4 1 4\n" + body, Format::Off);
  require_same_mesh(glued, spaced);
  CHECK(info.notes.empty());
  CHECK(glued.num_vertices() == 4);
  CHECK(glued.face_start == std::vector<std::uint32_t>{0, 4});
  const Mesh c = read_text("COFF3 1\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n", Format::Off);
  CHECK(c.vertex_colors.size() == 9);
  // A letter glued to the keyword is still no OFF variant; a digit before it (4OFF) is refused as before.
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Off, nullptr, "m.off"); }); };
  CHECK(err("OFFx 3 1\n") == "m.off:1: unsupported OFF variant 'OFFx' (supported: [ST][C][N]OFF)");
  CHECK(err("OFF3x 1\n") == "m.off:1: malformed count '3x' (expected: #vertices #faces #edges)");
}

TEST_CASE("OFF: NOFF normals, COFF integer and float colours, face colours", "[off]") {
  Mesh n = read_text("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0.6 0 0.8\n3 0 1 2\n", Format::Off);
  CHECK(n.vertex_normals == std::vector<double>{0, 0, 1, 0, 0, 1, 0.6, 0, 0.8});  // as parsed, not narrowed
  Mesh c = read_text("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 128\n0 1 0 0 0 51 255\n3 0 1 2 10 20 30\n", Format::Off);
  CHECK(c.color_channels == 4);
  CHECK(!c.colors_are_float);
  CHECK(c.vertex_colors == std::vector<float>{1, 0, 0, 1, 0, 1, 0, 128 / 255.0f, 0, 0, 0.2f, 1});
  CHECK(c.face_colors == std::vector<float>{10 / 255.0f, 20 / 255.0f, 30 / 255.0f, 1});
  // alpha 1 everywhere (what the writer gives rgb colours) reads as rgb
  Mesh opaque = read_text("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 51 255\n3 0 1 2\n", Format::Off);
  CHECK(opaque.color_channels == 3);
  CHECK(opaque.vertex_colors == std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 0.2f});
  Mesh f = read_text("COFF\n3 1 0\n0 0 0 1.0 0.5 0\n1 0 0 0 1.0 0\n0 1 0 0 0 1.0\n3 0 1 2\n", Format::Off);
  CHECK(f.colors_are_float);
  CHECK(f.color_channels == 3);
  CHECK(f.vertex_colors == std::vector<float>{1, 0.5f, 0, 0, 1, 0, 0, 0, 1});
}

TEST_CASE("OFF writer: header letters follow the attributes; round trip of colours", "[off]") {
  Mesh m = rich_mesh();
  WriteOptions o;
  o.format = Format::Off;
  WriteInfo wi;
  const std::string text = write_mesh_to_memory(m, o, &wi);
  CHECK(text.rfind("CNOFF\n11 3 0\n", 0) == 0);  // corner normals split into 4 more vertices
  CHECK(wi.split_vertices == 4);
  Mesh back = read_text(text, Format::Off);
  CHECK(back.face_colors == m.face_colors);
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const auto v = back.corner_vertex[c];
    for (int k = 0; k < 3; ++k)
      CHECK(back.vertex_colors[3 * v + std::size_t(k)] == m.vertex_colors[3 * m.corner_vertex[c] + std::size_t(k)]);
  }
}

TEST_CASE("OFF writer: face colours native after the indices; float colours keep a decimal point", "[off][colors]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({1, 1, 0});
  m.add_face({0, 1, 2});
  m.add_face({1, 3, 2});
  m.face_colors = {1, 0, 0, 0.5f, 0.25f, 1};
  WriteOptions o;
  o.format = Format::Off;
  WriteInfo wi;
  // uchar colours: round(255 c): 1 -> 255, 0.5 -> 128 (127.5 rounds up), 0.25 -> 64 (63.75)
  std::string text = write_mesh_to_memory(m, o, &wi);
  // four components r g b a (alpha 255 for rgb): what assimp and MeshLab read (issue 21, item 10)
  CHECK(text == "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2 255 0 0 255\n3 1 3 2 128 64 255 255\n");
  CHECK(wi.split_vertices == 0);
  CHECK(wi.notes.empty());
  // float colours: 1 0 0 written as integers would read back as 1/255 0 0
  m.colors_are_float = true;
  text = write_mesh_to_memory(m, o);
  CHECK(text.find("\n3 0 1 2 1.0 0.0 0.0 1.0\n3 1 3 2 0.5 0.25 1.0 1.0\n") != std::string::npos);
  const Mesh back = read_text(text, Format::Off);
  CHECK(back.colors_are_float);
  CHECK(back.num_vertices() == 4);
  CHECK(back.corner_vertex == m.corner_vertex);
  CHECK(back.face_colors == m.face_colors);
  // vertex colours too
  m.vertex_colors = {1, 1, 1, 0, 0, 0, 1, 0, 1, 0.5f, 0.5f, 0.5f};
  const Mesh vback = read_text(write_mesh_to_memory(m, o), Format::Off);
  CHECK(vback.vertex_colors == m.vertex_colors);
  CHECK(vback.face_colors == m.face_colors);
}

TEST_CASE("OFF: 9-digit values that are not floats are kept and written back as typed", "[off][precision]") {
  // The floats nearest to these are 123456.7890625, 1, 16777216, -7.654321193695068,
  // 0.26726123690605164... (see the OBJ test); the reader stores the doubles nearest to the text.
  const std::string text =
      "NOFF\n3 1 0\n"
      "123456.789 0.1 -7.65432109 0.267261242 0.534522484 0.801783726\n"
      "1.00000001 0 0 0 0 1\n"
      "0 16777217 0 0 0 1\n"
      "3 0 1 2\n";
  const Mesh m = read_text(text, Format::Off);
  CHECK(m.precision == ValuePrecision::Float);
  CHECK(m.positions == std::vector<double>{123456.789, 0.1, -7.65432109, 1.00000001, 0, 0, 0, 16777217, 0});
  CHECK(m.vertex_normals == std::vector<double>{0.267261242, 0.534522484, 0.801783726, 0, 0, 1, 0, 0, 1});
  WriteOptions o;
  o.format = Format::Off;
  const std::string out = write_mesh_to_memory(m, o);
  CHECK(out == text);  // the writer's layout is the one above: every value as typed
  const Mesh back = read_text(out, Format::Off);
  CHECK(back.positions == m.positions);
  CHECK(back.vertex_normals == m.vertex_normals);
}

TEST_CASE("OFF: errors name the file and line", "[off][errors]") {
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Off, nullptr, "m.off"); }); };
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").empty());
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") == "m.off:6: vertex index 3 out of range (3 vertices)");
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n") == "m.off:6: vertex index -1 out of range (3 vertices)");
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 7\n") == "m.off:6: vertex index 7 out of range (3 vertices)");  // short or not
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 1\n") == "m.off:6: malformed face size '-1'");
  CHECK(err("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") == "m.off:6: file ends after 1 of 2 faces");
  CHECK(err("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") == "m.off:6: vertex line has more values than the header 'OFF' declares");
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n") ==
        "m.off:7: more data than the header declares ('3' after the last face)");
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1\n3 0 1 2\n") == "m.off:5: vertex line has 2 values, expected 3 (x y z)");
  CHECK(err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 z\n3 0 1 2\n") == "m.off:5: malformed number 'z'");
  CHECK(err("OFF\n3 x 0\n") == "m.off:2: malformed count 'x' (expected: #vertices #faces #edges)");
  CHECK(err("4OFF\n") == "m.off:1: unsupported OFF variant '4OFF' (supported: [ST][C][N]OFF)");
  CHECK(err("PLY\n") == "m.off:1: not an OFF file (header is 'PLY')");
  CHECK(err("OFF BINARY\n3 1 0\n") ==
        "m.off: binary OFF: byte 11: the body ends before the counts #V #F #E (12 bytes) (read in Geomview's big-endian "
        "layout; pmp-library's and little-endian layouts do not fit either)");
  CHECK(err("OFF\n3 1 0 BINARY\n") == "m.off:2: unexpected 'BINARY' after the counts");
  CHECK(err("OFF\n1099511627776 1 0\n0 0 0\n").find("m.off:2: header claims 1099511627776 vertices") == 0);
}

TEST_CASE("OFF: a face line of 0, 1 or 2 vertices is skipped with its colour, leaving the mesh as if the line were absent",
          "[off][xcorpus]") {
  const std::string verts = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n";
  // Short lines with colours that would change what the others read as if they counted: a float
  // colour (the others are 0..255 integers), an alpha (the others are rgb), 10 digits (precision).
  struct Line {
    const char* indices;  // size and indices
    const char* colour;
  };
  const std::vector<Line> faces = {
      {"3 0 1 2", " 255 0 0"}, {"2 1 3", " 0.5 0.25 0.125 0.5"}, {"4 0 2 3 4", " 0 0 255"}, {"1 4", " 0.1234567891 0 0"},
      {"0", ""}, {"3 2 3 4", " 10 20 30"},
  };
  // And the same faces without colours.
  for (bool colours : {true, false}) {
    INFO((colours ? "face colours" : "no face colours"));
    std::string all, kept;
    std::size_t nkept = 0;
    for (const Line& f : faces) {
      const std::string text = std::string(f.indices) + (colours ? f.colour : "") + "\n";
      all += text;
      if (f.indices[0] >= '3') kept += text, ++nkept;
    }
    ReadInfo info, kept_info;
    const Mesh m = read_text("OFF\n5 6 0\n" + verts + all, Format::Off, &info);
    const Mesh want = read_text("OFF\n5 " + std::to_string(nkept) + " 0\n" + verts + kept, Format::Off, &kept_info);
    require_same_mesh(m, want);
    REQUIRE(want.num_faces() == 3);
    CHECK(want.face_colors.size() == (colours ? 9u : 0u));
    CHECK(!want.colors_are_float);
    CHECK(want.precision == ValuePrecision::Float);
    REQUIRE(info.notes.size() == kept_info.notes.size() + 1);
    CHECK(info.notes.back() == "skipped 3 of 6 face lines with fewer than 3 vertices (not a face), with their colours");
  }
  // Only short faces: a point cloud, with the note.
  ReadInfo none_info;
  const Mesh none = read_text("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n1 2 255 0 0\n", Format::Off, &none_info);
  CHECK(none.num_vertices() == 3);
  CHECK(none.num_faces() == 0);
  CHECK(none.face_colors.empty());
  CHECK(none_info.notes == std::vector<std::string>{"skipped 2 of 2 face lines with fewer than 3 vertices (not a face), with their colours"});
}

TEST_CASE("OFF: a face's indices may go on over the following lines (libigl-tutorial-data's quad files, one index a "
          "line), read as the same face on one line",
          "[off][xcorpus3]") {
  // The layout of inspired_mesh_quads_Conjugate.off (`4 887 \n46 \n888 \n0 \n\n4 888 ...`), small.
  // Truth: the same numbers with each face on one line, the layout every OFF reader reads.
  const std::string head = "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0.5 0\n";
  const std::string spread = head + "4 0 \n1 \n2 \n3 \n\n3 1 # a comment between indices\n4\n2\n";
  const std::string one_line = head + "4 0 1 2 3\n3 1 4 2\n";
  ReadInfo info;
  const Mesh m = read_text(spread, Format::Off, &info);
  CHECK(info.notes.empty());
  require_same_mesh(m, read_text(one_line, Format::Off));
  CHECK(m.num_faces() == 2);
  // A face colour follows the last index, on its line.
  const Mesh c = read_text(head + "4 0 1\n2 3 255 0 0\n3 1 4 2 0 255 0\n", Format::Off);
  require_same_mesh(c, read_text(head + "4 0 1 2 3 255 0 0\n3 1 4 2 0 255 0\n", Format::Off));
  CHECK(c.face_colors == std::vector<float>{1, 0, 0, 0, 1, 0});
  // A face whose indices run out at the end of the file still names the line and the count.
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Off, nullptr, "m.off"); }); };
  CHECK(err(head + "4 0 1 2 3\n3 1\n4\n") == "m.off:9: face line has 2 indices, its size says 3");
  CHECK(err(head + "4 0 1 2 3\n3 1\n4\n\n# end\n") == "m.off:9: face line has 2 indices, its size says 3");
  CHECK(err(head + "4 0 1 2 3\n9 1 2\n").find("m.off:9: face line has fewer indices than its size 9") == 0);
}

namespace {
// Binary OFF bytes written by the test, word by word, in one of the four layouts.
struct BinaryOff {
  bool big_endian = true;
  bool face_color_count = true;  // Geomview's ncolors after each face's indices (pmp-library writes none)
  std::string bytes;
  void word(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes += char(big_endian ? (v >> (24 - 8 * i)) & 0xff : (v >> (8 * i)) & 0xff);
  }
  void f32(float x) {
    std::uint32_t v;
    std::memcpy(&v, &x, 4);
    word(v);
  }
};
}  // namespace

TEST_CASE("Binary OFF (Geomview's big-endian layout and pmp-library's, either byte order) reads as the same text OFF",
          "[off][xcorpus6]") {
  // A square of two faces, one of them a quad, and a 2-index line that is no face; the truth is the
  // same mesh written as text OFF, and the literal values the test put into the bytes.
  const float P[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1f}, {0, 1, 0}, {2, 0.5f, -0.25f}};
  const std::string text = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0.1\n0 1 0\n2 0.5 -0.25\n4 0 1 2 3\n2 0 4\n3 1 4 2\n";
  const Mesh truth = read_text(text, Format::Off);
  for (bool big : {true, false})
    for (bool counts : {true, false}) {
      BinaryOff b{big, counts, "OFF BINARY\n"};
      b.word(5), b.word(3), b.word(0);
      for (auto& p : P) b.f32(p[0]), b.f32(p[1]), b.f32(p[2]);
      for (std::vector<std::uint32_t> f : {std::vector<std::uint32_t>{0, 1, 2, 3}, {0, 4}, {1, 4, 2}}) {
        b.word(std::uint32_t(f.size()));
        for (auto i : f) b.word(i);
        if (counts) b.word(0);
      }
      ReadInfo info;
      const Mesh m = read_text(b.bytes, Format::Off, &info, "b.off");
      INFO("big-endian " << big << ", colour counts " << counts);
      CHECK(m.face_start == std::vector<std::uint32_t>{0, 4, 7});
      CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 3, 1, 4, 2});
      CHECK(m.positions[8] == double(0.1f));
      CHECK(m.positions[14] == -0.25);
      CHECK(m.precision == ValuePrecision::Float);
      CHECK(m.num_vertices() == truth.num_vertices());
      for (std::size_t i = 0; i < m.positions.size(); ++i) CHECK(float(m.positions[i]) == float(truth.positions[i]));
      CHECK(m.face_start == truth.face_start);
      CHECK(m.corner_vertex == truth.corner_vertex);
      // Notes: the skipped 2-index line, and which layout when it is not Geomview's.
      CHECK(info.notes.size() == (big && counts ? 1u : 2u));
      CHECK(info.notes.back().find("skipped 1 faces with fewer than 3 vertices") == 0);
    }
}

TEST_CASE("Binary CNOFF: normals, rgba vertex colours and rgb face colours as floats (Geomview's layout)", "[off][xcorpus6]") {
  BinaryOff b{true, true, "CNOFF BINARY\r\n"};
  b.word(3), b.word(1), b.word(3);
  const float V[3][10] = {{0, 0, 0, 0, 0, 1, 1, 0, 0, 0.5f}, {1, 0, 0, 0, 0, 1, 0, 1, 0, 1}, {0, 1, 0, 0.6f, 0, 0.8f, 0, 0, 1, 1}};
  for (auto& v : V)
    for (float x : v) b.f32(x);
  b.word(3), b.word(0), b.word(1), b.word(2), b.word(3), b.f32(0.25f), b.f32(0.5f), b.f32(0.75f);
  const Mesh m = read_text(b.bytes, Format::Off);
  CHECK(m.vertex_normals == std::vector<double>{0, 0, 1, 0, 0, 1, double(0.6f), 0, double(0.8f)});
  CHECK(m.color_channels == 4);  // one vertex alpha is 0.5
  CHECK(m.vertex_colors == std::vector<float>{1, 0, 0, 0.5f, 0, 1, 0, 1, 0, 0, 1, 1});
  CHECK(m.face_colors == std::vector<float>{0.25f, 0.5f, 0.75f, 1});
  CHECK(m.colors_are_float);
  // The same body one byte short fits no layout: one line naming the file and the byte.
  const std::string cut = b.bytes.substr(0, b.bytes.size() - 1);
  const std::string e = error_of([&] { read_text(cut, Format::Off, nullptr, "c.off"); });
  CHECK(e.find("c.off: binary OFF: byte ") == 0);
  // Counts larger than the bytes are refused before any allocation.
  BinaryOff big{true, true, "OFF BINARY\n"};
  big.word(0x7fffffff), big.word(1), big.word(0);
  CHECK(error_of([&] { read_text(big.bytes, Format::Off, nullptr, "h.off"); }).find(
            "h.off: binary OFF: byte 23: the counts (2147483647 vertices, 1 faces) need more bytes than the file holds") == 0);
}

TEST_CASE("pmp-library's beetle.off (binary OFF, little-endian, no face colour counts) as Python's struct reads it",
          "[off][xcorpus6][corpus]") {
  // Truth: the file read with Python's struct.unpack ('<3i', then '<f' and '<i' words) outside
  // shadetool: 5105 vertices, 9664 triangles, the body ending exactly at the file's end.
  ReadInfo info;
  const Mesh m = read_mesh(data_path("corpus_extra/pmp_beetle_binary.off"), Format::Auto, &info);
  REQUIRE(m.num_vertices() == 5105);
  REQUIRE(m.num_faces() == 9664);
  CHECK(m.positions[0] == 1.4375);
  CHECK(m.positions[1] == double(12.78439998626709f));
  CHECK(m.positions[3 * 5104 + 2] == double(-30.760900497436523f));
  CHECK(std::vector<std::uint32_t>(m.corner_vertex.begin(), m.corner_vertex.begin() + 3) == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(std::vector<std::uint32_t>(m.corner_vertex.end() - 3, m.corner_vertex.end()) == std::vector<std::uint32_t>{5089, 5103, 5094});
  std::uint64_t index_sum = 0;
  for (auto i : m.corner_vertex) index_sum += i;
  CHECK(index_sum == 74547235u);
  double sy = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) sy += m.positions[3 * v + 1];
  CHECK(sy == Approx(154646.52290439606).epsilon(1e-12));
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "binary OFF read in little-endian without face colour counts (pmp-library before 3.0)");
}
