// glTF tangents after new normals (gltf/gltf_tangents.h): never stale, orthogonal to the new
// NORMAL, and with glTF's handedness: bitangent = w cross(N, T) points along -dP/dv of TEXCOORD_0
// as read (glTF's v runs down the image; the spec's bitangent points up it).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <shadetool/gltf/gltf_document.h>
#include <shadetool/gltf/gltf_tangents.h>
#include <shadetool/normals/update_mesh_normals.h>
#include "support/run_process.h"

using namespace shadetool;

namespace {

GltfDocument read(const std::string& path) { return read_gltf(shadetool_test::read_file(path), path); }

// For every triangle with texture area: each of its vertices' TANGENT is unit, orthogonal to
// NORMAL and its handedness is the triangle's (dP/dv from positions and TEXCOORD_0 as read).
void check_frames(const GltfDocument& doc, const GltfPrimitive& p, std::size_t& checked) {
  bool changed = false;
  const std::vector<double> uv = gltf_texcoords(doc, p, changed);
  const Mesh& m = p.mesh;
  REQUIRE(p.tangents.size() == 4 * m.num_vertices());
  REQUIRE(m.has_vertex_normals());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d t{p.tangents[4 * v], p.tangents[4 * v + 1], p.tangents[4 * v + 2]}, n = get3(m.vertex_normals, v);
    CHECK(std::fabs(dot(t, t) - 1) < 1e-6);
    CHECK(std::fabs(dot(t, n)) < 1e-5);
    CHECK(std::fabs(p.tangents[4 * v + 3]) == 1.0);
  }
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t* c = &m.corner_vertex[m.face_start[f]];
    const Vec3d p0 = m.position(c[0]), d1 = m.position(c[1]) - p0, d2 = m.position(c[2]) - p0;
    const double s1 = uv[2 * c[1]] - uv[2 * c[0]], t1 = uv[2 * c[1] + 1] - uv[2 * c[0] + 1];
    const double s2 = uv[2 * c[2]] - uv[2 * c[0]], t2 = uv[2 * c[2] + 1] - uv[2 * c[0] + 1];
    const double det = s1 * t2 - s2 * t1;
    if (std::fabs(det) < 1e-12) continue;
    const Vec3d dpdv = (d2 * s1 - d1 * s2) * (1.0 / det);  // divisor checked
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = c[k];
      const Vec3d t{p.tangents[4 * v], p.tangents[4 * v + 1], p.tangents[4 * v + 2]};
      const Vec3d b = cross(get3(m.vertex_normals, v), t) * p.tangents[4 * v + 3];
      CHECK(dot(b, dpdv) < 0);
      ++checked;
    }
  }
}

}  // namespace

TEST_CASE("glTF: new normals recompute TANGENT, orthogonal to them, with glTF's handedness", "[gltf][tangents]") {
  const std::string in = std::string(SHADETOOL_SOURCE_DIR) + "/data/scene.gltf";
  const std::string out = "gltf_tangents_out.glb";
  // Sheared positions make the old tangents wrong for the new normals.
  const auto run = shadetool_test::run_process({SHADETOOL_BIN, "normals", in, "--recompute", "--tangents", "-o", out, "-q"});
  INFO(run.err);
  REQUIRE(run.code == 0);
  const GltfDocument doc = read(out);
  std::size_t checked = 0, with_tangents = 0;
  for (const GltfPrimitive& p : doc.primitives) {
    bool changed = false;
    if (gltf_texcoords(doc, p, changed).empty()) {
      CHECK(p.tangents.empty());  // no TEXCOORD_0: no tangents
      continue;
    }
    ++with_tangents;
    check_frames(doc, p, checked);
  }
  CHECK(with_tangents >= 2);
  CHECK(checked > 0);
  std::remove(out.c_str());
}

TEST_CASE("glTF: a primitive with TANGENT but nothing to compute them from loses them with its old normals", "[gltf][tangents]") {
  GltfDocument doc = read(std::string(SHADETOOL_SOURCE_DIR) + "/data/scene.gltf");
  for (GltfPrimitive& p : doc.primitives) {
    if (std::find(p.attributes.begin(), p.attributes.end(), "TANGENT") == p.attributes.end()) continue;
    p.mesh.vertex_normals.clear();
    p.mesh.face_normals.clear();
    p.mesh.corner_normal_index.clear();
    const std::string note = gltf_update_tangents(doc, p, false);
    CHECK(note.find("TANGENT removed") != std::string::npos);
    CHECK(p.drop_tangents);
  }
}

TEST_CASE("glTF: transform --normals recompute recomputes TANGENT with the new normals", "[gltf][tangents]") {
  const std::string in = std::string(SHADETOOL_SOURCE_DIR) + "/data/scene.gltf";
  const std::string out = "gltf_tangents_shear.glb";
  const auto run = shadetool_test::run_process(
      {SHADETOOL_BIN, "transform", in, "--matrix", "1,0.5,0,0,0,1,0,0,0,0,2,0", "--normals", "recompute", "-o", out});
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK(run.err.find("TANGENT recomputed") != std::string::npos);
  const GltfDocument doc = read(out);
  std::size_t checked = 0;
  for (const GltfPrimitive& p : doc.primitives)
    if (!p.tangents.empty()) check_frames(doc, p, checked);
  CHECK(checked > 0);
  std::remove(out.c_str());
}
