// Tests of compressed glTF reading (gltf/engine/gltf_decompress, through read_gltf): files made by
// Draco's and meshoptimizer's own encoders (compressed_fixtures.h) decode to the mesh they were
// made from, and the written document is uncompressed.
#include <shadetool/gltf/gltf_document.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <tuple>

#include <catch2/catch.hpp>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include "compressed_fixtures.h"

using namespace shadetool;
using shadetool_test::FixtureMesh;

namespace {

// Each triangle as the sorted triple of its corners' (position, normal, uv): equal sets mean the
// same surface with the same attributes, whatever order a codec gave the vertices.
using Corner = std::array<double, 8>;
std::vector<std::array<Corner, 3>> triangles(const std::vector<double>& p, const std::vector<double>& n,
                                            const std::vector<double>& uv, const std::vector<std::uint32_t>& corners) {
  std::vector<std::array<Corner, 3>> out;
  for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
    std::array<Corner, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = corners[t + std::size_t(k)];
      tri[std::size_t(k)] = {p[3 * v], p[3 * v + 1], p[3 * v + 2], n[3 * v], n[3 * v + 1], n[3 * v + 2], uv[2 * v], uv[2 * v + 1]};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());  // same winding, first corner smallest
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::array<Corner, 3>> source_triangles(const FixtureMesh& m) {
  return triangles(std::vector<double>(m.positions.begin(), m.positions.end()), std::vector<double>(m.normals.begin(), m.normals.end()),
                   std::vector<double>(m.uvs.begin(), m.uvs.end()), m.indices);
}

// TEXCOORD_0 of the document's only primitive: the reader does not decode it into the Mesh (it
// stays in the buffers), so it is read from the written (uncompressed) .glb, by hand.
std::vector<double> texcoords_of(const GltfDocument& doc) {
  GltfWriteResult wr;
  const std::string out = write_gltf(doc, true, "out.glb", wr);
  std::uint32_t json_len;
  std::memcpy(&json_len, out.data() + 12, 4);
  const auto j = nlohmann::json::parse(out.substr(20, json_len));
  const std::string bin = out.substr(20 + json_len + 8);
  const auto& acc = j["accessors"][j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"].get<std::size_t>()];
  const auto& view = j["bufferViews"][acc["bufferView"].get<std::size_t>()];
  const std::size_t stride = view.value("byteStride", std::size_t(8));
  const std::size_t base = view.value("byteOffset", std::size_t(0)) + acc.value("byteOffset", std::size_t(0));
  std::vector<double> uv;
  for (std::size_t i = 0; i < acc["count"].get<std::size_t>(); ++i)
    for (int k = 0; k < 2; ++k) {
      float f;
      std::memcpy(&f, bin.data() + base + i * stride + 4 * std::size_t(k), 4);
      uv.push_back(f);
    }
  return uv;
}

void check_decodes_to_source(const std::string& bytes, const char* name, const char* extension) {
  const FixtureMesh m = shadetool_test::fixture_sphere();
  REQUIRE(!bytes.empty());
  const GltfDocument doc = read_gltf(bytes, name);
  REQUIRE(doc.primitives.size() == 1);
  const Mesh& mesh = doc.primitives[0].mesh;
  CHECK(mesh.num_faces() == m.indices.size() / 3);
  CHECK(triangles(mesh.positions, mesh.vertex_normals, texcoords_of(doc), mesh.corner_vertex) == source_triangles(m));
  REQUIRE(doc.notes.size() == 1);
  CHECK(doc.notes[0].find(extension) != std::string::npos);
  // Written uncompressed: no trace of the extension, no bytes no view holds.
  GltfWriteResult wr;
  const std::string out = write_gltf(doc, false, "out.gltf", wr);
  CHECK(out.find(extension) == std::string::npos);
  CHECK(out.find("fallback") == std::string::npos);
}

}  // namespace

TEST_CASE("Draco-compressed glTF decodes to the mesh it was encoded from, attributes by the extension's id map",
          "[gltf][draco]") {
  check_decodes_to_source(shadetool_test::draco_glb(shadetool_test::fixture_sphere()), "draco.glb", "KHR_draco_mesh_compression");
}

TEST_CASE("meshopt-compressed glTF (fallback buffer without uri) decodes to the mesh it was encoded from", "[gltf][meshopt]") {
  const FixtureMesh m = shadetool_test::fixture_sphere();
  check_decodes_to_source(shadetool_test::meshopt_glb(m), "meshopt.glb", "EXT_meshopt_compression");
  // meshopt keeps the vertex order: positions equal the source element for element.
  const GltfDocument doc = read_gltf(shadetool_test::meshopt_glb(m), "meshopt.glb");
  CHECK(doc.primitives[0].mesh.positions == std::vector<double>(m.positions.begin(), m.positions.end()));
  CHECK(doc.primitives[0].mesh.corner_vertex == m.indices);
}

TEST_CASE("meshopt's OCTAHEDRAL filter decodes 8-bit normals within their quantisation (2 degrees)", "[gltf][meshopt]") {
  const FixtureMesh m = shadetool_test::fixture_sphere();
  const GltfDocument doc = read_gltf(shadetool_test::meshopt_glb(m, true), "oct.glb");
  REQUIRE(doc.primitives.size() == 1);
  const std::vector<double>& n = doc.primitives[0].mesh.vertex_normals;
  REQUIRE(n.size() == m.normals.size());
  for (std::size_t v = 0; v < n.size() / 3; ++v) {
    double dot = 0, len = 0;
    for (int k = 0; k < 3; ++k) {
      dot += n[3 * v + std::size_t(k)] * double(m.normals[3 * v + std::size_t(k)]);
      len += n[3 * v + std::size_t(k)] * n[3 * v + std::size_t(k)];
    }
    REQUIRE(len > 0);
    CHECK(dot / std::sqrt(len) > std::cos(2.0 * kPi / 180));  // divisor checked above
  }
}

TEST_CASE("Corrupt compressed data is refused with the JSON path", "[gltf][draco][meshopt]") {
  const FixtureMesh m = shadetool_test::fixture_sphere();
  std::string draco = shadetool_test::draco_glb(m);
  // The Draco stream starts right after the BIN chunk header: overwrite its bytes.
  std::uint32_t json_len;
  std::memcpy(&json_len, draco.data() + 12, 4);
  for (std::size_t i = 20 + json_len + 8 + 16; i < draco.size(); ++i) draco[i] = char(0xA5);
  CHECK_THROWS_WITH(read_gltf(draco, "bad.glb"), Catch::Contains("meshes[0].primitives[0].extensions.KHR_draco_mesh_compression"));
  std::string meshopt = shadetool_test::meshopt_glb(m);
  std::memcpy(&json_len, meshopt.data() + 12, 4);
  meshopt[20 + json_len + 8] = char(0x00);  // the vertex stream's header byte (0xa0 | version)
  CHECK_THROWS_WITH(read_gltf(meshopt, "bad.glb"), Catch::Contains("bufferViews[0].extensions.EXT_meshopt_compression"));
}
