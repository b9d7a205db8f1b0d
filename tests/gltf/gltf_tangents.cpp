// glTF tangents after new normals (gltf/gltf_tangents.h): never stale, orthogonal to the new
// NORMAL, and with glTF's handedness: bitangent = w cross(N, T) points along -dP/dv of TEXCOORD_0
// as read (glTF's v runs down the image; the spec's bitangent points up it).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <shadetool/gltf/gltf_document.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/gltf/gltf_tangents.h>
#include <shadetool/gltf/gltf_transform.h>
#include <shadetool/normals/update_mesh_normals.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/transform_mesh.h>
#include "gltf/gltf_test_util.h"
#include "support/mikktspace_reference.h"
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

namespace {

// A textured torus (major radius 1, minor 0.4; 24 x 12 quads, seams duplicated) with its analytic
// NORMAL and TEXCOORD_0 u = i / 24, v = j / 12: curved everywhere, so that a map that is not a
// similarity changes MikkTSpace's frames (on a flat face A dP/du would stay exact).
std::string textured_torus_glb() {
  using namespace shadetool::gltftest;
  const int n = 24, m = 12;
  std::vector<float> pos, nor, uv;
  std::vector<std::uint32_t> idx;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      const double a = 2 * kPi * i / n, b = 2 * kPi * j / m;
      const Vec3d c{std::cos(a), std::sin(a), 0}, nn{std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b)};
      for (double x : {c.x + 0.4 * nn.x, c.y + 0.4 * nn.y, 0.4 * nn.z}) pos.push_back(float(x));
      for (double x : {nn.x, nn.y, nn.z}) nor.push_back(float(x));
      uv.push_back(float(double(i) / n));
      uv.push_back(float(double(j) / m));
    }
  auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      for (std::uint32_t v : {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)}) idx.push_back(v);
  Built b = base_doc();
  const int p = float_accessor(b, pos, "VEC3", 3, true), nm = float_accessor(b, nor, "VEC3", 3), t = float_accessor(b, uv, "VEC2", 2);
  const int ix = b.accessor({{"bufferView", b.view(bytes_of(idx))}, {"componentType", 5125}, {"count", idx.size()}, {"type", "SCALAR"}});
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", p}, {"NORMAL", nm}, {"TEXCOORD_0", t}}}, {"indices", ix}}})}}});
  return b.glb();
}

struct ReferenceComparison {
  std::size_t corners = 0, w_differs = 0, direction_differs = 0;
  double worst = 0;  // degrees
};

// A primitive's per-vertex TANGENT (glTF's w) against the reference MikkTSpace run on its own
// triangles (POSITION, NORMAL and TEXCOORD_0 as floats): glTF's w is the reference's negated
// (gltf_tangents.h). Empty `error` unless node failed.
ReferenceComparison compare_with_reference(const GltfDocument& doc, const GltfPrimitive& p, const std::vector<double>& tangents,
                                           std::string& error) {
  bool changed = false;
  const std::vector<double> uv = gltf_texcoords(doc, p, changed);
  const Mesh& m = p.mesh;
  REQUIRE(uv.size() == 2 * m.num_vertices());
  REQUIRE(tangents.size() == 4 * m.num_vertices());
  std::vector<float> corners;
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const std::uint32_t v = m.corner_vertex[c];
    const Vec3d x = m.position(v), nn = get3(m.vertex_normals, v);
    for (double f : {x.x, x.y, x.z, nn.x, nn.y, nn.z, uv[2 * v], uv[2 * v + 1]}) corners.push_back(float(f));
  }
  const std::vector<float> ref = shadetool_test::mikktspace_reference(corners, "gltf_tangents_ref", error);
  ReferenceComparison r;
  if (ref.size() != 4 * m.num_corners()) return r;
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const double* t = &tangents[4 * std::size_t(m.corner_vertex[c])];
    if (t[3] != -double(ref[4 * c + 3])) ++r.w_differs;
    const Vec3d a{t[0], t[1], t[2]}, e{ref[4 * c], ref[4 * c + 1], ref[4 * c + 2]};
    const Vec3d x = cross(a, e);
    const double deg = std::atan2(std::sqrt(dot(x, x)), dot(a, e)) * 180.0 / kPi;
    r.worst = std::max(r.worst, deg);
    if (!(deg <= 1e-3)) ++r.direction_differs;
    ++r.corners;
  }
  return r;
}

}  // namespace

// Issue 29: "a glTF whose normals changed is never written with stale tangents". A similarity
// (rotation, mirror, uniform scale) maps MikkTSpace frames onto MikkTSpace frames, so transform
// keeps A t (w flipped under a mirror); any other map changes them, so transform recomputes them.
// Both checked against the reference MikkTSpace run on the output's own floats.
TEST_CASE("glTF transform: mapped tangents under a similarity, recomputed otherwise, both MikkTSpace's", "[gltf][tangents][reference]") {
  if (shadetool_test::mikktspace_reference_dir().empty()) {
    WARN("SKIPPED: the MikkTSpace reference (node + npm install mikktspace failed: no node or no registry)");
    return;
  }
  {
    std::ofstream f("gltf_torus.glb", std::ios::binary);
    const std::string bytes = textured_torus_glb();
    f.write(bytes.data(), std::streamsize(bytes.size()));
  }
  // Frames to start from: MikkTSpace's (--tangents adds them; the normals stay as read).
  auto added = shadetool_test::run_process({SHADETOOL_BIN, "normals", "gltf_torus.glb", "--tangents", "-o", "gltf_torus_t.glb"});
  INFO(added.err);
  REQUIRE(added.code == 0);
  REQUIRE(added.err.find("TANGENT added") != std::string::npos);

  struct Case { const char* what; std::vector<std::string> flags; bool similarity; };
  const std::vector<Case> cases = {
      {"no map (a copy)", {}, true},
      {"rotation", {"--rotate", "30,1,1,1"}, true},
      {"mirror and rotation", {"--scale", "-1,1,1", "--rotate", "30,1,1,1"}, true},
      {"uniform scale with a mirror", {"--scale", "-2.5,-2.5,-2.5"}, true},
      {"non-uniform scale", {"--scale", "1,2,0.5"}, false},
      {"mirror, non-uniform scale and rotation", {"--scale", "1,2,-3", "--rotate", "30,1,1,1"}, false},
      {"shear", {"--matrix", "1,0.5,0,0,0,1,0,0,0,0,2,0"}, false}};
  for (const Case& k : cases) {
    std::vector<std::string> argv = {SHADETOOL_BIN, "transform", "gltf_torus_t.glb", "-o", "gltf_torus_m.glb"};
    argv.insert(argv.end(), k.flags.begin(), k.flags.end());
    const auto run = shadetool_test::run_process(argv);
    INFO(k.what << ": " << run.err);
    REQUIRE(run.code == 0);
    CHECK((run.err.find("TANGENT recomputed (MikkTSpace) with the new normals (the map is not a similarity") != std::string::npos) ==
          !k.similarity);
    const GltfDocument doc = read("gltf_torus_m.glb");
    REQUIRE(doc.primitives.size() == 1);
    std::string error;
    const ReferenceComparison r = compare_with_reference(doc, doc.primitives[0], doc.primitives[0].tangents, error);
    INFO(error);
    WARN("transform " << k.what << ": " << r.corners << " corners, worst " << r.worst << " degrees from the reference");
    CHECK(r.corners == doc.primitives[0].mesh.num_corners());
    CHECK(r.w_differs == 0);
    CHECK(r.direction_differs == 0);
  }

  // Why recomputing is needed: the mapped frames (A t) under a map that is not a similarity are
  // not MikkTSpace's frames of the mapped mesh.
  GltfDocument doc = read("gltf_torus_t.glb");
  GltfPrimitive& p = doc.primitives[0];
  const Affine3d M = compose_in_order({scale_map({1, 2, 0.5})});
  transform_gltf_extras(p, M, false);
  transform_mesh(p.mesh, M);
  std::string error;
  const ReferenceComparison mapped = compare_with_reference(doc, p, p.tangents, error);
  INFO(error);
  WARN("mapped (not recomputed) frames under --scale 1,2,0.5: worst " << mapped.worst << " degrees from the reference");
  CHECK(mapped.w_differs == 0);
  CHECK(mapped.direction_differs > 0);
  for (const char* f : {"gltf_torus.glb", "gltf_torus_t.glb", "gltf_torus_m.glb"}) std::remove(f);
}
