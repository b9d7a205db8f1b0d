// Tests of io/ply_format: ascii and both binary byte orders built by hand here (not by our
// writer), every count/index type, skipped elements and properties, colours, face attributes,
// bounded counts and the error messages.
#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

// Appends a value's bytes in the chosen byte order.
struct Bytes {
  std::string s;
  bool big = false;
  template <class T>
  Bytes& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof v);
    const std::uint16_t one = 1;
    char host_little;
    std::memcpy(&host_little, &one, 1);
    if (big == (host_little == 1)) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
};

}  // namespace

TEST_CASE("PLY ascii: positions, normals, uchar colours with alpha, face colours and normals, skipped parts", "[ply]") {
  const std::string text =
      "ply\n"
      "format ascii 1.0\n"
      "comment made by hand\n"
      "obj_info nothing\n"
      "element vertex 4\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "property float quality\n"
      "property float nx\n"
      "property float ny\n"
      "property float nz\n"
      "property uchar red\n"
      "property uchar green\n"
      "property uchar blue\n"
      "property uchar alpha\n"
      "property list uchar int extra\n"
      "element material 2\n"
      "property list uint float values\n"
      "element face 2\n"
      "property list uchar uint vertex_index\n"
      "property double nx\n"
      "property double ny\n"
      "property double nz\n"
      "property uchar red\n"
      "property uchar green\n"
      "property uchar blue\n"
      "end_header\n"
      "0 0 0 7 0 0 1 255 0 0 255 0\n"
      "1 0 0 7 0 0 1 0 255 0 128 2 5 6\n"
      "1 1 0 7 0 0 1 0 0 255 0 1 9\n"
      "0.5 0.25 0.125 7 0 0 1 51 102 153 255 0\n"
      "3 1.5 2.5 3.5\n"
      "0\n"
      "3 0 1 2 0 0 1 10 20 30\n"
      "4 0 1 2 3 0.6 0 0.8 255 255 255\n";
  ReadInfo info;
  Mesh m = read_text(text, Format::Ply, &info);
  CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5, 0.25, 0.125});
  CHECK(m.vertex_normals == std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  CHECK(m.color_channels == 4);
  CHECK(!m.colors_are_float);
  CHECK(m.vertex_colors[0] == 1.0f);
  CHECK(m.vertex_colors[7] == 128.0f / 255.0f);
  CHECK(m.vertex_colors[12] == 51.0f / 255.0f);
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 7});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2, 3});
  // face nx ny nz declared double: kept in double
  CHECK(m.precision == ValuePrecision::Double);
  CHECK(m.face_normals == std::vector<double>{0, 0, 1, 0.6, 0, 0.8});
  REQUIRE(m.face_colors.size() == 8);
  CHECK(m.face_colors[0] == 10.0f / 255.0f);
  CHECK(m.face_colors[3] == 1.0f);  // no face alpha: opaque
  REQUIRE(info.notes.size() == 2);  // the vertex list property and the unknown element, each named
  CHECK(info.notes[0] == "vertex list property 'extra' not kept (only scalar properties are)");
  CHECK(info.notes[1] == "skipped 2 'material' elements");
  CHECK(m.comments == std::vector<std::string>{"comment made by hand", "obj_info nothing"});
}

TEST_CASE("PLY binary: little- and big-endian with mixed count and index types", "[ply]") {
  for (bool big : {false, true}) {
    Bytes b;
    b.big = big;
    b.s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
          " 1.0\n"
          "element vertex 4\n"
          "property double x\nproperty double y\nproperty double z\n"
          "property short flags\n"
          "property float red\nproperty float green\nproperty float blue\n"
          "element edge 1\nproperty int a\nproperty int b\n"
          "element face 2\n"
          "property list ushort ushort vertex_indices\n"
          "property list int float texcoord\n"
          "end_header\n";
    const double P[4][3] = {{0.1, 0.2, 0.3}, {1, 0, 0}, {1, 1, 0}, {-1e-300, 1e300, 0}};
    for (auto& p : P) {
      b.put(p[0]).put(p[1]).put(p[2]).put<std::int16_t>(-7).put(0.25f).put(0.5f).put(1.0f);
    }
    b.put<std::int32_t>(0).put<std::int32_t>(1);
    b.put<std::uint16_t>(3).put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(2);
    b.put<std::int32_t>(6);
    for (float t : {0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 1.0f}) b.put(t);
    b.put<std::uint16_t>(4).put<std::uint16_t>(3).put<std::uint16_t>(2).put<std::uint16_t>(1).put<std::uint16_t>(0);
    b.put<std::int32_t>(8);
    for (float t : {0.5f, 0.5f, 0.25f, 0.25f, 0.125f, 0.125f, 0.0f, 1.0f}) b.put(t);
    ReadInfo info;
    Mesh m = read_text(b.s, Format::Ply, &info);
    CHECK(m.precision == ValuePrecision::Double);
    CHECK(m.positions == std::vector<double>{0.1, 0.2, 0.3, 1, 0, 0, 1, 1, 0, -1e-300, 1e300, 0});
    CHECK(m.colors_are_float);
    CHECK(m.vertex_colors == std::vector<float>{0.25f, 0.5f, 1, 0.25f, 0.5f, 1, 0.25f, 0.5f, 1, 0.25f, 0.5f, 1});
    CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 3, 2, 1, 0});
    CHECK(m.texcoords == std::vector<double>{0, 0, 1, 0, 1, 1, 0.5, 0.5, 0.25, 0.25, 0.125, 0.125, 0, 1});
    CHECK(m.corner_texcoord_index == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6});
  }
}

TEST_CASE("PLY binary float: values are the stored floats, bitwise", "[ply]") {
  Bytes b;
  b.s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float v[9] = {0.1f, 0.2f, 0.3f, 1e-40f /* subnormal */, -0.0f, 3.4e38f, 1, 1, 1};
  for (float x : v) b.put(x);
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  Mesh m = read_text(b.s, Format::Ply);
  CHECK(m.precision == ValuePrecision::Float);
  for (int i = 0; i < 9; ++i) {
    const float back = float(m.positions[std::size_t(i)]);
    CHECK(std::memcmp(&back, &v[i], sizeof back) == 0);
  }
}

TEST_CASE("PLY ascii declared float: values kept as parsed; binary float output narrows them", "[ply][precision]") {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "123456.789 0.1 -7.65432109\n1.00000001 0 0\n0 16777217 0\n3 0 1 2\n";
  const Mesh m = read_text(text, Format::Ply);
  CHECK(m.precision == ValuePrecision::Float);  // declared float: binary output uses float
  CHECK(m.positions == std::vector<double>{123456.789, 0.1, -7.65432109, 1.00000001, 0, 0, 0, 16777217, 0});
  WriteOptions o;
  o.format = Format::Ply;
  o.binary = false;
  const std::string asc = write_mesh_to_memory(m, o);
  CHECK(asc.find("property float x\n") != std::string::npos);
  CHECK(asc.find("\n123456.789 0.1 -7.65432109\n1.00000001 0 0\n0 16777217 0\n") != std::string::npos);
  CHECK(read_text(asc, Format::Ply).positions == m.positions);
  // binary float properties hold floats: 123456.789 -> 123456.7890625 (spacing 2^-7 there),
  // 1.00000001 -> 1, 16777217 -> 16777216 (2^24 + 1 needs 25 bits)
  o.binary = true;
  const Mesh b = read_text(write_mesh_to_memory(m, o), Format::Ply);
  CHECK(b.positions[0] == 123456.7890625);
  CHECK(b.positions[3] == 1.0);
  CHECK(b.positions[7] == 16777216.0);
}

TEST_CASE("PLY writer: binary by default, ascii on request, value and colour types follow the mesh", "[ply]") {
  Mesh m = rich_mesh();
  WriteOptions o;
  o.format = Format::Ply;
  WriteInfo wi;
  const std::string bin = write_mesh_to_memory(m, o, &wi);
  CHECK(bin.find("format binary_little_endian 1.0\n") != std::string::npos);
  CHECK(bin.find("property float x\n") != std::string::npos);
  CHECK(bin.find("property uchar red\n") != std::string::npos);
  CHECK(bin.find("property list uchar int vertex_indices\n") != std::string::npos);
  CHECK(bin.find("property list uchar float texcoord\n") != std::string::npos);
  o.binary = false;
  m.precision = ValuePrecision::Double;
  m.colors_are_float = true;
  const std::string asc = write_mesh_to_memory(m, o);
  CHECK(asc.find("format ascii 1.0\n") != std::string::npos);
  CHECK(asc.find("property double x\n") != std::string::npos);
  CHECK(asc.find("property float red\n") != std::string::npos);
}

TEST_CASE("PLY: corner normals are split into vertices on write", "[ply]") {
  Mesh m = rich_mesh();
  WriteOptions o;
  o.format = Format::Ply;
  WriteInfo wi;
  const std::string bytes = write_mesh_to_memory(m, o, &wi);
  // distinct (vertex, normal) pairs: v0 {0}, v1 {0,2}, v2 {0,2}, v3 {0,2}, v4 {1}, v5 {1,2}, v6 {0}
  CHECK(wi.split_vertices == 4);
  Mesh back = read_text(bytes, Format::Ply);
  CHECK(back.num_vertices() == 11);
  REQUIRE(back.has_vertex_normals());
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    CHECK(back.position(back.corner_vertex[c]) == m.position(m.corner_vertex[c]));
    CHECK(get3(back.vertex_normals, back.corner_vertex[c]) == get3(m.corner_normals, m.corner_normal_index[c]));
  }
}

TEST_CASE("PLY: bad input is refused with FILE:LINE messages, never a huge allocation", "[ply][errors]") {
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Ply, nullptr, "m.ply"); }); };
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").empty());
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") == "m.ply:13: face 0 of 1: vertex index 3 out of range (3 vertices)");
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n") == "m.ply:13: face 0 of 1: vertex index -1 out of range (3 vertices)");
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 0\n") == "m.ply:13: file ends early, in a face list count");
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n") ==
        "m.ply:14: more data than the header declares ('3' after the last element)");
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n").empty());  // NaN is read, info reports it
  CHECK(err(head + "0 0 0\n1 0 0\n0 1 0.0.1\n3 0 1 2\n") == "m.ply:12: malformed number '0.0.1' in vertex data");
  CHECK(err("ply\nformat ascii 1.0\nelement vertex 3\n") == "m.ply:3: PLY header has no end_header");
  CHECK(err("plyx\n") == "m.ply:1: not a PLY file (first line is not 'ply')");
  CHECK(err("ply\nformat binary_middle_endian 1.0\nend_header\n") == "m.ply:2: unknown PLY format 'binary_middle_endian'");
  CHECK(err("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n") == "m.ply:4: unknown property type 'quad'");
  CHECK(err("ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nproperty float z\nend_header\n0 0\n") ==
        "m.ply:3: vertex element has no x, y and z properties");
  // A header claiming 2^40 vertices fails before allocating anything.
  const std::string huge = "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\nproperty float x\n"
                           "property float y\nproperty float z\nend_header\n" + std::string(120, '\0');
  CHECK(err(huge) == "m.ply:3: header claims 1099511627776 vertex elements but only 120 bytes of data follow");
  CHECK(err("ply\nformat ascii 1.0\nelement vertex 1099511627776\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n0 0 0\n")
            .find("m.ply:3: header claims 1099511627776 vertex elements") == 0);
}

TEST_CASE("PLY binary: truncated bodies and counts that disagree with the body", "[ply][errors]") {
  auto err = [](const std::string& text) { return error_of([&] { read_text(text, Format::Ply, nullptr, "m.ply"); }); };
  Bytes b;
  b.s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) b.put(float(i));
  const std::string vertices_only = b.s;
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  CHECK(err(b.s).empty());
  CHECK(err(b.s.substr(0, b.s.size() - 2)) == "m.ply: file is truncated: it ends in face 0 of 1");
  CHECK(err(vertices_only.substr(0, vertices_only.size() - 5)) ==
        "m.ply:3: header claims 3 vertex elements but only 31 bytes of data follow");
  CHECK(err(b.s + std::string("\x01\x02", 2)) == "m.ply: 2 bytes after the last element: the header counts disagree with the body");
  CHECK(err(b.s + "\n").empty());  // a trailing newline is tolerated
  // a list count far beyond the bytes left
  Bytes c;
  c.s = vertices_only;
  c.put<std::uint8_t>(200).put<std::int32_t>(0);
  CHECK(err(c.s) == "m.ply: file is truncated: it ends in face 0 of 1");
}

TEST_CASE("PLY binary fast paths: triangles then a quad, both byte orders, errors mid-stream", "[ply]") {
  for (bool big : {false, true}) {
    Bytes b;
    b.big = big;
    b.s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
          " 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < 15; ++i) b.put(float(i) * 0.5f);
    const std::string vertices = b.s;
    b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    b.put<std::uint8_t>(4).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2).put<std::int32_t>(3);
    b.put<std::uint8_t>(3).put<std::int32_t>(2).put<std::int32_t>(3).put<std::int32_t>(4);
    b.put<std::uint8_t>(3).put<std::int32_t>(4).put<std::int32_t>(3).put<std::int32_t>(0);
    Mesh m = read_text(b.s, Format::Ply);
    CHECK(m.positions[3] == 1.5);
    CHECK(m.positions[14] == 7.0);
    CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 7, 10, 13});
    CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2, 3, 2, 3, 4, 4, 3, 0});
    // an index out of range after good triangles is reported for its face
    Bytes c;
    c.big = big;
    c.s = vertices;
    c.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    c.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(5).put<std::int32_t>(2);
    c.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(-1).put<std::int32_t>(2);
    c.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    CHECK(error_of([&] { read_text(c.s, Format::Ply, nullptr, "m.ply"); }) ==
          "m.ply: face 1 of 4: vertex index 5 out of range (5 vertices)");
  }
}

TEST_CASE("PLY tristrips: -1 restarts a strip, odd triangles wind like the first, joins are dropped with a note",
          "[ply][issue27]") {
  // issue 27, item 9: Stanford's Cyberware-era files (igea.ply) hold `element tristrips`; it was
  // skipped and the file read as a point cloud. Strip 0 1 2 3 4 is the triangles (0 1 2), (2 1 3),
  // (2 3 4) (the second reordered: a strip alternates its winding); -1 starts strip 5 6 7. The
  // truth: on a flat zig-zag every kept triangle's normal points the same way as the first's.
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
      "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n5 0 0\n5 1 0\n6 0 0\n";
  ReadInfo info;
  Mesh m = read_text(head + "11 0 1 2 3 4 -1 5 6 7 7 7\n", Format::Ply, &info, "s.ply");
  CHECK(m.face_start == std::vector<std::uint32_t>{0, 3, 6, 9, 12});
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4, 5, 6, 7});
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const Vec3d a = m.position(m.corner_vertex[3 * f]), b = m.position(m.corner_vertex[3 * f + 1]),
                c = m.position(m.corner_vertex[3 * f + 2]);
    CHECK(cross(b - a, c - a).z < 0);  // (0 1 2) winds clockwise seen from +z; so does every other
  }
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "triangle strips ('tristrips'): 2 strips read as 4 triangles, winding as the first of each strip "
                         "(as MeshLab reads them); 2 triangles with a repeated index (strip joins, no area) not kept");
  // An index beyond the vertices (other than -1) is an error naming the strip.
  CHECK(error_of([&] { read_text(head + "4 0 1 2 8\n", Format::Ply, nullptr, "s.ply"); }) ==
        "s.ply:18: tristrips 0 of 1: vertex index 8 out of range (8 vertices; -1 restarts a strip)");
}

TEST_CASE("PLY: faces in an element the reader does not take are an error, not a point cloud", "[ply][issue27]") {
  // issue 27, item 9: "no command may exit 0 on an input it could not use".
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element polygon 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  CHECK(error_of([&] { read_text(text, Format::Ply, nullptr, "p.ply"); }) ==
        "p.ply:7: element 'polygon' holds 1 faces (list vertex_indices) that shadetool does not read (it reads 'face', "
        "and 'tristrips' when there is no face element): nothing usable");
}

TEST_CASE("PLY: every element skipped is named in a note, fixed-size binary ones too", "[ply][issue27]") {
  // issue 27, item 10: Artec's pepper.ply has multi_texture_vertex (fixed-size records, skipped in
  // one jump) and multi_texture_face (lists); only the second was named.
  Bytes b;
  b.s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\n"
        "element multi_texture_vertex 2\nproperty uchar tx\nproperty float u\nproperty float v\n"
        "element multi_texture_face 1\nproperty uchar tx\nproperty list uchar int texture_vertex_indices\nend_header\n";
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b.put(x);
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  for (int i = 0; i < 2; ++i) b.put<std::uint8_t>(0).put(0.5f).put(0.25f);
  b.put<std::uint8_t>(0).put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(1);
  ReadInfo info;
  read_text(b.s, Format::Ply, &info);
  CHECK(info.notes == std::vector<std::string>{"skipped 2 'multi_texture_vertex' elements", "skipped 1 'multi_texture_face' elements"});
}

TEST_CASE("PLY: per-vertex texture coordinates stay per vertex under their names when no vertex needs a split",
          "[ply][issue27]") {
  // issue 27, item 12: Blender writes `s t`, MeshLab `texture_u texture_v`; both read only per-vertex
  // coordinates, and a per-face `texcoord` list came out (Blender: no UV layer; MeshLab refused quads).
  for (const std::string names : {"s t", "texture_u texture_v", "u v"}) {
    const std::string u = names.substr(0, names.find(' ')), v = names.substr(names.find(' ') + 1);
    const std::string text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                             "property float " + u + "\nproperty float " + v + "\nelement face 1\n"
                             "property list uchar int vertex_indices\nend_header\n"
                             "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0.25 1\n4 0 1 2 3\n";
    Mesh m = read_text(text, Format::Ply);
    WriteOptions o;
    o.format = Format::Ply;
    o.binary = false;
    const std::string out = write_mesh_to_memory(m, o);
    CHECK(out.find("property float " + u + "\nproperty float " + v + "\n") != std::string::npos);
    CHECK(out.find("texcoord") == std::string::npos);
    CHECK(out.find("0 1 0 0.25 1\n") != std::string::npos);
    // Read back: the same coordinates at the same corners.
    Mesh back = read_text(out, Format::Ply);
    CHECK(back.texcoords == m.texcoords);
    CHECK(back.corner_texcoord_index == m.corner_texcoord_index);
  }
  // When a vertex's corners disagree (a seam made by another step), the per-corner list is kept.
  Mesh m = read_text("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                     "property float s\nproperty float t\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                     "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n",
                     Format::Ply);
  m.texcoords.insert(m.texcoords.end(), {0.5, 0.5});
  m.corner_texcoord_index[3] = 4;  // vertex 0 in the second face: another coordinate
  WriteOptions o;
  o.format = Format::Ply;
  o.binary = false;
  const std::string out = write_mesh_to_memory(m, o);
  CHECK(out.find("property list uchar float texcoord\n") != std::string::npos);
  CHECK(out.find("property float s\n") == std::string::npos);
}

TEST_CASE("PLY tristrips: Stanford's igea.ply (corpus) reads as one closed, consistently wound surface", "[ply][issue27][corpus]") {
  // The truth is the surface's own: a closed genus-0 triangle mesh has F = 2V - 4 faces, and strips
  // read with the wrong alternation would leave every second triangle against its neighbours.
  const std::string path = "/work/shared/corpus/c3d/igea/igea.ply";
  if (!std::ifstream(path).good()) {
    WARN("corpus file " << path << " not here: skipped");
    return;
  }
  const Run r = run_cli("info --json " + path);
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out)["stats"];
  CHECK(j["vertices"] == 134345);
  CHECK(j["faces"] == 2 * 134345 - 4);
  CHECK(j["inconsistent_edges"] == 0);
  CHECK(j["closed_manifold"] == true);
}

TEST_CASE("PLY ascii: items whose lines hold values past the header's properties read as ply.c reads them (line mode), one note",
          "[ply][xcorpus]") {
  // VCGLIB's ascii writer (trimesh's fuze_ascii.ply) puts values after the declared ones on every
  // face line. The truth: the same file without those values, which the token reading reads. The
  // skipped `edge` element comes before the faces, so the failed token reading has noted it
  // before it fails: that note must not be left twice.
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
                           "element face 2\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
                           "property uchar blue\nend_header\n";
  const std::string clean = head + "0 0 0\n1 0 0\n0 1 0\n0 1\n3 0 1 2 255 0 0\n3 2 1 0 0 255 0\n";
  const std::string extra = head + "0 0 0\n1 0 0\n0 1 0\n0 1\n3 0 1 2 255 0 0 1 1 1 1 1 1\n\n3 2 1 0 0 255 0 9\n";
  ReadInfo clean_info, extra_info;
  const Mesh want = read_text(clean, Format::Ply, &clean_info);
  const Mesh got = read_text(extra, Format::Ply, &extra_info, "m.ply");
  require_same_mesh(got, want);
  REQUIRE(clean_info.notes == std::vector<std::string>{"skipped 1 'edge' elements"});
  CHECK(extra_info.notes == std::vector<std::string>{
                                "skipped 1 'edge' elements",
                                "2 face lines hold values beyond the header's properties (first: line 20): ignored, as the "
                                "PLY reference reader (ply.c) reads them"});
  // Vertex lines too, one note per element.
  ReadInfo vertex_info;
  const Mesh v = read_text(head + "0 0 0 5 5\n1 0 0\n0 1 0 5\n0 1\n3 0 1 2 255 0 0 1\n3 2 1 0 0 255 0\n", Format::Ply, &vertex_info);
  require_same_mesh(v, want);
  CHECK(vertex_info.notes == std::vector<std::string>{
                                 "skipped 1 'edge' elements",
                                 "2 vertex lines hold values beyond the header's properties (first: line 16): ignored, as the "
                                 "PLY reference reader (ply.c) reads them",
                                 "1 face line holds values beyond the header's properties (first: line 20): ignored, as the "
                                 "PLY reference reader (ply.c) reads them"});
  // An item spread over lines is still read by tokens (the format's rule), with no note.
  ReadInfo spread_info;
  const Mesh spread = read_text(head + "0 0\n0\n1 0 0\n0 1 0\n0\n1\n3 0 1 2\n255 0 0\n3 2 1 0 0 255 0\n", Format::Ply, &spread_info);
  require_same_mesh(spread, want);
  CHECK(spread_info.notes == clean_info.notes);
  // When both readings fail, the token reading's error is raised (index 3: the token reading took
  // the first face line's extra `9` as the next face's count; the line reading fails on index 7),
  // and neither reading's notes are left.
  ReadInfo bad_info;
  CHECK(error_of([&] { read_text(head + "0 0 0\n1 0 0\n0 1 0\n0 1\n3 0 1 2 255 0 0 9\n3 0 1 7 0 0 0\n", Format::Ply, &bad_info, "m.ply"); }) ==
        "m.ply:21: face 1 of 2: vertex index 3 out of range (3 vertices)");
  CHECK(bad_info.notes.empty());
}

namespace {

// One face record of the short-face tests: indices, then (rich layout) nx ny nz, red green blue
// alpha, quality, an int `flags`, and MeshLab's texcoord list (u v per corner).
struct FaceRecord {
  std::vector<int> idx;
  double n[3];
  int rgba[4];
  float quality;
  int flags;
};

// A PLY of 5 vertices and the given face records, in `format` (ascii, binary_little_endian,
// binary_big_endian); rich: with every face property above, else only the index list (the binary
// reader's triangle fast path). Written here, record by record, not by the writer under test.
std::string ply_with_faces(const std::string& format, bool rich, const std::vector<FaceRecord>& faces) {
  std::string h = "ply\nformat " + format + " 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face " + std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\n";
  if (rich)
    h += "property list uchar float texcoord\nproperty float nx\nproperty float ny\nproperty float nz\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
         "property float quality\nproperty int flags\n";
  h += "end_header\n";
  const float xyz[15] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1};
  const bool ascii = format == "ascii";
  Bytes b;
  b.big = format == "binary_big_endian";
  b.s = h;
  auto num = [&](auto v, auto as) {
    if (ascii) b.s += std::to_string(v) + " ";
    else b.put(decltype(as)(v));
  };
  for (int v = 0; v < 5; ++v) {
    for (int k = 0; k < 3; ++k) num(xyz[3 * v + k], float());
    if (ascii) b.s += "\n";
  }
  for (const FaceRecord& f : faces) {
    num(int(f.idx.size()), std::uint8_t());
    for (int i : f.idx) num(i, std::int32_t());
    if (rich) {
      num(int(2 * f.idx.size()), std::uint8_t());
      for (std::size_t c = 0; c < f.idx.size(); ++c) {
        num(0.25f * float(f.idx[c]), float());
        num(0.125f * float(c) + float(f.flags), float());
      }
      for (double x : f.n) num(float(x), float());
      for (int c : f.rgba) num(c, std::uint8_t());
      num(f.quality, float());
      num(f.flags, std::int32_t());
    }
    if (ascii) b.s += "\n";
  }
  return b.s;
}

}  // namespace

TEST_CASE("PLY: a face of 0, 1 or 2 vertices is skipped with its properties, leaving the mesh as if the record were absent",
          "[ply][xcorpus]") {
  // Faces with distinct values in every property, so that a value shifted to the wrong face shows.
  const std::vector<FaceRecord> all = {
      {{0, 1, 2}, {0, 0, 1}, {255, 0, 0, 255}, 1.5f, 10},
      {{1, 3}, {1, 0, 0}, {0, 255, 0, 128}, 2.5f, 20},       // 2 vertices
      {{0, 2, 3, 4}, {0, 1, 0}, {0, 0, 255, 255}, 3.5f, 30},
      {{4}, {0, 0, -1}, {9, 9, 9, 9}, 4.5f, 40},             // 1 vertex
      {{}, {0, -1, 0}, {7, 7, 7, 7}, 5.5f, 50},              // none
      {{2, 3, 4}, {-1, 0, 0}, {10, 20, 30, 40}, 6.5f, 60},
  };
  std::vector<FaceRecord> kept;
  for (const FaceRecord& f : all)
    if (f.idx.size() >= 3) kept.push_back(f);
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"})
    for (bool rich : {true, false}) {
      INFO(format << (rich ? ", every face property" : ", indices only"));
      ReadInfo info, kept_info;
      const Mesh m = read_text(ply_with_faces(format, rich, all), Format::Ply, &info);
      const Mesh want = read_text(ply_with_faces(format, rich, kept), Format::Ply, &kept_info);
      require_same_mesh(m, want);
      REQUIRE(want.num_faces() == 3);
      if (rich) {  // the properties read are the kept records' (not only equal to the other reading's)
        CHECK(want.face_properties.size() == 1);
        CHECK(want.face_properties[0].values == std::vector<double>{10, 30, 60});
        CHECK(want.face_quality == std::vector<float>{1.5f, 3.5f, 6.5f});
      }
      REQUIRE(info.notes.size() == kept_info.notes.size() + 1);
      CHECK(info.notes.back() ==
            "skipped 3 of 6 'face' elements with fewer than 3 vertex indices (not a face), with their properties");
    }
  // Binary triangles (the fast path) with a short face after some of them and at the start.
  for (const auto& order : std::vector<std::vector<int>>{{0, 5, 1, 0}, {1, 0, 5, 5}}) {
    std::vector<FaceRecord> tri, tri_kept;
    for (int k : order) tri.push_back(all[std::size_t(k)]);
    for (const FaceRecord& f : tri)
      if (f.idx.size() == 3) tri_kept.push_back(f);
    ReadInfo info;
    require_same_mesh(read_text(ply_with_faces("binary_little_endian", false, tri), Format::Ply, &info),
                      read_text(ply_with_faces("binary_little_endian", false, tri_kept), Format::Ply));
    CHECK(info.notes.size() == 1);
  }
  // Only short faces: the vertices are read, no face (a point cloud), with the note.
  ReadInfo none_info;
  const Mesh none = read_text(ply_with_faces("ascii", true, {all[1], all[3]}), Format::Ply, &none_info);
  CHECK(none.num_vertices() == 5);
  CHECK(none.num_faces() == 0);
  CHECK(none.face_colors.empty());
  CHECK(none_info.notes == std::vector<std::string>{
                               "skipped 2 of 2 'face' elements with fewer than 3 vertex indices (not a face), with their properties"});
  // An index out of range is still an error, short face or not.
  CHECK(error_of([&] { read_text(ply_with_faces("ascii", false, {all[0], {{0, 7}, {}, {}, 0, 0}}), Format::Ply, nullptr, "m.ply"); }) ==
        "m.ply:16: face 1 of 2: vertex index 7 out of range (5 vertices)");
}

TEST_CASE("PLY: header lines ending in a lone CR (classic Mac, Rhinoceros 6) read as the same header with LF ends",
          "[ply][xcorpus3]") {
  // Truth: the same bytes with each header line's CR replaced by LF, which every PLY reader reads.
  // The binary body starts right after `end_header` and its CR; its first byte here is 0x0a (the
  // float 0x3f80000a), so a reader that took CR LF as the line end would eat it and misread all.
  auto header = [](const std::string& eol) {
    return "ply" + eol + "format binary_little_endian 1.0" + eol + "comment Rhino" + eol + "element vertex 3" + eol +
           "property float x" + eol + "property float y" + eol + "property float z" + eol + "element face 1" + eol +
           "property list uchar int vertex_indices" + eol + "end_header" + eol;
  };
  Bytes body;
  for (std::uint32_t bits : {0x3f80000au, 0u, 0u, 0u, 0x3f800000u, 0u, 0u, 0u, 0x3f800000u}) {
    float f;
    std::memcpy(&f, &bits, 4);
    body.put(f);
  }
  body.put(std::uint8_t(3)).put(std::int32_t(0)).put(std::int32_t(1)).put(std::int32_t(2));
  const Mesh lf = read_text(header("\n") + body.s, Format::Ply);
  const Mesh cr = read_text(header("\r") + body.s, Format::Ply);
  require_same_mesh(cr, lf);
  CHECK(cr.num_faces() == 1);
  float x0;
  const std::uint32_t bits0 = 0x3f80000au;
  std::memcpy(&x0, &bits0, 4);
  CHECK(cr.positions[0] == double(x0));

  // Ascii with CR lines: the body's lines are the lines an editor shows, also in messages.
  const std::string ascii = "ply\rformat ascii 1.0\relement vertex 3\rproperty float x\rproperty float y\r"
                            "property float z\relement face 1\rproperty list uchar int vertex_indices\rend_header\r";
  const Mesh a = read_text(ascii + "0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r", Format::Ply);
  std::string as_lf = ascii + "0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r";
  std::replace(as_lf.begin(), as_lf.end(), '\r', '\n');
  require_same_mesh(a, read_text(as_lf, Format::Ply));
  CHECK(error_of([&] { read_text(ascii + "0 0 0\r1 0 0\r0 1 0\r3 0 1 3\r", Format::Ply, nullptr, "m.ply"); }) ==
        "m.ply:13: face 0 of 1: vertex index 3 out of range (3 vertices)");
}

TEST_CASE("draco's Box.ply (Rhinoceros 6, CR header lines): 24 vertices, 4 triangles and 4 quads, as assimp reads it",
          "[ply][xcorpus3][corpus]") {
  ReadInfo info;
  const std::string path = data_path("corpus_extra/rhino6_box_cr.ply");
  const Mesh m = read_mesh(path, Format::Auto, &info);
  CHECK(m.num_vertices() == 24);  // assimp info: 24 vertices, 12 faces after triangulating the quads
  CHECK(m.num_faces() == 8);
  std::size_t quads = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) quads += m.face_size(f) == 4;
  CHECK(quads == 4);
  CHECK(m.has_vertex_normals());
  CHECK(m.has_vertex_colors());
  // The file with its header's CRs made LFs (the body untouched) reads the same.
  std::string text = read_file(path);
  const std::size_t body = text.find("end_header\r") + std::strlen("end_header\r");
  std::replace(text.begin(), text.begin() + std::ptrdiff_t(body), '\r', '\n');
  require_same_mesh(m, read_text(text, Format::Ply));
  // A box: every face normal is one of the six axis directions, each written normal unit length.
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double* n = &m.vertex_normals[3 * v];
    CHECK(std::abs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-5);
  }
}
