// Files imitating other programs' exporters (issue 21): what they hold must come through every
// subcommand, and what other readers accept must be read. Each test builds its file by hand the way
// that exporter writes it (Blender's OBJ with materials and groups, a classic-Mac CR-only OBJ,
// a Windows CRLF OBJ with a UTF-8 BOM, a UTF-16 text file, OBJ elements other readers skip).
#include <algorithm>
#include <array>

#include <shadetool/io/engine/text_parse.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

// An OBJ as Blender 2.8x writes it (mtllib, o, usemtl, s, g), with a partial vt (a face without
// texture coordinates beside faces with them) and a degenerate face (repeated index) that
// `repair --remove-degenerate` removes.
const char* kBlenderObj =
    "# Blender v2.83.0 OBJ File: ''\n"
    "# www.blender.org\n"
    "mtllib two_materials.mtl\n"
    "o Cube\n"
    "v 1.000000 1.000000 -1.000000\n"
    "v 1.000000 -1.000000 -1.000000\n"
    "v 1.000000 1.000000 1.000000\n"
    "v 1.000000 -1.000000 1.000000\n"
    "v -1.000000 1.000000 -1.000000\n"
    "v -1.000000 -1.000000 -1.000000\n"
    "v -1.000000 1.000000 1.000000\n"
    "v -1.000000 -1.000000 1.000000\n"
    "vt 0.625000 0.500000\n"
    "vt 0.875000 0.500000\n"
    "vt 0.875000 0.750000\n"
    "vt 0.625000 0.750000\n"
    "g Cube_top\n"
    "usemtl Red\n"
    "s off\n"
    "f 1/1 5/2 7/3 3/4\n"
    "f 4 3 7 8\n"
    "usemtl Blue\n"
    "s 1\n"
    "f 8 7 5 6\n"
    "f 6 2 2\n"
    "g Cube_bottom\n"
    "f 6/1 2/2 4/3 8/4\n"
    "f 2 1 3 4\n"
    "f 6 5 1 2\n";

// The statement lines and faces of an OBJ text in order, faces as "f" (what "in place" means).
std::vector<std::string> statements_and_faces(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const std::string kw = line.substr(0, line.find(' '));
    if (kw == "f") out.push_back("f");
    else if (kw == "mtllib" || kw == "usemtl" || kw == "g" || kw == "o" || kw == "s") out.push_back(line);
  }
  return out;
}

}  // namespace

TEST_CASE("OBJ materials and groups stay in place through every subcommand", "[real_files][obj]") {
  ScratchDir dir;
  write_file(dir / "blender.obj", kBlenderObj);
  std::vector<std::string> expected = statements_and_faces(kBlenderObj);
  write_file(dir / "scene.json", R"({"lights": [{"type": "directional", "direction": [0, 0, -1]}]})");
  const std::vector<std::string> commands = {
      "normals", "normals --crease 30", "normals --faces", "repair", "transform --rotate 30,0,0,1 --scale 2,1,1",
      "transform --scale -1,1,1", "bake-lighting --scene '" + dir / "scene.json" + "'"};
  for (const std::string& cmd : commands) {
    INFO(cmd);
    const Run r = run_cli(cmd + " '" + dir / "blender.obj" + "' -o '" + dir / "out.obj" + "' -q");
    REQUIRE(r.code == 0);
    CHECK(statements_and_faces(read_file(dir / "out.obj")) == expected);
  }
  // --remove-degenerate removes `f 6 2 2`; the statements of the faces that remain stay with them.
  const Run r = run_cli("repair '" + dir / "blender.obj" + "' -o '" + dir / "out.obj" + "' --remove-degenerate -q");
  REQUIRE(r.code == 0);
  std::vector<std::string> without = expected;
  const auto it = std::find(without.begin(), without.end(), "s 1");
  REQUIRE(it != without.end());
  without.erase(it + 2);  // the second face after `s 1`
  CHECK(statements_and_faces(read_file(dir / "out.obj")) == without);
  // The partial vt comes back per face: the first face has its four, the second none.
  const std::string out = read_file(dir / "out.obj");
  CHECK(out.find("\nf 1/1/") != std::string::npos);
  CHECK(out.find("\nf 4//") != std::string::npos);
}

TEST_CASE("OBJ materials and groups: a format that cannot hold them says so in one note", "[real_files][obj]") {
  const Mesh m = read_text(kBlenderObj, Format::Obj);
  REQUIRE(m.has_groups());
  for (Format f : {Format::Ply, Format::Off, Format::Stl}) {
    WriteOptions o;
    o.format = f;
    WriteInfo wi;
    write_mesh_to_memory(m, o, &wi);
    INFO(format_extension(f));
    CHECK(std::count_if(wi.notes.begin(), wi.notes.end(), [](const std::string& n) {
            return n.find("materials and groups not written (8 mtllib/usemtl/g/o/s lines)") != std::string::npos;
          }) == 1);
  }
}

TEST_CASE("line endings: CR (classic Mac), CRLF and mixed read as LF; a UTF-8 BOM is skipped", "[real_files][text]") {
  const std::string lf = "# comment\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n";
  const Mesh expected = read_text(lf, Format::Obj);
  auto with = [&](const std::string& eol) {
    std::string s;
    for (char c : lf) s += c == '\n' ? eol : std::string(1, c);
    return s;
  };
  for (const std::string& text : {with("\r"), with("\r\n"), "\xEF\xBB\xBF" + with("\r\n"),
                                  std::string("v 0 0 0\rv 1 0 0\r\nv 0 1 0\nv 0 0 1\r\rf 1 2 3\nf 1 3 4\r")}) {
    const Mesh m = read_text(text, Format::Obj);
    CHECK(m.positions == expected.positions);
    CHECK(m.corner_vertex == expected.corner_vertex);
  }
  // Line numbers count CR-only lines as lines.
  CHECK(error_of([] { read_text("v 0 0 0\rv 1 0 0\rv x 0 0\r", Format::Obj, nullptr, "m.obj"); }) ==
        "m.obj:3: malformed number 'x'");
  // OFF and ascii STL the same way.
  const Mesh off = read_text("OFF\r3 1 0\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r", Format::Off);
  CHECK(off.num_faces() == 1);
  const Mesh stl = read_text("\xEF\xBB\xBFsolid t\rfacet normal 0 0 1\router loop\rvertex 0 0 0\rvertex 1 0 0\r"
                             "vertex 0 1 0\rendloop\rendfacet\rendsolid t\r",
                             Format::Stl);
  CHECK(stl.num_faces() == 1);
}

TEST_CASE("a CR-only OBJ is not an empty success: transform writes the mesh", "[real_files][text][cli]") {
  ScratchDir dir;
  write_file(dir / "mac.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
  const Run r = run_cli("transform '" + dir / "mac.obj" + "' --translate 1,0,0 -o '" + dir / "out.obj" + "' -q");
  REQUIRE(r.code == 0);
  CHECK(read_mesh(dir / "out.obj").num_faces() == 1);
}

TEST_CASE("UTF-16 text is refused as UTF-16, not as binary data; no vertex at all is an error", "[real_files][text]") {
  std::string utf16le = "\xFF\xFE";
  for (char c : std::string("v 0 0 0\r\nv 1 0 0\r\n")) utf16le += std::string(1, c) + '\0';
  std::string utf16be_no_bom;
  for (char c : std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")) utf16be_no_bom += std::string(1, '\0') + c;
  for (Format f : {Format::Obj, Format::Off, Format::Ply, Format::Stl}) {
    INFO(format_extension(f));
    CHECK(error_of([&] { read_text(utf16le, f, nullptr, "u.txt"); }) == "u.txt: UTF-16 text: save the file as UTF-8 or ASCII");
    CHECK(error_of([&] { read_text(utf16be_no_bom, f, nullptr, "u.txt"); }) == "u.txt: UTF-16 text: save the file as UTF-8 or ASCII");
  }
  // A file with content but no vertex: an error, for every format, never an empty mesh.
  CHECK(error_of([] { read_text("# only a comment\nmtllib a.mtl\n", Format::Obj, nullptr, "c.obj"); }) ==
        "c.obj: no vertex (`v` line) in the file: not a mesh");
  CHECK(error_of([] { read_text("OFF\n0 0 0\n", Format::Off, nullptr, "c.off"); }) ==
        "c.off: no vertex in the file: nothing to read as a mesh");
  CHECK(error_of([] { read_text("solid x\nendsolid x\n", Format::Stl, nullptr, "c.stl"); }) ==
        "c.stl: no vertex in the file: nothing to read as a mesh");
}

TEST_CASE("OBJ elements other readers skip are skipped with one counted note", "[real_files][obj]") {
  ReadInfo info;
  const Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf\nf  # empty face\nl 1 2\nl 2 3\np 1\n"
                           "curv 0 1 1 2\nvp 0.5\nf 1 2 3\n",
                           Format::Obj, &info);
  CHECK(m.num_faces() == 1);
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "skipped 7 lines: 2 `l` (polyline), 1 `p` (point), 2 `f` with no indices (no face), 2 with keywords "
                         "shadetool does not use (first: 'curv')");
  // Truly malformed numbers still stop.
  CHECK(error_of([] { read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n", Format::Obj, nullptr, "m.obj"); }) ==
        "m.obj:4: malformed face index '3x'");
}

TEST_CASE("PLY: a header line without a keyword (Blender 2.4x) is a comment, with one note cut at a word", "[real_files][ply]") {
  const std::string ply =
      "ply\r\nformat ascii 1.0\r\n"
      "Created by Blender3D 249 - www.blender.org, source file: 'untitled.blend'\r\n"
      "element vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "element face 1\r\nproperty list uchar uint vertex_indices\r\nend_header\r\n"
      "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
  ReadInfo info;
  const Mesh m = read_text(ply, Format::Ply, &info);
  CHECK(m.num_faces() == 1);
  REQUIRE(info.notes.size() == 1);
  CHECK(info.notes[0] == "1 header line without a PLY keyword read as comment (first: 'Created by Blender3D 249 "
                         "-\u2026')");
}

TEST_CASE("quoted text in messages is cut at a word with an ellipsis", "[real_files][text]") {
  CHECK(io::quoted_excerpt("short", 40) == "short");
  CHECK(io::quoted_excerpt("alpha beta gamma delta", 12) == "alpha beta\u2026");
  CHECK(io::quoted_excerpt(std::string(100, 'x'), 40) == std::string(40, 'x') + "\u2026");
  // never inside a UTF-8 sequence
  CHECK(io::quoted_excerpt(std::string(39, 'x') + "\u00e9\u00e9", 40) == std::string(39, 'x') + "\u2026");
}

namespace {

std::string binary_stl(const std::vector<std::array<float, 12>>& facets) {
  std::string s(80, ' ');
  const std::uint32_t n = std::uint32_t(facets.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& f : facets) {
    s.append(reinterpret_cast<const char*>(f.data()), 48);
    s.append(2, '\0');
  }
  return s;
}

}  // namespace

TEST_CASE("STL: zero and inverted facet normals are replaced on read, counted in a note", "[real_files][stl]") {
  // A tetrahedron as exporters write it: facet 0 with (0,0,0), facet 1 inverted, 2 and 3 right.
  const std::vector<std::array<float, 12>> facets = {
      {0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 0},    // z = 0 face, wound to -z: its normal is (0,0,-1)
      {0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},    // y = 0 face, wound to -y; stored +y (inverted)
      {-1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0},   // x = 0 face, -x, right
      {1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1}};  // slanted face, not unit but the right way
  ReadInfo info;
  const Mesh m = read_text(binary_stl(facets), Format::Stl, &info, "exporter.stl");
  REQUIRE(m.has_face_normals());
  CHECK(get3(m.face_normals, 0) == Vec3d{0, 0, -1});
  CHECK(get3(m.face_normals, 1) == Vec3d{0, -1, 0});
  CHECK(get3(m.face_normals, 2) == Vec3d{-1, 0, 0});
  CHECK(get3(m.face_normals, 3) == Vec3d{1, 1, 1});  // agreeing normals are kept as read
  CHECK(std::count_if(info.notes.begin(), info.notes.end(), [](const std::string& n) {
          return n == "facet normals replaced by the triangles' own: 1 zero, 1 against the winding";
        }) == 1);
}

TEST_CASE("no writer writes a zero or non-finite normal, nor a value its number type cannot hold", "[real_files][write]") {
  Mesh m;
  for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.vertex_normals = {0, 0, 1, 0, 0, 0, 0, 0, 1};  // one zero
  for (Format f : {Format::Obj, Format::Ply, Format::Off}) {
    WriteOptions o;
    o.format = f;
    o.name = "out";
    o.refuse_unusable_normals = true;  // as every subcommand writes
    CHECK(error_of([&] { write_mesh_to_memory(m, o); }).find("out: 1 normal is zero, NaN or infinite") == 0);
  }
  // STL holds no vertex normals: nothing zero is written, and its facet normal is the triangle's.
  WriteOptions stl;
  stl.format = Format::Stl;
  stl.binary = false;
  CHECK(write_mesh_to_memory(m, stl).find("facet normal 0 0 1\n") != std::string::npos);
  // A triangle with no area gets +z in STL, with a note.
  Mesh flat = m;
  flat.vertex_normals.clear();
  flat.set_position(2, {2, 0, 0});
  WriteInfo wi;
  CHECK(write_mesh_to_memory(flat, stl, &wi).find("facet normal 0 0 1\n") != std::string::npos);
  REQUIRE(wi.notes.size() == 1);
  // Beyond float: binary PLY widens to double (note), binary STL refuses, text writes as is.
  Mesh big = flat;
  big.vertex_normals.clear();
  big.set_position(1, {1e39, 0, 0});
  big.precision = ValuePrecision::Float;
  WriteOptions ply;
  ply.format = Format::Ply;
  WriteInfo wp;
  const Mesh back = read_text(write_mesh_to_memory(big, ply, &wp), Format::Ply);
  CHECK(back.positions[3] == 1e39);
  CHECK(wp.notes.back() == "values beyond the range of float: written as double");
  WriteOptions stl_bin;
  stl_bin.format = Format::Stl;
  stl_bin.name = "out.stl";
  CHECK(error_of([&] { write_mesh_to_memory(big, stl_bin); }).find("out.stl: a coordinate is beyond the range of float") == 0);
  big.set_position(1, {std::numeric_limits<double>::infinity(), 0, 0});
  for (Format f : {Format::Obj, Format::Ply, Format::Off, Format::Stl}) {
    WriteOptions o;
    o.format = f;
    CHECK(error_of([&] { write_mesh_to_memory(big, o); }).find("coordinates are NaN or infinite") != std::string::npos);
  }
}

TEST_CASE("numbers that do not fit: the reported cases of issue 21 item 15, through the CLI", "[real_files][cli]") {
  ScratchDir dir;
  // normals of an OBJ with coordinates 1e39 written to binary STL: refused, one line, no output
  write_file(dir / "big.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1e39 0\nf 1 2 3\n");
  Run r = run_cli("normals '" + dir / "big.obj" + "' -o '" + dir / "big.stl" + "'");
  CHECK(r.code == 1);
  CHECK(r.err.find("beyond the range of float") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(!fs::exists(dir / "big.stl"));
  // transform of a float PLY by --scale 1e39: written as double PLY, the values intact
  write_file(dir / "small.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  r = run_cli("transform '" + dir / "small.obj" + "' -o '" + dir / "scaled.ply" + "' --scale 1e39");
  REQUIRE(r.code == 0);
  CHECK(r.err.find("written as double") != std::string::npos);
  const Mesh back = read_mesh(dir / "scaled.ply");
  CHECK(back.positions[3] == 1e39);
  for (double x : back.positions) CHECK(std::isfinite(x));
}
