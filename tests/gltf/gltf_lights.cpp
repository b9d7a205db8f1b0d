// Tests of gltf/gltf_lights (the glTF door into a lighting Scene): every KHR_lights_punctual value
// the Scene is built from passes lighting/validate_scene.h's ranges, and a bad one is refused with
// one message naming its glTF JSON path (issue 26, item 3). The files are built byte by byte
// (gltf_test_util.h), independent of our writer.
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/gltf/gltf_lights.h>

#include <nlohmann/json.hpp>

#include "gltf_test_util.h"
#include "io/io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;
using namespace shadetool::gltftest;
using nlohmann::json;

namespace {

// A triangle placed by node 0, lit by `light` through node 1; `material` on the primitive when given.
std::string lit_glb(const json& light, const json& material = nullptr) {
  Built b = base_doc();
  const int pos = float_accessor(b, {0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3, true);
  json prim = {{"attributes", {{"POSITION", pos}}}};
  if (!material.is_null()) {
    prim["material"] = 0;
    b.doc["materials"] = json::array({material});
  }
  b.doc["meshes"] = json::array({{{"primitives", json::array({prim})}}});
  b.doc["nodes"] = json::array({{{"mesh", 0}}, {{"translation", {0, 0, 5}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}});
  b.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  b.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({light})}}}};
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  return b.glb();
}

std::string scene_error(const std::string& glb) {
  const GltfDocument d = read_gltf(glb, "l.glb");
  std::vector<std::string> notes;
  return error_of([&] { gltf_scene(d, d.primitives[0], notes); });
}

}  // namespace

TEST_CASE("glTF lights: a valid light passes validate_scene unchanged", "[gltf][lighting]") {
  const std::string glb = lit_glb({{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 8}});
  const GltfDocument d = read_gltf(glb, "l.glb");
  std::vector<std::string> notes;
  const Scene s = gltf_scene(d, d.primitives[0], notes);
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].diffuse == Vec3d{8, 4, 2});  // color x intensity, exactly
  CHECK(s.lights[0].position == Vec3d{0, 0, 5});
}

TEST_CASE("glTF lights: a negative, overflowing or mistyped value is refused, naming its glTF path", "[gltf][lighting][bad]") {
  const std::string at = "l.glb: extensions.KHR_lights_punctual.lights[0]";
  // Negative intensity: was lit with a negative radiance (darkening) before issue 26.
  CHECK_THAT(scene_error(lit_glb({{"type", "point"}, {"intensity", -2}})),
             Catch::Equals(at + ".intensity: must be >= 0, got -2"));
  // A negative colour times a negative intensity is positive: each is checked before the product.
  CHECK_THAT(scene_error(lit_glb({{"type", "point"}, {"color", {-1, -1, -1}}, {"intensity", -1}})),
             Catch::StartsWith(at + ".color: colour channels must be >= 0"));
  // color x intensity beyond double: was an Inf radiance (NaN colours) before issue 26.
  CHECK_THAT(scene_error(lit_glb({{"type", "directional"}, {"color", {1, 1, 4}}, {"intensity", 1e308}})),
             Catch::StartsWith(at + ".intensity: must be finite in every channel"));
  // A string: was nlohmann's raw type_error before issue 26.
  CHECK_THAT(scene_error(lit_glb({{"type", "point"}, {"intensity", "bright"}})),
             Catch::Equals(at + ".intensity: must be a number, got a string"));
  CHECK_THAT(scene_error(lit_glb({{"type", "spot"}, {"spot", {{"outerConeAngle", "wide"}}}})),
             Catch::Equals(at + ".spot.outerConeAngle: must be a number, got a string"));
  CHECK_THAT(scene_error(lit_glb({{"type", "spot"}, {"spot", {{"outerConeAngle", -0.5}}}})),
             Catch::StartsWith(at + ".spot.outerConeAngle: must be in [0, 90] degrees or 180"));
  CHECK_THAT(scene_error(lit_glb({{"type", "point"}, {"color", "red"}})),
             Catch::Equals(at + ".color: must be an array of 3 or more numbers, got a string"));
}

TEST_CASE("glTF lights: the material's factors pass the same colour rule", "[gltf][lighting][bad]") {
  CHECK_THAT(scene_error(lit_glb({{"type", "point"}}, {{"emissiveFactor", {0, -1, 0}}})),
             Catch::StartsWith("l.glb: materials[0].emissiveFactor: colour channels must be >= 0"));
  // A string inside the factor is a schema type error: the reader refuses the file before any light
  // is built (gltf/engine/gltf_schema.h), naming the element.
  CHECK_THROWS_WITH(read_gltf(lit_glb({{"type", "point"}}, {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, "x", 1}}}}}), "l.glb"),
                    "l.glb: materials[0].pbrMetallicRoughness.baseColorFactor[2]: a string, the schema wants a number");
}
