// Tests of files/mesh_files: format names and extensions, file-level errors, and the round trip of a
// mesh with polygons, normals and colours through every format (read, write, read back).
#include <algorithm>
#include <cstring>

#include <shadetool/lighting/lit_normals.h>

#include "io/io_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::iotest;

// WriteOptions for FORMAT, every other field at its default.
static WriteOptions write_as(Format format) {
  WriteOptions o;
  o.format = format;
  return o;
}

TEST_CASE("format names and extensions", "[mesh_io]") {
  CHECK(format_from_extension("a/b.OBJ") == Format::Obj);
  CHECK(format_from_extension("x.ply") == Format::Ply);
  CHECK(format_from_extension("x.off") == Format::Off);
  CHECK(format_from_extension("x.Stl") == Format::Stl);
  CHECK(parse_format_name("PLY", "--format") == Format::Ply);
  CHECK(std::string(format_extension(Format::Off)) == "off");
  CHECK(error_of([] { format_from_extension("mesh.xyz"); }) ==
        "mesh.xyz: unknown mesh format 'xyz' (expected .obj, .ply, .off, .stl or .glb/.gltf)");
  CHECK(error_of([] { format_from_extension("dir.d/mesh"); }) ==
        "dir.d/mesh: no file extension to tell the mesh format (expected .obj, .ply, .off, .stl or .glb/.gltf)");
  CHECK(error_of([] { parse_format_name("3mf", "--format"); }) ==
        "--format: unknown mesh format '3mf' (expected obj, ply, off, stl or gltf)");
}

TEST_CASE("read_mesh: missing file, directory, empty file, unknown extension", "[mesh_io][errors]") {
  ScratchDir dir;
  CHECK(error_of([&] { read_mesh(dir / "none.obj"); }) == dir / "none.obj" + ": cannot open: No such file or directory");
  std::filesystem::create_directory(dir / "d.obj");
  CHECK(error_of([&] { read_mesh(dir / "d.obj"); }) == dir / "d.obj" + ": is a directory, not a mesh file");
  write_file(dir / "empty.ply", "");
  CHECK(error_of([&] { read_mesh(dir / "empty.ply"); }) == dir / "empty.ply" + ": file is empty");
  write_file(dir / "m.txt", "v 0 0 0\n");
  CHECK(error_of([&] { read_mesh(dir / "m.txt"); }) == dir / "m.txt" + ": unknown mesh format 'txt' (expected .obj, .ply, .off, .stl or .glb/.gltf)");
  // an explicit format overrides the extension
  write_file(dir / "m.txt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(read_mesh(dir / "m.txt", Format::Obj).num_faces() == 1);
}

namespace {

// Asserts that `back` holds what `m` held, for the attributes a format carries. Positions and
// normals are compared per corner (writers may split vertices to carry corner normals): bitwise
// after a binary file, by the text contract (same_after_text: floats as floats) after a text file.
enum class Via { Binary, Text };
bool same(const Vec3d& a, const Vec3d& b, Via via) {
  if (via == Via::Binary) return std::memcmp(&a, &b, sizeof a) == 0;
  return same_after_text(a.x, b.x) && same_after_text(a.y, b.y) && same_after_text(a.z, b.z);
}
void check_same_geometry(const Mesh& m, const Mesh& back, Via via, bool normals, bool vcolors, bool fcolors,
                         bool texcoords) {
  REQUIRE(back.num_faces() == m.num_faces());
  REQUIRE(back.face_start == m.face_start);
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const Vec3d p = m.position(m.corner_vertex[c]), q = back.position(back.corner_vertex[c]);
    CHECK(same(p, q, via));
    if (normals) {
      const Vec3d n = get3(m.corner_normals, m.corner_normal_index[c]);
      const Vec3d nb = back.has_corner_normals() ? get3(back.corner_normals, back.corner_normal_index[c])
                                                 : get3(back.vertex_normals, back.corner_vertex[c]);
      CHECK(same(n, nb, via));
    }
    if (vcolors)
      for (int k = 0; k < 3; ++k)
        CHECK(back.vertex_colors[std::size_t(back.color_channels) * back.corner_vertex[c] + std::size_t(k)] ==
              m.vertex_colors[3 * m.corner_vertex[c] + std::size_t(k)]);
    if (texcoords)
      for (int k = 0; k < 2; ++k)
        CHECK(same_after_text(m.texcoords[2 * m.corner_texcoord_index[c] + std::size_t(k)],
                              back.texcoords[2 * back.corner_texcoord_index[c] + std::size_t(k)]));
  }
  if (fcolors) CHECK(back.face_colors == m.face_colors);
}

}  // namespace

TEST_CASE("round trip: OBJ keeps polygons, corner normals, texcoords and vertex colours exactly", "[mesh_io][roundtrip]") {
  ScratchDir dir;
  Mesh m = rich_mesh();
  m.colors_are_float = true;
  m.face_colors.clear();  // no face colours: no vertex is split (see the next test)
  WriteInfo wi;
  write_mesh(m, dir / "r.obj", WriteOptions{}, &wi);
  CHECK(wi.split_vertices == 0);
  ReadInfo ri;
  Mesh back = read_mesh(dir / "r.obj", Format::Auto, &ri);
  CHECK(back.num_vertices() == m.num_vertices());
  // rich_mesh holds floats (0.1f...): they print as "0.1" and come back as the same floats
  CHECK(same_after_text(m.positions, back.positions));
  CHECK(back.corner_vertex == m.corner_vertex);
  CHECK(same_after_text(m.corner_normals, back.corner_normals));
  CHECK(back.corner_normal_index == m.corner_normal_index);
  CHECK(same_after_text(m.texcoords, back.texcoords));
  CHECK(back.corner_texcoord_index == m.corner_texcoord_index);
  CHECK(back.vertex_colors == m.vertex_colors);
  CHECK(back.precision == ValuePrecision::Float);
  // a second trip gives the same bytes
  write_mesh(back, dir / "r2.obj", WriteOptions{});
  CHECK(read_file(dir / "r.obj") == read_file(dir / "r2.obj"));
}

TEST_CASE("round trip: OBJ carries face colours by splitting vertices; faces, normals, texcoords per corner kept",
          "[mesh_io][roundtrip]") {
  ScratchDir dir;
  const Mesh m = rich_mesh();  // 3 faces, 3 different colours, and vertex colours too
  WriteInfo wi;
  write_mesh(m, dir / "f.obj", WriteOptions{}, &wi);
  // Faces 0 (0 1 3), 1 (1 4 5 2), 2 (3 1 2 5 6): vertex 1 is in all three faces (2 more copies),
  // vertices 2, 3 and 5 in two each (1 more copy each), 0, 4 and 6 in one: 5 added, 12 in all.
  CHECK(wi.split_vertices == 5);
  REQUIRE(wi.notes.size() == 2);
  CHECK(wi.notes[0] ==
        "face colours written as vertex colours (v x y z r g b): 5 vertices added so that every face's corners carry its colour");
  CHECK(wi.notes[1] == "vertex colours replaced by the face colours: OBJ holds one colour per vertex");
  const Mesh back = read_mesh(dir / "f.obj");
  CHECK(back.num_vertices() == 12);
  REQUIRE(back.num_faces() == m.num_faces());
  CHECK(back.face_start == m.face_start);  // same faces, same sizes, same order
  REQUIRE(back.has_vertex_colors());
  REQUIRE(back.color_channels == 3);
  REQUIRE(back.has_corner_normals());
  REQUIRE(back.has_texcoords());
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
      INFO("face " << f << " corner " << c);
      CHECK(same(m.position(m.corner_vertex[c]), back.position(back.corner_vertex[c]), Via::Text));
      for (int k = 0; k < 3; ++k)  // every corner carries its face's colour (floats print and read back exactly)
        CHECK(back.vertex_colors[3 * back.corner_vertex[c] + std::size_t(k)] == m.face_colors[3 * f + std::size_t(k)]);
      CHECK(same(get3(m.corner_normals, m.corner_normal_index[c]), get3(back.corner_normals, back.corner_normal_index[c]),
                 Via::Text));
      for (int k = 0; k < 2; ++k)
        CHECK(same_after_text(m.texcoords[2 * m.corner_texcoord_index[c] + std::size_t(k)],
                              back.texcoords[2 * back.corner_texcoord_index[c] + std::size_t(k)]));
    }
  // the originals keep their place: the first 7 vertices are the input's, in order
  for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(same(m.position(v), back.position(v), Via::Text));
  // rgba face colours give `v x y z r g b`: alpha is left out with a note (7 numbers on a `v` line
  // read as x y z w r g b in common readers; issue 21, item 10)
  Mesh a = rich_mesh();
  a.vertex_colors.clear();
  a.color_channels = 4;
  a.face_colors = {1, 0, 0, 0.5f, 0, 1, 0, 0.25f, 0, 0, 1, 1};
  WriteInfo wa;
  write_mesh(a, dir / "a.obj", WriteOptions{}, &wa);
  CHECK(std::count_if(wa.notes.begin(), wa.notes.end(), [](const std::string& n) { return n.find("alpha") != std::string::npos; }) == 1);
  const Mesh ab = read_mesh(dir / "a.obj");
  REQUIRE(ab.color_channels == 3);
  for (std::size_t f = 0; f < a.num_faces(); ++f)
    for (std::uint32_t c = a.face_start[f]; c < a.face_start[f + 1]; ++c)
      for (int k = 0; k < 3; ++k)
        CHECK(ab.vertex_colors[3 * ab.corner_vertex[c] + std::size_t(k)] == a.face_colors[4 * f + std::size_t(k)]);
}

TEST_CASE("round trip: PLY binary and ascii, float and double", "[mesh_io][roundtrip]") {
  ScratchDir dir;
  for (bool binary : {true, false})
    for (auto prec : {ValuePrecision::Float, ValuePrecision::Double}) {
      Mesh m = rich_mesh();
      m.precision = prec;
      if (prec == ValuePrecision::Double) m.positions[0] = 0.1;  // not a float
      WriteOptions o;
      o.binary = binary;
      write_mesh(m, dir / "r.ply", o);
      Mesh back = read_mesh(dir / "r.ply");
      CHECK(back.precision == prec);
      check_same_geometry(m, back, binary ? Via::Binary : Via::Text, true, true, true, true);
      CHECK(back.num_vertices() == m.num_vertices() + 4);  // the split for corner normals
      // vertex order is kept: the first V vertices are the originals
      for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(same(m.position(v), back.position(v), binary ? Via::Binary : Via::Text));
    }
}

TEST_CASE("round trip: OFF keeps polygons, split corner normals and colours", "[mesh_io][roundtrip]") {
  ScratchDir dir;
  Mesh m = rich_mesh();
  write_mesh(m, dir / "r.off", WriteOptions{});
  Mesh back = read_mesh(dir / "r.off");
  check_same_geometry(m, back, Via::Text, true, true, true, false);
  // double data with 17 digits stays double and exact
  m.precision = ValuePrecision::Double;
  m.positions[0] = 1.0 / 3.0;
  write_mesh(m, dir / "r.off", WriteOptions{});
  back = read_mesh(dir / "r.off");
  CHECK(back.precision == ValuePrecision::Double);
  CHECK(back.positions[0] == 1.0 / 3.0);
}

TEST_CASE("round trip: STL binary and ascii keep triangles; positions bitwise (binary), same floats (ascii)",
          "[mesh_io][roundtrip]") {
  ScratchDir dir;
  Mesh m = testing::icosphere(1).mesh;
  for (double& x : m.positions) x = double(float(x));
  m.precision = ValuePrecision::Float;
  for (bool binary : {true, false}) {
    WriteOptions o;
    o.binary = binary;
    write_mesh(m, dir / "r.stl", o);
    ReadInfo ri;
    Mesh back = read_mesh(dir / "r.stl", Format::Auto, &ri);
    // Vertices come back in order of first appearance in the faces, each position bitwise
    // (binary) or as the same float (ascii: 0.1f is printed "0.1" and read back as 0.1).
    CHECK(back.num_vertices() == m.num_vertices());
    REQUIRE(back.num_corners() == m.num_corners());
    for (std::size_t c = 0; c < m.num_corners(); ++c) {
      const Vec3d p = m.position(m.corner_vertex[c]), q = back.position(back.corner_vertex[c]);
      CHECK(same(p, q, binary ? Via::Binary : Via::Text));
    }
    CHECK(ri.merged_vertices == m.num_corners() - m.num_vertices());
  }
}

TEST_CASE("round trip: the sample meshes in data/ through every format", "[mesh_io][roundtrip]") {
  ScratchDir dir;
  for (const char* name : {"cube.obj", "torus.obj", "icosphere.ply", "quad_sphere.obj", "dodecahedron.off",
                           "inconsistent_winding.obj", "non_manifold.obj"}) {
    const Mesh m = read_mesh(data_path(name));
    for (const char* ext : {"obj", "ply", "off"}) {
      const std::string out = dir / (std::string("x.") + ext);
      write_mesh(m, out, WriteOptions{});
      const Mesh back = read_mesh(out);
      INFO(name << " -> " << ext);
      if (std::string(ext) == "ply" && m.precision == ValuePrecision::Float) {
        // binary PLY with float properties (the precision hint): each value narrowed to float
        std::vector<double> narrowed = m.positions;
        for (double& x : narrowed) x = double(float(x));
        CHECK(back.positions == narrowed);
      } else if (!(std::string(ext) == "obj" && m.has_face_colors())) {
        CHECK(same_after_text(m.positions, back.positions));
      }
      CHECK(back.face_start == m.face_start);
      if (std::string(ext) == "obj" && m.has_face_colors()) {
        // face colours reach OBJ by splitting vertices: per corner, same position and its face's colour
        REQUIRE(back.num_corners() == m.num_corners());
        for (std::size_t f = 0; f < m.num_faces(); ++f)
          for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
            CHECK(same(m.position(m.corner_vertex[c]), back.position(back.corner_vertex[c]), Via::Text));
            for (int k = 0; k < m.color_channels; ++k)
              CHECK(back.vertex_colors[std::size_t(back.color_channels) * back.corner_vertex[c] + std::size_t(k)] ==
                    m.face_colors[std::size_t(m.color_channels) * f + std::size_t(k)]);
          }
      } else {
        CHECK(back.corner_vertex == m.corner_vertex);
      }
      CHECK(back.precision == m.precision);
    }
  }
}

namespace {

// The corner normals of `m` as unit-length directions, whatever kind it stores (corner, vertex, face).
Vec3d stored_normal(const Mesh& m, std::size_t f, std::uint32_t c) {
  if (m.has_corner_normals()) return get3(m.corner_normals, m.corner_normal_index[c]);
  if (m.has_vertex_normals()) return get3(m.vertex_normals, m.corner_vertex[c]);
  return get3(m.face_normals, f);
}

}  // namespace

// Every writer writes a stored normal off unit length divided by its length (the same direction,
// a note counts them); unit and nearly unit normals are written as read.
TEST_CASE("writers write unit normals: off-unit rows divided by their length",
          "[mesh_io][normals]") {
  // A hand-made OBJ with the defect of fuze.obj (MeshLab wrote `vn 0 0 -6.283185`): three
  // triangles whose vn have lengths 2*pi, 5 and 1 + 4e-4 (within the 1e-3 tolerance: kept as is).
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                          "vn 0 0 -6.283185\nvn 3 4 0\nvn 0 1.0004 0\n"
                          "f 1//1 3//1 2//1\nf 2//2 3//2 4//2\nf 1//3 2//3 4//3\n";
  const Mesh m = read_mesh_from_memory(obj, Format::Obj, "fuze_like.obj");
  REQUIRE(m.has_corner_normals());
  // the directions, by hand: (0, 0, -1), (3, 4, 0) / 5, and the nearly unit one as read
  const Vec3d expected[3] = {{0, 0, -1}, {0.6, 0.8, 0}, {0, 1.0004, 0}};
  for (Format format : {Format::Obj, Format::Ply, Format::Off, Format::Gltf}) {
    for (bool binary : {false, true}) {
      if (binary && (format == Format::Obj || format == Format::Off)) continue;
      INFO("format " << format_extension(format) << (binary ? " binary" : " ascii"));
      WriteOptions options;
      options.format = format;
      options.binary = binary;
      options.refuse_unusable_normals = true;
      WriteInfo wi;
      const std::string bytes = write_mesh_to_memory(m, options, &wi);
      CHECK(std::count(wi.notes.begin(), wi.notes.end(),
                       "2 normals not of unit length (5 to 6.283) written divided by their length: the same directions") == 1);
      const Mesh back = read_mesh_from_memory(bytes, format, "back");
      REQUIRE(back.num_faces() == 3);
      for (std::size_t f = 0; f < 3; ++f)
        for (std::uint32_t c = back.face_start[f]; c < back.face_start[f + 1]; ++c) {
          const Vec3d n = stored_normal(back, f, c);
          // float files hold the directions to float precision, double files (PLY binary of a
          // double mesh, OBJ text) to a few ulps of double
          CHECK(std::fabs(n.x - expected[f].x) < 1e-6);
          CHECK(std::fabs(n.y - expected[f].y) < 1e-6);
          CHECK(std::fabs(n.z - expected[f].z) < 1e-6);
        }
    }
  }
  // the normal within tolerance is written as it was read: OBJ text keeps its digits
  const std::string text = write_mesh_to_memory(m, write_as(Format::Obj));
  CHECK(text.find("vn 0 1.0004 0\n") != std::string::npos);
  CHECK(text.find("vn 0 0 -1\n") != std::string::npos);
  CHECK(text.find("vn 0.6 0.8 0\n") != std::string::npos);
  // a mesh whose normals are all unit: no copy, no note
  Mesh unit = m;
  unit.corner_normals = {0, 0, -1, 0.6, 0.8, 0, 0, 1, 0};
  WriteInfo wi;
  write_mesh_to_memory(unit, write_as(Format::Ply), &wi);
  CHECK(std::none_of(wi.notes.begin(), wi.notes.end(), [](const std::string& n) { return n.find("unit length") != std::string::npos; }));
}

// A file must shade in a viewer as our render shades it: the writers holding one normal per corner
// write the normals the lighting uses (core/shading_normals.h), and name the face normals they drop.
TEST_CASE("OBJ and glTF writers write the normals that shade, as the lighting uses them",
          "[mesh_io][normals]") {
  // A hand-made roof: two triangles meeting at a ridge along y, each with its facet normal
  // (what an STL holds) and a smooth vertex normal per vertex (what `shadetool normals` computes
  // for it): ridge vertices (0, 0, 1), eave vertices tilted outwards.
  Mesh m;
  m.positions = {-1, 0, 0, 0, 0, 1, 0, 1, 1, -1, 1, 0, 1, 0, 0, 1, 1, 0};
  m.face_start = {0, 3, 6, 9, 12};
  m.corner_vertex = {0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2};
  const double h = std::sqrt(0.5);
  m.face_normals = {-h, 0, h, -h, 0, h, h, 0, h, h, 0, h};  // the facets, by hand: (-1, 0, 1) / sqrt 2 ...
  m.vertex_normals = {-1, 0, 0, 0, 0, 1, 0, 0, 1, -1, 0, 0, 1, 0, 0, 1, 0, 0};  // smooth, by hand
  const std::vector<double> lit = lit_vertex_normals(m).normals;  // what bake-lighting and render use
  REQUIRE(lit == m.vertex_normals);
  for (Format format : {Format::Obj, Format::Gltf}) {
    INFO("format " << format_extension(format));
    WriteInfo wi;
    const std::string bytes = write_mesh_to_memory(m, write_as(format), &wi);
    const Mesh back = read_mesh_from_memory(bytes, format, "back");
    REQUIRE(back.num_faces() == m.num_faces());
    for (std::size_t f = 0; f < back.num_faces(); ++f)
      for (std::uint32_t c = back.face_start[f]; c < back.face_start[f + 1]; ++c) {
        const Vec3d n = stored_normal(back, f, c);
        const Vec3d want = get3(lit, m.corner_vertex[c]);
        CHECK(std::fabs(n.x - want.x) < 1e-7);
        CHECK(std::fabs(n.y - want.y) < 1e-7);
        CHECK(std::fabs(n.z - want.z) < 1e-7);
      }
    CHECK(std::count_if(wi.notes.begin(), wi.notes.end(), [](const std::string& n) {
            return n.find("face normals not written") != std::string::npos && n.find("the vertex normals shade it") != std::string::npos;
          }) == 1);
  }
  // PLY holds both: vertex and face normals back as written, no note
  WriteInfo wi;
  const Mesh ply = read_mesh_from_memory(write_mesh_to_memory(m, write_as(Format::Ply), &wi), Format::Ply, "back");
  CHECK(ply.vertex_normals == m.vertex_normals);
  REQUIRE(ply.face_normals.size() == m.face_normals.size());
  for (std::size_t i = 0; i < m.face_normals.size(); ++i) CHECK(std::fabs(ply.face_normals[i] - m.face_normals[i]) < 1e-7);
  CHECK(std::none_of(wi.notes.begin(), wi.notes.end(), [](const std::string& n) { return n.find("face normals") != std::string::npos; }));
  // face normals alone (an STL as read, `normals --faces`): they shade, per face, in both
  m.vertex_normals.clear();
  for (Format format : {Format::Obj, Format::Gltf}) {
    WriteInfo wf;
    const Mesh back = read_mesh_from_memory(write_mesh_to_memory(m, write_as(format), &wf), format, "back");
    for (std::size_t f = 0; f < back.num_faces(); ++f)
      for (std::uint32_t c = back.face_start[f]; c < back.face_start[f + 1]; ++c)
        CHECK(std::fabs(stored_normal(back, f, c).x - m.face_normals[3 * f]) < 1e-7);
    CHECK(wf.notes.empty());
  }
}

// files/mesh_files.cpp, whiten_nonfinite_colors: a colour read with a NaN or infinite value (trimesh's
// nancolor.obj: `v x y z nan nan nan`; a PLY with float colours holding inf) is no colour: its row
// is read as white (what an OBJ vertex without a colour gets), every other row exactly as written,
// one note, the values counted for `info`; the mesh then writes to every format. Before, every
// command that writes colours refused the file, naming its output.
TEST_CASE("read_mesh: NaN and infinite colours read as white rows, counted, the rest unchanged", "[mesh_io][colors]") {
  const std::string obj =
      "v 0 0 0 0.25 0.5 0.75\nv 1 0 0 nan nan nan\nv 0 1 0 0.125 inf 0.5\nv 0 0 1 0 1 0\nf 1 2 3\nf 1 3 4\n";
  ReadInfo info;
  const Mesh m = read_mesh_from_memory(obj, Format::Obj, "nan.obj", &info);
  REQUIRE(m.vertex_colors.size() == 12);
  const std::vector<float> want = {0.25f, 0.5f, 0.75f, 1, 1, 1, 1, 1, 1, 0, 1, 0};
  CHECK(m.vertex_colors == want);
  CHECK(info.nonfinite_color_values == 4);
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "2 vertex colours with a NaN or infinite value: read as white, the colour of a vertex without one");
  for (Format f : {Format::Obj, Format::Ply, Format::Off, Format::Gltf}) {
    INFO(format_extension(f));
    CHECK_NOTHROW(write_mesh_to_memory(m, write_as(f)));
  }
  // Finite colours: no note, nothing counted.
  ReadInfo clean;
  read_mesh_from_memory("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n", Format::Obj, "ok.obj", &clean);
  CHECK(clean.notes.empty());
  CHECK(clean.nonfinite_color_values == 0);
  // PLY float face colours: the same rule for face rows.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nproperty float red\nproperty float green\nproperty float blue\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0.5 -inf 0.5\n3 0 2 1 0.5 0.25 0\n";
  ReadInfo pinfo;
  const Mesh p = read_mesh_from_memory(ply, Format::Ply, "nan.ply", &pinfo);
  const std::vector<float> pwant = {1, 1, 1, 0.5f, 0.25f, 0};
  CHECK(p.face_colors == pwant);
  CHECK(pinfo.nonfinite_color_values == 1);
}
