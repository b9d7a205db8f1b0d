// Scene files: every field read as written, defaults as documented (OpenGL's), and every invalid
// field refused with one line naming the file, the JSON path and the problem.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/lighting/read_scene.h>

using namespace shadetool;

namespace {

std::string error_of(const std::string& json) {
  try {
    parse_scene(json, "scene.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A valid scene with `fragment` spliced into its lights array / root object.
std::string with_light(const std::string& light) { return R"({"lights": [)" + light + "]}"; }

}  // namespace

TEST_CASE("the studio example scene is read field by field", "[lighting][scene]") {
  const Scene s = read_scene(std::string(SHADETOOL_SOURCE_DIR) + "/data/scenes/studio.json");
  CHECK(s.model == ShadingModel::BlinnPhong);
  CHECK(s.model_given);
  CHECK(s.has_camera);
  // eye (0,0,5) looking at the origin with up +y: V is a translation by -5 along z
  CHECK(eye_world(s).z == Approx(5).margin(1e-15));
  CHECK(s.camera_from_world.t.z == Approx(-5).margin(1e-15));
  CHECK(s.global_ambient == Vec3d{0.1, 0.1, 0.1});
  CHECK_FALSE(s.two_sided);
  CHECK(s.material.diffuse == Vec3d{0.8, 0.5, 0.2});
  CHECK(s.material.shininess == 32);
  REQUIRE(s.lights.size() == 3);
  CHECK(s.lights[0].type == LightType::Directional);
  CHECK(s.lights[0].direction == Vec3d{0, -1, -1});
  CHECK(s.lights[0].ambient == Vec3d{0, 0, 0});  // default black, as OpenGL's lights
  CHECK(s.lights[1].type == LightType::Point);
  CHECK(s.lights[1].diffuse == Vec3d{1, 0.9, 0.8});   // color * intensity 1
  CHECK(s.lights[1].specular == Vec3d{1, 0.9, 0.8});
  CHECK(s.lights[1].attenuation == Vec3d{1, 0.1, 0.01});
  CHECK(s.lights[2].type == LightType::Spot);
  CHECK(s.lights[2].cutoff_degrees == 30);
  CHECK(s.lights[2].exponent == 8);
  CHECK(s.lights[2].diffuse == Vec3d{1, 1, 1});  // no color: white * intensity 1
}

TEST_CASE("the other example scenes are valid", "[lighting][scene]") {
  for (const char* name : {"sun.json", "stretched.json"}) {
    INFO(name);
    CHECK_NOTHROW(read_scene(std::string(SHADETOOL_SOURCE_DIR) + "/data/scenes/" + name));
  }
}

TEST_CASE("defaults: OpenGL's material and global ambient, identity M, no camera", "[lighting][scene]") {
  const Scene s = parse_scene("{}", "scene.json");
  CHECK(s.model == ShadingModel::BlinnPhong);
  CHECK_FALSE(s.model_given);
  CHECK_FALSE(s.has_camera);
  CHECK(eye_world(s) == Vec3d{0, 0, 0});
  CHECK(s.global_ambient == Vec3d{0.2, 0.2, 0.2});
  CHECK(s.material.ambient == Vec3d{0.2, 0.2, 0.2});
  CHECK(s.material.diffuse == Vec3d{0.8, 0.8, 0.8});
  CHECK(s.material.specular == Vec3d{0, 0, 0});
  CHECK(s.material.shininess == 0);
  CHECK(s.lights.empty());
  CHECK(s.world_from_object.A.m[1][1] == 1);
}

TEST_CASE("light colours: diffuse and specular default to color * intensity", "[lighting][scene]") {
  const Scene s = parse_scene(with_light(R"({"type": "point", "position": [1,2,3], "color": [1, 0.5, 0.25],
      "intensity": 2, "specular": [0.1, 0.1, 0.1], "ambient": [0.3, 0.3, 0.3]})"),
                              "scene.json");
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].diffuse == Vec3d{2, 1, 0.5});
  CHECK(s.lights[0].specular == Vec3d{0.1, 0.1, 0.1});
  CHECK(s.lights[0].ambient == Vec3d{0.3, 0.3, 0.3});
  CHECK(s.lights[0].attenuation == Vec3d{1, 0, 0});
  CHECK(s.lights[0].position == Vec3d{1, 2, 3});

  const Scene a = parse_scene(with_light(R"({"type": "ambient", "color": [1, 1, 0.5], "intensity": 0.5})"), "s");
  CHECK(a.lights[0].type == LightType::Ambient);
  CHECK(a.lights[0].ambient == Vec3d{0.5, 0.5, 0.25});
  CHECK(a.lights[0].diffuse == Vec3d{0, 0, 0});
}

TEST_CASE("camera as a view matrix, in the camera object or at the top level", "[lighting][scene]") {
  const char* view = "[1,0,0,-1, 0,1,0,-2, 0,0,1,-3, 0,0,0,1]";  // eye at (1,2,3)
  const Scene a = parse_scene(std::string(R"({"camera": {"view": )") + view + "}}", "s");
  const Scene b = parse_scene(std::string(R"({"view": )") + view + "}", "s");
  CHECK(eye_world(a) == Vec3d{1, 2, 3});
  CHECK(eye_world(b) == Vec3d{1, 2, 3});
  // world_from_object rows are read row-major: translation in the 4th column
  const Scene m = parse_scene(R"({"world_from_object": [2,0,0,7, 0,3,0,8, 0,0,4,9, 0,0,0,1]})", "s");
  CHECK(m.world_from_object.A.m[0][0] == 2);
  CHECK(m.world_from_object.A.m[2][2] == 4);
  CHECK(m.world_from_object.t == Vec3d{7, 8, 9});
}

TEST_CASE("invalid scenes: one line with file, JSON path and problem", "[lighting][scene]") {
  CHECK(error_of(R"({"modle": "phong"})") ==
        "scene.json: $.modle: unknown key in a scene (expected one of: model, world_from_object, camera, view, "
        "ambient, two_sided, material, lights)");
  CHECK(error_of(R"({"model": "gouraud"})") ==
        "scene.json: $.model: 'gouraud' is not one of lambert, phong, blinn-phong");
  CHECK(error_of(R"({"two_sided": 1})") == "scene.json: $.two_sided: must be true or false, got a number");
  CHECK(error_of(R"({"ambient": [0.1, 0.1]})") ==
        "scene.json: $.ambient: must be a colour [r, g, b] (3 numbers >= 0), got an array of 2");
  CHECK(error_of(R"({"material": {"diffuse": [0.5, -0.5, 0.5]}})") ==
        "scene.json: $.material.diffuse[1]: colour channels must be >= 0, got -0.5");
  CHECK(error_of(R"({"material": {"diffuse": [0.5, "red", 0.5]}})") ==
        "scene.json: $.material.diffuse[1]: must be a number, got a string");
  CHECK(error_of(R"({"material": {"shininess": -2}})") == "scene.json: $.material.shininess: must be >= 0, got -2");
  CHECK(error_of(R"({"material": {"colour": [1,1,1]}})") ==
        "scene.json: $.material.colour: unknown key in material (expected one of: ambient, diffuse, specular, "
        "emission, shininess)");
  CHECK(error_of(R"({"material": []})") == "scene.json: $.material: must be an object, got an array of 0");
  CHECK(error_of(R"({"lights": {}})") == "scene.json: $.lights: must be an array of lights, got an object");
  CHECK(error_of(with_light(R"({"direction": [0,0,-1]})")) == "scene.json: $.lights[0]: a light needs 'type'");
  CHECK(error_of(with_light(R"({"type": "sun"})")) ==
        "scene.json: $.lights[0].type: must be \"ambient\", \"directional\", \"point\", \"spot\", \"area\", \"sky\" or \"environment\", got \"sun\"");
  CHECK(error_of(with_light(R"({"type": "directional", "direction": [0,0,0]})")) ==
        "scene.json: $.lights[0].direction: zero-length direction");
  CHECK(error_of(with_light(R"({"type": "directional"})")) ==
        "scene.json: $.lights[0]: a directional light needs 'direction'");
  CHECK(error_of(with_light(R"({"type": "directional", "direction": [0,0,-1], "attenuation": [1,0,0]})")) ==
        "scene.json: $.lights[0].attenuation: unknown key in a directional light (expected one of: type, direction, "
        "color, intensity, ambient, diffuse, specular)");
  CHECK(error_of(with_light(R"({"type": "point", "position": [0,0,0]}, {"type": "point"})")) ==
        "scene.json: $.lights[1]: a point light needs 'position'");
  CHECK(error_of(with_light(R"({"type": "point", "position": [0,0,0], "intensity": -1})")) ==
        "scene.json: $.lights[0].intensity: must be >= 0, got -1");
  CHECK(error_of(with_light(R"({"type": "point", "position": [0,0,0], "attenuation": [0,0,0]})")) ==
        "scene.json: $.lights[0].attenuation: is [0, 0, 0]: 1/(kc + kl d + kq d^2) has no finite value");
  CHECK(error_of(with_light(R"({"type": "point", "position": [0,0,0], "attenuation": [1,-0.1,0]})")) ==
        "scene.json: $.lights[0].attenuation[1]: must be >= 0, got -0.1");
  const std::string spot = R"({"type": "spot", "position": [0,3,0], "direction": [0,-1,0], )";
  CHECK(error_of(with_light(spot + R"("cutoff": 95})")) ==
        "scene.json: $.lights[0].cutoff: must be in [0, 90] degrees or 180 (no cone), got 95");
  CHECK(error_of(with_light(spot + R"("cutoff": -1})")) ==
        "scene.json: $.lights[0].cutoff: must be in [0, 90] degrees or 180 (no cone), got -1");
  CHECK(error_of(with_light(spot + R"("exponent": 2})")) == "scene.json: $.lights[0]: a spot light needs 'cutoff'");
  CHECK(error_of(with_light(spot + R"("cutoff": 30, "exponent": -2})")) ==
        "scene.json: $.lights[0].exponent: must be >= 0, got -2");
  CHECK(error_of(with_light(R"({"type": "ambient", "direction": [0,0,1]})")) ==
        "scene.json: $.lights[0].direction: unknown key in an ambient light (expected one of: type, color, intensity)");
}

TEST_CASE("invalid matrices and cameras", "[lighting][scene]") {
  CHECK(error_of(R"({"world_from_object": [1,0,0,0, 0,1,0,0, 0,0,1,0]})") ==
        "scene.json: $.world_from_object: must be a 4x4 matrix as an array of 16 numbers (row-major), got an array "
        "of 12");
  CHECK(error_of(R"({"world_from_object": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1]})") ==
        "scene.json: $.world_from_object: bottom row must be 0 0 0 1 (an affine map; projections are not supported), "
        "got 0 0 1 1");
  CHECK(error_of(R"({"world_from_object": [1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1]})") ==
        "scene.json: $.world_from_object: the 3x3 part is singular (determinant 0): the map has no inverse");
  CHECK(error_of(R"({"world_from_object": [1,0,0,0, 0,1,0,0, 0,0,1,true, 0,0,0,1]})") ==
        "scene.json: $.world_from_object[11]: must be a number, got true");
  CHECK(error_of(R"({"camera": {"eye": [0,0,5], "target": [0,0,5]}})") ==
        "scene.json: $.camera.target: equals the eye: no view direction");
  CHECK(error_of(R"({"camera": {"eye": [0,5,0], "target": [0,0,0]}})") ==
        "scene.json: $.camera.up: is parallel to the view direction (target - eye)");
  CHECK(error_of(R"({"camera": {"eye": [0,0,5]}})") == "scene.json: $.camera: a camera needs 'target'");
  CHECK(error_of(R"({"camera": {"eye": [0,0,5], "target": [0,0,0], "up": [0,0,0]}})") ==
        "scene.json: $.camera.up: zero-length direction");
  CHECK(error_of(R"({"camera": {"eye": [0,0,5], "view": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}})") ==
        "scene.json: $.camera: give either \"view\" or \"eye\"/\"target\"/\"up\", not both");
  CHECK(error_of(R"({"camera": {"eye": [0,0,5], "target": [0,0,0]}, "view": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})") ==
        "scene.json: $: give either \"camera\" or \"view\", not both");
}

TEST_CASE("invalid JSON: syntax errors with line, duplicate keys with path, overflow", "[lighting][scene]") {
  CHECK(error_of("{\n  \"model\": \"phong\",\n  \"ambient\": [0.1, 0.1, 0.1,]\n}") ==
        "scene.json:3: invalid JSON at column 29: syntax error while parsing value - unexpected ']'; expected '[', "
        "'{', or a literal");
  CHECK(error_of("") ==
        "scene.json:1: invalid JSON at column 1: syntax error while parsing value - unexpected end of input; "
        "expected '[', '{', or a literal");
  CHECK(error_of(R"({"lights": [{"type": "point", "position": [0,0,0]}, {"type": "point", "type": "spot"}]})") ==
        "scene.json: $.lights[1]: duplicate key \"type\"");
  CHECK(error_of(R"({"material": {"shininess": 1e999}})") ==
        "scene.json: invalid JSON: number overflow parsing '1e999'");
  CHECK(error_of("[1, 2]") == "scene.json: $: must be an object, got an array of 2");
}

TEST_CASE("a missing scene file names the file", "[lighting][scene]") {
  try {
    read_scene("/nonexistent/scene.json");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) == "/nonexistent/scene.json: cannot read scene file: No such file or directory");
  }
}
