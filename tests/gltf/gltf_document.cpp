// Tests of gltf/gltf_document (read_gltf, write_gltf), gltf/gltf_transform and gltf/gltf_lights.
// Every file is built here, byte by byte (a small GLB writer independent of write_gltf), so that
// what is checked is the spec's layout, not our writer's idea of it.
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/gltf/gltf_lights.h>
#include <shadetool/gltf/gltf_morph_normals.h>
#include <shadetool/gltf/gltf_transform.h>

#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

#include <shadetool/core/math_constants.h>
#include "gltf_test_util.h"
#include "io/io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;
using namespace shadetool::gltftest;
using nlohmann::json;

namespace {

// Quad (0,0) (1,0) (1,1) (0,1) in z = 0 as two counter-clockwise triangles.
const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

std::string quad_glb(int index_type, int mode = 4) {
  Built b = base_doc();
  const int pos = float_accessor(b, kQuad, "VEC3", 3, true);
  const std::vector<std::uint32_t> tri = mode == 4 ? std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}
                                         : mode == 5 ? std::vector<std::uint32_t>{1, 2, 0, 3}  // strip
                                                     : std::vector<std::uint32_t>{0, 1, 2, 3};  // fan
  std::string raw;
  for (std::uint32_t i : tri) {
    if (index_type == 5121) raw += char(i);
    else if (index_type == 5123) { const std::uint16_t s = std::uint16_t(i); raw.append(reinterpret_cast<const char*>(&s), 2); }
    else raw.append(reinterpret_cast<const char*>(&i), 4);
  }
  const int idx = b.accessor({{"bufferView", b.view(raw)}, {"componentType", index_type}, {"count", tri.size()}, {"type", "SCALAR"}});
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}, {"mode", mode}}})}}});
  return b.glb();
}

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

json glb_json(const std::string& glb) { return json::parse(glb.substr(20, u32_at(glb, 12))); }

// The BIN chunk's bytes of a GLB built by make_glb (the second chunk, after its 8-byte header).
std::string glb_bin(const std::string& glb) { return glb.substr(20 + u32_at(glb, 12) + 8); }

// Signed area vector (z) of triangle t of a mesh in the plane z = 0.
double triangle_z(const Mesh& m, std::size_t t) {
  const Vec3d a = m.position(m.corner_vertex[3 * t]), b = m.position(m.corner_vertex[3 * t + 1]),
              c = m.position(m.corner_vertex[3 * t + 2]);
  return cross(b - a, c - a).z;
}

}  // namespace

TEST_CASE("glTF read: every index type gives the same triangles", "[gltf]") {
  for (int ct : {5121, 5123, 5125}) {
    INFO("componentType " << ct);
    const GltfDocument d = read_gltf(quad_glb(ct), "quad.glb");
    REQUIRE(d.primitives.size() == 1);
    const Mesh& m = d.primitives[0].mesh;
    CHECK(m.num_vertices() == 4);
    CHECK(m.corner_vertex == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
    CHECK(m.positions[3] == 1.0);
  }
}

TEST_CASE("glTF read: strips and fans unroll to counter-clockwise triangles (spec 3.7.2.1)", "[gltf]") {
  // Strip 1 2 0 3: triangles {1,2,0} and {2,3,0} (odd triangle order swapped); fan 0 1 2 3:
  // {1,2,0} and {2,3,0}. Both cover the quad, both counter-clockwise seen from +z.
  for (int mode : {5, 6}) {
    INFO("mode " << mode);
    const Mesh m = read_gltf(quad_glb(5123, mode), "q.glb").primitives[0].mesh;
    REQUIRE(m.num_faces() == 2);
    CHECK(triangle_z(m, 0) == Approx(1.0));
    CHECK(triangle_z(m, 1) == Approx(1.0));
  }
}

TEST_CASE("glTF read: interleaved, sparse and quantized accessors", "[gltf]") {
  Built b = base_doc();
  // Interleaved: x y z + one padding float (stride 16), vertex 2 replaced by a sparse value.
  std::vector<float> inter;
  for (std::size_t v = 0; v < 4; ++v) inter.insert(inter.end(), {kQuad[3 * v], kQuad[3 * v + 1], kQuad[3 * v + 2], 99.0f});
  const int iv = b.view(bytes_of(inter), 16);
  const int si = b.view(bytes_of(std::vector<std::uint16_t>{2}));
  const int sv = b.view(bytes_of(std::vector<float>{2, 2, 0.5f}));
  const int pos = b.accessor({{"bufferView", iv}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                              {"min", {0, 0, 0}}, {"max", {2, 2, 0.5}},
                              {"sparse", {{"count", 1}, {"indices", {{"bufferView", si}, {"componentType", 5123}}},
                                          {"values", {{"bufferView", sv}}}}}});
  // Quantized: NORMAL as normalised BYTE (127 -> 1, -128 -> -1 clamped), 4-byte stride.
  const std::string nb = std::string("\x00\x00\x7f\x00", 4) + std::string("\x00\x00\x80\x00", 4) + std::string("\x00\x40\x00\x00", 4) +
                         std::string("\x7f\x00\x00\x00", 4);
  const int nor = b.accessor({{"bufferView", b.view(nb, 4)}, {"componentType", 5120}, {"normalized", true}, {"count", 4}, {"type", "VEC3"}});
  b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", pos}, {"NORMAL", nor}}}}})}}});
  // Non-indexed TRIANGLES need a multiple of 3 vertices: use mode 6 (fan over 4 vertices).
  b.doc["meshes"][0]["primitives"][0]["mode"] = 6;
  const Mesh m = read_gltf(b.glb(), "q.glb").primitives[0].mesh;
  CHECK(m.position(1).x == 1.0);
  CHECK(m.position(2).x == 2.0);  // sparse substitution
  CHECK(m.position(2).z == 0.5);
  CHECK(m.position(3).y == 1.0);  // stride skipped the padding float
  CHECK(m.vertex_normals[2] == 1.0);
  CHECK(m.vertex_normals[5] == -1.0);  // -128 / 127 clamped to -1 (spec)
  CHECK(m.vertex_normals[7] == Approx(64.0 / 127.0));
}

TEST_CASE("glTF write: unchanged document writes the same data, a well-formed GLB", "[gltf][write]") {
  const std::string in = quad_glb(5123);
  const GltfDocument d = read_gltf(in, "q.glb");
  GltfWriteResult r;
  const std::string out = write_gltf(d, true, "out.glb", r);
  // GLB layout (spec 5): magic, version 2, total length; JSON chunk first, 4-byte aligned and
  // space-padded; BIN chunk second, 4-byte aligned.
  REQUIRE(out.size() >= 28);
  CHECK(out.substr(0, 4) == "glTF");
  CHECK(u32_at(out, 4) == 2);
  CHECK(u32_at(out, 8) == out.size());
  const std::uint32_t jlen = u32_at(out, 12);
  CHECK(jlen % 4 == 0);
  CHECK(u32_at(out, 16) == 0x4E4F534Au);
  CHECK(u32_at(out, 20 + jlen + 4) == 0x004E4942u);
  CHECK(u32_at(out, 20 + jlen) % 4 == 0);
  CHECK(20 + jlen + 8 + u32_at(out, 20 + jlen) == out.size());
  // Nothing changed: no accessor added, the primitive's references as read, same mesh back.
  const json jo = glb_json(out), ji = glb_json(in);
  CHECK(jo["accessors"].size() == ji["accessors"].size());
  CHECK(jo["meshes"] == ji["meshes"]);
  CHECK(jo["buffers"][0].count("uri") == 0);
  const GltfDocument back = read_gltf(out, "out.glb");
  CHECK(back.primitives[0].mesh.positions == d.primitives[0].mesh.positions);
  CHECK(back.primitives[0].mesh.corner_vertex == d.primitives[0].mesh.corner_vertex);
}

TEST_CASE("glTF write: new normals are a new float VEC3 accessor; corner normals split vertices", "[gltf][write]") {
  GltfDocument d = read_gltf(quad_glb(5123), "q.glb");
  Mesh& m = d.primitives[0].mesh;
  m.vertex_normals.assign(12, 0.0);
  for (std::size_t v = 0; v < 4; ++v) m.vertex_normals[3 * v + 2] = 1.0;
  GltfWriteResult r;
  json j = glb_json(write_gltf(d, true, "o.glb", r));
  const json& prim = j["meshes"][0]["primitives"][0];
  REQUIRE(prim["attributes"].contains("NORMAL"));
  const json& na = j["accessors"][prim["attributes"]["NORMAL"].get<std::size_t>()];
  CHECK(na["componentType"] == 5126);
  CHECK(na["type"] == "VEC3");
  CHECK(na["count"] == 4);
  CHECK(prim["indices"] == 1);  // faces unchanged: the indices as read

  // Corner normals, one per face: vertices 0 and 2 are shared by both faces and split.
  m.vertex_normals.clear();
  m.corner_normals = {0, 0, 1, 0, 0, -1};
  m.corner_normal_index = {0, 0, 0, 1, 1, 1};
  const GltfDocument back = read_gltf(write_gltf(d, true, "o.glb", r), "o.glb");
  const Mesh& bm = back.primitives[0].mesh;
  CHECK(bm.num_vertices() == 6);
  CHECK(r.split_vertices == 2);
  for (std::size_t c = 0; c < 6; ++c) CHECK(bm.vertex_normals[3 * bm.corner_vertex[c] + 2] == (c < 3 ? 1.0 : -1.0));
}

TEST_CASE("glTF write: .gltf text output embeds the buffer as a data URI and reads back", "[gltf][write]") {
  const GltfDocument d = read_gltf(quad_glb(5125), "q.glb");
  GltfWriteResult r;
  const std::string text = write_gltf(d, false, "o.gltf", r);
  const json j = json::parse(text);
  REQUIRE(j["buffers"].size() == 1);
  CHECK(j["buffers"][0]["uri"].get<std::string>().rfind("data:application/octet-stream;base64,", 0) == 0);
  CHECK(read_gltf(text, "o.gltf").primitives[0].mesh.corner_vertex == d.primitives[0].mesh.corner_vertex);
}

TEST_CASE("glTF transform: TANGENT by A, renormalised, w flipped under a mirror", "[gltf][transform]") {
  GltfPrimitive p;
  p.mesh.positions = {0, 0, 0};
  p.tangents = {1, 0, 0, 1, 0, 1, 0, -1};
  p.targets.resize(1);
  p.targets[0].position_deltas = {1, 2, 3, 0, 0, 0};
  Affine3d M;
  M.A = Mat3d::diagonal(-2, 3, 1);  // a mirror (det -6)
  M.t = {5, 5, 5};                  // translation does not act on vectors
  const GltfTransformReport rep = transform_gltf_extras(p, M, false);
  CHECK(rep.tangents == 2);
  CHECK(p.tangents == std::vector<double>{-1, 0, 0, -1, 0, 1, 0, 1});
  CHECK(p.targets[0].position_deltas == std::vector<double>{-2, 6, 3, 0, 0, 0});
}

TEST_CASE("glTF lights: KHR_lights_punctual and the first camera in world space", "[gltf][lighting]") {
  Built b = base_doc();
  const int pos = float_accessor(b, kQuad, "VEC3", 3, true);
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", pos}}}, {"mode", 6}}})}}});
  // Node 0: the mesh, translated by (1,2,3). Node 1: a sun rotated 90 degrees about +x (its -Z
  // becomes +Y... R_x(90) (0,0,-1) = (0,1,0)). Node 2: a point lamp at (0,4,0). Node 3: camera at
  // (0,0,10).
  const double h = std::sqrt(0.5);
  b.doc["nodes"] = json::array({{{"mesh", 0}, {"translation", {1, 2, 3}}},
                                {{"rotation", {h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                                {{"translation", {0, 4, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
                                {{"camera", 0}, {"translation", {0, 0, 10}}}});
  b.doc["scenes"] = json::array({{{"nodes", {0, 1, 2, 3}}}});
  b.doc["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 1}, {"znear", 0.1}}}}});
  b.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({{{"type", "directional"}, {"intensity", 3}},
                                                                          {{"type", "spot"}, {"color", {1, 0.5, 0}},
                                                                           {"spot", {{"outerConeAngle", kPi / 6}}}}})}}}};
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  const GltfDocument d = read_gltf(b.glb(), "l.glb");
  std::vector<std::string> notes;
  const Scene s = gltf_scene(d, d.primitives[0], notes);
  CHECK(s.world_from_object.t.x == 1.0);
  CHECK(s.world_from_object.t.z == 3.0);
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].type == LightType::Directional);
  CHECK(s.lights[0].direction.y == Approx(1.0));
  CHECK(s.lights[0].direction.z == Approx(0.0).margin(1e-12));
  CHECK(s.lights[0].diffuse.x == 3.0);
  CHECK(s.lights[1].type == LightType::Spot);
  CHECK(s.lights[1].position.y == 4.0);
  CHECK(s.lights[1].cutoff_degrees == Approx(30.0));
  CHECK(s.lights[1].attenuation.z == 1.0);  // inverse square
  CHECK(s.lights[1].attenuation.x == 0.0);
  CHECK(s.lights[1].diffuse.y == 0.5);
  REQUIRE(s.has_camera);
  CHECK(s.camera_from_world.t.z == -10.0);  // the eye at (0,0,10) maps to the origin
}

TEST_CASE("glTF bad input: one message naming the JSON path", "[gltf][bad]") {
  std::string glb = quad_glb(5123);
  json j = glb_json(glb);
  std::string bin = glb_bin(glb);
  SECTION("index out of range") {
    std::vector<std::uint16_t> idx = {0, 1, 2, 0, 2, 9};
    std::memcpy(&bin[48], idx.data(), 12);
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }),
               Catch::Contains("x.glb: meshes[0].primitives[0].indices: index 9"));
  }
  SECTION("accessor beyond its view") {
    j["accessors"][0]["count"] = 5;
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }), Catch::Contains("x.glb: accessors[0]"));
  }
  SECTION("indices of a float type") {
    j["accessors"][1]["componentType"] = 5126;
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }), Catch::Contains("accessors[1].componentType"));
  }
  SECTION("a node that is its own ancestor") {
    j["nodes"] = json::array({{{"children", {1}}}, {{"children", {0}}}});
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }), Catch::Contains("x.glb: nodes["));
  }
  SECTION("Inf in POSITION") {
    const float inf = std::numeric_limits<float>::infinity();
    std::memcpy(&bin[12], &inf, 4);
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }),
               Catch::Contains("meshes[0].primitives[0].attributes.POSITION: vertex 1"));
  }
  // What tinygltf refuses in its own words, named by its JSON path first: glTF 2.0 5.11.4
  // (byteStride 4..252, a multiple of 4), GLB 4.4.3.3 (buffer 0 in the BIN chunk), 5.18 (an image
  // has a uri or a bufferView).
  SECTION("byteStride not a multiple of 4") {
    j["bufferViews"][0]["byteStride"] = 6;
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }),
               Catch::Contains("x.glb: bufferViews[0].byteStride: 6 is not a multiple of 4"));
  }
  SECTION("byteStride above 252") {
    j["bufferViews"][0]["byteStride"] = 256;
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }), Catch::Contains("bufferViews[0].byteStride: 256"));
  }
  SECTION("buffer 0 longer than the BIN chunk") {
    j["buffers"][0]["byteLength"] = bin.size() + 64;
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }),
               Catch::Contains("x.glb: buffers[0].byteLength: " + std::to_string(bin.size() + 64) +
                               " bytes declared, but the GLB's BIN chunk holds " + std::to_string(bin.size())));
  }
  SECTION("an image with neither uri nor bufferView") {
    j["images"] = json::array({{{"name", "lost"}}});
    CHECK_THAT(error_of([&] { read_gltf(make_glb(j, bin), "x.glb"); }), Catch::Contains("x.glb: images[0]: neither uri nor bufferView"));
  }
}

TEST_CASE("glTF morph targets: NORMAL deltas from displaced positions", "[gltf][normals]") {
  // A unit right triangle in z = 0 (normal +z). Target 0 translates it (normal unchanged: delta
  // 0); target 1 lifts vertex 1 to z = 1, tilting the plane to normal (-1, 0, 1)/sqrt 2 at every
  // vertex of the single face.
  GltfPrimitive p;
  p.mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  p.mesh.add_face({0, 1, 2});
  p.mesh.vertex_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  p.targets.resize(2);
  p.targets[0].position_deltas = {5, 5, 5, 5, 5, 5, 5, 5, 5};
  p.targets[1].position_deltas = {0, 0, 0, 0, 0, 1, 0, 0, 0};
  // The "normals computation": the face normal at every vertex (one face; exact).
  auto face_normal = [](Mesh& m) {
    const Vec3d a = m.position(0), b = m.position(1), c = m.position(2);
    const Vec3d n = cross(b - a, c - a);
    const double l = length(n);
    m.vertex_normals.clear();
    for (int v = 0; v < 3; ++v) m.vertex_normals.insert(m.vertex_normals.end(), {n.x / l, n.y / l, n.z / l});
  };
  CHECK(recompute_morph_normal_deltas(p, face_normal) == 2);
  for (double d : p.targets[0].normal_deltas) CHECK(d == Approx(0.0).margin(1e-15));
  const double h = std::sqrt(0.5);
  for (int v = 0; v < 3; ++v) {
    CHECK(p.targets[1].normal_deltas[3 * v] == Approx(-h));
    CHECK(p.targets[1].normal_deltas[3 * v + 1] == Approx(0.0).margin(1e-15));
    CHECK(p.targets[1].normal_deltas[3 * v + 2] == Approx(h - 1));
  }
  // Corner normals: nothing recomputed (the caller says so).
  p.mesh.corner_normal_index = {0, 0, 0};
  p.mesh.corner_normals = {0, 0, 1};
  CHECK(recompute_morph_normal_deltas(p, face_normal) == 0);
}

namespace {

// A GLB of an n x n grid of vertices in z = 0 (2 (n-1)^2 triangles, uint32 indices), with a
// TEXCOORD_0 that only passes through; over 1 MiB for n = 300, so read_file_bytes maps it.
std::string grid_glb(int n) {
  Built b = base_doc();
  std::vector<float> p, uv;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      p.insert(p.end(), {float(k), float(i) * 0.5f, 0.0f});
      uv.insert(uv.end(), {float(k) / float(n), float(i) / float(n)});
    }
  std::vector<std::uint32_t> idx;
  for (int i = 0; i + 1 < n; ++i)
    for (int k = 0; k + 1 < n; ++k) {
      const std::uint32_t a = std::uint32_t(i * n + k), c = a + std::uint32_t(n);
      idx.insert(idx.end(), {a, a + 1, c + 1, a, c + 1, c});
    }
  const int pos = float_accessor(b, p, "VEC3", 3, true);
  const int tex = float_accessor(b, uv, "VEC2", 2);
  const int ind = b.accessor({{"bufferView", b.view(bytes_of(idx))}, {"componentType", 5125}, {"count", idx.size()}, {"type", "SCALAR"}});
  const json primitive = {{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", tex}}}, {"indices", ind}};
  b.doc["meshes"] = json::array({{{"primitives", json::array({primitive})}}});
  return b.glb();
}

// What a document is, for comparing two reads: its meshes, and what the writer makes of it
// unchanged and with the positions moved (new accessors appended after the buffers as read).
std::vector<std::string> written(GltfDocument d) {
  std::vector<std::string> out;
  GltfWriteResult r;
  out.push_back(write_gltf(d, true, "o.glb", r));
  out.push_back(write_gltf(d, false, "o.gltf", r));
  for (GltfPrimitive& p : d.primitives)
    for (double& x : p.mesh.positions) x += 0.25;
  out.push_back(write_gltf(d, true, "o.glb", r));
  return out;
}

}  // namespace

TEST_CASE("glTF read from a file: the BIN chunk read in place gives the document tinygltf's copy gives", "[gltf]") {
  // Truth: read_gltf(string_view), where tinygltf copies every buffer into its model as it always
  // has. read_gltf(FileBytes&&) reads buffer 0 where it lies in the file; the meshes and every
  // byte written from them must be the same, for a mapped file and for a small one read into memory.
  ScratchDir dir;
  for (int n : {3, 300}) {
    INFO("grid " << n << " x " << n);
    const std::string glb = grid_glb(n);
    const std::string path = dir / ("grid" + std::to_string(n) + ".glb");
    write_file(path, glb);
    const GltfDocument copied = read_gltf(glb, path);
    const GltfDocument in_place = read_gltf(io::read_file_bytes(path), path);
    REQUIRE(in_place.primitives.size() == 1);
    CHECK(in_place.primitives[0].mesh.positions == copied.primitives[0].mesh.positions);
    CHECK(in_place.primitives[0].mesh.corner_vertex == copied.primitives[0].mesh.corner_vertex);
    CHECK(in_place.primitives[0].mesh.num_faces() == std::size_t(2 * (n - 1) * (n - 1)));
    CHECK(written(in_place) == written(copied));
  }
}

TEST_CASE("glTF read from a file: a bad BIN chunk or index gives tinygltf's message either way", "[gltf][bad]") {
  // Cases the in-place read must not accept or word differently: it leaves them to tinygltf.
  ScratchDir dir;
  const std::string glb = quad_glb(5123);
  const json j = glb_json(glb);
  const std::string bin = glb_bin(glb);
  std::vector<std::pair<std::string, std::string>> cases;
  {
    json k = j;
    k["buffers"][0]["byteLength"] = bin.size() + 64;  // longer than the BIN chunk
    cases.emplace_back("byteLength beyond the chunk", make_glb(k, bin));
  }
  {
    std::string g = glb;  // the BIN chunk's type is not BIN
    g[20 + u32_at(glb, 12) + 4] = 'X';
    cases.emplace_back("chunk type", g);
  }
  {
    std::string b = bin;  // index 9 of 4 vertices
    const std::uint16_t nine = 9;
    std::memcpy(&b[48 + 10], &nine, 2);
    cases.emplace_back("index out of range", make_glb(j, b));
  }
  {
    json k = j;  // a second buffer without a uri: tinygltf gives it the BIN chunk too
    k["buffers"].push_back({{"byteLength", 4}});
    cases.emplace_back("two buffers in the BIN chunk", make_glb(k, bin));
  }
  for (const auto& [what, bytes] : cases) {
    INFO(what);
    const std::string path = dir / "bad.glb";
    write_file(path, bytes);
    const std::string expected = error_of([&] { read_gltf(bytes, path); });
    const std::string got = error_of([&] { read_gltf(io::read_file_bytes(path), path); });
    CHECK(got == expected);
    if (what == "index out of range") CHECK_THAT(expected, Catch::Contains("index 9"));
  }
}

TEST_CASE("glTF read: external buffers by percent-encoded uri, longer than byteLength, or short", "[gltf]") {
  // Truth: the same quad read from a GLB. A file longer than byteLength is valid glTF (the
  // validator flags only a shorter one); its first byteLength bytes are the buffer.
  ScratchDir dir;
  const std::string glb = quad_glb(5123);
  const Mesh expected = read_gltf(glb, "q.glb").primitives.at(0).mesh;
  json j = glb_json(glb);
  const std::string bin = glb_bin(glb);
  j["buffers"][0]["uri"] = "quad%20data.bin";  // the file "quad data.bin"
  j["buffers"][0]["byteLength"] = bin.size();
  const std::string path = dir / "quad.gltf";
  write_file(path, j.dump());
  SECTION("percent-encoded uri, exact size") {
    write_file(dir / "quad data.bin", bin);
    const GltfDocument doc = read_gltf(io::read_file_bytes(path), path);
    CHECK(doc.primitives.at(0).mesh.positions == expected.positions);
    CHECK(doc.primitives.at(0).mesh.corner_vertex == expected.corner_vertex);
  }
  SECTION("a file 100 bytes longer than byteLength") {
    write_file(dir / "quad data.bin", bin + std::string(100, '\x7f'));
    const GltfDocument doc = read_gltf(io::read_file_bytes(path), path);
    CHECK(doc.primitives.at(0).mesh.positions == expected.positions);
    CHECK(doc.primitives.at(0).mesh.corner_vertex == expected.corner_vertex);
  }
  SECTION("a file shorter than byteLength: refused, named by its path") {
    write_file(dir / "quad data.bin", bin.substr(0, 40));
    CHECK_THAT(error_of([&] { read_gltf(io::read_file_bytes(path), path); }),
               Catch::Contains("buffers[0].byteLength: " + std::to_string(bin.size()) +
                               " bytes declared, but 'quad%20data.bin' holds 40"));
  }
}

TEST_CASE("glTF read: indices without a bufferView are zeros, then their sparse values (5.1.1)", "[gltf]") {
  // Truth: the same quad with its indices in a buffer view. tinygltf's loader refuses such indices;
  // the reader gives it the JSON without them and reads them itself.
  const std::string glb = quad_glb(5123);
  const Mesh expected = read_gltf(glb, "q.glb").primitives.at(0).mesh;
  json j = glb_json(glb);
  std::string bin = glb_bin(glb);
  SECTION("sparse values give the triangles") {
    const std::size_t at = bin.size();
    bin += std::string("\0\1\2\3\4\5\0\0", 8);  // sparse indices 0..5 (UNSIGNED_BYTE), padded
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 6}});
    j["buffers"][0]["byteLength"] = bin.size();
    j["accessors"][1].erase("bufferView");
    j["accessors"][1]["sparse"] = {{"count", 6},
                                   {"indices", {{"bufferView", int(j["bufferViews"].size()) - 1}, {"componentType", 5121}}},
                                   {"values", {{"bufferView", 1}}}};
    const GltfDocument doc = read_gltf(make_glb(j, bin), "q.glb");
    CHECK(doc.primitives.at(0).mesh.positions == expected.positions);
    CHECK(doc.primitives.at(0).mesh.corner_vertex == expected.corner_vertex);
  }
  SECTION("no sparse values: every index 0") {
    j["accessors"][1].erase("bufferView");
    const std::string message = error_of([&] {
      const GltfDocument doc = read_gltf(make_glb(j, bin), "q.glb");
      for (const auto& p : doc.primitives)
        for (std::uint32_t v : p.mesh.corner_vertex) CHECK(v == 0);
    });
    CHECK_THAT(message, !Catch::Contains("invalid bufferView"));
  }
}
