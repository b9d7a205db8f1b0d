// gltf_decompress.cpp: Draco and meshopt decoding for glTF (see gltf_decompress.h).
#include "gltf_decompress.h"

#include <cstdint>
#include <cstring>

#include <draco/compression/decode.h>
#include <meshoptimizer.h>

#include <shadetool/core/error.h>

namespace shadetool::io::gltf {

namespace {

using nlohmann::json;

constexpr const char* kDraco = "KHR_draco_mesh_compression";
constexpr const char* kMeshopt = "EXT_meshopt_compression";

const json* extension(const json& object, const char* name) {
  if (!object.is_object() || !object.contains("extensions") || !object["extensions"].is_object()) return nullptr;
  const json& e = object["extensions"];
  return e.contains(name) ? &e[name] : nullptr;
}

void erase_extension(json& object, const char* name) {
  if (!object.contains("extensions") || !object["extensions"].is_object()) return;
  object["extensions"].erase(name);
  if (object["extensions"].empty()) object.erase("extensions");
}

void erase_from_list(json& j, const char* key, const char* name) {
  if (!j.contains(key) || !j[key].is_array()) return;
  json kept = json::array();
  for (const json& e : j[key])
    if (!(e.is_string() && e.get<std::string>() == name)) kept.push_back(e);
  if (kept.empty()) j.erase(key);
  else j[key] = std::move(kept);
}

// An accessor index whose accessor has no bufferView (Draco's, before decoding).
bool is_accessor_without_view(const json& j, const json& index) {
  if (!index.is_number_integer() || index.get<long long>() < 0 || !j.contains("accessors") || !j["accessors"].is_array() ||
      index.get<std::size_t>() >= j["accessors"].size())
    return false;
  const json& a = j["accessors"][index.get<std::size_t>()];
  return a.is_object() && !a.contains("bufferView");
}

std::size_t size_field(const json& o, const char* key, const std::string& path, const std::string& name, bool required) {
  if (!o.contains(key)) {
    if (required) fail(name, 0, path + "." + key + ": missing");
    return 0;
  }
  if (!o[key].is_number_integer() || o[key].get<long long>() < 0) fail(name, 0, path + "." + key + ": not a non-negative integer");
  return o[key].get<std::size_t>();
}

// EXT_meshopt_compression: the view's decoded bytes, written into its own buffer.
void decode_meshopt_view(GltfSource& s, std::size_t v, const json& ext, const std::string& name) {
  const std::string path = "bufferViews[" + std::to_string(v) + "].extensions." + kMeshopt;
  tinygltf::Model& model = s.model;
  const std::size_t buffer = size_field(ext, "buffer", path, name, true);
  const std::size_t offset = size_field(ext, "byteOffset", path, name, false);
  const std::size_t length = size_field(ext, "byteLength", path, name, true);
  const std::size_t stride = size_field(ext, "byteStride", path, name, true);
  const std::size_t count = size_field(ext, "count", path, name, true);
  const std::string mode = ext.value("mode", std::string());
  const std::string filter = ext.contains("filter") && ext["filter"].is_string() ? ext["filter"].get<std::string>() : "NONE";
  if (buffer >= model.buffers.size()) fail(name, 0, path + ".buffer: " + std::to_string(buffer) + " is not a buffer index");
  const std::vector<unsigned char>& src = model.buffers[buffer].data;
  if (offset > src.size() || length > src.size() - offset)
    fail(name, 0, path + ": bytes " + std::to_string(offset) + "+" + std::to_string(length) + " beyond buffers[" +
                      std::to_string(buffer) + "] (" + std::to_string(src.size()) + " bytes)");
  tinygltf::BufferView& view = model.bufferViews[v];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
    fail(name, 0, "bufferViews[" + std::to_string(v) + "].buffer: not a buffer index");
  std::vector<unsigned char>& dst = model.buffers[std::size_t(view.buffer)].data;
  const std::size_t out_bytes = count * stride;  // count and stride checked against the view below
  if (stride == 0 || out_bytes / stride != count || out_bytes > view.byteLength || view.byteOffset > dst.size() ||
      out_bytes > dst.size() - view.byteOffset)
    fail(name, 0, path + ": count " + std::to_string(count) + " x byteStride " + std::to_string(stride) +
                      " does not fit bufferViews[" + std::to_string(v) + "] in its buffer");
  // meshopt reads a few bytes past what it needs in its fast path only within the given size.
  unsigned char* out = dst.data() + view.byteOffset;
  const unsigned char* in = src.data() + offset;
  int rc = -1;
  if (mode == "ATTRIBUTES") {
    if (stride % 4 != 0 || stride > 256) fail(name, 0, path + ".byteStride: ATTRIBUTES need a multiple of 4 up to 256");
    rc = meshopt_decodeVertexBuffer(out, count, stride, in, length);
  } else if (mode == "TRIANGLES" || mode == "INDICES") {
    if (stride != 2 && stride != 4) fail(name, 0, path + ".byteStride: " + mode + " need 2 or 4");
    rc = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out, count, stride, in, length)
                             : meshopt_decodeIndexSequence(out, count, stride, in, length);
  } else {
    fail(name, 0, path + ".mode: '" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
  }
  if (rc != 0) fail(name, 0, path + ": the meshopt data does not decode (meshoptimizer returned " + std::to_string(rc) + ")");
  if (filter == "OCTAHEDRAL") {
    if (mode != "ATTRIBUTES" || (stride != 4 && stride != 8)) fail(name, 0, path + ".filter: OCTAHEDRAL needs ATTRIBUTES of stride 4 or 8");
    meshopt_decodeFilterOct(out, count, stride);
  } else if (filter == "QUATERNION") {
    if (mode != "ATTRIBUTES" || stride != 8) fail(name, 0, path + ".filter: QUATERNION needs ATTRIBUTES of stride 8");
    meshopt_decodeFilterQuat(out, count, stride);
  } else if (filter == "EXPONENTIAL") {
    if (mode != "ATTRIBUTES" || stride % 4 != 0) fail(name, 0, path + ".filter: EXPONENTIAL needs ATTRIBUTES of a stride multiple of 4");
    meshopt_decodeFilterExp(out, count, stride);
  } else if (filter != "NONE") {
    fail(name, 0, path + ".filter: '" + filter + "' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
  }
  view.extensions.erase(kMeshopt);
}

// Every Draco point's value converted to the accessor's component type, appended as bytes.
template <class T>
bool append_converted(const draco::PointAttribute& att, std::size_t points, int comps, std::vector<unsigned char>& out) {
  std::vector<T> value(static_cast<std::size_t>(comps));
  for (std::size_t p = 0; p < points; ++p) {
    if (!att.ConvertValue<T>(att.mapped_index(draco::PointIndex(std::uint32_t(p))), std::int8_t(comps), value.data())) return false;
    const std::size_t at = out.size();
    out.resize(at + sizeof(T) * std::size_t(comps));
    std::memcpy(out.data() + at, value.data(), sizeof(T) * std::size_t(comps));
  }
  return true;
}

int type_comps(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;  // matrices are not vertex attributes Draco carries
  }
}

// Appends `bytes` as a new bufferView of the decoded buffer (model and JSON) and points accessor
// `a` at it.
struct DecodedBuffer {
  GltfSource& s;
  int buffer = -1;
  void attach(int a, std::vector<unsigned char> bytes, std::size_t elem, bool indices) {
    tinygltf::Model& model = s.model;
    if (buffer < 0) {
      model.buffers.emplace_back();
      buffer = int(model.buffers.size() - 1);
    }
    std::vector<unsigned char>& data = model.buffers[std::size_t(buffer)].data;
    const std::size_t stride = indices ? elem : (elem + 3) / 4 * 4;  // vertex elements on 4-byte boundaries
    while (data.size() % 4) data.push_back(0);
    const std::size_t offset = data.size(), count = elem ? bytes.size() / elem : 0;
    data.resize(offset + count * stride, 0);
    for (std::size_t i = 0; i < count; ++i) std::memcpy(&data[offset + i * stride], &bytes[i * elem], elem);
    tinygltf::BufferView view;
    view.buffer = buffer;
    view.byteOffset = offset;
    view.byteLength = count * stride;
    view.byteStride = stride != elem ? stride : 0;
    view.target = indices ? TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER : TINYGLTF_TARGET_ARRAY_BUFFER;
    model.bufferViews.push_back(view);
    json jv = {{"buffer", buffer}, {"byteOffset", offset}, {"byteLength", count * stride}, {"target", view.target}};
    if (view.byteStride) jv["byteStride"] = stride;
    s.json["bufferViews"].push_back(jv);
    const int index = int(model.bufferViews.size() - 1);
    model.accessors[std::size_t(a)].bufferView = index;
    model.accessors[std::size_t(a)].byteOffset = 0;
    json& ja = s.json["accessors"][std::size_t(a)];
    ja["bufferView"] = index;
    ja.erase("byteOffset");
  }
};

void decode_draco_primitive(GltfSource& s, DecodedBuffer& decoded, std::size_t m, std::size_t p, const json& ext,
                            const std::string& name) {
  const std::string path = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "].extensions." + kDraco;
  tinygltf::Model& model = s.model;
  const std::size_t v = size_field(ext, "bufferView", path, name, true);
  if (v >= model.bufferViews.size()) fail(name, 0, path + ".bufferView: " + std::to_string(v) + " is not a bufferView index");
  const tinygltf::BufferView& view = model.bufferViews[v];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size() ||
      view.byteOffset > model.buffers[std::size_t(view.buffer)].data.size() ||
      view.byteLength > model.buffers[std::size_t(view.buffer)].data.size() - view.byteOffset)
    fail(name, 0, path + ".bufferView: bufferViews[" + std::to_string(v) + "] lies beyond its buffer");
  draco::DecoderBuffer in;
  in.Init(reinterpret_cast<const char*>(model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset), view.byteLength);
  draco::Decoder decoder;
  auto result = decoder.DecodeMeshFromBuffer(&in);
  if (!result.ok()) fail(name, 0, path + ": the Draco data does not decode (" + result.status().error_msg_string() + ")");
  const std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
  const std::size_t points = mesh->num_points();
  const tinygltf::Primitive& prim = model.meshes[m].primitives[p];

  // Corners into the primitive's indices accessor, in its component type.
  if (prim.indices >= 0) {
    if (std::size_t(prim.indices) >= model.accessors.size()) fail(name, 0, path + ": the primitive's indices are not an accessor");
    const tinygltf::Accessor& a = model.accessors[std::size_t(prim.indices)];
    if (a.count != 3 * std::size_t(mesh->num_faces()))
      fail(name, 0, path + ": accessors[" + std::to_string(prim.indices) + "] has " + std::to_string(a.count) +
                        " indices, the Draco mesh " + std::to_string(mesh->num_faces()) + " triangles");
    const int cb = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                   : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                   : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                               : 0;
    if (cb == 0) fail(name, 0, path + ": accessors[" + std::to_string(prim.indices) + "] is not UNSIGNED_BYTE/SHORT/INT");
    std::vector<unsigned char> bytes(a.count * std::size_t(cb));
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh->face(f)[k].value();
        if (cb < 4 && index >= (1u << (8 * cb))) fail(name, 0, path + ": a decoded index does not fit the indices' component type");
        std::memcpy(&bytes[(3 * f.value() + std::uint32_t(k)) * std::uint32_t(cb)], &index, std::size_t(cb));  // little-endian
      }
    if (a.bufferView < 0) decoded.attach(prim.indices, std::move(bytes), std::size_t(cb), true);
  }

  // Attributes by the extension's map of unique ids.
  if (!ext.contains("attributes") || !ext["attributes"].is_object()) fail(name, 0, path + ".attributes: missing");
  for (const auto& [attr, id] : ext["attributes"].items()) {
    if (!id.is_number_integer() || id.get<long long>() < 0) fail(name, 0, path + ".attributes." + attr + ": not a Draco attribute id");
    const draco::PointAttribute* att = mesh->GetAttributeByUniqueId(id.get<std::uint32_t>());
    if (!att) fail(name, 0, path + ".attributes." + attr + ": the Draco mesh has no attribute " + std::to_string(id.get<long long>()));
    const auto it = prim.attributes.find(attr);
    if (it == prim.attributes.end() || it->second < 0 || std::size_t(it->second) >= model.accessors.size())
      fail(name, 0, path + ".attributes." + attr + ": the primitive has no accessor for it");
    const tinygltf::Accessor& a = model.accessors[std::size_t(it->second)];
    if (a.bufferView >= 0) continue;  // already decoded (shared with another primitive)
    const int comps = type_comps(a.type);
    if (comps == 0) fail(name, 0, path + ".attributes." + attr + ": accessor type is not SCALAR or VEC2..4");
    if (a.count != points)
      fail(name, 0, path + ".attributes." + attr + ": accessors[" + std::to_string(it->second) + "] has " +
                        std::to_string(a.count) + " elements, the Draco mesh " + std::to_string(points) + " points");
    std::vector<unsigned char> bytes;
    bool ok = false;
    std::size_t cb = 0;
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: ok = append_converted<float>(*att, points, comps, bytes), cb = 4; break;
      case TINYGLTF_COMPONENT_TYPE_BYTE: ok = append_converted<std::int8_t>(*att, points, comps, bytes), cb = 1; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: ok = append_converted<std::uint8_t>(*att, points, comps, bytes), cb = 1; break;
      case TINYGLTF_COMPONENT_TYPE_SHORT: ok = append_converted<std::int16_t>(*att, points, comps, bytes), cb = 2; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: ok = append_converted<std::uint16_t>(*att, points, comps, bytes), cb = 2; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: ok = append_converted<std::uint32_t>(*att, points, comps, bytes), cb = 4; break;
      default: ok = false;  // componentType is a JSON integer, not a library enum
    }
    if (!ok) fail(name, 0, path + ".attributes." + attr + ": the Draco attribute does not convert to accessors[" +
                               std::to_string(it->second) + "]'s component type");
    decoded.attach(it->second, std::move(bytes), cb * std::size_t(comps), false);
  }
}

}  // namespace

std::string prepare_compressed(GltfSource& s, CompressedPlan& plan) {
  json& j = s.json;
  plan = CompressedPlan();
  bool changed = false;
  if (j.contains("buffers") && j["buffers"].is_array()) {
    plan.fallback_lengths.assign(j["buffers"].size(), 0);
    for (std::size_t b = 0; b < j["buffers"].size(); ++b) {
      json& buf = j["buffers"][b];
      const json* ext = extension(buf, kMeshopt);
      if (!ext || !ext->is_object() || !ext->value("fallback", false) || buf.contains("uri")) continue;
      if (!buf.contains("byteLength") || !buf["byteLength"].is_number_integer() || buf["byteLength"].get<long long>() < 0)
        fail(s.name, 0, "buffers[" + std::to_string(b) + "].byteLength: not a non-negative integer");
      plan.fallback_lengths[b] = buf["byteLength"].get<std::size_t>();
      buf["uri"] = "data:application/octet-stream;base64,AAAAAA==";  // 4 zero bytes, replaced by the decoded views
      buf["byteLength"] = 4;
      changed = true;
    }
  }
  if (j.contains("meshes") && j["meshes"].is_array())
    for (std::size_t m = 0; m < j["meshes"].size(); ++m) {
      const json& mesh = j["meshes"][m];
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
        const json& prim = mesh["primitives"][p];
        if (!extension(prim, kDraco)) continue;
        const bool hidden = prim.contains("indices") && is_accessor_without_view(j, prim["indices"]);
        plan.draco_indices.push_back({m, p, hidden ? prim["indices"].get<int>() : -1});
      }
    }
  if (!changed && plan.draco_indices.empty()) return std::string();
  if (plan.draco_indices.empty()) return j.dump();
  // The loader never sees the extension (a tinygltf built with Draco would decode it itself).
  json for_loader = j;
  for (const auto& d : plan.draco_indices) {
    json& prim = for_loader["meshes"][d.mesh]["primitives"][d.primitive];
    if (d.accessor >= 0) prim.erase("indices");
    erase_extension(prim, kDraco);
  }
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) erase_from_list(for_loader, key, kDraco);
  return for_loader.dump();
}

void decode_compressed(GltfSource& s, const CompressedPlan& plan, std::vector<std::string>& notes) {
  json& j = s.json;
  tinygltf::Model& model = s.model;
  const std::vector<std::size_t>& fallback_lengths = plan.fallback_lengths;
  for (const auto& d : plan.draco_indices)
    if (d.accessor >= 0 && d.mesh < model.meshes.size() && d.primitive < model.meshes[d.mesh].primitives.size())
      model.meshes[d.mesh].primitives[d.primitive].indices = d.accessor;
  for (std::size_t b = 0; b < fallback_lengths.size() && b < model.buffers.size(); ++b)
    if (fallback_lengths[b] > 0) {  // the placeholder's 4 bytes become the buffer's declared length
      model.buffers[b].data.assign(fallback_lengths[b], 0);
      j["buffers"][b].erase("uri");
      j["buffers"][b]["byteLength"] = fallback_lengths[b];
    }
  std::size_t views = 0;
  if (j.contains("bufferViews") && j["bufferViews"].is_array())
    for (std::size_t v = 0; v < j["bufferViews"].size() && v < model.bufferViews.size(); ++v) {
      const json* ext = extension(j["bufferViews"][v], kMeshopt);
      if (!ext) ext = extension(j["bufferViews"][v], "KHR_meshopt_compression");  // the ratified name, same fields
      if (!ext) continue;
      if (!ext->is_object()) fail(s.name, 0, "bufferViews[" + std::to_string(v) + "].extensions: not an object");
      decode_meshopt_view(s, v, *ext, s.name);
      erase_extension(j["bufferViews"][v], kMeshopt);
      erase_extension(j["bufferViews"][v], "KHR_meshopt_compression");
      ++views;
    }
  std::size_t primitives = 0;
  DecodedBuffer decoded{s};
  if (!j.contains("bufferViews") || !j["bufferViews"].is_array()) j["bufferViews"] = json::array();
  if (j.contains("meshes") && j["meshes"].is_array())
    for (std::size_t m = 0; m < j["meshes"].size() && m < model.meshes.size(); ++m) {
      json& mesh = j["meshes"][m];
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (std::size_t p = 0; p < mesh["primitives"].size() && p < model.meshes[m].primitives.size(); ++p) {
        const json* ext = extension(mesh["primitives"][p], kDraco);
        if (!ext) continue;
        if (!ext->is_object()) fail(s.name, 0, "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "].extensions." + kDraco + ": not an object");
        decode_draco_primitive(s, decoded, m, p, *ext, s.name);
        erase_extension(mesh["primitives"][p], kDraco);
        model.meshes[m].primitives[p].extensions.erase(kDraco);
        ++primitives;
      }
    }
  if (views > 0) {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
      erase_from_list(j, key, kMeshopt);
      erase_from_list(j, key, "KHR_meshopt_compression");
    }
    notes.push_back(std::to_string(views) + " meshopt-compressed bufferViews (EXT_meshopt_compression) decoded (glTF output is written uncompressed)");
  }
  if (primitives > 0) {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) erase_from_list(j, key, kDraco);
    notes.push_back(std::to_string(primitives) + " Draco-compressed primitives (KHR_draco_mesh_compression) decoded (glTF output is written uncompressed)");
  }
  if (j["bufferViews"].empty()) j.erase("bufferViews");
  s.compact_buffers = views > 0 || primitives > 0;
}

}  // namespace shadetool::io::gltf
