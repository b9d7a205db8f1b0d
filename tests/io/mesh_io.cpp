// Tests of io/mesh_io: format names and extensions, file-level errors, and the round trip of a
// mesh with polygons, normals and colours through every format (read, write, read back).
#include <cstring>

#include "io_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::iotest;

TEST_CASE("format names and extensions", "[mesh_io]") {
  CHECK(format_from_extension("a/b.OBJ") == Format::Obj);
  CHECK(format_from_extension("x.ply") == Format::Ply);
  CHECK(format_from_extension("x.off") == Format::Off);
  CHECK(format_from_extension("x.Stl") == Format::Stl);
  CHECK(parse_format_name("PLY", "--format") == Format::Ply);
  CHECK(std::string(format_extension(Format::Off)) == "off");
  CHECK(error_of([] { format_from_extension("mesh.xyz"); }) ==
        "mesh.xyz: unknown mesh format 'xyz' (expected .obj, .ply, .off or .stl)");
  CHECK(error_of([] { format_from_extension("dir.d/mesh"); }) ==
        "dir.d/mesh: no file extension to tell the mesh format (expected .obj, .ply, .off or .stl)");
  CHECK(error_of([] { parse_format_name("gltf", "--format"); }) ==
        "--format: unknown mesh format 'gltf' (expected obj, ply, off or stl)");
}

TEST_CASE("read_mesh: missing file, directory, empty file, unknown extension", "[mesh_io][errors]") {
  ScratchDir dir;
  CHECK(error_of([&] { read_mesh(dir / "none.obj"); }) == dir / "none.obj" + ": cannot open: No such file or directory");
  std::filesystem::create_directory(dir / "d.obj");
  CHECK(error_of([&] { read_mesh(dir / "d.obj"); }) == dir / "d.obj" + ": is a directory, not a mesh file");
  write_file(dir / "empty.ply", "");
  CHECK(error_of([&] { read_mesh(dir / "empty.ply"); }) == dir / "empty.ply" + ": file is empty");
  write_file(dir / "m.txt", "v 0 0 0\n");
  CHECK(error_of([&] { read_mesh(dir / "m.txt"); }) == dir / "m.txt" + ": unknown mesh format 'txt' (expected .obj, .ply, .off or .stl)");
  // an explicit format overrides the extension
  write_file(dir / "m.txt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(read_mesh(dir / "m.txt", Format::Obj).num_faces() == 1);
}

namespace {

// Asserts that `back` holds what `m` held, for the attributes a format carries. Positions and
// normals are compared per corner (writers may split vertices to carry corner normals).
void check_same_geometry(const Mesh& m, const Mesh& back, bool normals, bool vcolors, bool fcolors, bool texcoords) {
  REQUIRE(back.num_faces() == m.num_faces());
  REQUIRE(back.face_start == m.face_start);
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const Vec3d p = m.position(m.corner_vertex[c]), q = back.position(back.corner_vertex[c]);
    CHECK(std::memcmp(&p, &q, sizeof p) == 0);  // bitwise
    if (normals) {
      const Vec3d n = get3(m.corner_normals, m.corner_normal_index[c]);
      const Vec3d nb = back.has_corner_normals() ? get3(back.corner_normals, back.corner_normal_index[c])
                                                 : get3(back.vertex_normals, back.corner_vertex[c]);
      CHECK(n == nb);
    }
    if (vcolors)
      for (int k = 0; k < 3; ++k)
        CHECK(back.vertex_colors[std::size_t(back.color_channels) * back.corner_vertex[c] + std::size_t(k)] ==
              m.vertex_colors[3 * m.corner_vertex[c] + std::size_t(k)]);
    if (texcoords)
      for (int k = 0; k < 2; ++k)
        CHECK(back.texcoords[2 * back.corner_texcoord_index[c] + std::size_t(k)] ==
              m.texcoords[2 * m.corner_texcoord_index[c] + std::size_t(k)]);
  }
  if (fcolors) CHECK(back.face_colors == m.face_colors);
}

}  // namespace

TEST_CASE("round trip: OBJ keeps polygons, corner normals, texcoords and vertex colours exactly", "[mesh_io][roundtrip]") {
  ScratchDir dir;
  Mesh m = rich_mesh();
  m.colors_are_float = true;
  WriteInfo wi;
  write_mesh(m, dir / "r.obj", WriteOptions{}, &wi);
  CHECK(wi.split_vertices == 0);
  ReadInfo ri;
  Mesh back = read_mesh(dir / "r.obj", Format::Auto, &ri);
  CHECK(back.num_vertices() == m.num_vertices());
  CHECK(back.positions == m.positions);
  CHECK(back.corner_vertex == m.corner_vertex);
  CHECK(back.corner_normals == m.corner_normals);
  CHECK(back.corner_normal_index == m.corner_normal_index);
  CHECK(back.texcoords == m.texcoords);
  CHECK(back.corner_texcoord_index == m.corner_texcoord_index);
  CHECK(back.vertex_colors == m.vertex_colors);
  CHECK(back.precision == ValuePrecision::Float);
  // a second trip gives the same bytes
  write_mesh(back, dir / "r2.obj", WriteOptions{});
  CHECK(read_file(dir / "r.obj") == read_file(dir / "r2.obj"));
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
      check_same_geometry(m, back, true, true, true, true);
      CHECK(back.num_vertices() == m.num_vertices() + 4);  // the split for corner normals
      // vertex order is kept: the first V vertices are the originals
      for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(back.position(v) == m.position(v));
    }
}

TEST_CASE("round trip: OFF keeps polygons, split corner normals and colours", "[mesh_io][roundtrip]") {
  ScratchDir dir;
  Mesh m = rich_mesh();
  write_mesh(m, dir / "r.off", WriteOptions{});
  Mesh back = read_mesh(dir / "r.off");
  check_same_geometry(m, back, true, true, true, false);
  // double data with 17 digits stays double and exact
  m.precision = ValuePrecision::Double;
  m.positions[0] = 1.0 / 3.0;
  write_mesh(m, dir / "r.off", WriteOptions{});
  back = read_mesh(dir / "r.off");
  CHECK(back.precision == ValuePrecision::Double);
  CHECK(back.positions[0] == 1.0 / 3.0);
}

TEST_CASE("round trip: STL binary and ascii keep triangles and positions bitwise", "[mesh_io][roundtrip]") {
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
    // Vertices come back in order of first appearance in the faces, each position bitwise.
    CHECK(back.num_vertices() == m.num_vertices());
    REQUIRE(back.num_corners() == m.num_corners());
    for (std::size_t c = 0; c < m.num_corners(); ++c) {
      const Vec3d p = m.position(m.corner_vertex[c]), q = back.position(back.corner_vertex[c]);
      CHECK(std::memcmp(&p, &q, sizeof p) == 0);
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
      CHECK(back.positions == m.positions);
      CHECK(back.face_start == m.face_start);
      CHECK(back.corner_vertex == m.corner_vertex);
      CHECK(back.precision == m.precision);
    }
  }
}
