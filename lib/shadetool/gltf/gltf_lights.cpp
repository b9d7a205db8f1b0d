// gltf_lights.cpp: KHR_lights_punctual, the first camera and a primitive's node -> Scene (see the
// header for the unit mapping).
#include <shadetool/gltf/gltf_lights.h>

#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/lighting/validate_scene.h>
#include "engine/gltf_source.h"

namespace shadetool {

namespace {

using nlohmann::json;

const char* json_kind(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "a number";
  }
  return "?";
}

// obj[key] as a number (absent: fallback); Error `NAME: PATH.KEY: must be a number, got a string`.
double number_or(const json& obj, const char* key, double fallback, const std::string& name, const std::string& path) {
  if (!obj.is_object() || !obj.contains(key)) return fallback;
  const json& v = obj[key];
  if (!v.is_number()) fail(name, 0, path + "." + key + ": must be a number, got " + json_kind(v));
  return v.get<double>();
}

// The first three numbers of obj[key] (absent: fallback; glTF's colour factors have 3 or 4).
Vec3d vec3_or(const json& obj, const char* key, Vec3d fallback, const std::string& name, const std::string& path) {
  if (!obj.is_object() || !obj.contains(key)) return fallback;
  const json& v = obj[key];
  if (!v.is_array() || v.size() < 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    fail(name, 0, path + "." + key + ": must be an array of 3 or more numbers, got " + json_kind(v));
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

// Where each light of the Scene came from: its KHR_lights_punctual entry and the node placing it.
struct GltfLightSource {
  std::size_t light = 0;  // index into extensions.KHR_lights_punctual.lights
  std::size_t node = 0;
  bool has_intensity = false;
};

std::string light_path(std::size_t index) {
  return "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
}

}  // namespace

Scene gltf_scene(const GltfDocument& doc, const GltfPrimitive& prim, std::vector<std::string>& notes) {
  if (!doc.source) fail("<glTF>", 0, "the document was not read from a file: no lights or camera");
  const json& j = doc.source->json;
  const std::string& name = doc.source->name;
  Scene scene;
  scene.global_ambient = {0, 0, 0};
  const std::vector<GltfNodePlacement> nodes = gltf_scene_nodes(doc);  // scene order, depth first

  std::size_t instances = 0;
  std::string placement = "(identity: no node shows the mesh)", camera_node = "cameras";
  for (const auto& [i, M] : nodes)
    if (j["nodes"][i].value("mesh", -1) == long(prim.mesh_index) && instances++ == 0) {
      scene.world_from_object = M;
      placement = "nodes[" + std::to_string(i) + "]";
    }
  if (instances > 1)
    notes.push_back("mesh " + std::to_string(prim.mesh_index) + " is shown by " + std::to_string(instances) +
                    " nodes: lit where the first one places it");
  if (instances == 0) notes.push_back("no node shows mesh " + std::to_string(prim.mesh_index) + ": lit in its object space");

  for (const auto& [i, M] : nodes)
    if (j["nodes"][i].contains("camera")) {
      scene.has_camera = invert_affine(M, scene.camera_from_world);
      camera_node = "nodes[" + std::to_string(i) + "]";
      break;
    }

  const json* lights = nullptr;
  if (j.contains("extensions") && j["extensions"].contains("KHR_lights_punctual") &&
      j["extensions"]["KHR_lights_punctual"].contains("lights"))
    lights = &j["extensions"]["KHR_lights_punctual"]["lights"];
  bool ranged = false;
  std::vector<GltfLightSource> sources;
  for (const auto& [i, M] : nodes) {
    const json& node = j["nodes"][i];
    if (!node.contains("extensions") || !node["extensions"].contains("KHR_lights_punctual")) continue;
    const std::string node_path = "nodes[" + std::to_string(i) + "].extensions.KHR_lights_punctual";
    const json& ext = node["extensions"]["KHR_lights_punctual"];
    long index = -1;
    if (ext.is_object() && ext.contains("light")) {
      if (!ext["light"].is_number()) fail(name, 0, node_path + ".light: must be a number, got " + json_kind(ext["light"]));
      index = ext["light"].get<long>();
    }
    if (!lights || !lights->is_array() || index < 0 || std::size_t(index) >= lights->size())
      fail(name, 0, node_path + ".light: " + std::to_string(index) + " is not a light index");
    const json& L = (*lights)[std::size_t(index)];
    const std::string path = light_path(std::size_t(index));
    if (!L.is_object()) fail(name, 0, path + ": must be an object, got " + json_kind(L));
    if (L.contains("type") && !L["type"].is_string()) fail(name, 0, path + ".type: must be a string, got " + json_kind(L["type"]));
    const std::string type = L.value("type", "");
    // KHR_lights_punctual: color in [0, 1]^3 (linear), intensity >= 0; both checked before their
    // product (validate_scene checks the product: finite, >= 0).
    const Vec3d color = vec3_or(L, "color", {1, 1, 1}, name, path);
    const double intensity = number_or(L, "intensity", 1.0, name, path);
    require_colour(color, name, path + ".color");
    require_non_negative(intensity, name, path + ".intensity");
    Light light;
    light.diffuse = light.specular = color * intensity;
    light.position = M.t;
    light.direction = transform_vector(M, {0, 0, -1});
    if (type == "directional") {
      light.type = LightType::Directional;
    } else if (type == "point" || type == "spot") {
      light.type = type == "point" ? LightType::Point : LightType::Spot;
      light.attenuation = {0, 0, 1};
      if (type == "spot") {
        const double outer = L.contains("spot") ? number_or(L["spot"], "outerConeAngle", kPi / 4, name, path + ".spot") : kPi / 4;
        light.cutoff_degrees = std::min(90.0, outer / kRadiansPerDegree);
      }
      ranged = ranged || L.contains("range");
    } else {
      fail(name, 0, path + ".type: '" + type + "' is not directional, point or spot");
    }
    if (!(squared_length(light.direction) > 0)) light.direction = {0, 0, -1};  // a zero-scale node
    scene.lights.push_back(light);
    sources.push_back({std::size_t(index), i, L.contains("intensity")});
  }
  if (ranged) notes.push_back("KHR_lights_punctual `range` is not applied (lights attenuate 1/d^2 without a cutoff)");

  // Material: base colour as the diffuse reflectance, emissive as emission.
  scene.material.ambient = {0, 0, 0};
  scene.material.diffuse = {1, 1, 1};
  scene.material.specular = {0, 0, 0};
  std::string material = "(default material)";
  const json& jprim = j["meshes"][prim.mesh_index]["primitives"][prim.primitive_index];
  if (jprim.contains("material") && j.contains("materials")) {
    const std::size_t m = jprim["material"].get<std::size_t>();
    if (m < j["materials"].size()) {
      const json& mat = j["materials"][m];
      material = "materials[" + std::to_string(m) + "]";
      if (mat.contains("pbrMetallicRoughness"))
        scene.material.diffuse = vec3_or(mat["pbrMetallicRoughness"], "baseColorFactor", {1, 1, 1}, name, material + ".pbrMetallicRoughness");
      scene.material.emission = vec3_or(mat, "emissiveFactor", {0, 0, 0}, name, material);
    }
  }

  // Every Scene passes validate_scene; here its messages name the glTF JSON paths.
  ScenePaths paths;
  paths.scene = [&](const std::string& field) -> std::string {
    if (field == "world_from_object") return placement;
    if (field.rfind("camera", 0) == 0) return camera_node;
    if (field == "material.diffuse") return material + ".pbrMetallicRoughness.baseColorFactor";
    if (field == "material.emission") return material + ".emissiveFactor";
    if (field.rfind("material", 0) == 0) return material;
    return "(scene ambient)";
  };
  paths.light = [&](std::size_t i, const std::string& field) -> std::string {
    const GltfLightSource& src = sources[i];
    if (field == "diffuse" || field == "specular") return light_path(src.light) + (src.has_intensity ? ".intensity" : ".color");
    if (field == "position" || field == "direction") return "nodes[" + std::to_string(src.node) + "]";
    if (field == "cutoff") return light_path(src.light) + ".spot.outerConeAngle";
    return light_path(src.light);
  };
  validate_scene(scene, name, paths);
  return scene;
}

}  // namespace shadetool
