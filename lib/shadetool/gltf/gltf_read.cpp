// gltf_read.cpp: .gltf / .glb -> GltfDocument (see gltf_document.h).
#include <shadetool/gltf/gltf_document.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/error.h>
#include "engine/gltf_accessor.h"
#include "engine/gltf_decompress.h"
#include "engine/gltf_schema.h"
#include "engine/gltf_source.h"

namespace shadetool {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using io::gltf::accessor_doubles;

std::uint32_t le32(const char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

// The JSON chunk of a GLB (binary glTF 2.0: 12-byte header, then chunks of length, type, data).
std::string_view glb_json(std::string_view bytes, const std::string& name) {
  if (bytes.size() < 20) fail(name, 0, "GLB header truncated (" + std::to_string(bytes.size()) + " bytes)");
  if (le32(bytes.data() + 4) != 2) fail(name, 0, "GLB version " + std::to_string(le32(bytes.data() + 4)) + ": only glTF 2.0 is read");
  const std::uint32_t length = le32(bytes.data() + 8);
  if (length > bytes.size()) fail(name, 0, "GLB header says " + std::to_string(length) + " bytes, the file has " + std::to_string(bytes.size()));
  const std::uint32_t chunk = le32(bytes.data() + 12);
  if (le32(bytes.data() + 16) != 0x4E4F534Au) fail(name, 0, "GLB: the first chunk is not JSON");
  if (chunk > length - 20) fail(name, 0, "GLB: the JSON chunk overruns the file");
  return bytes.substr(20, chunk);
}

bool has_extension(const json& j, const char* ext) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"})
    if (j.contains(key) && j[key].is_array())
      for (const auto& e : j[key])
        if (e.is_string() && e.get<std::string>() == ext) return true;
  return false;
}

// A URI's percent-encoded bytes decoded (RFC 3986, 2.1; as tinygltf decodes a buffer's uri): an
// exporter writes "my%20mesh.bin" for the file "my mesh.bin". A '%' without two hex digits is kept.
std::string uri_decoded(const std::string& uri) {
  const auto hex = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
  };
  std::string out;
  out.reserve(uri.size());
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// External buffer files longer than their byteLength, by canonical path: valid glTF (the Khronos
// validator's BUFFER_BYTE_LENGTH_MISMATCH is for a shorter file only), whose first byteLength bytes
// are the buffer. tinygltf refuses any size but byteLength ("File size mismatch"), so the reader's
// file callback (read_buffer_file) hands it those bytes.
using LongerFiles = std::vector<std::pair<std::string, std::uint64_t>>;

std::string canonical_or_same(const std::string& path) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(fs::path(path), ec);
  return ec ? path : c.string();
}

bool read_buffer_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  if (!tinygltf::ReadWholeFile(out, err, path, nullptr)) return false;
  const LongerFiles& longer = *static_cast<const LongerFiles*>(user);
  const std::string key = canonical_or_same(path);
  for (const auto& [file, length] : longer)
    if (file == key && out->size() > length) out->resize(std::size_t(length));
  return true;
}

// Every external buffer must be there and hold its byteLength: one line naming its JSON path,
// before tinygltf's own words. Returns the files longer than their byteLength (LongerFiles).
LongerFiles require_buffer_files(const json& j, const std::string& name) {
  LongerFiles longer;
  if (!j.contains("buffers") || !j["buffers"].is_array()) return longer;
  const fs::path base = fs::path(name).parent_path();
  for (std::size_t b = 0; b < j["buffers"].size(); ++b) {
    const json& buf = j["buffers"][b];
    if (!buf.is_object() || !buf.contains("uri") || !buf["uri"].is_string()) continue;
    const std::string uri = buf["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) continue;
    const std::string at = "buffers[" + std::to_string(b) + "]";
    std::error_code ec;
    const fs::path file = base / uri_decoded(uri);
    if (!fs::is_regular_file(file, ec))
      fail(name, 0, at + ".uri: cannot read '" + uri + "' (no such file beside the .gltf)");
    if (!buf.contains("byteLength") || !buf["byteLength"].is_number_unsigned()) continue;  // tinygltf's schema words
    const std::uint64_t declared = buf["byteLength"].get<std::uint64_t>();
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) continue;
    if (size < declared)
      fail(name, 0, at + ".byteLength: " + std::to_string(declared) + " bytes declared, but '" + uri + "' holds " +
                        std::to_string(size));
    if (size > declared) longer.emplace_back(canonical_or_same(file.string()), declared);
  }
  return longer;
}

// A buffer view's byteStride, where tinygltf refuses it in its own words: glTF 2.0 5.11.4 (4 to
// 252, a multiple of 4).
void require_byte_strides(const json& j, const std::string& name) {
  if (!j.contains("bufferViews") || !j["bufferViews"].is_array()) return;
  for (std::size_t v = 0; v < j["bufferViews"].size(); ++v) {
    const json& view = j["bufferViews"][v];
    if (!view.is_object() || !view.contains("byteStride") || !view["byteStride"].is_number_integer()) continue;
    const long long stride = view["byteStride"].get<long long>();
    if (stride < 4 || stride > 252 || stride % 4 != 0)
      fail(name, 0, "bufferViews[" + std::to_string(v) + "].byteStride: " + std::to_string(stride) +
                        " is not a multiple of 4 from 4 to 252");
  }
}

// A GLB's buffer 0 without a uri is the BIN chunk (glTF 2.0, 5.1.4 / GLB 4.4.3.3): its byteLength
// must fit in the chunk (which may be up to 3 bytes longer). An image needs a uri or a bufferView
// (5.18). Named by their JSON path here; tinygltf's loader says them without one.
void require_bin_chunk_and_images(std::string_view bytes, bool binary, std::size_t json_chunk, const json& j,
                                  const std::string& name) {
  if (binary && j.contains("buffers") && j["buffers"].is_array() && !j["buffers"].empty() && j["buffers"][0].is_object() &&
      !j["buffers"][0].contains("uri") && j["buffers"][0].contains("byteLength") &&
      j["buffers"][0]["byteLength"].is_number_unsigned()) {
    const std::uint64_t declared = j["buffers"][0]["byteLength"].get<std::uint64_t>();
    const std::uint64_t header = 20 + std::uint64_t(json_chunk);
    std::uint64_t chunk = 0;  // no BIN chunk: 0 bytes
    if (header + 8 <= bytes.size() && le32(bytes.data() + header + 4) == 0x004E4942u)
      chunk = std::min<std::uint64_t>(le32(bytes.data() + header), bytes.size() - header - 8);
    if (declared > chunk)
      fail(name, 0, "buffers[0].byteLength: " + std::to_string(declared) + " bytes declared, but the GLB's BIN chunk holds " +
                        std::to_string(chunk));
  }
  if (!j.contains("images") || !j["images"].is_array()) return;
  for (std::size_t i = 0; i < j["images"].size(); ++i) {
    const json& image = j["images"][i];
    if (image.is_object() && !image.contains("uri") && !image.contains("bufferView"))
      fail(name, 0, "images[" + std::to_string(i) + "]: neither uri nor bufferView (glTF 2.0 5.18: one is required)");
  }
}

// Primitives whose indices accessor has no bufferView: {mesh, primitive, accessor}. Such an
// accessor is zeros, then its sparse values (glTF 2.0, 5.1.1: "When bufferView is undefined, the
// accessor MUST be initialized with zeros"), as engine/gltf_accessor.cpp reads it; tinygltf's loader
// refuses it as indices ("accessor[N] invalid bufferView"), so the loader is given the JSON without
// those indices and they are put back into its model after.
std::vector<std::array<std::size_t, 3>> viewless_indices(const json& j) {
  std::vector<std::array<std::size_t, 3>> out;
  if (!j.contains("meshes") || !j["meshes"].is_array() || !j.contains("accessors") || !j["accessors"].is_array()) return out;
  const json& accessors = j["accessors"];
  for (std::size_t m = 0; m < j["meshes"].size(); ++m) {
    const json& mesh = j["meshes"][m];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
      const json& prim = mesh["primitives"][p];
      if (!prim.is_object() || !prim.contains("indices") || !prim["indices"].is_number_unsigned()) continue;
      const std::size_t a = prim["indices"].get<std::size_t>();
      if (prim.contains("extensions") && prim["extensions"].is_object() && !prim["extensions"].empty()) continue;  // compressed: decode_compressed's
      if (a < accessors.size() && accessors[a].is_object() && !accessors[a].contains("bufferView")) out.push_back({m, p, a});
    }
  }
  return out;
}

// The node graph must be a forest (glTF 2.0, 3.5.3): no node is its own ancestor, none has two
// parents. Iterative walk, so that a deep chain does not exhaust the stack.
void require_node_forest(const json& j, const std::string& name) {
  if (!j.contains("nodes") || !j["nodes"].is_array()) return;
  const std::size_t n = j["nodes"].size();
  std::vector<long> parent(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const json& node = j["nodes"][i];
    if (!node.is_object() || !node.contains("children")) continue;
    const json& ch = node["children"];
    if (!ch.is_array()) continue;
    for (std::size_t k = 0; k < ch.size(); ++k) {
      const std::string path = "nodes[" + std::to_string(i) + "].children[" + std::to_string(k) + "]";
      if (!ch[k].is_number_integer() || ch[k].get<long>() < 0 || std::size_t(ch[k].get<long>()) >= n)
        fail(name, 0, path + ": not a node index");
      const std::size_t c = ch[k].get<std::size_t>();
      if (c == i) fail(name, 0, path + ": node " + std::to_string(i) + " is its own child (the node graph must not be recursive)");
      if (parent[c] >= 0)
        fail(name, 0, path + ": node " + std::to_string(c) + " already has parent " + std::to_string(parent[c]) +
                          " (the node graph must be a forest)");
      parent[c] = long(i);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {  // a cycle: walking up from i returns to i
    std::size_t steps = 0;
    for (long p = parent[i]; p >= 0; p = parent[std::size_t(p)])
      if (std::size_t(p) == i || ++steps > n)
        fail(name, 0, "nodes[" + std::to_string(i) + "]: the node is its own ancestor (the node graph must not be recursive)");
  }
}

// Keeps an image's bytes exactly as read (no decoding): the writer moves them into a bufferView.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                      int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

struct AttributeRule {
  const char* what;
  bool (*allowed)(int type, int component, bool normalized, bool quantized);
  const char* expected;
};

bool position_ok(int type, int c, bool, bool q) {
  return type == TINYGLTF_TYPE_VEC3 &&
         (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
          (q && (c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                 c == TINYGLTF_COMPONENT_TYPE_SHORT || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
}
bool normal_ok(int type, int c, bool n, bool q) {
  return type == TINYGLTF_TYPE_VEC3 &&
         (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
          (q && n && (c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_SHORT)));
}
bool tangent_ok(int type, int c, bool n, bool q) {
  return type == TINYGLTF_TYPE_VEC4 &&
         (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
          (q && n && (c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_SHORT)));
}
bool color_ok(int type, int c, bool n, bool) {
  return (type == TINYGLTF_TYPE_VEC3 || type == TINYGLTF_TYPE_VEC4) &&
         (c == TINYGLTF_COMPONENT_TYPE_FLOAT ||
          (n && (c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || c == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
}
bool delta_ok(int type, int c, bool, bool q) {
  return type == TINYGLTF_TYPE_VEC3 &&
         (c == TINYGLTF_COMPONENT_TYPE_FLOAT || (q && (c == TINYGLTF_COMPONENT_TYPE_BYTE || c == TINYGLTF_COMPONENT_TYPE_SHORT)));
}

const AttributeRule kPosition{"POSITION", position_ok, "FLOAT VEC3 (or [UNSIGNED_]BYTE/SHORT VEC3 with KHR_mesh_quantization)"};
const AttributeRule kNormal{"NORMAL", normal_ok, "FLOAT VEC3 (or normalized BYTE/SHORT VEC3 with KHR_mesh_quantization)"};
const AttributeRule kTangent{"TANGENT", tangent_ok, "FLOAT VEC4 (or normalized BYTE/SHORT VEC4 with KHR_mesh_quantization)"};
const AttributeRule kColor{"COLOR_0", color_ok, "VEC3/VEC4 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT"};
const AttributeRule kDelta{"delta", delta_ok, "FLOAT VEC3 (or BYTE/SHORT VEC3 with KHR_mesh_quantization)"};

// Decodes attribute `index` of a primitive after checking its type against `rule` and its count.
std::vector<double> decode_attribute(const GltfSource& source, int index, const AttributeRule& rule, bool quantized,
                                     std::size_t expected_count, const std::string& path, const std::string& name) {
  const tinygltf::Model& model = source.model;
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    fail(name, 0, path + ": " + std::to_string(index) + " is not an accessor index");
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  if (!rule.allowed(a.type, a.componentType, a.normalized, quantized))
    fail(name, 0, path + ": accessors[" + std::to_string(index) + "] has componentType " + std::to_string(a.componentType) +
                      (a.normalized ? " normalized" : "") + ", type " + std::to_string(io::gltf::type_components(a.type)) +
                      " components; " + rule.what + " must be " + rule.expected);
  if (expected_count != std::size_t(-1) && a.count != expected_count)
    fail(name, 0, path + ": accessors[" + std::to_string(index) + "] has " + std::to_string(a.count) +
                      " elements, POSITION has " + std::to_string(expected_count));
  return accessor_doubles(source, index, name);
}

void decode_primitive(const GltfSource& source, bool quantized, GltfPrimitive& gp, const std::string& name) {
  const tinygltf::Model& model = source.model;
  const tinygltf::Primitive& prim = model.meshes[gp.mesh_index].primitives[gp.primitive_index];
  const std::string path = gp.json_path;
  auto pos = prim.attributes.find("POSITION");
  if (pos == prim.attributes.end()) fail(name, 0, path + ".attributes: no POSITION");
  Mesh& mesh = gp.mesh;
  mesh.positions = decode_attribute(source, pos->second, kPosition, quantized, std::size_t(-1), path + ".attributes.POSITION", name);
  const std::size_t V = mesh.num_vertices();
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      fail(name, 0, path + ".attributes.POSITION: vertex " + std::to_string(i / 3) + " has a NaN or infinite coordinate");
  if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end())
    mesh.vertex_normals = decode_attribute(source, it->second, kNormal, quantized, V, path + ".attributes.NORMAL", name);
  if (auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end())
    gp.tangents = decode_attribute(source, it->second, kTangent, quantized, V, path + ".attributes.TANGENT", name);
  if (auto it = prim.attributes.find("COLOR_0"); it != prim.attributes.end()) {
    const std::vector<double> c = decode_attribute(source, it->second, kColor, quantized, V, path + ".attributes.COLOR_0", name);
    const tinygltf::Accessor& a = model.accessors[std::size_t(it->second)];
    mesh.color_channels = a.type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
    mesh.colors_are_float = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    gp.color_component_type = a.componentType;
    mesh.vertex_colors.assign(c.begin(), c.end());
  }
  gp.mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  for (auto& [attr, index] : prim.attributes) {  // every other attribute: its count must agree too
    gp.attributes.push_back(attr);
    if (index < 0 || std::size_t(index) >= model.accessors.size())
      fail(name, 0, path + ".attributes." + attr + ": " + std::to_string(index) + " is not an accessor index");
    if (model.accessors[std::size_t(index)].count != V)
      fail(name, 0, path + ".attributes." + attr + ": accessors[" + std::to_string(index) + "] has " +
                        std::to_string(model.accessors[std::size_t(index)].count) + " elements, POSITION has " + std::to_string(V));
  }
  for (std::size_t t = 0; t < prim.targets.size(); ++t) {
    GltfMorphTarget target;
    const std::string tp = path + ".targets[" + std::to_string(t) + "].";
    for (auto& [attr, index] : prim.targets[t]) {
      if (attr == "POSITION") target.position_deltas = decode_attribute(source, index, kDelta, quantized, V, tp + attr, name);
      else if (attr == "NORMAL") target.normal_deltas = decode_attribute(source, index, kDelta, quantized, V, tp + attr, name);
      else if (attr == "TANGENT") target.tangent_deltas = decode_attribute(source, index, kDelta, quantized, V, tp + attr, name);
    }
    gp.targets.push_back(std::move(target));
  }

  // Corners: the indices (or 0..V-1), strips and fans unrolled (spec 3.7.2.1).
  mesh.corner_vertex = io::gltf::primitive_corners(source, prim.indices, prim.mode, V, path, name);
  const std::vector<std::uint32_t>& cv = mesh.corner_vertex;
  const std::size_t F = cv.size() / 3;
  reserve_bulk(mesh.face_start, F + 1);
  mesh.face_start.resize(F + 1);
  for (std::size_t f = 0; f <= F; ++f) mesh.face_start[f] = std::uint32_t(3 * f);
  mesh.precision = ValuePrecision::Float;
  gp.read_vertices = V;
  gp.read_tangents = gp.tangents;
  gp.read_targets = gp.targets;
}

// The BIN chunk of a GLB, to be read in place instead of copied into tinygltf's buffer, when
// tinygltf would load it without a complaint and nothing else needs it in the model: buffer 0 has
// no uri (it is the BIN chunk: glTF 2.0 4.4.3.3) and a byteLength within the chunk, every other
// buffer has a uri, no image lies in a bufferView (tinygltf reads those from the loaded buffer),
// nothing is compressed (the decoders write into the model's buffers), and the chunks pass
// tinygltf's own checks (JSON chunk padded to 4 bytes; a BIN chunk of at least 4 bytes, a multiple
// of 4, within the file). Empty otherwise: tinygltf loads the file as it is.
std::string_view bin_in_place(std::string_view bytes, std::size_t json_chunk, const json& j) {
  if (json_chunk % 4 != 0) return {};
  if (!j.contains("buffers") || !j["buffers"].is_array() || j["buffers"].empty()) return {};
  const json& buffers = j["buffers"];
  if (!buffers[0].is_object() || buffers[0].contains("uri") || !buffers[0].contains("byteLength") ||
      !buffers[0]["byteLength"].is_number_integer() || buffers[0]["byteLength"].get<long long>() <= 0)
    return {};
  for (std::size_t b = 1; b < buffers.size(); ++b)
    if (!buffers[b].is_object() || !buffers[b].contains("uri") || !buffers[b]["uri"].is_string() ||
        buffers[b]["uri"].get<std::string>().empty())
      return {};
  if (j.contains("images") && j["images"].is_array())
    for (const json& image : j["images"])
      if (!image.is_object() || image.contains("bufferView")) return {};
  const std::string_view text = bytes.substr(20, json_chunk);
  for (const char* compressed : {"meshopt_compression", "draco_mesh_compression"})
    if (text.find(compressed) != std::string_view::npos) return {};
  const std::uint64_t length = le32(bytes.data() + 8), bin_header = 20 + std::uint64_t(json_chunk);
  if (bin_header + 8 > length) return {};
  const std::uint64_t chunk = le32(bytes.data() + bin_header);
  if (chunk < 4 || chunk % 4 != 0 || bin_header + 8 + chunk > length || le32(bytes.data() + bin_header + 4) != 0x004E4942u)
    return {};
  const std::uint64_t byte_length = buffers[0]["byteLength"].get<std::uint64_t>();
  if (byte_length > chunk) return {};
  return bytes.substr(std::size_t(bin_header + 8), std::size_t(byte_length));
}

// `file`: the bytes' owner when the reader may keep them (the BIN chunk is then read in place), or null.
GltfDocument read_document(std::string_view bytes, const std::string& name, io::FileBytes* file) {
  const bool binary = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
  const std::string_view json_text = binary ? glb_json(bytes, name) : bytes;
  auto source = std::make_shared<GltfSource>();
  source->name = name;
  try {
    source->json = json::parse(json_text.begin(), json_text.end());
  } catch (const json::exception& e) {
    std::string what = e.what();
    fail(name, 0, "not valid glTF JSON: " + what.substr(what.find(']') == std::string::npos ? 0 : what.find(']') + 2));
  }
  if (!source->json.is_object()) fail(name, 0, "not valid glTF JSON: the document is not an object");
  io::gltf::require_schema_types(source->json, name);
  io::gltf::CompressedPlan compressed;  // what the loader must not see (engine/gltf_decompress.h)
  std::string edited_json = io::gltf::prepare_compressed(*source, compressed);
  const LongerFiles longer = require_buffer_files(source->json, name);
  require_byte_strides(source->json, name);
  require_bin_chunk_and_images(bytes, binary, json_text.size(), source->json, name);
  require_node_forest(source->json, name);
  const std::vector<std::array<std::size_t, 3>> viewless = viewless_indices(source->json);
  if (!viewless.empty()) {  // the loader's JSON without them (viewless_indices)
    json for_loader = edited_json.empty() ? source->json : json::parse(edited_json);
    for (const auto& [m, p, a] : viewless) for_loader["meshes"][m]["primitives"][p].erase("indices");
    edited_json = for_loader.dump();
  }

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  loader.SetStoreOriginalJSONForExtrasAndExtensions(false);
  if (!longer.empty())
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &read_buffer_file, &tinygltf::WriteWholeFile,
                           const_cast<LongerFiles*>(&longer)});
  std::string err, warn;
  std::string base = fs::path(name).parent_path().string();
  if (base.empty()) base = ".";
  std::string glb;  // a GLB whose JSON chunk was edited: header, the edited chunk, the rest as read
  // The BIN chunk in place: tinygltf is given the JSON with buffer 0 as 4 bytes in a data URI (it
  // refuses a buffer without bytes), and no BIN chunk; the model's buffer 0 is emptied after.
  const std::string_view bin = binary && file && edited_json.empty() ? bin_in_place(bytes, json_text.size(), source->json)
                                                                   : std::string_view();
  if (!bin.empty()) {
    json for_loader = source->json;
    for_loader["buffers"][0]["uri"] = "data:application/octet-stream;base64,AAAAAA==";
    for_loader["buffers"][0]["byteLength"] = 4;
    edited_json = for_loader.dump();
    while (edited_json.size() % 4) edited_json += ' ';
    const std::uint32_t header[5] = {0x46546C67u, 2, std::uint32_t(20 + edited_json.size()), std::uint32_t(edited_json.size()),
                                     0x4E4F534Au};
    glb.append(reinterpret_cast<const char*>(header), sizeof header);
    glb += edited_json;
  } else if (binary && !edited_json.empty()) {
    while (edited_json.size() % 4) edited_json += ' ';
    const std::string_view rest = bytes.substr(20 + json_text.size());
    const std::uint32_t header[5] = {0x46546C67u, 2, std::uint32_t(20 + edited_json.size() + rest.size()),
                                     std::uint32_t(edited_json.size()), 0x4E4F534Au};
    glb.append(reinterpret_cast<const char*>(header), sizeof header);
    glb += edited_json;
    glb += rest;
  }
  const std::string_view glb_bytes = glb.empty() ? bytes : std::string_view(glb);
  const std::string_view text = edited_json.empty() ? json_text : std::string_view(edited_json);
  const bool ok = binary ? loader.LoadBinaryFromMemory(&source->model, &err, &warn,
                                                       reinterpret_cast<const unsigned char*>(glb_bytes.data()),
                                                       unsigned(glb_bytes.size()), base)
                         : loader.LoadASCIIFromString(&source->model, &err, &warn, text.data(), unsigned(text.size()), base);
  if (!ok) {
    std::string line = err.empty() ? std::string("tinygltf could not read the file") : err;
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fail(name, 0, line);
  }

  for (const auto& [m, p, a] : viewless) source->model.meshes[m].primitives[p].indices = int(a);
  if (!bin.empty()) {
    source->model.buffers[0].data = std::vector<unsigned char>();
    source->model.buffers[0].uri.clear();
    source->file = std::move(*file);  // the view `bin` stays valid: the bytes do not move
    source->bin_buffer = 0;
    source->bin = bin;
  }

  GltfDocument doc;
  doc.was_binary = binary;
  io::gltf::decode_compressed(*source, compressed, doc.notes);
  const bool quantized = has_extension(source->json, "KHR_mesh_quantization");
  const tinygltf::Model& model = source->model;
  std::vector<std::string> positionless;  // JSON paths of triangle primitives without POSITION
  for (std::size_t m = 0; m < model.meshes.size(); ++m)
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      const int mode = model.meshes[m].primitives[p].mode;
      if (!(mode < 0 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
            mode == TINYGLTF_MODE_TRIANGLE_FAN)) {
        ++doc.passed_through_primitives;
        const auto& attrs = model.meshes[m].primitives[p].attributes;
        const auto pos = attrs.find("POSITION");
        if (pos != attrs.end() && pos->second >= 0 && static_cast<std::size_t>(pos->second) < model.accessors.size())
          doc.passed_through_vertices += model.accessors[static_cast<std::size_t>(pos->second)].count;
        continue;
      }
      GltfPrimitive gp;
      gp.mesh_index = m;
      gp.primitive_index = p;
      gp.json_path = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
      // No POSITION: nothing to draw. glTF 2.0 (3.7.2.1) lets a primitive omit it ("client
      // implementations SHOULD skip primitive's rendering"; the validator's warning
      // MESH_PRIMITIVE_NO_POSITION): left as it is, named in a note, not refused.
      if (!model.meshes[m].primitives[p].attributes.count("POSITION")) {
        positionless.push_back(gp.json_path);
        continue;
      }
      decode_primitive(*source, quantized, gp, name);
      doc.primitives.push_back(std::move(gp));
    }
  if (!positionless.empty())
    doc.notes.push_back(positionless[0] + (positionless.size() > 1 ? " and " + std::to_string(positionless.size() - 1) + " more primitives" : "") +
                        ": no POSITION (nothing to draw, glTF 2.0 3.7.2.1): left as it is, not in the mesh");
  doc.source = std::move(source);
  return doc;
}

}  // namespace

GltfDocument read_gltf(std::string_view bytes, const std::string& name) { return read_document(bytes, name, nullptr); }

GltfDocument read_gltf(io::FileBytes&& file, const std::string& name) {
  io::FileBytes owned = std::move(file);
  return read_document(owned.view(), name, &owned);
}

std::string gltf_source_name(const GltfDocument& document) {
  return document.source ? document.source->name : std::string("<glTF>");
}

std::vector<std::string> gltf_external_files(const GltfDocument& document) {
  std::vector<std::string> out;
  if (!document.source) return out;
  const json& j = document.source->json;
  const fs::path base = fs::path(document.source->name).parent_path();
  for (const char* key : {"buffers", "images"}) {
    if (!j.contains(key) || !j[key].is_array()) continue;
    for (const json& item : j[key]) {
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      std::string decoded;  // %XX (RFC 3986) decoded, as readers resolve it
      for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
          decoded += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
          i += 2;
        } else {
          decoded += uri[i];
        }
      }
      out.push_back((base / uri).string());
      if (decoded != uri) out.push_back((base / decoded).string());
    }
  }
  return out;
}

bool gltf_name_is_text(const std::string& name) {
  if (name.size() < 5) return false;
  std::string ext = name.substr(name.size() - 5);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".gltf";
}

}  // namespace shadetool
