// gltf_schema.cpp: glTF 2.0 core schema types (see gltf_schema.h). The tables follow the
// specification's schema files (glTF 2.0, section 5: "Properties Reference").
#include "gltf_schema.h"

#include <vector>

#include <shadetool/core/error.h>

namespace shadetool::io::gltf {

namespace {

using nlohmann::json;

enum class Kind {
  String,
  Number,
  Integer,      // any integer (enums: mode, componentType, target, filters)
  Count,        // integer >= 0 (byteOffset, count, byteLength, texCoord)
  Bool,
  Object,       // any object (extras are not checked at all)
  Index,        // integer >= 0, below the size of `target`
  Strings,      // array of strings
  Numbers,      // array of numbers
  Indices,      // array of indices into `target`
  IndexMap,     // object whose values are indices into `target` (attributes)
  IndexMaps,    // array of such objects (morph targets)
  Child,        // one object of schema `child`
  Children,     // array of objects of schema `child`
};

struct Schema;
struct Property {
  const char* name;
  Kind kind;
  const char* target = nullptr;   // Index, Indices, IndexMap(s): the top-level array indexed
  const Schema* child = nullptr;  // Child, Children
};
struct Schema {
  std::vector<Property> properties;
};

// Every object also has name (string), extensions (object) and extras (anything).
const Schema kTextureInfo{{{"index", Kind::Index, "textures"}, {"texCoord", Kind::Count}, {"scale", Kind::Number},
                           {"strength", Kind::Number}}};
const Schema kPbr{{{"baseColorFactor", Kind::Numbers}, {"baseColorTexture", Kind::Child, nullptr, &kTextureInfo},
                   {"metallicFactor", Kind::Number}, {"roughnessFactor", Kind::Number},
                   {"metallicRoughnessTexture", Kind::Child, nullptr, &kTextureInfo}}};
const Schema kMaterial{{{"pbrMetallicRoughness", Kind::Child, nullptr, &kPbr},
                        {"normalTexture", Kind::Child, nullptr, &kTextureInfo},
                        {"occlusionTexture", Kind::Child, nullptr, &kTextureInfo},
                        {"emissiveTexture", Kind::Child, nullptr, &kTextureInfo},
                        {"emissiveFactor", Kind::Numbers}, {"alphaMode", Kind::String}, {"alphaCutoff", Kind::Number},
                        {"doubleSided", Kind::Bool}}};
const Schema kAsset{{{"version", Kind::String}, {"minVersion", Kind::String}, {"generator", Kind::String},
                     {"copyright", Kind::String}}};
const Schema kScene{{{"nodes", Kind::Indices, "nodes"}}};
const Schema kNode{{{"camera", Kind::Index, "cameras"}, {"children", Kind::Indices, "nodes"}, {"skin", Kind::Index, "skins"},
                    {"matrix", Kind::Numbers}, {"mesh", Kind::Index, "meshes"}, {"rotation", Kind::Numbers},
                    {"scale", Kind::Numbers}, {"translation", Kind::Numbers}, {"weights", Kind::Numbers}}};
const Schema kPrimitive{{{"attributes", Kind::IndexMap, "accessors"}, {"indices", Kind::Index, "accessors"},
                         {"material", Kind::Index, "materials"}, {"mode", Kind::Integer},
                         {"targets", Kind::IndexMaps, "accessors"}}};
const Schema kMesh{{{"primitives", Kind::Children, nullptr, &kPrimitive}, {"weights", Kind::Numbers}}};
const Schema kSparseIndices{{{"bufferView", Kind::Index, "bufferViews"}, {"byteOffset", Kind::Count},
                             {"componentType", Kind::Integer}}};
const Schema kSparseValues{{{"bufferView", Kind::Index, "bufferViews"}, {"byteOffset", Kind::Count}}};
const Schema kSparse{{{"count", Kind::Count}, {"indices", Kind::Child, nullptr, &kSparseIndices},
                      {"values", Kind::Child, nullptr, &kSparseValues}}};
const Schema kAccessor{{{"bufferView", Kind::Index, "bufferViews"}, {"byteOffset", Kind::Count},
                        {"componentType", Kind::Integer}, {"normalized", Kind::Bool}, {"count", Kind::Count},
                        {"type", Kind::String}, {"max", Kind::Numbers}, {"min", Kind::Numbers},
                        {"sparse", Kind::Child, nullptr, &kSparse}}};
const Schema kBufferView{{{"buffer", Kind::Index, "buffers"}, {"byteOffset", Kind::Count}, {"byteLength", Kind::Count},
                          {"byteStride", Kind::Count}, {"target", Kind::Integer}}};
const Schema kBuffer{{{"uri", Kind::String}, {"byteLength", Kind::Count}}};
const Schema kTexture{{{"sampler", Kind::Index, "samplers"}, {"source", Kind::Index, "images"}}};
const Schema kImage{{{"uri", Kind::String}, {"mimeType", Kind::String}, {"bufferView", Kind::Index, "bufferViews"}}};
const Schema kSampler{{{"magFilter", Kind::Integer}, {"minFilter", Kind::Integer}, {"wrapS", Kind::Integer},
                       {"wrapT", Kind::Integer}}};
const Schema kOrthographic{{{"xmag", Kind::Number}, {"ymag", Kind::Number}, {"zfar", Kind::Number}, {"znear", Kind::Number}}};
const Schema kPerspective{{{"aspectRatio", Kind::Number}, {"yfov", Kind::Number}, {"zfar", Kind::Number}, {"znear", Kind::Number}}};
const Schema kCamera{{{"type", Kind::String}, {"orthographic", Kind::Child, nullptr, &kOrthographic},
                      {"perspective", Kind::Child, nullptr, &kPerspective}}};
const Schema kSkin{{{"inverseBindMatrices", Kind::Index, "accessors"}, {"skeleton", Kind::Index, "nodes"},
                    {"joints", Kind::Indices, "nodes"}}};
const Schema kChannelTarget{{{"node", Kind::Index, "nodes"}, {"path", Kind::String}}};
const Schema kChannel{{{"sampler", Kind::Count}, {"target", Kind::Child, nullptr, &kChannelTarget}}};
const Schema kAnimationSampler{{{"input", Kind::Index, "accessors"}, {"interpolation", Kind::String},
                                {"output", Kind::Index, "accessors"}}};
const Schema kAnimation{{{"channels", Kind::Children, nullptr, &kChannel},
                         {"samplers", Kind::Children, nullptr, &kAnimationSampler}}};
const Schema kRoot{{{"asset", Kind::Child, nullptr, &kAsset}, {"scene", Kind::Index, "scenes"},
                    {"scenes", Kind::Children, nullptr, &kScene}, {"nodes", Kind::Children, nullptr, &kNode},
                    {"meshes", Kind::Children, nullptr, &kMesh}, {"accessors", Kind::Children, nullptr, &kAccessor},
                    {"bufferViews", Kind::Children, nullptr, &kBufferView}, {"buffers", Kind::Children, nullptr, &kBuffer},
                    {"materials", Kind::Children, nullptr, &kMaterial}, {"textures", Kind::Children, nullptr, &kTexture},
                    {"images", Kind::Children, nullptr, &kImage}, {"samplers", Kind::Children, nullptr, &kSampler},
                    {"cameras", Kind::Children, nullptr, &kCamera}, {"skins", Kind::Children, nullptr, &kSkin},
                    {"animations", Kind::Children, nullptr, &kAnimation}, {"extensionsUsed", Kind::Strings},
                    {"extensionsRequired", Kind::Strings}}};

const char* type_of(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return v.get<long long>() < 0 ? "a negative integer" : "an integer";
    case json::value_t::number_float: return "a number";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
  }
  return "a value";
}

struct Checker {
  const json& root;
  const std::string& name;

  [[noreturn]] void bad(const std::string& path, const json& v, const std::string& wants) const {
    fail(name, 0, path + ": " + type_of(v) + ", the schema wants " + wants);
  }
  void count(const json& v, const std::string& path) const {
    if (!v.is_number_integer() || v.get<long long>() < 0) bad(path, v, "an integer >= 0");
  }
  void index(const json& v, const std::string& path, const char* target) const {
    if (!v.is_number_integer() || v.get<long long>() < 0) bad(path, v, std::string("an index into ") + target + " (an integer >= 0)");
    const std::size_t n = root.contains(target) && root[target].is_array() ? root[target].size() : 0;
    if (v.get<std::size_t>() >= n)
      fail(name, 0, path + ": " + std::to_string(v.get<long long>()) + " is not an index into " + target + " (" +
                        std::to_string(n) + " of them)");
  }
  void object(const json& o, const Schema& schema, const std::string& path) const {
    if (!o.is_object()) bad(path.empty() ? "the document" : path, o, "an object");
    auto at = [&path](const char* key) { return path.empty() ? std::string(key) : path + "." + key; };
    if (o.contains("name") && !o["name"].is_string()) bad(at("name"), o["name"], "a string");
    if (o.contains("extensions")) {
      const json& e = o["extensions"];
      if (!e.is_object()) bad(at("extensions"), e, "an object");
      // extension.schema.json: "additionalProperties": {"type": "object"}: each extension's value
      // is an object (assimp's wrongTypes/badExtension.gltf: a string for KHR_texture_transform).
      for (auto it = e.begin(); it != e.end(); ++it)
        if (!it.value().is_object()) bad(at("extensions") + "." + it.key(), it.value(), "an object");
    }
    for (const Property& p : schema.properties)
      if (o.contains(p.name)) property(o[p.name], p, at(p.name));
  }
  void property(const json& v, const Property& p, const std::string& at) const {
    switch (p.kind) {
      case Kind::String: if (!v.is_string()) bad(at, v, "a string"); break;
      case Kind::Number: if (!v.is_number()) bad(at, v, "a number"); break;
      case Kind::Integer: if (!v.is_number_integer()) bad(at, v, "an integer"); break;
      case Kind::Count: count(v, at); break;
      case Kind::Bool: if (!v.is_boolean()) bad(at, v, "a boolean"); break;
      case Kind::Object: if (!v.is_object()) bad(at, v, "an object"); break;
      case Kind::Index: index(v, at, p.target); break;
      case Kind::Strings:
      case Kind::Numbers:
      case Kind::Indices:
      case Kind::IndexMaps:
      case Kind::Children: {
        if (!v.is_array()) bad(at, v, "an array");
        for (std::size_t i = 0; i < v.size(); ++i) {
          const std::string ai = at + "[" + std::to_string(i) + "]";
          if (p.kind == Kind::Strings && !v[i].is_string()) bad(ai, v[i], "a string");
          if (p.kind == Kind::Numbers && !v[i].is_number()) bad(ai, v[i], "a number");
          if (p.kind == Kind::Indices) index(v[i], ai, p.target);
          if (p.kind == Kind::IndexMaps) index_map(v[i], ai, p.target);
          if (p.kind == Kind::Children) object(v[i], *p.child, ai);
        }
        break;
      }
      case Kind::IndexMap: index_map(v, at, p.target); break;
      case Kind::Child: object(v, *p.child, at); break;
    }
  }
  void index_map(const json& v, const std::string& at, const char* target) const {
    if (!v.is_object()) bad(at, v, "an object");
    for (const auto& [key, value] : v.items()) index(value, at + "." + key, target);
  }
};

}  // namespace

void require_schema_types(const json& document, const std::string& name) {
  const Checker checker{document, name};
  checker.object(document, kRoot, "");
}

}  // namespace shadetool::io::gltf
