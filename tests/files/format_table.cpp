// Tests of files/format_table: one entry per format, names and messages derived from it, detection
// of every writer's output, and the attribute table checked against what the writers and readers
// actually carry (a format that "holds" an attribute gives it back; one that does not, does not).
#include <shadetool/files/format_table.h>

#include "io/io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

TEST_CASE("format table: names, extensions and lists come from the entries", "[format_table]") {
  const auto& table = mesh_formats();
  REQUIRE(table.size() == 5);
  std::vector<std::string> names;
  for (const FormatEntry& e : table) {
    names.emplace_back(e.name);
    CHECK(find_format(e.name) == &e);
    CHECK(&format_entry(e.format) == &e);
    REQUIRE(!e.extensions.empty());
    for (const char* ext : e.extensions) {
      CHECK(find_format(ext) == &e);
      CHECK(format_from_extension(std::string("dir/x.") + ext) == e.format);
    }
    CHECK(std::string(format_extension(e.format)) == e.extensions.front());
  }
  CHECK(format_names() == names);
  CHECK(format_list(false) == "obj, ply, off, stl or gltf");
  CHECK(format_list(true) == ".obj, .ply, .off, .stl or .glb/.gltf");
  CHECK(find_format("OBJ") == &format_entry(Format::Obj));
  CHECK(find_format("glb") == &format_entry(Format::Gltf));
  CHECK(find_format("3mf") == nullptr);
  CHECK(find_format("") == nullptr);
}

TEST_CASE("format table: detect() recognises every writer's output, in both forms", "[format_table]") {
  const Mesh m = rich_mesh();
  for (const FormatEntry& e : mesh_formats()) {
    for (bool binary : {true, false}) {
      if (!binary && !e.has_binary_form) continue;
      WriteOptions o;
      o.format = e.format;
      o.binary = binary;
      const std::string bytes = write_mesh_to_memory(m, o);
      INFO(e.name << (binary ? " binary" : " ascii"));
      CHECK(e.detect(bytes));
      CHECK(detect_format(bytes) == e.format);
      for (const FormatEntry& other : mesh_formats())
        if (&other != &e) CHECK_FALSE(other.detect(bytes));
    }
  }
  // Files other programs write, by hand: comments first, a keyword-less OFF, an STL whose 80-byte
  // header says "solid" but whose size says binary.
  CHECK(detect_format("# Blender v2.79\nmtllib a.mtl\no Cube\nv 1 1 1\n") == Format::Obj);
  CHECK(detect_format("ply\r\nformat ascii 1.0\r\n") == Format::Ply);
  CHECK(detect_format("# comment\nCOFF\n3 1 0\n") == Format::Off);
  std::string stl(84, '\0');
  stl.replace(0, 5, "solid");
  CHECK(detect_format(stl) == Format::Stl);
  CHECK(detect_format("hello world\n") == Format::Auto);
}

namespace {

// Which attribute kinds a mesh carries, in the broad sense a reader gives them back (an OBJ
// writes vertex normals that read back as corner normals: both are "normals"). The test normal is
// (0, 0.6, 0.8), which no writer computes for the flat square (an STL writes (0, 0, 1) facets).
bool has_test_normal(const std::vector<double>& a) {
  for (std::size_t i = 0; i + 2 < a.size(); i += 3)
    if (std::fabs(a[i + 1] - 0.6) < 1e-6 && std::fabs(a[i + 2] - 0.8) < 1e-6) return true;
  return false;
}
struct Carried {
  bool normals, texcoords, colors;
};
Carried carried(const Mesh& m) {
  return {has_test_normal(m.vertex_normals) || has_test_normal(m.corner_normals) || has_test_normal(m.face_normals),
          m.has_texcoords(), m.has_vertex_colors() || m.has_face_colors()};
}

}  // namespace

TEST_CASE("format table: holds matches what survives a write and a read, attribute by attribute", "[format_table]") {
  // One mesh per attribute, nothing else on it.
  struct Case {
    const char* what;
    Holds FormatAttributes::*field;
    void (*add)(Mesh&);
    bool Carried::*kind;
  };
  const Case cases[] = {
      {"vertex normals", &FormatAttributes::vertex_normals,
       [](Mesh& m) { m.vertex_normals.assign(3 * m.num_vertices(), 0.0); for (std::size_t v = 0; v < m.num_vertices(); ++v) { m.vertex_normals[3 * v + 1] = 0.6; m.vertex_normals[3 * v + 2] = 0.8; } },
       &Carried::normals},
      {"corner normals", &FormatAttributes::corner_normals,
       [](Mesh& m) { m.corner_normals = {0, 0.6, 0.8}; m.corner_normal_index.assign(m.num_corners(), 0); }, &Carried::normals},
      {"face normals", &FormatAttributes::face_normals,
       [](Mesh& m) { m.face_normals.assign(3 * m.num_faces(), 0.0); for (std::size_t f = 0; f < m.num_faces(); ++f) { m.face_normals[3 * f + 1] = 0.6; m.face_normals[3 * f + 2] = 0.8; } },
       &Carried::normals},
      {"texcoords", &FormatAttributes::texcoords,
       [](Mesh& m) { m.texcoords = {0, 0, 1, 0, 0, 1}; m.corner_texcoord_index.assign(m.num_corners(), 1); }, &Carried::texcoords},
      {"vertex colours", &FormatAttributes::vertex_colors,
       [](Mesh& m) { m.vertex_colors.assign(3 * m.num_vertices(), 0.5f); }, &Carried::colors},
      {"face colours", &FormatAttributes::face_colors,
       [](Mesh& m) { m.face_colors.assign(3 * m.num_faces(), 0.25f); }, &Carried::colors},
  };
  for (const Case& c : cases) {
    Mesh m;
    for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{1, 1, 0}, Vec3d{0, 1, 0}}) m.add_vertex(p);
    m.add_face({0, 1, 2});
    m.add_face({0, 2, 3});
    c.add(m);
    for (const FormatEntry& e : mesh_formats()) {
      WriteOptions o;
      o.format = e.format;
      const Mesh back = read_mesh_from_memory(write_mesh_to_memory(m, o), e.format, std::string("t.") + e.name);
      INFO(c.what << " through " << e.name);
      CHECK(carried(back).*(c.kind) == (e.holds.*(c.field) != Holds::No));
    }
  }
}
