// Tests of lighting/validate_scene.h: the one check every way of building a Scene passes through
// (issue 26, item 3). The door of hand-built scenes is checked here value by value against the
// ranges scene.h lists; the JSON door (parse_scene, also Python's dicts) here and in
// read_scene.cpp; the glTF door in tests/gltf/gltf_lights.cpp; Python's in tests/python.
#include <catch2/catch.hpp>

#include <limits>

#include <shadetool/core/error.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/lighting/validate_scene.h>
#include "lighting_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

std::string error_of(const Scene& s) {
  try {
    validate_scene(s, "hand");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

Light point_light() {
  Light L;
  L.type = LightType::Point;
  L.position = {0, 0, 5};
  return L;
}

}  // namespace

TEST_CASE("validate_scene passes OpenGL's defaults and every light kind in range", "[lighting][validate]") {
  Scene s;
  CHECK(error_of(s).empty());
  s.lights = {directional({0, 0, -1}), point_light()};
  Light spot = point_light();
  spot.type = LightType::Spot;
  spot.cutoff_degrees = 90;  // the edge of the range is in it
  Light sky;
  sky.type = LightType::Sky;
  Light sphere;
  sphere.type = LightType::Area;
  sphere.shape = AreaShape::Sphere;
  sphere.radius = 1;
  s.lights.insert(s.lights.end(), {spot, sky, sphere});
  s.lights[0].diffuse = {1e300, 0, 0};  // HDR: no upper bound
  CHECK(error_of(s).empty());
}

TEST_CASE("validate_scene refuses each value out of scene.h's range, naming its path", "[lighting][validate]") {
  const double inf = std::numeric_limits<double>::infinity();
  Scene s;
  s.lights = {point_light()};
  SECTION("a negative light colour") {
    s.lights[0].diffuse = {1, -0.5, 1};
    CHECK(error_of(s) == "hand: $.lights[0].diffuse: colour channels must be >= 0, got [1, -0.5, 1]");
  }
  SECTION("an overflowed light colour") {
    s.lights[0].specular = {inf, 1, 1};
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.lights[0].specular: must be finite in every channel"));
  }
  SECTION("a NaN material colour") {
    s.material.emission = {0, std::nan(""), 0};
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.material.emission: must be finite"));
  }
  SECTION("negative shininess") {
    s.material.shininess = -1;
    CHECK(error_of(s) == "hand: $.material.shininess: must be >= 0, got -1");
  }
  SECTION("attenuation all zero") {
    s.lights[0].attenuation = {0, 0, 0};
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.lights[0].attenuation: is [0, 0, 0]"));
  }
  SECTION("a zero direction") {
    s.lights[0] = directional({0, 0, 0});
    CHECK(error_of(s) == "hand: $.lights[0].direction: zero-length direction");
  }
  SECTION("a spot cutoff between 90 and 180") {
    s.lights[0].type = LightType::Spot;
    s.lights[0].cutoff_degrees = 120;
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.lights[0].cutoff: must be in [0, 90] degrees or 180"));
  }
  SECTION("a non-finite position") {
    s.lights[0].position = {0, inf, 0};
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.lights[0].position: must be finite"));
  }
  SECTION("an area polygon of two vertices") {
    s.lights[0].type = LightType::Area;
    s.lights[0].vertices = {{0, 0, 0}, {1, 0, 0}};
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.lights[0].vertices: must be 3 to 64 points, got 2"));
  }
  SECTION("an environment light without its map") {
    s.lights[0].type = LightType::Environment;
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.lights[0].image:"));
  }
  SECTION("a singular world_from_object") {
    s.world_from_object.A.m[2][2] = 0;
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.world_from_object: the 3x3 part is singular"));
  }
  SECTION("far not beyond near") {
    s.lens.near = 2;
    s.lens.far = 1;
    CHECK_THAT(error_of(s), Catch::StartsWith("hand: $.camera.far:"));
  }
}

TEST_CASE("the JSON door: parse_scene's scenes pass validate_scene, its refusals name the JSON path",
          "[lighting][validate]") {
  const Scene s = parse_scene(R"({"lights": [{"type": "spot", "position": [0, 0, 5], "direction": [0, 0, -1],
                                             "cutoff": 30, "intensity": 2}]})",
                              "s.json");
  CHECK_NOTHROW(validate_scene(s, "s.json"));
  CHECK_THROWS_WITH(parse_scene(R"({"lights": [{"type": "point", "position": [0, 0, 1], "intensity": -1}]})", "s.json"),
                    "s.json: $.lights[0].intensity: must be >= 0, got -1");
  CHECK_THROWS_WITH(parse_scene(R"({"lights": [{"type": "point", "position": [0, 0, 1], "color": [10, 1, 1],
                                                "intensity": 1e308}]})",
                                "s.json"),
                    Catch::StartsWith("s.json: $.lights[0].intensity: color x intensity overflows"));
}
