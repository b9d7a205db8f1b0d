// gltf_lights.cpp: KHR_lights_punctual, the first camera and a primitive's node -> Scene (see the
// header for the unit mapping).
#include <shadetool/gltf/gltf_lights.h>

#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/gltf/gltf_scene.h>
#include "engine/gltf_source.h"

namespace shadetool {

namespace {

using nlohmann::json;

Vec3d vec3_or(const json& j, const char* key, Vec3d fallback) {
  if (!j.contains(key) || !j[key].is_array() || j[key].size() < 3) return fallback;
  return {j[key][0].get<double>(), j[key][1].get<double>(), j[key][2].get<double>()};
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
  for (const auto& [i, M] : nodes)
    if (j["nodes"][i].value("mesh", -1) == long(prim.mesh_index) && instances++ == 0) scene.world_from_object = M;
  if (instances > 1)
    notes.push_back("mesh " + std::to_string(prim.mesh_index) + " is shown by " + std::to_string(instances) +
                    " nodes: lit where the first one places it");
  if (instances == 0) notes.push_back("no node shows mesh " + std::to_string(prim.mesh_index) + ": lit in its object space");

  for (const auto& [i, M] : nodes)
    if (j["nodes"][i].contains("camera")) {
      scene.has_camera = invert_affine(M, scene.camera_from_world);
      break;
    }

  const json* lights = nullptr;
  if (j.contains("extensions") && j["extensions"].contains("KHR_lights_punctual") &&
      j["extensions"]["KHR_lights_punctual"].contains("lights"))
    lights = &j["extensions"]["KHR_lights_punctual"]["lights"];
  bool ranged = false;
  for (const auto& [i, M] : nodes) {
    const json& node = j["nodes"][i];
    if (!node.contains("extensions") || !node["extensions"].contains("KHR_lights_punctual")) continue;
    const std::string path = "nodes[" + std::to_string(i) + "].extensions.KHR_lights_punctual.light";
    const long index = node["extensions"]["KHR_lights_punctual"].value("light", -1L);
    if (!lights || index < 0 || std::size_t(index) >= lights->size())
      fail(name, 0, path + ": " + std::to_string(index) + " is not a light index");
    const json& L = (*lights)[std::size_t(index)];
    const std::string type = L.value("type", "");
    const Vec3d color = vec3_or(L, "color", {1, 1, 1});
    const double intensity = L.value("intensity", 1.0);
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
        const double outer = L.contains("spot") ? L["spot"].value("outerConeAngle", kPi / 4) : kPi / 4;
        light.cutoff_degrees = std::min(90.0, outer / kRadiansPerDegree);
      }
      ranged = ranged || L.contains("range");
    } else {
      fail(name, 0, "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "].type: '" + type +
                        "' is not directional, point or spot");
    }
    if (!(squared_length(light.direction) > 0)) light.direction = {0, 0, -1};  // a zero-scale node
    scene.lights.push_back(light);
  }
  if (ranged) notes.push_back("KHR_lights_punctual `range` is not applied (lights attenuate 1/d^2 without a cutoff)");

  // Material: base colour as the diffuse reflectance, emissive as emission.
  scene.material.ambient = {0, 0, 0};
  scene.material.diffuse = {1, 1, 1};
  scene.material.specular = {0, 0, 0};
  const json& jprim = j["meshes"][prim.mesh_index]["primitives"][prim.primitive_index];
  if (jprim.contains("material") && j.contains("materials")) {
    const std::size_t m = jprim["material"].get<std::size_t>();
    if (m < j["materials"].size()) {
      const json& mat = j["materials"][m];
      if (mat.contains("pbrMetallicRoughness")) scene.material.diffuse = vec3_or(mat["pbrMetallicRoughness"], "baseColorFactor", {1, 1, 1});
      scene.material.emission = vec3_or(mat, "emissiveFactor", {0, 0, 0});
    }
  }
  return scene;
}

}  // namespace shadetool
