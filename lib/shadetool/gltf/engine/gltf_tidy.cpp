// gltf_tidy.cpp: pruning unreferenced accessors and bufferViews, exact accessor bounds (see
// gltf_tidy.h).
#include "gltf_tidy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>

namespace shadetool::io::gltf {

namespace {

using nlohmann::json;

// Extensions that hold no accessor or bufferView index (their indices name materials, images,
// textures, lights or nothing; CESIUM_RTC holds a centre; EXT_mesh_features' numbers are feature
// counts, _FEATURE_ID_n suffixes, textures and property tables), and the three whose indices are
// remapped here (EXT_mesh_gpu_instancing's accessors, KHR_draco_mesh_compression's and
// EXT_structural_metadata's bufferViews).
const std::set<std::string> kNoAccessorReferences = {
    "KHR_lights_punctual", "KHR_materials_anisotropy", "KHR_materials_clearcoat", "KHR_materials_dispersion",
    "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_iridescence",
    "KHR_materials_pbrSpecularGlossiness", "KHR_materials_sheen", "KHR_materials_specular",
    "KHR_materials_transmission", "KHR_materials_unlit", "KHR_materials_variants", "KHR_materials_volume",
    "KHR_mesh_quantization", "KHR_texture_basisu", "KHR_texture_transform", "KHR_xmp_json_ld", "EXT_texture_webp",
    "EXT_texture_avif", "EXT_lights_image_based", "MSFT_lod", "MSFT_texture_dds",
    "EXT_mesh_gpu_instancing", "KHR_draco_mesh_compression", "KHR_materials_common", "CESIUM_RTC", "EXT_mesh_features",
    "EXT_structural_metadata"};

bool is_index(const json& v) { return v.is_number_integer() && v.get<long long>() >= 0; }

// Applies `f` to every accessor index in the document (a reference to the JSON value).
template <class F>
void for_each_accessor_ref(json& j, F f) {
  if (j.contains("meshes") && j["meshes"].is_array())
    for (json& mesh : j["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (json& prim : mesh["primitives"]) {
        if (!prim.is_object()) continue;
        if (prim.contains("attributes") && prim["attributes"].is_object())
          for (auto& [k, v] : prim["attributes"].items()) f(v);
        if (prim.contains("indices")) f(prim["indices"]);
        if (prim.contains("targets") && prim["targets"].is_array())
          for (json& t : prim["targets"])
            if (t.is_object())
              for (auto& [k, v] : t.items()) f(v);
      }
    }
  if (j.contains("skins") && j["skins"].is_array())
    for (json& s : j["skins"])
      if (s.is_object() && s.contains("inverseBindMatrices")) f(s["inverseBindMatrices"]);
  if (j.contains("animations") && j["animations"].is_array())
    for (json& a : j["animations"]) {
      if (!a.is_object() || !a.contains("samplers") || !a["samplers"].is_array()) continue;
      for (json& s : a["samplers"]) {
        if (!s.is_object()) continue;
        if (s.contains("input")) f(s["input"]);
        if (s.contains("output")) f(s["output"]);
      }
    }
  if (j.contains("nodes") && j["nodes"].is_array())
    for (json& n : j["nodes"]) {
      if (!n.is_object() || !n.contains("extensions") || !n["extensions"].is_object()) continue;
      json& ext = n["extensions"];
      if (ext.contains("EXT_mesh_gpu_instancing") && ext["EXT_mesh_gpu_instancing"].is_object() &&
          ext["EXT_mesh_gpu_instancing"].contains("attributes") && ext["EXT_mesh_gpu_instancing"]["attributes"].is_object())
        for (auto& [k, v] : ext["EXT_mesh_gpu_instancing"]["attributes"].items()) f(v);
    }
}

// Applies `f` to every bufferView of EXT_structural_metadata's property tables (the binary table
// format: propertyTables[].properties.*.values, arrayOffsets and stringOffsets; its property
// textures name textures, its property attributes name attributes, its schema holds no index).
template <class F>
void for_each_metadata_view_ref(json& j, F f) {
  if (!j.contains("extensions") || !j["extensions"].is_object() || !j["extensions"].contains("EXT_structural_metadata"))
    return;
  json& meta = j["extensions"]["EXT_structural_metadata"];
  if (!meta.is_object() || !meta.contains("propertyTables") || !meta["propertyTables"].is_array()) return;
  for (json& table : meta["propertyTables"]) {
    if (!table.is_object() || !table.contains("properties") || !table["properties"].is_object()) continue;
    for (auto& [name, property] : table["properties"].items()) {
      if (!property.is_object()) continue;
      for (const char* key : {"values", "arrayOffsets", "stringOffsets"})
        if (property.contains(key)) f(property[key]);
    }
  }
}

// Applies `f` to every bufferView index held outside the accessors (images, Draco's data,
// EXT_structural_metadata's property tables).
template <class F>
void for_each_other_view_ref(json& j, F f) {
  for_each_metadata_view_ref(j, f);
  if (j.contains("images") && j["images"].is_array())
    for (json& im : j["images"])
      if (im.is_object() && im.contains("bufferView")) f(im["bufferView"]);
  if (j.contains("meshes") && j["meshes"].is_array())
    for (json& mesh : j["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (json& prim : mesh["primitives"])
        if (prim.is_object() && prim.contains("extensions") && prim["extensions"].is_object() &&
            prim["extensions"].contains("KHR_draco_mesh_compression") &&
            prim["extensions"]["KHR_draco_mesh_compression"].is_object() &&
            prim["extensions"]["KHR_draco_mesh_compression"].contains("bufferView"))
          f(prim["extensions"]["KHR_draco_mesh_compression"]["bufferView"]);
    }
}

template <class F>
void for_each_accessor_view_ref(json& accessor, F f) {
  if (!accessor.is_object()) return;
  if (accessor.contains("bufferView")) f(accessor["bufferView"]);
  if (accessor.contains("sparse") && accessor["sparse"].is_object())
    for (const char* part : {"indices", "values"})
      if (accessor["sparse"].contains(part) && accessor["sparse"][part].is_object() &&
          accessor["sparse"][part].contains("bufferView"))
        f(accessor["sparse"][part]["bufferView"]);
}

// Whether extension `name` holds a number anywhere in the document: an extension's data is the
// value of its name in an `extensions` object (glTF 2.0 3.12), and an index is a number there. One
// that is listed in extensionsUsed but holds none (FB_ngon_encoding's empty objects; an extension
// named without any object, as assimp's KHR_technique_webgl files have) cannot name an accessor
// or a bufferView.
bool holds_number(const json& v) {
  if (v.is_number()) return true;
  if (v.is_object() || v.is_array())
    for (const json& x : v)
      if (holds_number(x)) return true;
  return false;
}

bool extension_holds_number(const json& v, const std::string& name) {
  if (v.is_object()) {
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (it.key() == "extensions" && it->is_object() && it->contains(name) && holds_number((*it)[name])) return true;
      if (extension_holds_number(*it, name)) return true;
    }
  } else if (v.is_array()) {
    for (const json& x : v)
      if (extension_holds_number(x, name)) return true;
  }
  return false;
}

std::vector<long> remap_of(const std::vector<bool>& used) {
  std::vector<long> to(used.size(), -1);
  long next = 0;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) to[i] = next++;
  return to;
}

}  // namespace

std::size_t prune_unreferenced(json& j, std::string& bytes, std::vector<std::string>& notes, bool compact) {
  if (!j.contains("accessors") || !j["accessors"].is_array() || !j.contains("bufferViews") || !j["bufferViews"].is_array())
    return 0;
  json& accessors = j["accessors"];
  json& views = j["bufferViews"];
  std::vector<bool> accessor_used(accessors.size(), false), view_used(views.size(), false);
  auto mark = [](std::vector<bool>& used) {
    return [&used](json& v) {
      if (is_index(v) && v.get<std::size_t>() < used.size()) used[v.get<std::size_t>()] = true;
    };
  };
  for_each_accessor_ref(j, mark(accessor_used));
  for (std::size_t a = 0; a < accessors.size(); ++a)
    if (accessor_used[a]) for_each_accessor_view_ref(accessors[a], mark(view_used));
  for_each_other_view_ref(j, mark(view_used));
  const std::size_t dead_accessors = std::size_t(std::count(accessor_used.begin(), accessor_used.end(), false));
  const std::size_t dead_views = std::size_t(std::count(view_used.begin(), view_used.end(), false));
  if (dead_accessors == 0 && dead_views == 0 && !compact) return 0;

  // An extension this pass does not know may refer to what looks unreferenced: keep everything,
  // unless it holds no number anywhere (then it names no index).
  if (j.contains("extensionsUsed") && j["extensionsUsed"].is_array())
    for (const json& e : j["extensionsUsed"])
      if (e.is_string() && !kNoAccessorReferences.count(e.get<std::string>()) && extension_holds_number(j, e.get<std::string>())) {
        notes.push_back(std::to_string(dead_accessors) + " accessors and " + std::to_string(dead_views) +
                        " bufferViews no property refers to are kept: extension " + e.get<std::string>() +
                        " may refer to them");
        return 0;
      }

  // A view outside buffer 0 (not merged by the writer) is kept where it is, unmoved.
  for (std::size_t v = 0; v < views.size(); ++v)
    if (!views[v].is_object() || views[v].value("buffer", 0) != 0) view_used[v] = true;
  // A property table's view keeps its offset mod 8 (its components may be 8 bytes: FLOAT64, INT64,
  // UINT64 offsets; EXT_structural_metadata aligns each to its component size), every other view its
  // offset mod 4 (no glTF component is longer).
  std::vector<std::size_t> view_alignment(views.size(), 4);
  for_each_metadata_view_ref(j, [&view_alignment](json& v) {
    if (is_index(v) && v.get<std::size_t>() < view_alignment.size()) view_alignment[v.get<std::size_t>()] = 8;
  });
  const std::vector<long> accessor_to = remap_of(accessor_used), view_to = remap_of(view_used);
  auto remap = [](const std::vector<long>& to) {
    return [&to](json& v) {
      if (is_index(v) && v.get<std::size_t>() < to.size()) v = to[v.get<std::size_t>()];
    };
  };
  for_each_accessor_ref(j, remap(accessor_to));
  for_each_other_view_ref(j, remap(view_to));

  // The buffer from the views kept, each at a 4-byte (8-byte) boundary plus its old offset mod 4 (8).
  std::string packed;
  packed.reserve(bytes.size() + (std::size_t(1) << 20));  // room for the GLB headers and JSON in front
  json kept_views = json::array();
  for (std::size_t v = 0; v < views.size(); ++v) {
    if (!view_used[v]) continue;
    json view = views[v];
    if (view.value("buffer", 0) == 0) {
      const std::size_t offset = view.value("byteOffset", std::size_t(0)), length = view.value("byteLength", std::size_t(0));
      const std::size_t alignment = view_alignment[v];
      while (packed.size() % alignment != offset % alignment) packed.push_back('\0');
      const std::size_t now = packed.size();
      if (offset <= bytes.size()) packed.append(bytes, offset, std::min(length, bytes.size() - offset));
      packed.resize(now + length, '\0');
      view["byteOffset"] = now;
      if (now == 0) view.erase("byteOffset");
    }
    kept_views.push_back(std::move(view));
  }
  while (packed.size() % 4) packed.push_back('\0');
  json kept_accessors = json::array();
  for (std::size_t a = 0; a < accessors.size(); ++a) {
    if (!accessor_used[a]) continue;
    json acc = accessors[a];
    for_each_accessor_view_ref(acc, remap(view_to));
    kept_accessors.push_back(std::move(acc));
  }
  accessors = std::move(kept_accessors);
  views = std::move(kept_views);
  const std::size_t saved = bytes.size() - std::min(bytes.size(), packed.size());
  bytes = std::move(packed);
  if (dead_accessors > 0 || dead_views > 0)
    notes.push_back(std::to_string(dead_accessors) + " accessors and " + std::to_string(dead_views) +
                    " bufferViews that nothing refers to any more removed (" + std::to_string(saved) + " bytes)");
  return dead_accessors;
}

namespace {

int components_of(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  if (type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

int bytes_of(int component_type) {
  switch (component_type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
  }
}

// One raw component at `p` as a double (integers exactly, floats as float32).
double raw_component(const unsigned char* p, int component_type) {
  switch (component_type) {
    case 5120: return double(std::int8_t(p[0]));
    case 5121: return double(p[0]);
    case 5122: { std::int16_t v; std::memcpy(&v, p, 2); return double(v); }
    case 5123: { std::uint16_t v; std::memcpy(&v, p, 2); return double(v); }
    case 5125: { std::uint32_t v; std::memcpy(&v, p, 4); return double(v); }
    case 5126: { float v; std::memcpy(&v, p, 4); return double(v); }
    default: return 0;
  }
}

// Where the dense elements of accessor `a` are in `bytes` (its bufferView's; `first` null when it
// has no bufferView: zeros); false when they are not all in buffer 0 within bounds, or it is a
// matrix whose columns are padded (glTF 2.0 3.6.2.4: MAT2 of bytes, MAT3 of bytes or shorts; left
// alone).
struct DenseLayout {
  const unsigned char* first = nullptr;
  std::size_t count = 0, stride = 0, elem = 0;
  int comps = 0, component_type = 0, component_bytes = 0;
};

// The bytes [offset, offset + length) and byteStride of bufferView `ref` when it is in buffer 0
// within `bytes`.
bool view_span(const json& j, const json& ref, const std::string& bytes, std::size_t& offset, std::size_t& length,
               std::size_t& stride) {
  const json& views = j["bufferViews"];
  if (!is_index(ref) || ref.get<std::size_t>() >= views.size()) return false;
  const json& v = views[ref.get<std::size_t>()];
  if (!v.is_object() || v.value("buffer", 0) != 0) return false;
  offset = v.value("byteOffset", std::size_t(0));
  length = v.value("byteLength", std::size_t(0));
  stride = v.value("byteStride", std::size_t(0));
  return offset + length <= bytes.size();
}

bool dense_layout(const json& j, const json& a, const std::string& bytes, DenseLayout& d) {
  d = DenseLayout();
  d.comps = components_of(a.value("type", std::string()));
  d.component_type = a.value("componentType", 0);
  d.component_bytes = bytes_of(d.component_type);
  d.count = a.value("count", std::size_t(0));
  if (d.comps == 0 || d.component_bytes == 0) return false;
  const std::string type = a.value("type", std::string());
  if ((type == "MAT2" && d.component_bytes == 1) || (type == "MAT3" && d.component_bytes <= 2)) return false;  // padded columns
  d.elem = std::size_t(d.comps) * std::size_t(d.component_bytes);
  if (!a.contains("bufferView")) return true;
  std::size_t offset, length, stride;
  if (!view_span(j, a["bufferView"], bytes, offset, length, stride)) return false;
  d.stride = stride == 0 ? d.elem : stride;
  const std::size_t start = a.value("byteOffset", std::size_t(0));
  if (d.count > 0 && start + (d.count - 1) * d.stride + d.elem > length) return false;
  d.first = reinterpret_cast<const unsigned char*>(bytes.data()) + offset + start;
  return true;
}

bool has_sparse(const json& a) { return a.contains("sparse") && a["sparse"].is_object(); }

// Reads the `count` elements of accessor `a` (values, count * comps); false as dense_layout, or
// when its sparse substitutions are out of bounds.
bool accessor_values(const json& j, const json& a, const std::string& bytes, std::vector<double>& out) {
  DenseLayout d;
  if (!dense_layout(j, a, bytes, d)) return false;
  const int comps = d.comps, ct = d.component_type, cb = d.component_bytes;
  const std::size_t count = d.count, elem = d.elem;
  out.assign(count * std::size_t(comps), 0.0);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (d.first)
    for (std::size_t i = 0; i < count; ++i)
      for (int k = 0; k < comps; ++k)
        out[i * std::size_t(comps) + std::size_t(k)] = raw_component(d.first + i * d.stride + std::size_t(k * cb), ct);
  if (has_sparse(a)) {
    const json& s = a["sparse"];
    const std::size_t n = s.value("count", std::size_t(0));
    if (!s.contains("indices") || !s.contains("values") || !s["indices"].is_object() || !s["values"].is_object()) return false;
    std::size_t io, il, is, vo, vl, vs;
    if (!view_span(j, s["indices"].value("bufferView", json()), bytes, io, il, is) ||
        !view_span(j, s["values"].value("bufferView", json()), bytes, vo, vl, vs))
      return false;
    const int ict = s["indices"].value("componentType", 0), icb = bytes_of(ict);
    const std::size_t ioff = io + s["indices"].value("byteOffset", std::size_t(0));
    const std::size_t voff = vo + s["values"].value("byteOffset", std::size_t(0));
    if (icb == 0 || ioff + n * std::size_t(icb) > io + il || voff + n * elem > vo + vl) return false;
    for (std::size_t i = 0; i < n; ++i) {
      const double index = raw_component(data + ioff + i * std::size_t(icb), ict);
      if (!(index >= 0) || std::size_t(index) >= count) return false;
      for (int k = 0; k < comps; ++k)
        out[std::size_t(index) * std::size_t(comps) + std::size_t(k)] = raw_component(data + voff + i * elem + std::size_t(k * cb), ct);
    }
  }
  return true;
}

// The same value at the component's precision: floats compared as float32, integers exactly.
bool same_bound(const json& written, double exact, int component_type) {
  if (!written.is_number()) return false;
  const double w = written.get<double>();
  if (component_type == 5126) return float(w) == float(exact);
  return w == exact;
}

}  // namespace

std::size_t align_accessors(json& j, std::string& bytes, std::vector<std::string>& notes) {
  if (!j.contains("accessors") || !j["accessors"].is_array() || !j.contains("bufferViews") || !j["bufferViews"].is_array())
    return 0;
  json& views = j["bufferViews"];
  // Accessors read as vertex attributes (a primitive's attributes, its morph targets'): each element
  // at a multiple of 4 bytes (glTF 2.0 3.6.2.4), not only each component at a multiple of its size.
  std::vector<bool> vertex_attribute(j["accessors"].size(), false);
  if (j.contains("meshes") && j["meshes"].is_array())
    for (const json& mesh : j["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (const json& prim : mesh["primitives"]) {
        if (!prim.is_object()) continue;
        auto mark = [&vertex_attribute](const json& attributes) {
          if (!attributes.is_object()) return;
          for (const json& v : attributes)
            if (is_index(v) && v.get<std::size_t>() < vertex_attribute.size()) vertex_attribute[v.get<std::size_t>()] = true;
        };
        if (prim.contains("attributes")) mark(prim["attributes"]);
        if (prim.contains("targets") && prim["targets"].is_array())
          for (const json& t : prim["targets"]) mark(t);
      }
    }
  std::size_t moved = 0, moved_attributes = 0;
  std::string first, first_attribute;
  for (std::size_t i = 0; i < j["accessors"].size(); ++i) {
    json& a = j["accessors"][i];
    if (!a.is_object() || a.contains("sparse") || !a.contains("bufferView") || !is_index(a["bufferView"]) ||
        a["bufferView"].get<std::size_t>() >= views.size())
      continue;
    const json& v = views[a["bufferView"].get<std::size_t>()];
    const int comps = components_of(a.value("type", std::string()));
    const int cb = bytes_of(a.value("componentType", 0));
    if (!v.is_object() || v.value("buffer", 0) != 0 || comps == 0 || cb == 0) continue;
    const std::size_t view_offset = v.value("byteOffset", std::size_t(0)), view_length = v.value("byteLength", std::size_t(0));
    const std::size_t start = view_offset + a.value("byteOffset", std::size_t(0));
    const std::size_t stride = v.value("byteStride", std::size_t(0));
    const std::size_t elem = std::size_t(comps) * std::size_t(cb), count = a.value("count", std::size_t(0));
    const std::size_t step = stride ? stride : elem;
    const bool components_aligned = start % std::size_t(cb) == 0 && stride % std::size_t(cb) == 0;
    const bool elements_aligned = !vertex_attribute[i] || (start % 4 == 0 && step % 4 == 0);
    if (components_aligned && elements_aligned) continue;
    if (view_offset + view_length > bytes.size() || (count > 0 && start + (count - 1) * step + elem > view_offset + view_length))
      continue;  // out of bounds: the reader refused such files already; nothing to copy
    // A vertex attribute's elements padded to 4 bytes (a byteStride then names the padding); any
    // other accessor packed, or strided as it was.
    const std::size_t out_stride = stride || vertex_attribute[i] ? (elem + 3) / 4 * 4 : elem;
    while (bytes.size() % 4) bytes.push_back('\0');
    const std::size_t at = bytes.size();
    bytes.resize(at + count * out_stride, '\0');
    for (std::size_t e = 0; e < count; ++e) std::memcpy(&bytes[at + e * out_stride], &bytes[start + e * step], elem);
    json nv = {{"buffer", 0}, {"byteOffset", at}, {"byteLength", count * out_stride}};
    if (stride || out_stride != elem) nv["byteStride"] = out_stride;
    if (v.contains("target")) nv["target"] = v["target"];
    views.push_back(std::move(nv));
    a["bufferView"] = views.size() - 1;
    a.erase("byteOffset");
    if (components_aligned) {
      if (moved_attributes++ == 0) first_attribute = "accessors[" + std::to_string(i) + "]";
    } else if (moved++ == 0) {
      first = "accessors[" + std::to_string(i) + "]";
    }
  }
  if (moved_attributes > 0)
    notes.push_back(std::to_string(moved_attributes) + " vertex attribute accessors whose elements did not start on " +
                    "multiples of 4 bytes (first " + first_attribute + ") copied to bufferViews with a byteStride " +
                    "of a multiple of 4 (glTF 2.0 3.6.2.4)");
  if (moved > 0)
    notes.push_back(std::to_string(moved) + " accessors whose data did not start on a multiple of its component size " +
                    "(first " + first + ") copied to aligned bufferViews (glTF 2.0 3.6.2.4)");
  return moved + moved_attributes;
}

std::size_t exact_bounds(json& j, const std::string& bytes, std::vector<std::string>& notes) {
  if (!j.contains("accessors") || !j["accessors"].is_array()) return 0;
  std::size_t corrected = 0;
  std::string first;
  std::vector<double> values;
  for (std::size_t i = 0; i < j["accessors"].size(); ++i) {
    json& a = j["accessors"][i];
    if (!a.is_object() || (!a.contains("min") && !a.contains("max"))) continue;
    DenseLayout d;
    if (!dense_layout(j, a, bytes, d)) continue;
    const int comps = d.comps, ct = d.component_type;
    const std::size_t count = d.count;
    if (count == 0) continue;
    std::vector<double> lo(std::size_t(comps), std::numeric_limits<double>::infinity()), hi(std::size_t(comps), -lo[0]);
    auto bound = [&](std::size_t k, double v) {
      if (std::isnan(v)) return;  // NaN takes no part in a bound
      lo[k] = std::min(lo[k], v);
      hi[k] = std::max(hi[k], v);
    };
    if (d.first && !has_sparse(a)) {  // read in place (no copy of the values)
      for (std::size_t e = 0; e < count; ++e)
        for (std::size_t k = 0; k < std::size_t(comps); ++k)
          bound(k, raw_component(d.first + e * d.stride + k * std::size_t(d.component_bytes), ct));
    } else {
      if (!accessor_values(j, a, bytes, values)) continue;
      for (std::size_t e = 0; e < count; ++e)
        for (std::size_t k = 0; k < std::size_t(comps); ++k) bound(k, values[e * std::size_t(comps) + k]);
    }
    bool same = a.contains("min") && a.contains("max") && a["min"].is_array() && a["max"].is_array() &&
                a["min"].size() == std::size_t(comps) && a["max"].size() == std::size_t(comps);
    for (std::size_t k = 0; same && k < std::size_t(comps); ++k)
      same = same_bound(a["min"][k], lo[k], ct) && same_bound(a["max"][k], hi[k], ct);
    if (same) continue;
    bool finite = true;
    for (std::size_t k = 0; k < std::size_t(comps); ++k) finite = finite && std::isfinite(lo[k]) && std::isfinite(hi[k]);
    if (!finite) continue;  // an all-NaN component has no bound to write
    a["min"] = lo;
    a["max"] = hi;
    if (corrected++ == 0) first = "accessors[" + std::to_string(i) + "]";
  }
  if (corrected > 0)
    notes.push_back(std::to_string(corrected) + " accessors' min/max did not match their values (first " + first +
                    "): written exact (glTF 2.0 3.6.2.5)");
  return corrected;
}

}  // namespace shadetool::io::gltf
