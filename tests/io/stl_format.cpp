// Tests of io/stl_format: binary and ascii bytes built here, merging of identical positions,
// facet normals, fan triangulation on write, and the error messages.
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/geometry/degenerate_face.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

std::string binary_stl(const std::vector<std::array<float, 12>>& facets, std::uint32_t claimed) {
  std::string s(80, ' ');
  s.replace(0, 5, "solid");  // binary files may start with "solid": the size decides
  char n[4];
  std::memcpy(n, &claimed, 4);  // tests run on little-endian hosts (x86, arm64)
  s.append(n, 4);
  for (auto& f : facets) {
    for (float x : f) {
      char b[4];
      std::memcpy(b, &x, 4);
      s.append(b, 4);
    }
    s.append(2, '\0');
  }
  return s;
}

}  // namespace

TEST_CASE("STL binary: identical positions merge into shared vertices", "[stl]") {
  // two triangles of the unit square sharing the diagonal (0,0,0)-(1,1,0)
  const std::string bytes = binary_stl({{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}}, 2);
  ReadInfo info;
  Mesh m = read_text(bytes, Format::Stl, &info);
  CHECK(m.num_vertices() == 4);
  CHECK(m.num_faces() == 2);
  CHECK(info.merged_vertices == 2);
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "merged 2 corners with identical positions into 4 shared vertices");
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  CHECK(m.face_normals == std::vector<double>{0, 0, 1, 0, 0, 1});
  CHECK(m.precision == ValuePrecision::Float);
}

TEST_CASE("STL: -0 and 0 are one position, NaN is never merged, zero normals are not kept", "[stl]") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string bytes =
      binary_stl({{0, 0, 0, 0, 0, 0, 1, 0, 0, nan, 1, 0}, {0, 0, 0, -0.0f, -0.0f, -0.0f, nan, 1, 0, 1, 0, 0}}, 2);
  ReadInfo info;
  Mesh m = read_text(bytes, Format::Stl, &info);
  CHECK(m.num_vertices() == 4);  // (0,0,0), (1,0,0), two NaN vertices
  CHECK(info.merged_vertices == 2);
  CHECK(!m.has_face_normals());
}

TEST_CASE("STL ascii: facets, several solids, polygons kept, merging", "[stl]") {
  const std::string text =
      "solid one\n"
      "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
      "    endloop\n  endfacet\n"
      "endsolid one\n"
      "solid two\r\n"
      "facet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 1 0\r\nvertex 0 1 0\r\nvertex -1 0.5 0\r\nendloop\r\nendfacet\r\n"
      "endsolid two\r\n";
  ReadInfo info;
  Mesh m = read_text(text, Format::Stl, &info);
  CHECK(m.num_vertices() == 5);
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 7});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4});
  CHECK(info.merged_vertices == 2);
}

TEST_CASE("STL ascii: 9-digit values that are not floats are kept and written back as typed", "[stl][precision]") {
  const std::string text =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 123456.789 0.1 0\nvertex 123457.789 0.1 0\n"
      "vertex 123456.789 1.00000001 0\nendloop\nendfacet\nendsolid s\n";
  const Mesh m = read_text(text, Format::Stl);
  CHECK(m.precision == ValuePrecision::Float);
  CHECK(m.positions == std::vector<double>{123456.789, 0.1, 0, 123457.789, 0.1, 0, 123456.789, 1.00000001, 0});
  WriteOptions o;
  o.format = Format::Stl;
  o.binary = false;
  const std::string out = write_mesh_to_memory(m, o);
  CHECK(out.find("facet normal 0 0 1\nouter loop\nvertex 123456.789 0.1 0\nvertex 123457.789 0.1 0\n"
                 "vertex 123456.789 1.00000001 0\n") != std::string::npos);
  CHECK(read_text(out, Format::Stl).positions == m.positions);
}

TEST_CASE("STL writer: a convex polygon as the fan from corner 0, computed unit normals, binary layout", "[stl]") {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({2, 0, 0});
  m.add_vertex({2, 2, 0});
  m.add_vertex({0, 2, 0});
  m.add_face({0, 1, 2, 3});
  WriteOptions o;
  o.format = Format::Stl;
  WriteInfo wi;
  const std::string bin = write_mesh_to_memory(m, o, &wi);
  REQUIRE(bin.size() == 84 + 2 * 50);
  CHECK(bin.compare(0, 5, "solid") != 0);  // a binary header must not look like ascii
  float first[12];
  std::memcpy(first, bin.data() + 84, sizeof first);
  // normal (0,0,1): cross((2,0,0),(2,2,0)) = (0,0,4), length 4
  CHECK(first[0] == 0.0f);
  CHECK(first[1] == 0.0f);
  CHECK(first[2] == 1.0f);
  CHECK(first[9] == 2.0f);  // third corner of the first fan triangle: (2,2,0)
  REQUIRE(wi.notes.size() == 1);
  CHECK(wi.notes[0] == "split 1 polygons into triangles for STL (ear clipping: inside each outline, in its winding)");
  o.binary = false;
  const std::string text = write_mesh_to_memory(m, o);
  CHECK(text.find("facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 2 2 0\nendloop\nendfacet\n") !=
        std::string::npos);
  Mesh back = read_text(text, Format::Stl);
  CHECK(back.num_vertices() == 4);
  CHECK(back.num_faces() == 2);
}

TEST_CASE("STL writer: a concave polygon is written inside its outline, every facet facing as the polygon", "[stl][polygon_triangles]") {
  // An L of three unit squares in z = 0, counter-clockwise seen from +z, starting at (0,2): the
  // fan from corner 0 put its third triangle, (0,2) (2,1) (1,1), outside the L and turned over.
  // Truth: area 3 (closed form), every facet normal +z, no facet's centroid in the missing square.
  Mesh m;
  for (const auto& p : std::vector<std::array<double, 2>>{{0, 2}, {0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}}) m.add_vertex({p[0], p[1], 0});
  m.add_face({0, 1, 2, 3, 4, 5});
  WriteOptions o;
  o.format = Format::Stl;
  const std::string bin = write_mesh_to_memory(m, o);
  REQUIRE(bin.size() == 84 + 4 * 50);
  double area = 0;
  for (int t = 0; t < 4; ++t) {
    float f[12];
    std::memcpy(f, bin.data() + 84 + 50 * t, sizeof f);
    CHECK(f[0] == 0.0f);
    CHECK(f[1] == 0.0f);
    CHECK(f[2] == 1.0f);  // facing +z, as the polygon
    const double ax = f[6] - f[3], ay = f[7] - f[4], bx = f[9] - f[3], by = f[10] - f[4];
    const double a = (ax * by - ay * bx) / 2;
    CHECK(a > 0);  // wound as the polygon
    area += a;
    const double gx = (f[3] + f[6] + f[9]) / 3, gy = (f[4] + f[7] + f[10]) / 3;
    CHECK(!(gx > 1 && gy > 1));  // not in the square the L leaves out
  }
  CHECK(area == Approx(3.0));
}

TEST_CASE("STL: errors", "[stl][errors]") {
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Stl, nullptr, "m.stl"); }); };
  const std::string good = binary_stl({{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0}}, 1);
  CHECK(err(good).empty());
  CHECK(err(good.substr(0, good.size() - 1)) ==
        "m.stl: binary STL header says 1 triangles (134 bytes) but the file has 133 bytes: truncated or not STL");
  CHECK(err(binary_stl({}, 1000000000)) ==
        "m.stl: binary STL header says 1000000000 triangles (50000000084 bytes) but the file has 84 bytes: truncated or not STL");
  CHECK(err("hello") == "m.stl: not an STL file (too short for binary STL and no 'solid' keyword)");
  CHECK(err("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n") ==
        "m.stl:6: facet has 2 vertices (a face needs at least 3)");
  CHECK(err("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 q\n") == "m.stl:5: malformed number 'q'");
  CHECK(err("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n") == "m.stl:5: file ends inside a facet");
  CHECK(err("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n") ==
        "m.stl:9: file ends inside a solid (no endsolid)");
  CHECK(err("solid x\nfacet normal 0 0 1\nouter lop\n") == "m.stl:3: expected 'loop', found 'lop'");
}

TEST_CASE("STL: a facet with no area written with +z reads back without a note (no winding to be against)",
          "[stl][issue27]") {
  // issue 27, item 13: the writer gives triangles of zero area the facet normal +z (STL has no
  // 'none'); the reader took +z as "against the winding" (3 such in one model) and replaced it by
  // the triangle's own normal, (0,0,0).
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({2, 0, 0});  // collinear with 0 and 1: the second triangle has no area
  m.add_face({0, 1, 2});
  m.add_face({0, 1, 3});
  for (bool binary : {true, false}) {
    WriteOptions o;
    o.format = Format::Stl;
    o.binary = binary;
    WriteInfo wi;
    const std::string bytes = write_mesh_to_memory(m, o, &wi);
    REQUIRE(wi.notes.size() == 1);  // the writer says it wrote +z
    ReadInfo ri;
    Mesh back = read_text(bytes, Format::Stl, &ri);
    REQUIRE(back.num_faces() == 2);
    CHECK(get3(back.face_normals, 1) == Vec3d{0, 0, 1});
    for (const std::string& n : ri.notes) CHECK(n.find("against the winding") == std::string::npos);
    for (const std::string& n : ri.notes) CHECK(n.find("facet normals replaced") == std::string::npos);
  }
}

TEST_CASE("STL: a facet degenerate by the library's rule keeps its authored normal (no noise direction)", "[stl][degenerate]") {
  // The third corner is 1e-15 off the line of the other two: sin(angle) ~ 1e-15 < 64 eps, so info,
  // repair and normals call the facet degenerate (geometry/degenerate_face.h), and its cross
  // product's direction (here +z) is rounding, not a winding. The authored normal (-z) must not be
  // replaced as "against the winding" (it was, before the reader used the rule).
  const std::vector<std::array<float, 12>> facets = {
      {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0},       // a proper triangle, normal +z as authored
      {0, 0, -1, 0, 0, 0, 1, 0, 0, 2, 1e-15f, 0},  // collinear to double precision
  };
  Mesh m;
  REQUIRE(face_degenerate_kind([&] {
            Mesh t;
            t.add_vertex({0, 0, 0});
            t.add_vertex({1, 0, 0});
            t.add_vertex({2, double(1e-15f), 0});
            t.add_face({0, 1, 2});
            return t;
          }(), 0) == DegenerateKind::ZeroArea);
  ReadInfo ri;
  m = read_text(binary_stl(facets, 2), Format::Stl, &ri);
  REQUIRE(m.num_faces() == 2);
  CHECK(get3(m.face_normals, 1) == Vec3d{0, 0, -1});
  for (const std::string& n : ri.notes) CHECK(n.find("against the winding") == std::string::npos);
  // Written without face normals, the degenerate facet gets +z and the writer's note, as one of
  // exactly zero area does, not the direction of its rounding noise.
  Mesh plain = m;
  plain.face_normals.clear();
  WriteOptions o;
  o.format = Format::Stl;
  o.binary = false;
  WriteInfo wi;
  const std::string text = write_mesh_to_memory(plain, o, &wi);
  CHECK(wi.notes.size() == 1);
}

namespace {

// A binary STL of `attributes.size()` copies of one triangle with the given 80-byte header and
// attribute words (little-endian), built byte by byte here.
std::string binary_stl_with_attributes(const std::string& header, const std::vector<std::uint16_t>& attributes) {
  std::string s = header;
  s.resize(80, ' ');
  const std::uint32_t n = std::uint32_t(attributes.size());
  s += std::string{char(n & 0xff), char((n >> 8) & 0xff), char((n >> 16) & 0xff), char(n >> 24)};
  const float tri[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (std::size_t t = 0; t < attributes.size(); ++t) {
    for (float x : tri) {
      char b[4];
      std::memcpy(b, &x, 4);  // tests run on little-endian hosts (x86, arm64)
      s.append(b, 4);
    }
    s += std::string{char(attributes[t] & 0xff), char(attributes[t] >> 8)};
  }
  return s;
}

}  // namespace

TEST_CASE("STL binary: Materialise colours (COLOR= header, bit 15 clear: R G B in bits 0-4, 5-9, 10-14) read as face colours",
          "[stl][color]") {
  // Magics' convention (its "STL colour" documentation, and Wikipedia's STL page): header
  // "COLOR=" + R G B A of the default; per facet bit 15 clear = its own 5-bit colour, R lowest.
  // Expected values are written from that layout by hand: 31 = full, 16 of 31, the default bytes / 255.
  const std::string header = std::string("STLB ATF 12.4.0.73 COLOR=") + char(0xd9) + char(0xd3) + char(0xc9) + char(0xff);
  const std::uint16_t own = std::uint16_t(31 | (0 << 5) | (16 << 10));  // R 31, G 0, B 16, bit 15 clear
  const std::uint16_t use_default = 0x8000;
  ReadInfo info;
  const Mesh m = read_text(binary_stl_with_attributes(header, {own, use_default}), Format::Stl, &info);
  REQUIRE(m.has_face_colors());
  CHECK(m.color_channels == 3);
  CHECK(!m.colors_are_float);
  CHECK(m.face_colors[0] == Approx(1.0));
  CHECK(m.face_colors[1] == Approx(0.0));
  CHECK(m.face_colors[2] == Approx(16.0 / 31.0));
  CHECK(m.face_colors[3] == Approx(0xd9 / 255.0));
  CHECK(m.face_colors[4] == Approx(0xd3 / 255.0));
  CHECK(m.face_colors[5] == Approx(0xc9 / 255.0));
  bool named = false;
  for (const auto& n : info.notes) named = named || n.find("1 facets with their own colour, 1 with the header's default") != std::string::npos;
  CHECK(named);

  // The same bytes through PLY and back: the colours survive as bytes round(v * 255).
  WriteOptions o;
  o.format = Format::Ply;
  const Mesh back = read_text(write_mesh_to_memory(m, o), Format::Ply);
  REQUIRE(back.has_face_colors());
  CHECK(back.face_colors[0] * 255 == Approx(255));
  CHECK(back.face_colors[2] * 255 == Approx(std::round(16.0 / 31.0 * 255)));
}

TEST_CASE("STL binary: attribute bytes without a COLOR= header are not colours, and a note counts them", "[stl][color]") {
  // Meshmixer writes 0xFFFF on every facet, VisCAM B G R with bit 15 set: no marker tells them apart.
  ReadInfo info;
  const Mesh m = read_text(binary_stl_with_attributes("MESHMIXER-STL-BINARY-FORMAT", {0xffff, 0xffff, 0}), Format::Stl, &info);
  CHECK(!m.has_face_colors());
  bool named = false;
  for (const auto& n : info.notes) named = named || n.find("attribute bytes non-zero on 2 of 3 facets") != std::string::npos;
  CHECK(named);
  // All-zero attribute bytes (what most exporters write) say nothing: no note about them.
  ReadInfo plain;
  read_text(binary_stl_with_attributes("plain", {0, 0}), Format::Stl, &plain);
  for (const auto& n : plain.notes) CHECK(n.find("attribute") == std::string::npos);
  // A COLOR= header whose facets all hold 0 would make every facet black: read as no colours, with a note.
  ReadInfo copied;
  const Mesh c = read_text(binary_stl_with_attributes("COLOR=abcd", {0, 0}), Format::Stl, &copied);
  CHECK(!c.has_face_colors());
}

TEST_CASE("STL: an ascii file with a control byte (cut or overwritten) is refused naming the byte's line, not as a binary count",
          "[stl]") {
  // OpenSCAD's tests/data/stl/unparseable.stl: "solid ... facet normal ... vertex 2.000000e+0", then
  // spaces and a 0x10 byte. The line is counted here from the bytes the test builds.
  std::string bytes = "solid cut\n  facet normal 0 0 1\n    outer loop\n      vertex 2.0e+0";
  bytes += std::string(100, ' ');
  bytes += '\x10';
  bytes += "  ";
  const std::string expect_line = std::to_string(1 + std::count(bytes.begin(), bytes.end(), '\n'));  // 4
  const std::string e = error_of([&] { read_text(bytes, Format::Stl, nullptr, "cut.stl"); });
  CHECK(e.rfind("cut.stl:" + expect_line + ": starts with 'solid' (ascii STL) but holds the control byte 0x10", 0) == 0);
  // A binary file whose 80-byte header starts with "solid" keeps the binary message (one line, no facet before its
  // control bytes).
  std::string bin(80, ' ');
  bin.replace(0, 5, "solid");
  bin += std::string("\x01\0\0\0", 4) + std::string(49, '\x01');
  CHECK(error_of([&] { read_text(bin, Format::Stl, nullptr, "m.stl"); }).find("truncated or not STL") != std::string::npos);
}

TEST_CASE("STL: NaN/Inf facet normals (OpenSCAD writes `facet normal nan nan nan` on slivers) become the triangle's own, +z without area",
          "[stl]") {
  // Truth by hand: (0,0,0),(1,0,0),(0,1,0) wound counter-clockwise seen from +z has normal +z; the
  // second triangle (0,0,0),(0,0,1),(1,0,0) has (0,0,1)x(1,0,0) = (0,1,0); the third has no area.
  const std::string text =
      "solid s\n"
      "facet normal nan nan nan\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "facet normal inf -inf 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 1 0 0\nendloop\nendfacet\n"
      "facet normal nan nan nan\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 4 0 0\nendloop\nendfacet\n"
      "endsolid s\n";
  ReadInfo info;
  const Mesh m = read_text(text, Format::Stl, &info);
  REQUIRE(m.has_face_normals());
  CHECK(m.face_normals == std::vector<double>{0, 0, 1, 0, 1, 0, 0, 0, 1});
  bool named = false;
  for (const auto& n : info.notes) named = named || n.find("3 NaN or Inf (+z where no area)") != std::string::npos;
  CHECK(named);
  // The same file with the normals the test computed above written in place of NaN/Inf (the sliver's
  // left NaN: it has none) reads to the same face normals.
  std::string fixed = text;
  fixed.replace(fixed.find("nan nan nan"), 11, "0 0 1");
  fixed.replace(fixed.find("inf -inf 0"), 10, "0 1 0");
  CHECK(read_text(fixed, Format::Stl).face_normals == m.face_normals);
}

TEST_CASE("STL: facet normals in another frame (Meshmixer: (nx, nz, -ny) of the triangle's own) are replaced, whole file",
          "[stl]") {
  // A closed tetrahedron wound outward; each facet's normal computed here by cross product, then
  // written either as is or as Meshmixer writes it (its Y-up frame: every facet of PrusaSlicer's
  // Meshmixer printer beds is exactly (nx, nz, -ny) of its triangle's own).
  const std::array<std::array<float, 3>, 4> p = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const std::array<std::array<int, 3>, 4> tris = {{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  auto facets = [&](bool meshmixer) {
    std::vector<std::array<float, 12>> out;
    for (const auto& t : tris) {
      const auto &a = p[std::size_t(t[0])], &b = p[std::size_t(t[1])], &c = p[std::size_t(t[2])];
      const float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);  // > 0: no face of it is degenerate
      for (float& x : n) x /= len;
      const std::array<float, 3> w = meshmixer ? std::array<float, 3>{n[0], n[2], -n[1]} : std::array<float, 3>{n[0], n[1], n[2]};
      out.push_back({w[0], w[1], w[2], a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]});
    }
    return out;
  };
  ReadInfo clean_info;
  const Mesh clean = read_text(binary_stl(facets(false), 4), Format::Stl, &clean_info);
  REQUIRE(clean.has_face_normals());  // the right normals are kept as read
  CHECK(clean.face_normals[0] == Approx(0.0).margin(1e-7));
  CHECK(clean.face_normals[2] == Approx(-1.0));  // face {0,2,1} lies in z = 0, outward is -z
  ReadInfo info;
  const Mesh m = read_text(binary_stl(facets(true), 4), Format::Stl, &info);
  // Every facet's normal is its triangle's own: the clean file's normals (computed by the test).
  REQUIRE(m.has_face_normals());
  for (std::size_t k = 0; k < 12; ++k) CHECK(m.face_normals[k] == Approx(clean.face_normals[k]).margin(1e-6));
  bool named = false;
  for (const auto& n : info.notes)
    named = named || n.rfind("facet normals replaced by the triangles' own on all 4 facets with area: the median is", 0) == 0;
  CHECK(named);
  CHECK(m.positions == clean.positions);
  CHECK(m.corner_vertex == clean.corner_vertex);
}
