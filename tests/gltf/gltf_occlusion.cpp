// Tests of gltf/gltf_occlusion: a glTF scene's primitives occlude each other, in world space.
// Truth: the projected solid angle of a square above a point, parallel to its plane (the
// point-to-parallel-rectangle form factor, summed over the four quadrants around the foot point;
// e.g. Howell's catalogue of view factors, B-3), computed here, not by the library.
#include <shadetool/gltf/gltf_occlusion.h>

#include <cmath>

#include <catch2/catch.hpp>

#include <shadetool/core/math_constants.h>
#include "gltf/gltf_test_util.h"

using namespace shadetool;
using namespace shadetool::gltftest;

namespace {

// Form factor from a point to a rectangle X by Y (in units of its height) with one corner above it.
double corner_form_factor(double X, double Y) {
  const double a = std::sqrt(1 + X * X), b = std::sqrt(1 + Y * Y);
  return (X / a * std::atan(Y / a) + Y / b * std::atan(X / b)) / (2 * kPi);
}

// A 3 x 3 grid over [-1, 1]^2 in the plane y = 0, facing +y: vertex 4 is its centre.
std::vector<float> grid_positions() {
  std::vector<float> p;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) p.insert(p.end(), {float(i - 1), 0.0f, float(k - 1)});
  return p;
}
std::vector<std::uint16_t> grid_indices() {
  std::vector<std::uint16_t> t;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i) {
      const std::uint16_t a = std::uint16_t(3 * k + i), b = std::uint16_t(a + 1), c = std::uint16_t(a + 3), d = std::uint16_t(a + 4);
      t.insert(t.end(), {a, c, b, b, c, d});  // counter-clockwise seen from +y
    }
  return t;
}

// Mesh 0: the floor grid; mesh 1: the same grid as an occluder. Node 0 places the floor (a mirror
// in x and a scale by 4 around (3, -2, 1)); node 1 the occluder, scaled by `a` at height h above.
std::string floor_and_roof(double a, double h, bool with_roof_node = true) {
  Built b = base_doc();
  const std::vector<float> pos = grid_positions();
  const std::vector<std::uint16_t> idx = grid_indices();
  const int p0 = float_accessor(b, pos, "VEC3", 3, true);
  const int i0 = b.accessor({{"bufferView", b.view(bytes_of(idx))}, {"componentType", 5123}, {"count", idx.size()}, {"type", "SCALAR"}});
  const int p1 = float_accessor(b, pos, "VEC3", 3, true);
  b.doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", p0}}}, {"indices", i0}}})}},
                                 {{"primitives", json::array({{{"attributes", {{"POSITION", p1}}}, {"indices", i0}}})}}});
  b.doc["nodes"] = json::array({{{"translation", {3, -2, 1}}, {"scale", {-4, 1, 4}}, {"mesh", 0}},
                                {{"translation", {3, -2 + h, 1}}, {"scale", {a, 1, a}}, {"mesh", 1}}});
  b.doc["scenes"] = json::array({{{"nodes", with_roof_node ? json{0, 1} : json{0}}}});
  return b.glb();
}

}  // namespace

TEST_CASE("glTF occlusion: a primitive is occluded by another node's primitive, placed in world space", "[visibility][gltf]") {
  const double a = 1.5, h = 2.0;
  const double open_truth = 1 - 4 * corner_form_factor(a / h, a / h);  // 0.587...
  const GltfDocument doc = read_gltf(floor_and_roof(a, h), "room.glb");
  AmbientOcclusionOptions o;
  o.samples = 4096;
  const GltfSceneOcclusion ao = gltf_scene_occlusion(doc, false, o, "room.glb");
  REQUIRE(ao.primitives.size() == 2);
  REQUIRE(ao.instances == 2);
  CHECK(ao.normals_computed[0]);
  const float centre = ao.primitives[0].open_fraction[4];
  INFO("open fraction at the floor's centre " << centre << ", truth " << open_truth);
  // Low-discrepancy samples: far inside the Monte Carlo band sqrt(F (1 - F) / N) = 0.0077.
  CHECK(std::fabs(centre - open_truth) < 0.02);
  // Without the roof's node, the roof's mesh is in no node of the scene: it stays in its object
  // space, the square [-1, 1]^2 at y = 0, which is 2 above the floor's centre (3, -2, 1) and off to
  // the side: relative to the foot point it spans x in [-4, -2], z in [-2, 0], i.e. (in units of
  // the height 2) the corner rectangle 2 x 1 minus the corner rectangle 1 x 1.
  const double open_aside = 1 - (corner_form_factor(2, 1) - corner_form_factor(1, 1));  // 0.9712
  const GltfDocument aside_doc = read_gltf(floor_and_roof(a, h, false), "room.glb");
  const GltfSceneOcclusion aside = gltf_scene_occlusion(aside_doc, false, o, "room.glb");
  CHECK(aside.instances == 2);
  CHECK(std::fabs(aside.primitives[0].open_fraction[4] - open_aside) < 0.01);
  REQUIRE(aside.notes.size() == 2);
  CHECK(aside.notes[1].find("no node of the scene shows meshes[1].primitives[0]") != std::string::npos);
}

TEST_CASE("glTF occlusion: per face, the face centres of the floor under the roof", "[visibility][gltf]") {
  const double a = 8.0, h = 0.5;  // a roof far wider than the floor, close above it: almost closed
  const GltfDocument doc = read_gltf(floor_and_roof(a, h), "room.glb");
  AmbientOcclusionOptions o;
  o.samples = 1024;
  const GltfSceneOcclusion ao = gltf_scene_occlusion(doc, true, o, "room.glb");
  REQUIRE(ao.primitives[0].open_fraction.size() == 8);
  for (float v : ao.primitives[0].open_fraction) CHECK(v < 0.05f);  // the roof covers all but ~2% of the sky
}
