// compressed_fixtures.h: glTF files compressed by the libraries' own encoders (Draco's
// draco::Encoder, meshoptimizer's meshopt_encodeVertexBuffer/IndexBuffer), and the same mesh
// uncompressed, written here as GLB by hand (not by shadetool's writer): the truth the decoders
// are checked against (tests/gltf/gltf_compressed.cpp; tests/gltf/fixtures for gltf_cli.sh).
//
// The mesh: a 9 x 9 latitude-longitude grid on the unit sphere (81 vertices, 128 triangles), with
// NORMAL = position and TEXCOORD_0 = (u, v) of the grid. fixture_sphere uses its own pi: the
// fixtures do not depend on the library.
// Draco: attributes added TEXCOORD_0, NORMAL, POSITION with unique ids 10, 20, 5 (the extension's
// map, not the order, names them), no quantization (lossless). meshopt: one view per attribute
// and the indices, in a fallback buffer without a uri (EXT_meshopt_compression.fallback).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

namespace shadetool_test {

struct FixtureMesh {
  std::vector<float> positions, normals, uvs;  // #V by 3, #V by 3, #V by 2
  std::vector<std::uint32_t> indices;          // #F by 3
};

inline FixtureMesh fixture_sphere() {
  FixtureMesh m;
  const int n = 9;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      const double u = double(k) / (n - 1), v = double(i) / (n - 1);
      const double theta = 0.1 + 0.8 * pi * v, phi = 1.5 * pi * u;  // no pole, no seam: every vertex distinct
      const float p[3] = {float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))};
      m.positions.insert(m.positions.end(), p, p + 3);
      m.normals.insert(m.normals.end(), p, p + 3);
      m.uvs.push_back(float(u));
      m.uvs.push_back(float(v));
    }
  for (int i = 0; i + 1 < n; ++i)
    for (int k = 0; k + 1 < n; ++k) {
      const std::uint32_t a = std::uint32_t(i * n + k), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  return m;
}

inline std::string glb(const nlohmann::json& doc, const std::string& bin) {
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  std::string data = bin;
  while (data.size() % 4) data += '\0';
  std::string out;
  auto put = [&out](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  out += "glTF";
  put(2);
  put(std::uint32_t(12 + 8 + text.size() + (data.empty() ? 0 : 8 + data.size())));
  put(std::uint32_t(text.size()));
  put(0x4E4F534Au);
  out += text;
  if (!data.empty()) {
    put(std::uint32_t(data.size()));
    put(0x004E4942u);
    out += data;
  }
  return out;
}

inline nlohmann::json minmax(const std::vector<float>& v, int comps, bool max) {
  nlohmann::json out = nlohmann::json::array();
  for (int k = 0; k < comps; ++k) {
    float b = v[std::size_t(k)];
    for (std::size_t i = std::size_t(k); i < v.size(); i += std::size_t(comps)) b = max ? std::max(b, v[i]) : std::min(b, v[i]);
    out.push_back(double(b));
  }
  return out;
}

inline nlohmann::json scene_part() {
  return {{"asset", {{"version", "2.0"}, {"generator", "shadetool tests (hand-written)"}}},
          {"scene", 0}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", {{{"mesh", 0}}}}};
}

// The mesh uncompressed: POSITION 0, NORMAL 1, TEXCOORD_0 2, indices 3 (UNSIGNED_SHORT).
inline std::string plain_glb(const FixtureMesh& m) {
  nlohmann::json doc = scene_part();
  std::string bin;
  nlohmann::json views = nlohmann::json::array();
  auto add = [&](const void* p, std::size_t n, int target, int stride) {
    while (bin.size() % 4) bin += '\0';
    nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", n}, {"target", target}};
    if (stride) v["byteStride"] = stride;
    bin.append(static_cast<const char*>(p), n);
    views.push_back(v);
  };
  std::vector<std::uint16_t> idx(m.indices.begin(), m.indices.end());
  add(m.positions.data(), 4 * m.positions.size(), 34962, 12);
  add(m.normals.data(), 4 * m.normals.size(), 34962, 12);
  add(m.uvs.data(), 4 * m.uvs.size(), 34962, 8);
  add(idx.data(), 2 * idx.size(), 34963, 0);
  const std::size_t V = m.positions.size() / 3;
  doc["bufferViews"] = views;
  doc["accessors"] = {
      {{"bufferView", 0}, {"componentType", 5126}, {"count", V}, {"type", "VEC3"}, {"min", minmax(m.positions, 3, false)}, {"max", minmax(m.positions, 3, true)}},
      {{"bufferView", 1}, {"componentType", 5126}, {"count", V}, {"type", "VEC3"}},
      {{"bufferView", 2}, {"componentType", 5126}, {"count", V}, {"type", "VEC2"}},
      {{"bufferView", 3}, {"componentType", 5123}, {"count", idx.size()}, {"type", "SCALAR"}}};
  doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}}}}}};
  doc["buffers"] = {{{"byteLength", (bin.size() + 3) / 4 * 4}}};
  return glb(doc, bin);
}

// Draco: the accessors have no bufferView; the extension's bufferView holds the Draco mesh.
inline std::string draco_glb(const FixtureMesh& m) {
  const int F = int(m.indices.size() / 3);
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(F);
  const int uv = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  const int nor = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  for (int f = 0; f < F; ++f) {
    const std::uint32_t* c = &m.indices[3 * std::size_t(f)];
    builder.SetAttributeValuesForFace(uv, draco::FaceIndex(f), &m.uvs[2 * c[0]], &m.uvs[2 * c[1]], &m.uvs[2 * c[2]]);
    builder.SetAttributeValuesForFace(nor, draco::FaceIndex(f), &m.normals[3 * c[0]], &m.normals[3 * c[1]], &m.normals[3 * c[2]]);
    builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &m.positions[3 * c[0]], &m.positions[3 * c[1]], &m.positions[3 * c[2]]);
  }
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  mesh->attribute(uv)->set_unique_id(10);
  mesh->attribute(nor)->set_unique_id(20);
  mesh->attribute(pos)->set_unique_id(5);
  draco::Encoder encoder;
  encoder.SetSpeedOptions(5, 5);
  draco::EncoderBuffer out;
  if (!encoder.EncodeMeshToBuffer(*mesh, &out).ok()) return std::string();
  // The decoded point count (what the accessors must say) from Draco's own decoder.
  draco::DecoderBuffer in;
  in.Init(out.data(), out.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&in);
  if (!decoded.ok()) return std::string();
  const std::size_t points = decoded.value()->num_points();
  nlohmann::json doc = scene_part();
  doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", out.size()}}};
  doc["accessors"] = {
      {{"componentType", 5126}, {"count", points}, {"type", "VEC3"}, {"min", minmax(m.positions, 3, false)}, {"max", minmax(m.positions, 3, true)}},
      {{"componentType", 5126}, {"count", points}, {"type", "VEC3"}},
      {{"componentType", 5126}, {"count", points}, {"type", "VEC2"}},
      {{"componentType", 5123}, {"count", m.indices.size()}, {"type", "SCALAR"}}};
  doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3},
                                     {"extensions", {{"KHR_draco_mesh_compression",
                                                      {{"bufferView", 0}, {"attributes", {{"POSITION", 5}, {"NORMAL", 20}, {"TEXCOORD_0", 10}}}}}}}}}}}};
  doc["buffers"] = {{{"byteLength", (out.size() + 3) / 4 * 4}}};
  return glb(doc, std::string(out.data(), out.size()));
}

// meshopt: buffer 0 (the BIN chunk) holds the compressed streams; buffer 1, the fallback, has no
// uri and no bytes; each view lies in buffer 1 and says where its compressed bytes are.
// With `octahedral_normals`: NORMAL as 8-bit octahedral BYTE VEC3 (stride 4, normalized;
// KHR_mesh_quantization) through meshopt_encodeFilterOct, the view's filter OCTAHEDRAL.
inline std::string meshopt_glb(const FixtureMesh& m, bool octahedral_normals = false) {
  nlohmann::json doc = scene_part();
  doc["extensionsUsed"] = {"EXT_meshopt_compression"};
  doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  if (octahedral_normals) {
    doc["extensionsUsed"].push_back("KHR_mesh_quantization");
    doc["extensionsRequired"].push_back("KHR_mesh_quantization");
  }
  std::string bin;
  std::size_t fallback = 0;
  nlohmann::json views = nlohmann::json::array();
  const std::size_t V = m.positions.size() / 3;
  auto add_vertices = [&](const float* data, std::size_t stride) {
    std::vector<unsigned char> enc(meshopt_encodeVertexBufferBound(V, stride));
    enc.resize(meshopt_encodeVertexBuffer(enc.data(), enc.size(), data, V, stride));
    while (bin.size() % 4) bin += '\0';
    views.push_back({{"buffer", 1}, {"byteOffset", fallback}, {"byteLength", V * stride}, {"byteStride", stride}, {"target", 34962},
                     {"extensions", {{"EXT_meshopt_compression", {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", enc.size()},
                                                                  {"byteStride", stride}, {"count", V}, {"mode", "ATTRIBUTES"}}}}}});
    bin.append(reinterpret_cast<const char*>(enc.data()), enc.size());
    fallback += V * stride;
  };
  add_vertices(m.positions.data(), 12);
  if (octahedral_normals) {
    std::vector<float> n4;
    for (std::size_t v = 0; v < V; ++v) n4.insert(n4.end(), {m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2], 0.0f});
    std::vector<std::int8_t> oct(4 * V);
    meshopt_encodeFilterOct(oct.data(), V, 4, 8, n4.data());
    std::vector<unsigned char> enc(meshopt_encodeVertexBufferBound(V, 4));
    enc.resize(meshopt_encodeVertexBuffer(enc.data(), enc.size(), oct.data(), V, 4));
    while (bin.size() % 4) bin += '\0';
    views.push_back({{"buffer", 1}, {"byteOffset", fallback}, {"byteLength", V * 4}, {"byteStride", 4}, {"target", 34962},
                     {"extensions", {{"EXT_meshopt_compression", {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", enc.size()},
                                                                  {"byteStride", 4}, {"count", V}, {"mode", "ATTRIBUTES"},
                                                                  {"filter", "OCTAHEDRAL"}}}}}});
    bin.append(reinterpret_cast<const char*>(enc.data()), enc.size());
    fallback += V * 4;
  } else {
    add_vertices(m.normals.data(), 12);
  }
  add_vertices(m.uvs.data(), 8);
  std::vector<unsigned char> enc(meshopt_encodeIndexBufferBound(m.indices.size(), V));
  enc.resize(meshopt_encodeIndexBuffer(enc.data(), enc.size(), m.indices.data(), m.indices.size()));
  while (bin.size() % 4) bin += '\0';
  views.push_back({{"buffer", 1}, {"byteOffset", fallback}, {"byteLength", 2 * m.indices.size()}, {"target", 34963},
                   {"extensions", {{"EXT_meshopt_compression", {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", enc.size()},
                                                                {"byteStride", 2}, {"count", m.indices.size()}, {"mode", "TRIANGLES"}}}}}});
  bin.append(reinterpret_cast<const char*>(enc.data()), enc.size());
  fallback += 2 * m.indices.size();
  doc["bufferViews"] = views;
  doc["accessors"] = {
      {{"bufferView", 0}, {"componentType", 5126}, {"count", V}, {"type", "VEC3"}, {"min", minmax(m.positions, 3, false)}, {"max", minmax(m.positions, 3, true)}},
      octahedral_normals ? nlohmann::json{{"bufferView", 1}, {"componentType", 5120}, {"normalized", true}, {"count", V}, {"type", "VEC3"}}
                         : nlohmann::json{{"bufferView", 1}, {"componentType", 5126}, {"count", V}, {"type", "VEC3"}},
      {{"bufferView", 2}, {"componentType", 5126}, {"count", V}, {"type", "VEC2"}},
      {{"bufferView", 3}, {"componentType", 5123}, {"count", m.indices.size()}, {"type", "SCALAR"}}};
  doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}}}}}};
  doc["buffers"] = {{{"byteLength", (bin.size() + 3) / 4 * 4}},
                    {{"byteLength", (fallback + 3) / 4 * 4}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
  return glb(doc, bin);
}

}  // namespace shadetool_test
