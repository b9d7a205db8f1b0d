// gltf_tangents.cpp: see gltf_tangents.h.
#include <shadetool/gltf/gltf_tangents.h>

#include <algorithm>

#include <shadetool/core/error.h>
#include <shadetool/normals/tangent_vertices.h>
#include <shadetool/normals/tangents.h>
#include "engine/gltf_accessor.h"
#include "engine/gltf_source.h"

namespace shadetool {

std::vector<double> gltf_texcoords(const GltfDocument& doc, const GltfPrimitive& p, bool& changed) {
  if (!doc.source) return {};
  const tinygltf::Model& model = doc.source->model;
  const auto& prim = model.meshes[p.mesh_index].primitives[p.primitive_index];
  const auto it = prim.attributes.find("TEXCOORD_0");
  if (it == prim.attributes.end()) return {};
  if (p.mesh.num_vertices() != p.read_vertices) {
    changed = true;
    return {};
  }
  std::vector<double> uv = io::gltf::accessor_doubles(*doc.source, it->second, doc.source->name);
  if (uv.size() != 2 * p.read_vertices)
    fail(doc.source->name, 0, p.json_path + ".attributes.TEXCOORD_0: not one VEC2 per vertex");
  return uv;
}

namespace {

bool has_normal_texture(const GltfDocument& doc, const GltfPrimitive& p) {
  const tinygltf::Model& model = doc.source->model;
  const int material = model.meshes[p.mesh_index].primitives[p.primitive_index].material;
  return material >= 0 && std::size_t(material) < model.materials.size() &&
         model.materials[std::size_t(material)].normalTexture.index >= 0;
}

}  // namespace

std::string gltf_update_tangents(const GltfDocument& doc, GltfPrimitive& p, bool add) {
  if (!doc.source) return "";
  const bool had = std::find(p.attributes.begin(), p.attributes.end(), "TANGENT") != p.attributes.end();
  const bool normal_map = has_normal_texture(doc, p);
  if (!had && !normal_map && !add) return "";
  const Mesh& m = p.mesh;
  const std::string why = had ? "TANGENT" : normal_map ? "a normalTexture" : "--tangents";
  auto drop = [&](const std::string& reason) {
    p.corner_tangents.clear();
    if (!had) return "no tangents (" + reason + ")";
    p.drop_tangents = true;
    return "TANGENT removed (" + reason + "): tangents of the old normals would shade the normal map wrongly";
  };
  if (!m.has_vertex_normals() && !m.has_corner_normals() && !m.has_face_normals()) return drop("no normals");
  bool changed = false;
  const std::vector<double> uv = gltf_texcoords(doc, p, changed);
  if (changed) return drop("the command changed the vertices, TEXCOORD_0 cannot follow");
  if (uv.empty()) return drop("no TEXCOORD_0: MikkTSpace needs texture coordinates");
  Mesh textured = m;
  textured.texcoords = uv;
  textured.texcoord_dims = 2;
  textured.corner_texcoord_index = m.corner_vertex;
  TangentFrames frames = mikktspace_tangents(textured);
  for (std::size_t c = 0; c < frames.tangents.size() / 4; ++c) frames.tangents[4 * c + 3] = -frames.tangents[4 * c + 3];
  p.corner_tangents = std::move(frames.tangents);
  p.drop_tangents = false;
  const std::string zero = frames.zero_corners > 0 ? "; " + tangent_zero_corners_note(frames.zero_corners) : std::string();
  return (had ? "TANGENT recomputed (MikkTSpace) with the new normals" : "TANGENT added (MikkTSpace; " + why + ")") + zero;
}

std::string gltf_world_tangents(const GltfDocument& doc, Mesh& world, bool holds_tangents) {
  const bool any = std::any_of(doc.primitives.begin(), doc.primitives.end(), [](const GltfPrimitive& p) {
    return !p.corner_tangents.empty() || !p.tangents.empty();
  });
  if (!any) return "";
  if (!holds_tangents) return "TANGENT not written: the output format cannot hold tangents (write .ply or .glb)";
  if (!world.has_texcoords()) return "TANGENT not written: the merged mesh has no texture coordinates";
  const TangentFrames frames = mikktspace_tangents(world);
  const std::size_t added = store_tangents_per_vertex(world, frames.tangents);
  return "TANGENT: MikkTSpace frames of the world-space mesh written as vertex properties tx ty tz tw (" +
         std::to_string(added) + " vertices split where corners' frames differ)";
}

}  // namespace shadetool
