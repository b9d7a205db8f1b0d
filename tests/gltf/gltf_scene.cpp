// Tests of gltf/gltf_scene: the scene graph's world matrices and the world-space mesh, against
// positions worked out by hand from glTF 2.0's node rules (3.5.2-3.5.3: world = parent * T R S;
// 3.7.2.1: a node with det < 0 draws its triangles clockwise).
#include <shadetool/gltf/gltf_scene.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <catch2/catch.hpp>

#include <shadetool/core/error.h>
#include <shadetool/files/mesh_files.h>
#include "gltf_test_util.h"

using namespace shadetool;
using namespace shadetool::gltftest;

namespace {

// One triangle (0,0,0) (1,0,0) (0,1,0), normal +z, TEXCOORD_0 (0,0) (1,0) (0,1); a second mesh
// (one triangle at z = 5, no normal). Nodes are set by each test.
Built two_meshes(bool second_has_normal = false) {
  Built b = base_doc();
  const int pos = float_accessor(b, {0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3, true);
  const int nrm = float_accessor(b, {0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int uv = float_accessor(b, {0, 0, 1, 0, 0, 1}, "VEC2", 2);
  const int pos2 = float_accessor(b, {0, 0, 5, 1, 0, 5, 0, 1, 5}, "VEC3", 3, true);
  json second = {{"POSITION", pos2}};
  if (second_has_normal) second["NORMAL"] = nrm;
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}}}})}},
                                 {{"primitives", json::array({{{"attributes", second}}})}}});
  return b;
}

Mesh world_of(Built& b, std::vector<std::string>& notes) {
  const std::string glb = b.glb();
  return gltf_world_mesh(read_gltf(glb, "scene.glb"), notes);
}

// The geometric normal of face f (unnormalised).
Vec3d face_cross(const Mesh& m, std::size_t f) {
  const Vec3d a = m.position(m.corner_vertex[3 * f]), b = m.position(m.corner_vertex[3 * f + 1]), c = m.position(m.corner_vertex[3 * f + 2]);
  return cross(b - a, c - a);
}

bool has_note(const std::vector<std::string>& notes, const std::string& part) {
  return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

void require_near(const Vec3d& a, const Vec3d& b) {
  CHECK(a.x == Approx(b.x).margin(1e-12));
  CHECK(a.y == Approx(b.y).margin(1e-12));
  CHECK(a.z == Approx(b.z).margin(1e-12));
}

}  // namespace

TEST_CASE("glTF scene: T R S under a parent, a matrix mirror, a hidden node, an unplaced mesh", "[gltf][scene]") {
  Built b = two_meshes();
  const double h = std::sqrt(0.5);
  b.doc["scenes"] = json::array({{{"nodes", {0, 2, 3}}}});
  b.doc["nodes"] = json::array({
      {{"translation", {10, 0, 0}}, {"rotation", {0, 0, h, h}}, {"children", {1}}},  // 90 degrees about z
      {{"scale", {2, 1, 1}}, {"mesh", 0}},
      {{"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}, {"mesh", 0}},  // mirror in x
      {{"scale", {0, 0, 0}}, {"mesh", 0}},                                           // hidden
  });
  std::vector<std::string> notes;
  const Mesh m = world_of(b, notes);
  REQUIRE(m.num_faces() == 3);  // two placements of mesh 0, mesh 1 once in object space
  REQUIRE(m.num_vertices() == 9);
  // nodes[1]: p -> R_z(90) (2x, y, z) + (10, 0, 0), by hand.
  require_near(m.position(0), {10, 0, 0});
  require_near(m.position(1), {10, 2, 0});
  require_near(m.position(2), {9, 0, 0});
  // nodes[2]: x -> -x.
  require_near(m.position(3), {0, 0, 0});
  require_near(m.position(4), {-1, 0, 0});
  require_near(m.position(5), {0, 1, 0});
  // mesh 1 as read.
  require_near(m.position(6), {0, 0, 5});
  // Every placed face faces +z, as the normals say: the mirror's winding was reversed.
  REQUIRE(m.has_corner_normals());  // mesh 1 has no normal: corner normals for all
  for (std::size_t f = 0; f < 3; ++f) {
    CHECK(face_cross(m, f).z > 0);
    for (int k = 0; k < 3; ++k) {
      const Vec3d n = get3(m.corner_normals, m.corner_normal_index[3 * f + std::size_t(k)]);
      require_near(n, {0, 0, 1});
    }
  }
  // TEXCOORD_0 with v flipped for both placements; mesh 1's corners have none.
  REQUIRE(m.has_texcoords());
  for (std::size_t f = 0; f < 2; ++f) {
    // The mirror's corners are re-wound: find each corner's vertex's texture coordinate.
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = m.corner_vertex[3 * f + std::size_t(k)] - std::uint32_t(3 * f);
      const std::uint32_t t = m.corner_texcoord_index[3 * f + std::size_t(k)];
      const double u_read[3] = {0, 1, 0}, v_read[3] = {0, 0, 1};
      CHECK(m.texcoords[2 * t] == u_read[v]);
      CHECK(m.texcoords[2 * t + 1] == 1 - v_read[v]);
    }
  }
  for (int k = 0; k < 3; ++k) CHECK(m.corner_texcoord_index[6 + std::size_t(k)] == kNoTexcoord);
  CHECK(has_note(notes, "nodes[3]: singular matrix"));
  CHECK(has_note(notes, "no node of the scene shows meshes[1].primitives[0]"));
  CHECK(has_note(notes, "1 faces of primitives without normals get their faces' normals"));
  CHECK(has_note(notes, "1 repeated"));
}

TEST_CASE("glTF scene: every primitive with vertex normals keeps vertex normals; a non-unit quaternion is a rotation", "[gltf][scene]") {
  Built b = two_meshes(true);
  b.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  // 90 degrees about x, the quaternion scaled by 3 (glTF asks for unit length; read as the rotation).
  b.doc["nodes"] = json::array({{{"rotation", {3 * std::sqrt(0.5), 0, 0, 3 * std::sqrt(0.5)}}, {"mesh", 0}}, {{"mesh", 1}}});
  std::vector<std::string> notes;
  const Mesh m = world_of(b, notes);
  REQUIRE(m.has_vertex_normals());
  REQUIRE_FALSE(m.has_corner_normals());
  require_near(m.position(2), {0, 0, 1});  // (0,1,0) turned about x
  require_near(get3(m.vertex_normals, 0), {0, -1, 0});  // +z turned about x
  require_near(m.position(3), {0, 0, 5});
  CHECK(face_cross(m, 0).y < 0);
}

TEST_CASE("glTF scene: a document without scenes places its root nodes; bad node values are one error naming the path", "[gltf][scene]") {
  Built b = two_meshes();
  b.doc.erase("scene");
  b.doc.erase("scenes");
  b.doc["nodes"] = json::array({{{"translation", {0, 0, 1}}, {"children", {1}}}, {{"mesh", 0}}, {{"mesh", 1}, {"translation", {1, 1, 1}}}});
  std::vector<std::string> notes;
  const Mesh m = world_of(b, notes);
  REQUIRE(m.num_faces() == 2);
  require_near(m.position(0), {0, 0, 1});
  require_near(m.position(3), {1, 1, 6});

  for (const json& bad : {json{{"rotation", {0, 0, 0, 0}}, {"mesh", 0}}, json{{"scale", {1, 1}}, {"mesh", 0}},
                          json{{"translation", {0, "x", 0}}, {"mesh", 0}}, json{{"matrix", {1, 0, 0}}, {"mesh", 0}}}) {
    Built c = two_meshes();
    c.doc["nodes"] = json::array({bad});
    std::vector<std::string> n;
    try {
      world_of(c, n);
      FAIL("accepted " << bad.dump());
    } catch (const Error& e) {
      const std::string what = e.what();
      CHECK(what.find("scene.glb") != std::string::npos);
      CHECK(what.find("nodes[0].") != std::string::npos);
    }
  }
}

TEST_CASE("glTF scene: EXT_mesh_gpu_instancing places the mesh once per instance, by node * T R S", "[gltf][scene]") {
  // xcorpus4: glTF-Blender-IO's 24_gpu_instancing.gltf (1899 teapots on 2 nodes) became 2 teapots
  // in every world-space output, silently. Positions by hand: instance 0 only the node's
  // translation; instance 1 p -> (10, 0, 0) + (0, 0, 3) + R_z(90) (2 p).
  Built b = two_meshes();
  const double h = std::sqrt(0.5);
  const int t = float_accessor(b, {0, 0, 0, 0, 0, 3}, "VEC3", 3);
  const int r = float_accessor(b, {0, 0, 0, 1, 0, 0, float(h), float(h)}, "VEC4", 4);
  const int s = float_accessor(b, {1, 1, 1, 2, 2, 2}, "VEC3", 3);
  b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  b.doc["nodes"] = json::array({{{"mesh", 0}, {"translation", {10, 0, 0}},
                                 {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t}, {"ROTATION", r}, {"SCALE", s}}}}}}}}});
  std::vector<std::string> notes;
  const Mesh m = world_of(b, notes);
  REQUIRE(m.num_faces() == 3);  // two instances of mesh 0, mesh 1 once in object space
  require_near(m.position(0), {10, 0, 0});
  require_near(m.position(1), {11, 0, 0});
  require_near(m.position(2), {10, 1, 0});
  require_near(m.position(3), {10, 0, 3});
  require_near(m.position(4), {10, 2, 3});
  require_near(m.position(5), {8, 0, 3});
  CHECK(face_cross(m, 1).z > 0);  // a rotation and a positive scale keep the face up
  CHECK(has_note(notes, "2 of them EXT_mesh_gpu_instancing instances"));

  // Only TRANSLATION: rotation and scale identity.
  Built c = two_meshes();
  const int t2 = float_accessor(c, {0, 0, 0, 5, 0, 0, 0, 5, 0}, "VEC3", 3);
  c.doc["nodes"] = json::array({{{"mesh", 0}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t2}}}}}}}}});
  std::vector<std::string> n2;
  const Mesh m2 = world_of(c, n2);
  REQUIRE(m2.num_faces() == 4);
  require_near(m2.position(4), {6, 0, 0});
  require_near(m2.position(8), {0, 6, 0});

  // Attributes of different counts: one error naming the file and the JSON path.
  Built d = two_meshes();
  const int t3 = float_accessor(d, {0, 0, 0, 5, 0, 0, 0, 5, 0}, "VEC3", 3);
  const int s3 = float_accessor(d, {1, 1, 1, 2, 2, 2}, "VEC3", 3);
  d.doc["nodes"] = json::array({{{"mesh", 0}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t3}, {"SCALE", s3}}}}}}}}});
  std::vector<std::string> n3;
  try {
    world_of(d, n3);
    FAIL("accepted instance attributes of 3 and 2 elements");
  } catch (const Error& e) {
    const std::string what = e.what();
    CHECK(what.find("scene.glb") != std::string::npos);
    CHECK(what.find("nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE: 2 instances, not 3") != std::string::npos);
  }
}

TEST_CASE("glTF scene: read_mesh gives the world-space mesh", "[gltf][scene]") {
  Built b = two_meshes();
  b.doc["scenes"] = json::array({{{"nodes", {0}}}});
  b.doc["nodes"] = json::array({{{"translation", {0, 0, -5}}, {"mesh", 1}}});
  ReadInfo info;
  const std::string glb = b.glb();
  const Mesh m = read_mesh_from_memory(glb, Format::Gltf, "scene.glb", &info);
  REQUIRE(m.num_faces() == 2);
  require_near(m.position(0), {0, 0, 0});  // mesh 0 in no node: as read
  require_near(m.position(3), {0, 0, 0});  // mesh 1 at z = 5 moved by -5
}

// mode5.gltf's shape (412 primitives on 54 shared POSITION accessors): flattened into one mesh,
// each primitive instance must carry the vertices its faces use, not the whole shared accessor
// (that wrote 104,696 vertices for 3,610 used); a vertex no primitive uses is written once.
TEST_CASE("glTF scene: primitives sharing one POSITION accessor carry the vertices they use; an unused one once",
          "[gltf][scene]") {
  Built b = base_doc();
  // 6 vertices with colours: A uses 0 1 2, B uses 1 3 2, vertex 4 and 5 by nobody
  const int pos = float_accessor(b, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 7, 7, 7, 8, 8, 8}, "VEC3", 3, true);
  const int col = float_accessor(b, {0.1f, 0, 0, 0.2f, 0, 0, 0.3f, 0, 0, 0.4f, 0, 0, 0.5f, 0, 0, 0.6f, 0, 0}, "VEC3", 3);
  auto indices = [&](const std::vector<std::uint16_t>& ix) {
    return b.accessor({{"bufferView", b.view(bytes_of(ix))}, {"componentType", 5123}, {"count", ix.size()}, {"type", "SCALAR"}});
  };
  const int ia = indices({0, 1, 2}), ib = indices({1, 3, 2});
  const json attrs = {{"POSITION", pos}, {"COLOR_0", col}};
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", attrs}, {"indices", ia}},
                                                              {{"attributes", attrs}, {"indices", ib}}})}}});
  // the mesh shown twice: at the origin and moved by +10 in x
  b.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  b.doc["nodes"] = json::array({{{"mesh", 0}}, {{"mesh", 0}, {"translation", {10, 0, 0}}}});
  std::vector<std::string> notes;
  const Mesh m = world_of(b, notes);
  REQUIRE(m.num_faces() == 4);
  // by hand: A's first instance 3 used + the 2 nobody uses, its second 3; B's two 3 + 3
  CHECK(m.num_vertices() == 14);
  std::vector<bool> used(m.num_vertices(), false);
  for (std::uint32_t v : m.corner_vertex) used[v] = true;
  CHECK(std::count(used.begin(), used.end(), false) == 2);  // 4 and 5, once (not once per instance)
  // every corner keeps its position and colour (the colour names the vertex it came from);
  // faces in the order primitives, then their instances: A at 0, A at +10, B at 0, B at +10
  const double want_red[4][3] = {{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, {0.2, 0.4, 0.3}, {0.2, 0.4, 0.3}};
  const Vec3d want_pos[4][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                {{10, 0, 0}, {11, 0, 0}, {10, 1, 0}},
                                {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                {{11, 0, 0}, {11, 1, 0}, {10, 1, 0}}};
  REQUIRE(m.color_channels >= 3);
  for (std::size_t f = 0; f < 4; ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t v = m.corner_vertex[3 * f + k];
      require_near(m.position(v), want_pos[f][k]);
      CHECK(m.vertex_colors[v * std::size_t(m.color_channels)] == Approx(want_red[f][k]).margin(1e-6));
    }
  CHECK(has_note(notes, "10 vertex copies not written"));
}

TEST_CASE("glTF write: per-corner texture coordinates become TEXCOORD_0 (vertices split, v flipped) and read back", "[gltf][write]") {
  // A quad of two triangles whose shared diagonal has a seam: vertex 0 has (0, 0) in face 0 and
  // (0.5, 0.25) in face 1. Four vertices, five distinct (vertex, texture coordinate) pairs.
  Mesh m;
  for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{1, 1, 0}, Vec3d{0, 1, 0}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.texcoords = {0, 0, 1, 0, 1, 1, 0.5, 0.25, 0, 1};
  m.corner_texcoord_index = {0, 1, 2, 3, 2, 4};
  WriteOptions o;
  o.format = Format::Gltf;
  const std::string glb = write_mesh_to_memory(m, o);
  // The file read by hand (glTF 2.0, 5): JSON chunk, then the BIN chunk after it.
  std::uint32_t json_len = 0;
  std::memcpy(&json_len, glb.data() + 12, 4);
  const json j = json::parse(glb.substr(20, json_len));
  const std::string bin = glb.substr(20 + json_len + 8);
  const json& prim = j["meshes"][0]["primitives"][0];
  REQUIRE(prim["attributes"].contains("TEXCOORD_0"));
  const json& acc = j["accessors"][prim["attributes"]["TEXCOORD_0"].get<std::size_t>()];
  CHECK(acc["type"] == "VEC2");
  CHECK(acc["componentType"] == 5126);
  REQUIRE(acc["count"] == 5);
  const json& view = j["bufferViews"][acc["bufferView"].get<std::size_t>()];
  const std::size_t at = view.value("byteOffset", std::size_t(0)) + acc.value("byteOffset", std::size_t(0));
  const std::size_t stride = view.value("byteStride", std::size_t(8));
  std::vector<std::pair<float, float>> uv;
  for (std::size_t i = 0; i < 5; ++i) {
    float u, v;
    std::memcpy(&u, bin.data() + at + i * stride, 4);
    std::memcpy(&v, bin.data() + at + i * stride + 4, 4);
    uv.push_back({u, v});
  }
  std::sort(uv.begin(), uv.end());
  const std::vector<std::pair<float, float>> flipped = {{0, 0}, {0, 1}, {0.5f, 0.75f}, {1, 0}, {1, 1}};  // (u, 1 - v)
  CHECK(uv == flipped);
  // Read back: the world mesh (one primitive, no node transform) gives each corner its (u, v).
  const Mesh back = read_mesh_from_memory(glb, Format::Gltf, "t.glb");
  REQUIRE(back.has_texcoords());
  REQUIRE(back.num_corners() == 6);
  for (std::size_t c = 0; c < 6; ++c) {
    const std::uint32_t t = back.corner_texcoord_index[c], t0 = m.corner_texcoord_index[c];
    CHECK(back.position(back.corner_vertex[c]) == m.position(m.corner_vertex[c]));
    CHECK(back.texcoords[2 * t] == Approx(m.texcoords[2 * t0]).margin(1e-7));
    CHECK(back.texcoords[2 * t + 1] == Approx(m.texcoords[2 * t0 + 1]).margin(1e-7));
  }
}
