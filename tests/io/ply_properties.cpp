// PLY's other scalar properties (a scanner's confidence, a face's flags, ...) are kept by name and
// declared type (core/mesh.h: vertex_properties, face_properties), follow their vertices and faces
// through the steps that remove or duplicate them, and are written back as read. The files are
// written here by hand, with values at the ends of each type's range.
#include <shadetool/files/mesh_files.h>
#include <shadetool/repair/degenerate_faces.h>
#include <shadetool/repair/weld_vertices.h>

#include <algorithm>
#include <cstring>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

// Four vertices (vertex 3 a copy of vertex 0's position), two triangles and a face repeating an
// index; every scalar type as an extra, plus nx ny without nz (an incomplete attribute: extras
// too) and a vertex list (skipped, noted).
const char* kScannerPly =
    "ply\nformat ascii 1.0\ncomment scanner output\n"
    "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property char c8\nproperty uchar u8\nproperty short s16\nproperty ushort u16\nproperty int s32\nproperty uint u32\n"
    "property float confidence\nproperty double time\nproperty float nx\nproperty float ny\n"
    "property list uchar float neighbours\n"
    "element face 3\nproperty list uchar int vertex_indices\nproperty uchar flags\nproperty double area_hint\n"
    "end_header\n"
    "0 0 0 -128 255 -32768 65535 -2147483648 4294967295 0.5 1e300 0.25 0.5 2 1 2\n"
    "1 0 0 127 0 32767 0 2147483647 0 0.75 -1e-300 0 1 0\n"
    "0 1 0 0 1 -1 1 -1 1 1.0 0.1 1 0 1 9\n"
    "0 0 0 1 2 3 4 5 6 0.125 7 0 0 0\n"
    "3 0 1 2 7 0.5\n"
    "3 3 1 2 8 0.25\n"
    "3 0 0 1 9 0\n";

const MeshProperty* find(const std::vector<MeshProperty>& v, const std::string& name) {
  for (const auto& p : v)
    if (p.name == name) return &p;
  return nullptr;
}

void require_same_properties(const Mesh& a, const Mesh& b) {
  REQUIRE(a.vertex_properties.size() == b.vertex_properties.size());
  REQUIRE(a.face_properties.size() == b.face_properties.size());
  for (auto list : {&Mesh::vertex_properties, &Mesh::face_properties})
    for (std::size_t k = 0; k < (a.*list).size(); ++k) {
      INFO((a.*list)[k].name);
      CHECK((a.*list)[k].name == (b.*list)[k].name);
      CHECK((a.*list)[k].type == (b.*list)[k].type);
      CHECK((a.*list)[k].values == (b.*list)[k].values);  // exact: every type round-trips
    }
}

}  // namespace

TEST_CASE("PLY: other scalar properties are read by name and type, and written back exactly", "[ply][properties]") {
  ReadInfo info;
  const Mesh m = read_mesh_from_memory(kScannerPly, Format::Ply, "scan.ply", &info);
  REQUIRE(m.vertex_properties.size() == 10);
  const MeshProperty* c8 = find(m.vertex_properties, "c8");
  REQUIRE(c8);
  CHECK(c8->type == "char");
  CHECK(c8->values == std::vector<double>{-128, 127, 0, 1});
  CHECK(find(m.vertex_properties, "u32")->values[0] == 4294967295.0);
  CHECK(find(m.vertex_properties, "s32")->values[0] == -2147483648.0);
  CHECK(find(m.vertex_properties, "time")->type == "double");
  CHECK(find(m.vertex_properties, "time")->values[0] == 1e300);
  CHECK(find(m.vertex_properties, "confidence")->type == "float");
  // nx ny without nz: no normals, the two kept as properties.
  CHECK_FALSE(m.has_vertex_normals());
  REQUIRE(find(m.vertex_properties, "ny"));
  CHECK(find(m.vertex_properties, "ny")->values == std::vector<double>{0.5, 1, 0, 0});
  CHECK(find(m.face_properties, "flags")->values == std::vector<double>{7, 8, 9});
  CHECK(find(m.face_properties, "area_hint")->type == "double");
  CHECK(std::any_of(info.notes.begin(), info.notes.end(),
                    [](const std::string& n) { return n.find("vertex list property 'neighbours' not kept") != std::string::npos; }));

  for (bool binary : {false, true}) {
    WriteOptions o;
    o.format = Format::Ply;
    o.binary = binary;
    const std::string bytes = write_mesh_to_memory(m, o);
    // Declared with their own types, after the known properties.
    CHECK(bytes.find("property char c8\nproperty uchar u8\nproperty short s16\nproperty ushort u16\nproperty int s32\n"
                     "property uint u32\nproperty float confidence\nproperty double time\nproperty float nx\nproperty float ny\n") !=
          std::string::npos);
    CHECK(bytes.find("property uchar flags\nproperty double area_hint\n") != std::string::npos);
    const Mesh back = read_mesh_from_memory(bytes, Format::Ply, "back.ply");
    INFO((binary ? "binary" : "ascii"));
    require_same_properties(m, back);
  }
}

TEST_CASE("PLY properties and quality follow their vertices and faces through weld, face removal and splits", "[ply][properties]") {
  Mesh m = read_mesh_from_memory(kScannerPly, Format::Ply, "scan.ply");
  m.vertex_quality = {0.1f, 0.2f, 0.3f, 0.4f};
  m.face_quality = {1.5f, 2.5f, 3.5f};
  // Weld: vertex 3 (same position as 0) merges into vertex 0, which keeps its own values.
  const WeldResult w = weld_vertices(m, 0.0);
  REQUIRE(w.removed == 1);
  CHECK(find(m.vertex_properties, "c8")->values == std::vector<double>{-128, 127, 0});
  CHECK(m.vertex_quality == std::vector<float>{0.1f, 0.2f, 0.3f});
  // Removing the face with a repeated index takes its values along.
  REQUIRE(remove_faces(m, {0, 0, 1}) == 1);
  CHECK(find(m.face_properties, "flags")->values == std::vector<double>{7, 8});
  CHECK(m.face_quality == std::vector<float>{1.5f, 2.5f});
  // Corner normals split vertex 0 for PLY: the copy carries vertex 0's values.
  m.corner_normals = {0, 0, 1, 0, 1, 0};
  m.corner_normal_index = {0, 0, 0, 1, 0, 0};  // face 1's first corner (vertex 0) has another normal
  WriteOptions o;
  o.format = Format::Ply;
  WriteInfo wi;
  const Mesh back = read_mesh_from_memory(write_mesh_to_memory(m, o, &wi), Format::Ply, "back.ply");
  REQUIRE(wi.split_vertices == 1);
  REQUIRE(back.num_vertices() == 4);
  CHECK(find(back.vertex_properties, "u16")->values == std::vector<double>{65535, 0, 1, 65535});
  CHECK(back.vertex_quality == std::vector<float>{0.1f, 0.2f, 0.3f, 0.1f});
  CHECK(find(back.face_properties, "area_hint")->values == std::vector<double>{0.5, 0.25});
}

TEST_CASE("PLY properties: a name the output already uses, a wrong length, and formats without them are named in notes", "[ply][properties]") {
  Mesh m = read_mesh_from_memory(kScannerPly, Format::Ply, "scan.ply");
  m.vertex_normals.assign(3 * m.num_vertices(), 0.0);  // now the output has nx ny nz of its own
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.vertex_normals[3 * v + 2] = 1;
  m.face_properties[0].values.pop_back();  // flags: 2 values for 3 faces
  WriteOptions o;
  o.format = Format::Ply;
  o.binary = false;
  WriteInfo wi;
  const std::string bytes = write_mesh_to_memory(m, o, &wi);
  auto noted = [&](const std::string& part) {
    return std::any_of(wi.notes.begin(), wi.notes.end(), [&](const std::string& n) { return n.find(part) != std::string::npos; });
  };
  CHECK(noted("vertex property 'nx' not written: the output already has a property of that name"));
  CHECK(noted("face property 'flags' not written: 2 values for 3 faces"));
  const Mesh back = read_mesh_from_memory(bytes, Format::Ply, "back.ply");  // a valid header: nx once
  CHECK(back.has_vertex_normals());
  CHECK(find(back.vertex_properties, "nx") == nullptr);
  CHECK(find(back.face_properties, "area_hint") != nullptr);
  o.format = Format::Obj;
  WriteInfo wo;
  write_mesh_to_memory(m, o, &wo);
  CHECK(std::any_of(wo.notes.begin(), wo.notes.end(), [](const std::string& n) {
    return n.find("vertex/face properties not written (c8, u8") != std::string::npos && n.find("only PLY holds them") != std::string::npos;
  }));
}

TEST_CASE("PLY header comments (MeshLab's TextureFile, obj_info) are kept: PLY as read, OBJ as # lines, others noted", "[ply][comments]") {
  const std::string ply =
      "ply\nformat ascii 1.0\ncomment TextureFile scan_tex.png\nobj_info num_cols 640\nCreated by Blender3D\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const Mesh m = read_mesh_from_memory(ply, Format::Ply, "tex.ply");
  REQUIRE(m.comments == std::vector<std::string>{"comment TextureFile scan_tex.png", "obj_info num_cols 640",
                                                 "comment Created by Blender3D"});
  WriteOptions o;
  o.format = Format::Ply;
  const std::string once = write_mesh_to_memory(m, o);
  CHECK(once.find("comment written by shadetool\ncomment TextureFile scan_tex.png\nobj_info num_cols 640\n") != std::string::npos);
  // A second round trip does not repeat our own line.
  const std::string twice = write_mesh_to_memory(read_mesh_from_memory(once, Format::Ply, "once.ply"), o);
  CHECK(twice.find("comment written by shadetool") == twice.rfind("comment written by shadetool"));
  o.format = Format::Obj;
  CHECK(write_mesh_to_memory(m, o).find("# written by shadetool\n# comment TextureFile scan_tex.png\n") != std::string::npos);
  o.format = Format::Stl;
  WriteInfo wi;
  write_mesh_to_memory(m, o, &wi);
  CHECK(std::any_of(wi.notes.begin(), wi.notes.end(), [](const std::string& n) {
    return n.find("3 comment lines not written (first: 'comment TextureFile scan_tex.png'): STL holds none") != std::string::npos;
  }));
}
