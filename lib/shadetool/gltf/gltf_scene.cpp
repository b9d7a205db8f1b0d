// gltf_scene.cpp: see gltf_scene.h.
#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/gltf/gltf_tangents.h>

#include <algorithm>
#include <cmath>

#include <shadetool/core/compact_vertices.h>
#include <shadetool/core/error.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/transform/classify_affine.h>
#include <shadetool/transform/transform_mesh.h>
#include "engine/gltf_accessor.h"
#include "engine/gltf_source.h"

namespace shadetool {

namespace {

using nlohmann::json;

// nodes[i].key as `size` finite numbers, or `fallback` when absent.
std::vector<double> node_numbers(const json& node, const char* key, std::size_t size, std::vector<double> fallback,
                                 const std::string& path, const std::string& name) {
  if (!node.contains(key)) return fallback;
  const json& a = node[key];
  if (!a.is_array() || a.size() != size) fail(name, 0, path + "." + key + ": not an array of " + std::to_string(size) + " numbers");
  std::vector<double> v(size);
  for (std::size_t k = 0; k < size; ++k) {
    if (!a[k].is_number()) fail(name, 0, path + "." + key + "[" + std::to_string(k) + "]: not a number");
    v[k] = a[k].get<double>();
    if (!std::isfinite(v[k])) fail(name, 0, path + "." + key + "[" + std::to_string(k) + "]: not finite");
  }
  return v;
}

// A node's local matrix (glTF 2.0, 3.5.2): `matrix` (column-major 4x4) or T * R * S.
Affine3d local_matrix(const json& node, const std::string& path, const std::string& name) {
  Affine3d M;
  if (node.contains("matrix")) {
    const std::vector<double> m = node_numbers(node, "matrix", 16, {}, path, name);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) M.A.m[r][c] = m[std::size_t(4 * c + r)];
    M.t = {m[12], m[13], m[14]};
    return M;
  }
  const std::vector<double> s = node_numbers(node, "scale", 3, {1, 1, 1}, path, name);
  const std::vector<double> t = node_numbers(node, "translation", 3, {0, 0, 0}, path, name);
  std::vector<double> q = node_numbers(node, "rotation", 4, {0, 0, 0, 1}, path, name);
  // (x, y, z, w) divided by its length: the rotation a quaternion rounded off unit length means.
  // Components scaled by their largest first (a power of two), so the square cannot overflow.
  const double big = std::fmax(std::fmax(std::fabs(q[0]), std::fabs(q[1])), std::fmax(std::fabs(q[2]), std::fabs(q[3])));
  if (!(big > 0)) fail(name, 0, path + ".rotation: the zero quaternion is no rotation");
  int e = 0;
  std::frexp(big, &e);
  for (double& c : q) c = std::ldexp(c, -e);
  const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);  // >= 1/2: checked above
  const double x = q[0] / len, y = q[1] / len, z = q[2] / len, w = q[3] / len;
  const Mat3d R{{{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                  {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                  {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}}};
  M.A = R * Mat3d::diagonal(s[0], s[1], s[2]);
  M.t = {t[0], t[1], t[2]};
  return M;
}

std::string node_path(std::size_t i) { return "nodes[" + std::to_string(i) + "]"; }

// What the merged mesh carries, decided from every primitive before any is placed.
struct MergePlan {
  enum class Normals { None, Vertex, Corner } normals = Normals::None;
  bool face_normals = false;
  bool vertex_colors = false, face_colors = false, vertex_quality = false, face_quality = false;
  int channels = 3;
  bool colors_float = false;
  // Counts for the notes.
  std::size_t normals_from_geometry = 0, face_normals_dropped = 0, white_vertex = 0, white_face = 0, zero_vq = 0, zero_fq = 0;
};

MergePlan plan_merge(const GltfDocument& doc) {
  MergePlan plan;
  bool all_vertex = !doc.primitives.empty(), any_normals = false, all_face = !doc.primitives.empty(), any_face = false;
  for (const GltfPrimitive& p : doc.primitives) {
    const Mesh& m = p.mesh;
    all_vertex = all_vertex && m.has_vertex_normals() && !m.has_corner_normals();
    any_normals = any_normals || m.has_vertex_normals() || m.has_corner_normals() || m.has_face_normals();
    all_face = all_face && m.has_face_normals();
    any_face = any_face || m.has_face_normals();
    plan.vertex_colors = plan.vertex_colors || m.has_vertex_colors();
    plan.face_colors = plan.face_colors || m.has_face_colors();
    plan.vertex_quality = plan.vertex_quality || m.has_vertex_quality();
    plan.face_quality = plan.face_quality || m.has_face_quality();
    if (m.has_vertex_colors() || m.has_face_colors()) {
      plan.channels = std::max(plan.channels, m.color_channels);
      plan.colors_float = plan.colors_float || m.colors_are_float;
    }
  }
  plan.normals = all_vertex ? MergePlan::Normals::Vertex : any_normals ? MergePlan::Normals::Corner : MergePlan::Normals::None;
  plan.face_normals = all_face;
  if (any_face && !all_face)
    for (const GltfPrimitive& p : doc.primitives)
      plan.face_normals_dropped += p.mesh.has_face_normals() && (p.mesh.has_corner_normals() || p.mesh.has_vertex_normals());
  return plan;
}

// Colours of `count` elements with `channels` each, widened to `to` channels (alpha 1); absent: white.
void append_colors(std::vector<float>& out, const std::vector<float>& in, std::size_t count, int channels, int to) {
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 0; k < to; ++k) out.push_back(in.empty() ? 1.0f : k < channels ? in[i * std::size_t(channels) + std::size_t(k)] : 1.0f);
}

// Appends `part` (already placed) to `out` as the plan says; uv: #V by 2 TEXCOORD_0 or empty.
void append_part(Mesh& out, const Mesh& part, const std::vector<double>& uv, MergePlan& plan) {
  const std::uint32_t base = std::uint32_t(out.num_vertices());
  const std::size_t first_corner = out.corner_vertex.size();
  out.positions.insert(out.positions.end(), part.positions.begin(), part.positions.end());
  for (std::size_t f = 0; f < part.num_faces(); ++f) {
    for (std::uint32_t c = part.face_start[f]; c < part.face_start[f + 1]; ++c) out.corner_vertex.push_back(base + part.corner_vertex[c]);
    out.face_start.push_back(std::uint32_t(out.corner_vertex.size()));
  }
  switch (plan.normals) {
    case MergePlan::Normals::None: break;
    case MergePlan::Normals::Vertex:
      out.vertex_normals.insert(out.vertex_normals.end(), part.vertex_normals.begin(), part.vertex_normals.end());
      break;
    case MergePlan::Normals::Corner: {
      const std::uint32_t pool = std::uint32_t(out.corner_normals.size() / 3);
      if (part.has_corner_normals()) {
        out.corner_normals.insert(out.corner_normals.end(), part.corner_normals.begin(), part.corner_normals.end());
        for (std::uint32_t i : part.corner_normal_index) out.corner_normal_index.push_back(pool + i);
      } else if (part.has_vertex_normals()) {
        out.corner_normals.insert(out.corner_normals.end(), part.vertex_normals.begin(), part.vertex_normals.end());
        for (std::uint32_t v : part.corner_vertex) out.corner_normal_index.push_back(pool + v);
      } else {
        const std::vector<double> fn = part.has_face_normals() ? part.face_normals : face_normals(part);
        if (!part.has_face_normals()) plan.normals_from_geometry += part.num_faces();
        out.corner_normals.insert(out.corner_normals.end(), fn.begin(), fn.end());
        for (std::size_t f = 0; f < part.num_faces(); ++f)
          for (std::uint32_t c = part.face_start[f]; c < part.face_start[f + 1]; ++c) out.corner_normal_index.push_back(pool + std::uint32_t(f));
      }
      break;
    }
  }
  if (plan.face_normals) out.face_normals.insert(out.face_normals.end(), part.face_normals.begin(), part.face_normals.end());
  if (plan.vertex_colors) {
    if (!part.has_vertex_colors()) plan.white_vertex += part.num_vertices();
    append_colors(out.vertex_colors, part.vertex_colors, part.num_vertices(), part.color_channels, plan.channels);
  }
  if (plan.face_colors) {
    if (!part.has_face_colors()) plan.white_face += part.num_faces();
    append_colors(out.face_colors, part.face_colors, part.num_faces(), part.color_channels, plan.channels);
  }
  if (plan.vertex_quality) {
    if (!part.has_vertex_quality()) plan.zero_vq += part.num_vertices();
    if (part.has_vertex_quality()) out.vertex_quality.insert(out.vertex_quality.end(), part.vertex_quality.begin(), part.vertex_quality.end());
    else out.vertex_quality.resize(out.vertex_quality.size() + part.num_vertices(), 0.0f);
  }
  if (plan.face_quality) {
    if (!part.has_face_quality()) plan.zero_fq += part.num_faces();
    if (part.has_face_quality()) out.face_quality.insert(out.face_quality.end(), part.face_quality.begin(), part.face_quality.end());
    else out.face_quality.resize(out.face_quality.size() + part.num_faces(), 0.0f);
  }
  // Texture coordinates: per corner into a pool; corners of a part without get kNoTexcoord.
  if (!uv.empty() || out.has_texcoords()) {
    if (!out.has_texcoords()) out.corner_texcoord_index.assign(first_corner, kNoTexcoord);
    const std::uint32_t pool = std::uint32_t(out.texcoords.size() / 2);
    for (std::size_t v = 0; v < uv.size() / 2; ++v) {
      out.texcoords.push_back(uv[2 * v]);
      out.texcoords.push_back(1 - uv[2 * v + 1]);  // glTF's origin top left -> bottom left
    }
    for (std::uint32_t v : part.corner_vertex) out.corner_texcoord_index.push_back(uv.empty() ? kNoTexcoord : pool + v);
  }
}

// Which vertices each primitive instance carries into the world mesh. Primitives often share one
// POSITION accessor, each using a part of it (mode5.gltf: 412 primitives on 54 accessors, a
// primitive using 3 to 43 of up to 254 vertices): copying the whole accessor with every instance
// wrote each vertex once per primitive, all but one copy unreferenced (104,696 vertices, 3,610
// used). An instance carries the vertices its primitive's faces use; a vertex that no primitive
// of its accessor uses (unreferenced in the input too) goes with the first instance of the first
// such primitive, so nothing read is dropped. A primitive whose vertex count a command changed
// (read_vertices differs) is its own group. first[i]: the mask of primitive i's first instance;
// used[i]: of the others.
struct WorldVertices {
  std::vector<std::vector<bool>> first, used;
};

WorldVertices world_vertices(const GltfDocument& document) {
  const std::size_t P = document.primitives.size();
  WorldVertices w;
  w.used.resize(P);
  std::vector<long long> group(P);
  for (std::size_t i = 0; i < P; ++i) {
    const GltfPrimitive& p = document.primitives[i];
    const std::size_t V = p.mesh.num_vertices();
    w.used[i].assign(V, false);
    for (std::uint32_t v : p.mesh.corner_vertex)
      if (v < V) w.used[i][v] = true;
    group[i] = -1 - (long long)(i);  // its own, unless it shares an accessor as read
    if (document.source && V == p.read_vertices && p.mesh_index < document.source->model.meshes.size() &&
        p.primitive_index < document.source->model.meshes[p.mesh_index].primitives.size()) {
      const auto& attrs = document.source->model.meshes[p.mesh_index].primitives[p.primitive_index].attributes;
      const auto it = attrs.find("POSITION");
      if (it != attrs.end() && it->second >= 0) group[i] = it->second;
    }
  }
  w.first = w.used;
  std::vector<bool> owned(P, false);  // i is the first primitive of its group
  for (std::size_t i = 0; i < P; ++i) {
    if (owned[i]) continue;
    std::vector<bool> any = w.used[i];
    std::vector<std::size_t> members{i};
    for (std::size_t j = i + 1; j < P; ++j)
      if (group[j] == group[i]) {
        owned[j] = true;
        members.push_back(j);
        for (std::size_t v = 0; v < any.size() && v < w.used[j].size(); ++v) any[v] = any[v] || w.used[j][v];
      }
    for (std::size_t v = 0; v < any.size(); ++v)
      if (!any[v]) w.first[i][v] = true;  // unreferenced in the input: kept once
  }
  return w;
}

// Appends `part` (already placed) carrying only the vertices `keep` marks (world_vertices);
// returns how many it left out.
std::size_t append_kept(Mesh& out, Mesh part, std::vector<double> uv, const std::vector<bool>& keep, MergePlan& plan) {
  const std::vector<std::uint32_t> old_to_new = compact_vertices(part, keep);
  std::size_t kept = 0;
  for (std::uint32_t n : old_to_new) kept += n != kRemovedVertex;
  compact_vertex_rows(uv, 2, old_to_new, kept);
  append_part(out, part, uv, plan);
  return old_to_new.size() - kept;
}

}  // namespace

std::vector<GltfNodePlacement> gltf_scene_nodes(const GltfDocument& document) {
  std::vector<GltfNodePlacement> out;
  if (!document.source) return out;
  const json& j = document.source->json;
  const std::string& name = document.source->name;
  if (!j.contains("nodes") || !j["nodes"].is_array()) return out;
  const json& nodes = j["nodes"];
  std::vector<std::size_t> roots;
  const std::size_t scene = j.contains("scene") && j["scene"].is_number_unsigned() ? j["scene"].get<std::size_t>() : 0;
  if (j.contains("scenes") && j["scenes"].is_array() && scene < j["scenes"].size() && j["scenes"][scene].contains("nodes")) {
    for (const auto& n : j["scenes"][scene]["nodes"])
      if (n.is_number_unsigned()) roots.push_back(n.get<std::size_t>());
  } else {  // no scene: every node that is nobody's child
    std::vector<bool> child(nodes.size(), false);
    for (const auto& n : nodes)
      if (n.is_object() && n.contains("children"))
        for (const auto& c : n["children"])
          if (c.is_number_unsigned() && c.get<std::size_t>() < child.size()) child[c.get<std::size_t>()] = true;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (!child[i]) roots.push_back(i);
  }
  // The node graph was checked to be a forest on reading (gltf_read.cpp): this walk ends.
  std::vector<GltfNodePlacement> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it)
    if (*it < nodes.size()) stack.push_back({*it, local_matrix(nodes[*it], node_path(*it), name)});
  while (!stack.empty()) {
    const GltfNodePlacement top = stack.back();
    stack.pop_back();
    out.push_back(top);
    if (!nodes[top.node].contains("children")) continue;
    const json& ch = nodes[top.node]["children"];
    for (std::size_t k = ch.size(); k-- > 0;) {
      const std::size_t c = ch[k].get<std::size_t>();
      if (c < nodes.size()) stack.push_back({c, compose(top.world, local_matrix(nodes[c], node_path(c), name))});
    }
  }
  return out;
}

namespace {

// The placements of node `n`'s mesh: the node itself, or with EXT_mesh_gpu_instancing one per
// instance, world_from_node * T_i R_i S_i (the instance's TRANSLATION, ROTATION, SCALE accessors:
// the same rules as a node's T R S, glTF 2.0 3.5.2, so local_matrix reads them); `instanced` says
// which.
std::vector<GltfNodePlacement> instance_placements(const GltfDocument& document, const GltfNodePlacement& n, bool& instanced) {
  instanced = false;
  const json& node = document.source->json["nodes"][n.node];
  if (!node.contains("extensions") || !node["extensions"].is_object() || !node["extensions"].contains("EXT_mesh_gpu_instancing"))
    return {n};
  const std::string& name = document.source->name;
  const std::string path = node_path(n.node) + ".extensions.EXT_mesh_gpu_instancing.attributes";
  const json& ext = node["extensions"]["EXT_mesh_gpu_instancing"];
  if (!ext.is_object() || !ext.contains("attributes") || !ext["attributes"].is_object()) fail(name, 0, path + ": missing (an object)");
  const json& attributes = ext["attributes"];
  struct Part { const char* key; std::size_t size; std::vector<double> values; };
  Part parts[3] = {{"TRANSLATION", 3, {}}, {"ROTATION", 4, {}}, {"SCALE", 3, {}}};
  std::size_t count = 0;
  bool any = false;
  for (Part& part : parts) {
    if (!attributes.contains(part.key)) continue;
    const json& a = attributes[part.key];
    if (!a.is_number_unsigned()) fail(name, 0, path + "." + part.key + ": not an accessor index");
    part.values = io::gltf::accessor_doubles(*document.source, a.get<int>(), name);
    const std::size_t c = part.values.size() / part.size;  // size > 0
    if (c * part.size != part.values.size())
      fail(name, 0, path + "." + part.key + ": not " + std::to_string(part.size) + " numbers per instance");
    if (any && c != count) fail(name, 0, path + "." + part.key + ": " + std::to_string(c) + " instances, not " + std::to_string(count));
    count = c;
    any = true;
  }
  if (!any) return {n};  // no attribute: the node's mesh once (the extension's default)
  std::vector<GltfNodePlacement> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    json trs = json::object();
    for (const Part& part : parts)
      if (!part.values.empty())
        trs[part.key[0] == 'T' ? "translation" : part.key[0] == 'R' ? "rotation" : "scale"] =
            std::vector<double>(part.values.begin() + std::ptrdiff_t(i * part.size), part.values.begin() + std::ptrdiff_t((i + 1) * part.size));
    out.push_back({n.node, compose(n.world, local_matrix(trs, path + " (instance " + std::to_string(i) + ")", name))});
  }
  instanced = true;
  return out;
}

}  // namespace

std::vector<GltfPrimitivePlacements> gltf_primitive_placements(const GltfDocument& document) {
  std::vector<GltfPrimitivePlacements> out(document.primitives.size());
  const std::vector<GltfNodePlacement> placements = gltf_scene_nodes(document);
  if (placements.empty()) return out;
  const json& nodes = document.source->json["nodes"];
  for (std::size_t i = 0; i < document.primitives.size(); ++i)
    for (const GltfNodePlacement& n : placements) {
      const json& node = nodes[n.node];
      if (!node.contains("mesh") || !node["mesh"].is_number_unsigned() || node["mesh"].get<std::size_t>() != document.primitives[i].mesh_index)
        continue;
      out[i].in_scene = true;
      bool instanced = false;
      const std::vector<GltfNodePlacement> instances = instance_placements(document, n, instanced);
      if (instanced) out[i].gpu_instances += instances.size();
      for (const GltfNodePlacement& placed : instances) {
        if (classify_affine(placed.world).path == TransformPath::Singular) {
          out[i].singular_nodes.push_back(n.node);
          continue;
        }
        out[i].nodes.push_back(placed);
        if (node.contains("skin")) out[i].skinned_nodes.push_back(n.node);
      }
    }
  return out;
}

Mesh gltf_placed_mesh(const GltfDocument& document, const GltfPrimitive& primitive, const GltfNodePlacement* placement) {
  Mesh placed = primitive.mesh;
  if (placement) {
    const std::string name = gltf_source_name(document);
    transform_mesh(placed, placement->world, {}, name + ": " + node_path(placement->node) + " (" + primitive.json_path + ")");
  }
  return placed;
}

Mesh gltf_world_mesh(const GltfDocument& document, std::vector<std::string>& notes) {
  MergePlan plan = plan_merge(document);
  const std::vector<GltfPrimitivePlacements> placements = gltf_primitive_placements(document);

  const WorldVertices carried = world_vertices(document);

  Mesh out;
  std::vector<std::string> unplaced, hidden, skinned, morphed, uv_changed;
  std::size_t instances = 0, repeated = 0, left_out = 0, gpu_instances = 0;
  bool any_placed = false;
  for (std::size_t i = 0; i < document.primitives.size(); ++i) {
    const GltfPrimitive& p = document.primitives[i];
    const GltfPrimitivePlacements& where = placements[i];
    bool changed = false;
    const std::vector<double> uv = gltf_texcoords(document, p, changed);
    if (changed) uv_changed.push_back(p.json_path);
    if (!p.targets.empty()) morphed.push_back(p.json_path);
    gpu_instances += where.gpu_instances;
    for (std::size_t n : where.singular_nodes) hidden.push_back(node_path(n));
    for (std::size_t n : where.skinned_nodes) skinned.push_back(node_path(n));
    if (!where.in_scene) {  // in no node of the scene: once, in its object space
      unplaced.push_back(p.json_path);
      left_out += append_kept(out, p.mesh, uv, carried.first[i], plan);
      ++instances;
      continue;
    }
    for (std::size_t k = 0; k < where.nodes.size(); ++k) {
      left_out += append_kept(out, gltf_placed_mesh(document, p, &where.nodes[k]), uv, k == 0 ? carried.first[i] : carried.used[i], plan);
      ++instances;
      repeated += k > 0;
      any_placed = true;
    }
  }

  auto list = [](std::vector<std::string> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    std::string s;
    for (std::size_t i = 0; i < v.size() && i < 4; ++i) s += (i ? ", " : "") + v[i];
    if (v.size() > 4) s += " and " + std::to_string(v.size() - 4) + " more";
    return s;
  };
  if (any_placed)
    notes.push_back(std::to_string(instances) + " glTF primitive instances placed in world space by their nodes' matrices" +
                    (repeated ? " (" + std::to_string(repeated) + " repeated: meshes shown by several nodes" +
                                    (gpu_instances ? " or instances" : "") + ")" : std::string()) +
                    (gpu_instances ? "; " + std::to_string(gpu_instances) + " of them EXT_mesh_gpu_instancing instances" +
                                     " (node * T R S of each)" : std::string()));
  if (left_out)
    notes.push_back(std::to_string(left_out) + " vertex copies not written: each primitive instance carries the vertices " +
                    "its faces use (primitives share POSITION accessors; a vertex no face uses is written once)");
  if (!unplaced.empty()) notes.push_back("no node of the scene shows " + list(unplaced) + ": written in object space");
  if (!hidden.empty()) notes.push_back(list(hidden) + ": singular matrix (scale 0): the mesh it shows is not placed there");
  if (!skinned.empty()) notes.push_back(list(skinned) + ": skinned mesh placed by its node (the bind pose; joints not applied)");
  if (!morphed.empty()) notes.push_back(list(morphed) + ": morph targets not applied (the base shape)");
  if (!uv_changed.empty()) notes.push_back(list(uv_changed) + ": TEXCOORD_0 not carried (the command changed the vertices)");
  if (plan.normals_from_geometry)
    notes.push_back(std::to_string(plan.normals_from_geometry) + " faces of primitives without normals get their faces' normals");
  if (plan.face_normals_dropped)
    notes.push_back(std::to_string(plan.face_normals_dropped) + " primitives' face normals not kept (not every primitive has face normals)");
  if (plan.white_vertex) notes.push_back(std::to_string(plan.white_vertex) + " vertices of primitives without COLOR_0 written white");
  if (plan.white_face) notes.push_back(std::to_string(plan.white_face) + " faces of primitives without face colours written white");
  if (plan.zero_vq) notes.push_back(std::to_string(plan.zero_vq) + " vertices of primitives without quality written as quality 0");
  if (plan.zero_fq) notes.push_back(std::to_string(plan.zero_fq) + " faces of primitives without quality written as quality 0");
  if (plan.vertex_colors || plan.face_colors) {
    out.color_channels = plan.channels;
    out.colors_are_float = plan.colors_float;
  }
  if (out.has_texcoords()) out.texcoord_dims = 2;
  if (document.passed_through_primitives > 0)
    notes.push_back(std::to_string(document.passed_through_primitives) + " POINTS/LINES primitives not in the mesh");
  return out;
}

}  // namespace shadetool
