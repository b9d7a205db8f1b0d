// Tests of the readers (io/obj_format, io/off_format, io/engine/ply_body) on files other programs'
// users wrote, from trimesh's test corpus (github.com/mikedh/trimesh models/, MIT licence), copied
// into data/corpus_extra/ (MANIFEST.tsv there names each file's source). Each test checks what
// trimesh's own tests (tests/test_obj.py, test_off.py, test_texture.py) assert of the file, and a
// truth the reader did not produce: the file rewritten by the test into a form every reader
// reads (continuations joined, counts spaced from the keyword), or its binary twin.
#include <cmath>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

std::string extra_path(const std::string& name) { return data_path("corpus_extra/" + name); }

Mesh read_extra(const std::string& name, ReadInfo* info = nullptr) {
  ReadInfo local;
  Mesh m = read_mesh(extra_path(name), Format::Auto, info ? info : &local);
  return m;
}

// Triangles a fan triangulation gives (trimesh counts faces after it): sum of (size - 2).
std::size_t fan_triangles(const Mesh& m) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) n += m.face_size(f) - 2;
  return n;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

}  // namespace

TEST_CASE("trimesh's jacked.obj (`f 2/2/ 4/4/ 1/1/`): every corner's vt is its vertex, no normals", "[xcorpus][obj]") {
  ReadInfo info;
  const Mesh m = read_extra("jacked.obj", &info);
  CHECK(info.notes.empty());
  CHECK(m.num_vertices() == 8);
  CHECK(m.num_faces() == 12);
  // trimesh test_trailing: one uv per vertex; the file writes every corner i/i/.
  CHECK(m.corner_texcoord_index == m.corner_vertex);
  CHECK(m.texcoords.size() / std::size_t(m.texcoord_dims) == 8);
  CHECK(!m.has_corner_normals());
  // The same file without the trailing slashes.
  const std::string text = read_file(extra_path("jacked.obj"));
  require_same_mesh(m, read_mesh_from_memory(replaced(replaced(text, "/ ", " "), "/\n", "\n"), Format::Obj, "jacked.obj"));
}

TEST_CASE("trimesh's notenoughindices.obj and polygonfaces.obj: `1//` corners, a 2-vertex `f` skipped with a note",
          "[xcorpus][obj]") {
  ReadInfo info;
  const Mesh m = read_extra("notenoughindices.obj", &info);
  CHECK(m.num_vertices() == 3);
  CHECK(m.num_faces() == 1);  // trimesh: len(m.faces) == 1
  CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(info.notes == std::vector<std::string>{"skipped 1 line: 1 `f` with fewer than 3 vertices (not a face)"});
  const Mesh p = read_extra("polygonfaces.obj");
  CHECK(p.face_start == std::vector<std::uint32_t>{0, 5});
  CHECK(p.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 3, 4});
}

TEST_CASE("trimesh's wallhole.obj (faces continued by `\\`): 66 triangles, the mesh of its joined lines", "[xcorpus][obj]") {
  const Mesh m = read_extra("wallhole.obj");
  CHECK(fan_triangles(m) == 66);  // trimesh test_backslash_continuation_character
  const std::string text = read_file(extra_path("wallhole.obj"));
  // The file has CRLF line endings: a continued line ends in `\` CR LF.
  REQUIRE(text.find(" \\\r\n") != std::string::npos);
  require_same_mesh(m, read_mesh_from_memory(replaced(text, " \\\r\n", " "), Format::Obj, "wallhole.obj"));
}

TEST_CASE("trimesh's whitespace.off (`\\t   OFF8 6 12 # or nah`): 8 vertices, 6 quads (12 triangles)", "[xcorpus][off]") {
  const Mesh m = read_extra("whitespace.off");
  CHECK(m.num_vertices() == 8);
  CHECK(fan_triangles(m) == 12);  // trimesh test_whitespace
  const std::string text = read_file(extra_path("whitespace.off"));
  require_same_mesh(m, read_mesh_from_memory(replaced(text, "OFF8", "OFF 8"), Format::Off, "whitespace.off"));
}

TEST_CASE("trimesh's fuze_ascii.ply (values past the declared ones on every face line) reads as its binary twin fuze.ply",
          "[xcorpus][ply]") {
  ReadInfo info;
  const Mesh a = read_extra("fuze_ascii.ply", &info);
  const Mesh b = read_extra("fuze.ply");
  CHECK(info.notes == std::vector<std::string>{"1000 face lines hold values beyond the header's properties (first: line 523): "
                                               "ignored, as the PLY reference reader (ply.c) reads them"});
  // Same model, written by VCGLIB as binary floats and as 6-decimal text.
  CHECK(a.face_start == b.face_start);
  CHECK(a.corner_vertex == b.corner_vertex);
  CHECK(a.vertex_colors == b.vertex_colors);
  auto close = [](const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!(std::fabs(x[i] - y[i]) <= 1e-6)) return false;  // 6 decimals: half a unit of the last is 5e-7
    return true;
  };
  CHECK(close(a.positions, b.positions));
  REQUIRE(a.has_texcoords());
  CHECK(close(a.texcoords, b.texcoords));  // trimesh test_texture loads its uv
  CHECK(a.corner_texcoord_index == b.corner_texcoord_index);
  // (Face colours: the ascii lines say `9 1 1 1`, the binary 255 255 255 255: each file's own.)
}

TEST_CASE("trimesh's reference.obj: 845 vt lines no face references are named in a note", "[xcorpus][obj]") {
  ReadInfo info;
  const Mesh m = read_extra("reference.obj", &info);
  CHECK(m.num_vertices() == 845);
  CHECK(!m.has_texcoords());
  CHECK(info.notes == std::vector<std::string>{"845 texture coordinates (vt) no face references: not read"});
}
