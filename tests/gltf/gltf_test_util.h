// gltf_test_util.h: a small GLB writer for the glTF tests, independent of write_gltf: files are
// built byte by byte, so what is checked is the spec's layout (glTF 2.0, 5), not our writer's.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadetool::gltftest {

using nlohmann::json;

// A GLB assembled by hand: JSON chunk (space-padded) and BIN chunk (zero-padded), glTF 2.0 5.
inline std::string make_glb(const json& doc, const std::string& bin) {
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  std::string data = bin;
  while (data.size() % 4) data += '\0';
  auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string out = "glTF" + u32(2) + u32(std::uint32_t(12 + 8 + text.size() + 8 + data.size()));
  out += u32(std::uint32_t(text.size())) + u32(0x4E4F534Au) + text;
  out += u32(std::uint32_t(data.size())) + u32(0x004E4942u) + data;
  return out;
}

template <class T>
inline std::string bytes_of(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// A document with one primitive: `positions` (float VEC3) and indices of component type `ct`.
struct Built {
  json doc;
  std::string bin;
  int view(const std::string& bytes, int stride = 0) {
    while (bin.size() % 4) bin += '\0';
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
    if (stride) v["byteStride"] = stride;
    bin += bytes;
    doc["bufferViews"].push_back(v);
    return int(doc["bufferViews"].size() - 1);
  }
  int accessor(json a) {
    doc["accessors"].push_back(a);
    return int(doc["accessors"].size() - 1);
  }
  std::string glb() {
    json d = doc;
    d["buffers"] = json::array({{{"byteLength", (bin.size() + 3) / 4 * 4}}});
    return make_glb(d, bin);
  }
};

inline Built base_doc() {
  Built b;
  b.doc = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", json::array({{{"nodes", {0}}}})},
           {"nodes", json::array({{{"mesh", 0}}})}, {"bufferViews", json::array()}, {"accessors", json::array()}};
  return b;
}

inline int float_accessor(Built& b, const std::vector<float>& v, const char* type, int comps, bool minmax = false) {
  json a = {{"bufferView", b.view(bytes_of(v))}, {"componentType", 5126}, {"count", v.size() / std::size_t(comps)}, {"type", type}};
  if (minmax) {
    std::vector<float> lo(std::size_t(comps), 1e30f), hi(std::size_t(comps), -1e30f);
    for (std::size_t i = 0; i < v.size(); ++i) lo[i % std::size_t(comps)] = std::min(lo[i % std::size_t(comps)], v[i]), hi[i % std::size_t(comps)] = std::max(hi[i % std::size_t(comps)], v[i]);
    a["min"] = lo;
    a["max"] = hi;
  }
  return b.accessor(a);
}

}  // namespace shadetool::gltftest
