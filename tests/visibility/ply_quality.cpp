// Tests of the PLY `quality` property the occlusion command writes (lib/shadetool/io/ply_format.cpp): a file
// laid out as MeshLab exports per-vertex and per-face quality is read into vertex_quality /
// face_quality, written back in both encodings unchanged, and a quality array that no longer
// matches the element count is left out with a note rather than misattributed.
#include <catch2/catch.hpp>

#include <string>

#include <shadetool/files/mesh_files.h>

using namespace shadetool;

namespace {

// Laid out as MeshLab's exporter (vcglib's export_ply) writes vertex and face quality: a float
// `quality` after the coordinates and after the index list, a space ending each ASCII line.
const char* kMeshLabPly =
    "ply\n"
    "format ascii 1.0\n"
    "comment VCGLIB generated\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property float quality\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property float quality\n"
    "end_header\n"
    "0 0 0 0.25 \n"
    "1 0 0 0.5 \n"
    "1 1 0 0.75 \n"
    "0 1 0 1 \n"
    "3 0 1 2 0.125 \n"
    "3 0 2 3 0.375 \n";

}  // namespace

TEST_CASE("PLY quality is read as MeshLab writes it and written back unchanged", "[visibility][ply]") {
  const Mesh m = read_mesh_from_memory(kMeshLabPly, Format::Ply, "meshlab.ply");
  REQUIRE(m.vertex_quality == std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f});
  REQUIRE(m.face_quality == std::vector<float>{0.125f, 0.375f});
  for (const bool binary : {false, true}) {
    WriteOptions o;
    o.format = Format::Ply;
    o.binary = binary;
    const std::string bytes = write_mesh_to_memory(m, o);
    REQUIRE(bytes.find("property float quality\nelement face") != std::string::npos);
    REQUIRE(bytes.find("vertex_indices\nproperty float quality\nend_header") != std::string::npos);
    const Mesh back = read_mesh_from_memory(bytes, Format::Ply, "back.ply");
    REQUIRE(back.vertex_quality == m.vertex_quality);
    REQUIRE(back.face_quality == m.face_quality);
    REQUIRE(back.positions == m.positions);
  }
}

TEST_CASE("Quality that does not match the element count is left out with a note", "[visibility][ply]") {
  Mesh m = read_mesh_from_memory(kMeshLabPly, Format::Ply, "meshlab.ply");
  m.vertex_quality.pop_back();  // as if a step had removed a vertex without carrying quality
  WriteOptions o;
  o.format = Format::Ply;
  WriteInfo info;
  const std::string bytes = write_mesh_to_memory(m, o, &info);
  REQUIRE(bytes.find("property float quality\nelement face") == std::string::npos);
  REQUIRE(info.notes.size() == 1);
  REQUIRE(info.notes[0].find("vertex quality not written") != std::string::npos);
  // Other formats say they cannot hold it.
  o.format = Format::Obj;
  WriteInfo obj;
  write_mesh_to_memory(m, o, &obj);
  bool named = false;
  for (const auto& n : obj.notes) named = named || n.find("only PLY holds it") != std::string::npos;
  REQUIRE(named);
}
