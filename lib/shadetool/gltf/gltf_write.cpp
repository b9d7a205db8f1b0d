// gltf_write.cpp: GltfDocument -> .glb / .gltf bytes (see gltf_document.h). The JSON as read is
// passed through; only buffers, bufferViews, accessors, images' sources and the changed
// primitives' attribute/index references are edited.
#include <shadetool/gltf/gltf_document.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cctype>
#include <cstring>
#include <limits>
#include <unordered_map>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/error.h>
#include <shadetool/core/shading_normals.h>
#include <shadetool/core/unit_normals.h>
#include <shadetool/geometry/polygon_triangles.h>

#include "engine/gltf_accessor.h"
#include "engine/gltf_source.h"
#include "engine/gltf_tidy.h"

namespace shadetool {

namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUByte = 5121, kUShort = 5123, kUInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

const char* type_name(int comps) {
  switch (comps) {
    case 1: return "SCALAR";
    case 2: return "VEC2";
    case 3: return "VEC3";
    case 4: return "VEC4";
    case 9: return "MAT3";
    case 16: return "MAT4";
    default: return "VEC4";
  }
}

// The output's single buffer and the JSON arrays that index into it.
struct OutBuffer {
  std::string bytes;
  json* views;
  json* accessors;

  void align(std::size_t a) {
    while (bytes.size() % a) bytes.push_back('\0');
  }
  // A new bufferView of `count` elements of `elem` bytes, `stride` apart (stride >= elem; the
  // padding bytes are zero). Returns its index.
  int add_view(const unsigned char* data, std::size_t count, std::size_t elem, std::size_t stride, int target) {
    align(4);
    const std::size_t offset = bytes.size();
    if (stride == elem) {
      bytes.append(reinterpret_cast<const char*>(data), count * elem);
    } else {
      bytes.resize(offset + count * stride, '\0');
      for (std::size_t i = 0; i < count; ++i) std::memcpy(&bytes[offset + i * stride], data + i * elem, elem);
    }
    json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", count * stride}};
    if (stride != elem) v["byteStride"] = stride;
    if (target) v["target"] = target;
    views->push_back(v);
    return int(views->size() - 1);
  }
  int add_accessor(json a) {
    accessors->push_back(std::move(a));
    return int(accessors->size() - 1);
  }
};

// Vertex attributes: every element must start on a 4-byte boundary (glTF 2.0, 3.6.2.4).
std::size_t vertex_stride(std::size_t elem) { return (elem + 3) / 4 * 4; }

// Float accessor from doubles (count * comps). With min/max (POSITION needs them).
int add_float_accessor(OutBuffer& out, const std::vector<double>& values, int comps, bool minmax, bool vertex_attribute) {
  const std::size_t count = values.size() / std::size_t(comps);
  std::vector<float> f(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) f[i] = float(values[i]);
  const std::size_t elem = 4 * std::size_t(comps);
  const int view = out.add_view(reinterpret_cast<const unsigned char*>(f.data()), count, elem, elem,
                                vertex_attribute ? kArrayBuffer : 0);
  json a = {{"bufferView", view}, {"componentType", kFloat}, {"count", count}, {"type", type_name(comps)}};
  if (minmax && count > 0) {
    std::vector<double> lo(std::size_t(comps), std::numeric_limits<double>::infinity()), hi(std::size_t(comps), -lo[0]);
    for (std::size_t i = 0; i < count; ++i)
      for (int k = 0; k < comps; ++k) {
        lo[std::size_t(k)] = std::min(lo[std::size_t(k)], double(f[i * std::size_t(comps) + std::size_t(k)]));
        hi[std::size_t(k)] = std::max(hi[std::size_t(k)], double(f[i * std::size_t(comps) + std::size_t(k)]));
      }
    a["min"] = lo;
    a["max"] = hi;
  }
  return out.add_accessor(std::move(a));
}

// COLOR_0 in the component type the input had (float, or normalised ubyte / ushort).
int add_color_accessor(OutBuffer& out, const std::vector<float>& colors, int channels, int component_type, std::size_t& clamped) {
  if (component_type != kUByte && component_type != kUShort) {
    // glTF COLOR_0 holds [0, 1] (spec 3.7.2.1; the validator's ACCESSOR_NON_CLAMPED): clamped.
    std::vector<double> d(colors.begin(), colors.end());
    for (double& c : d)
      if (c < 0 || c > 1) c = std::clamp(c, 0.0, 1.0), ++clamped;
    return add_float_accessor(out, d, channels, false, true);
  }
  const std::size_t count = colors.size() / std::size_t(channels);
  const double scale = component_type == kUByte ? 255.0 : 65535.0;
  const std::size_t cb = component_type == kUByte ? 1 : 2;
  std::vector<unsigned char> raw(colors.size() * cb);
  for (std::size_t i = 0; i < colors.size(); ++i) {
    const double c = std::clamp(double(colors[i]), 0.0, 1.0);  // NaN refused before writing
    const auto q = std::uint16_t(std::lround(c * scale));
    if (cb == 1) raw[i] = std::uint8_t(q);
    else std::memcpy(&raw[2 * i], &q, 2);
  }
  const std::size_t elem = cb * std::size_t(channels);
  const int view = out.add_view(raw.data(), count, elem, vertex_stride(elem), kArrayBuffer);
  return out.add_accessor({{"bufferView", view}, {"componentType", component_type}, {"normalized", true},
                           {"count", count}, {"type", type_name(channels)}});
}

// An attribute passed through, its elements gathered through `source_vertex` (output vertex ->
// input vertex); same component type, type and normalisation as the original accessor.
int add_gathered_accessor(OutBuffer& out, const GltfSource& source, int index, const std::vector<std::uint32_t>& source_vertex,
                          const std::string& name) {
  const tinygltf::Accessor& a = source.model.accessors[std::size_t(index)];
  const std::vector<unsigned char> raw = io::gltf::accessor_bytes(source, index, name);
  const std::size_t elem = std::size_t(io::gltf::type_components(a.type)) * std::size_t(io::gltf::component_bytes(a.componentType));
  std::vector<unsigned char> g(source_vertex.size() * elem);
  for (std::size_t i = 0; i < source_vertex.size(); ++i) std::memcpy(&g[i * elem], &raw[source_vertex[i] * elem], elem);
  const int view = out.add_view(g.data(), source_vertex.size(), elem, vertex_stride(elem), kArrayBuffer);
  json acc = {{"bufferView", view}, {"componentType", a.componentType}, {"count", source_vertex.size()},
              {"type", type_name(io::gltf::type_components(a.type))}};
  if (a.normalized) acc["normalized"] = true;
  if (!a.minValues.empty() && !a.maxValues.empty()) {  // min/max of a subset-with-repeats: the same set of values
    acc["min"] = a.minValues;
    acc["max"] = a.maxValues;
  }
  return out.add_accessor(std::move(acc));
}

int add_index_accessor(OutBuffer& out, const std::vector<std::uint32_t>& idx, std::size_t vertices) {
  if (vertices <= 65535) {
    std::vector<std::uint16_t> s(idx.begin(), idx.end());
    const int view = out.add_view(reinterpret_cast<const unsigned char*>(s.data()), s.size(), 2, 2, kElementArrayBuffer);
    return out.add_accessor({{"bufferView", view}, {"componentType", kUShort}, {"count", s.size()}, {"type", "SCALAR"}});
  }
  const int view = out.add_view(reinterpret_cast<const unsigned char*>(idx.data()), idx.size(), 4, 4, kElementArrayBuffer);
  return out.add_accessor({{"bufferView", view}, {"componentType", kUInt}, {"count", idx.size()}, {"type", "SCALAR"}});
}

template <class T>
std::vector<T> gather(const std::vector<T>& a, std::size_t comps, const std::vector<std::uint32_t>& source_vertex) {
  std::vector<T> out(source_vertex.size() * comps);
  for (std::size_t i = 0; i < source_vertex.size(); ++i)
    for (std::size_t k = 0; k < comps; ++k) out[i * comps + k] = a[source_vertex[i] * comps + k];
  return out;
}

// Capacity for the output in one block; big blocks are advised as huge pages (first touch of fresh
// memory is most of the cost of writing, as in core/bulk_reserve.h; only the 2 MiB-aligned
// interior is advised).
void reserve_output(std::string& s, std::size_t n) {
  const bool fresh = s.capacity() < n;
  s.reserve(n);
  if (fresh) advise_huge_pages(s.data(), n);
}

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const std::uint32_t v = std::uint32_t(std::uint8_t(in[i])) << 16 | std::uint32_t(std::uint8_t(in[i + 1])) << 8 | std::uint8_t(in[i + 2]);
    out += t[v >> 18];
    out += t[(v >> 12) & 63];
    out += t[(v >> 6) & 63];
    out += t[v & 63];
  }
  if (i < in.size()) {
    std::uint32_t v = std::uint32_t(std::uint8_t(in[i])) << 16;
    if (i + 1 < in.size()) v |= std::uint32_t(std::uint8_t(in[i + 1])) << 8;
    out += t[v >> 18];
    out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string mime_for(const std::string& uri, const std::string& given) {
  if (!given.empty()) return given;
  if (uri.rfind("data:", 0) == 0) {
    const std::size_t semi = uri.find_first_of(";,");
    return uri.substr(5, semi == std::string::npos ? std::string::npos : semi - 5);
  }
  std::string ext = uri.substr(uri.find_last_of('.') == std::string::npos ? uri.size() : uri.find_last_of('.') + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "png") return "image/png";
  if (ext == "jpg" || ext == "jpeg") return "image/jpeg";
  if (ext == "webp") return "image/webp";
  if (ext == "ktx2") return "image/ktx2";
  return "application/octet-stream";
}

// Output vertices for a mesh whose normals or colours are per corner or per face, or (a fresh
// document: `texcoords`) whose texture coordinates are per corner: one per distinct (vertex,
// normal-or-face, texture coordinate) triple, in order of first use.
struct Split {
  std::vector<std::uint32_t> source_vertex;  // output vertex -> mesh vertex
  std::vector<std::uint32_t> corner_output;  // corner -> output vertex; empty when corners_kept
  bool corners_kept = false;                 // no split: corner -> mesh.corner_vertex (not copied)
};

struct CornerKey {
  std::uint64_t vertex_and_second;
  std::uint32_t texcoord, tangent;
  bool operator==(const CornerKey& o) const {
    return vertex_and_second == o.vertex_and_second && texcoord == o.texcoord && tangent == o.tangent;
  }
};
struct CornerKeyHash {
  std::size_t operator()(const CornerKey& k) const {
    return std::hash<std::uint64_t>()(k.vertex_and_second ^ (std::uint64_t(k.texcoord) * 0x9E3779B97F4A7C15ull) ^
                                      (std::uint64_t(k.tangent) * 0xff51afd7ed558ccdull));
  }
};

// Per corner, the first corner of its vertex with the same tangent frame (#C by 4 `tangents`).
std::vector<std::uint32_t> tangent_classes(const Mesh& mesh, const std::vector<double>& tangents) {
  const std::size_t C = mesh.num_corners();
  std::vector<std::uint32_t> order(C), cls(C);
  for (std::size_t c = 0; c < C; ++c) order[c] = std::uint32_t(c);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    if (mesh.corner_vertex[a] != mesh.corner_vertex[b]) return mesh.corner_vertex[a] < mesh.corner_vertex[b];
    for (int k = 0; k < 4; ++k)
      if (tangents[4 * std::size_t(a) + k] != tangents[4 * std::size_t(b) + k]) return tangents[4 * std::size_t(a) + k] < tangents[4 * std::size_t(b) + k];
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  auto same = [&](std::uint32_t a, std::uint32_t b) {
    return mesh.corner_vertex[a] == mesh.corner_vertex[b] &&
           std::equal(&tangents[4 * std::size_t(a)], &tangents[4 * std::size_t(a)] + 4, &tangents[4 * std::size_t(b)]);
  };
  for (std::size_t i = 0; i < C; ++i) cls[order[i]] = i > 0 && same(order[i - 1], order[i]) ? cls[order[i - 1]] : order[i];
  return cls;
}

Split split_vertices(const Mesh& mesh, bool texcoords, const std::vector<std::uint32_t>& tangent_class) {
  Split s;
  const ShadingNormals normals = shading_normals(mesh);  // the normals NORMAL holds
  const bool per_face = normals == ShadingNormals::Face || mesh.has_face_colors();
  const bool per_corner = normals == ShadingNormals::Corner;
  const bool per_tangent = !tangent_class.empty();
  if (!per_face && !per_corner && !texcoords && !per_tangent) {
    s.source_vertex.resize(mesh.num_vertices());
    for (std::size_t v = 0; v < s.source_vertex.size(); ++v) s.source_vertex[v] = std::uint32_t(v);
    s.corners_kept = true;
    return s;
  }
  s.corner_output.resize(mesh.num_corners());
  // Split by tangent frames only (the rest is per vertex already): every vertex keeps its index
  // for the first frame its corners use, the vertices split off are appended, so that a primitive
  // whose frames agree at every vertex keeps its vertex order, and the accessors as read stay
  // valid beside the new TANGENT.
  const bool keep_order = per_tangent && !per_face && !per_corner && !texcoords;
  if (keep_order) {
    s.source_vertex.resize(mesh.num_vertices());
    for (std::size_t v = 0; v < s.source_vertex.size(); ++v) s.source_vertex[v] = std::uint32_t(v);
  }
  std::vector<bool> claimed(keep_order ? mesh.num_vertices() : 0, false);
  std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> seen;
  seen.reserve(mesh.num_corners());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      const std::uint32_t v = mesh.corner_vertex[c];
      const std::uint64_t second = per_face ? std::uint64_t(f) : per_corner ? std::uint64_t(mesh.corner_normal_index[c]) : 0;
      const CornerKey key{std::uint64_t(v) << 32 | second, texcoords ? mesh.corner_texcoord_index[c] : 0,
                          per_tangent ? tangent_class[c] : 0};
      if (keep_order && !claimed[v]) {
        claimed[v] = true;
        seen.emplace(key, v);
        s.corner_output[c] = v;
        continue;
      }
      auto [it, fresh] = seen.emplace(key, std::uint32_t(s.source_vertex.size()));
      if (fresh) s.source_vertex.push_back(v);
      s.corner_output[c] = it->second;
    }
  return s;
}

bool same_vertex_data(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

struct PrimitiveWriter {
  OutBuffer& out;
  const GltfSource* source;       // null for a fresh document
  const tinygltf::Model* model;  // source's model, or null
  const std::string& name;
  GltfWriteResult& result;

  void write(const GltfPrimitive& gp, json& jprim) {
    const Mesh& mesh = gp.mesh;
    const tinygltf::Primitive* src = model ? &model->meshes[gp.mesh_index].primitives[gp.primitive_index] : nullptr;
    auto source_attribute = [src](const char* attr) {
      if (!src) return -1;
      const auto it = src->attributes.find(attr);
      return it == src->attributes.end() ? -1 : it->second;
    };
    json& attrs = jprim["attributes"];
    const bool texcoords = !model && mesh.has_texcoords();  // a fresh document: TEXCOORD_0 from the mesh
    const bool corner_tangents = gp.corner_tangents.size() == 4 * mesh.num_corners() && mesh.num_corners() > 0;
    const Split split = split_vertices(mesh, texcoords, corner_tangents ? tangent_classes(mesh, gp.corner_tangents)
                                                                        : std::vector<std::uint32_t>());
    const std::uint32_t* corner_output = split.corners_kept ? mesh.corner_vertex.data() : split.corner_output.data();
    const ShadingNormals normals = shading_normals(mesh);  // core/shading_normals.h: what NORMAL holds
    const bool identity = split.source_vertex.size() == mesh.num_vertices() && normals != ShadingNormals::Corner &&
                          normals != ShadingNormals::Face && !mesh.has_face_colors() && !texcoords &&
                          (split.corners_kept || std::equal(split.corner_output.begin(), split.corner_output.end(), mesh.corner_vertex.begin()));
    const std::size_t out_vertices = split.source_vertex.size();
    const bool same_vertices = model && mesh.num_vertices() == gp.read_vertices;
    const bool keep_all = identity && same_vertices;  // accessors as read stay valid
    if (!identity && out_vertices > mesh.num_vertices()) result.split_vertices += out_vertices - mesh.num_vertices();

    // POSITION
    if (!keep_all || !io::gltf::accessor_equals(*source, source_attribute("POSITION"), mesh.positions, name))
      attrs["POSITION"] = add_float_accessor(out, gather(mesh.positions, 3, split.source_vertex), 3, true, true);

    // NORMAL: per vertex, per corner (pool) or per face, all as vertex normals of the output.
    if (normals != ShadingNormals::None) {
      if (const std::string note = face_normals_not_written_note(mesh, "glTF"); !note.empty())
        result.notes.push_back(gp.json_path + ": " + note);
      // Kept as read unless a row is off unit length (then written anew, divided by its length).
      const bool unchanged = keep_all && mesh.has_vertex_normals() && source_attribute("NORMAL") >= 0 &&
                             io::gltf::accessor_equals(*source, source_attribute("NORMAL"), mesh.vertex_normals, name) &&
                             !any_off_unit_normal(mesh.vertex_normals);
      if (!unchanged) {
        std::vector<double> n(3 * out_vertices, 0.0);
        for (std::size_t f = 0; f < mesh.num_faces(); ++f)
          for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            const std::size_t o = corner_output[c];
            const double* src = normals == ShadingNormals::Face     ? &mesh.face_normals[3 * f]
                                : normals == ShadingNormals::Corner ? &mesh.corner_normals[3 * std::size_t(mesh.corner_normal_index[c])]
                                                                    : &mesh.vertex_normals[3 * std::size_t(mesh.corner_vertex[c])];
            std::copy(src, src + 3, &n[3 * o]);
          }
        if (normals == ShadingNormals::Vertex)
          n = gather(mesh.vertex_normals, 3, split.source_vertex);  // isolated vertices keep theirs too
        OffUnitNormals off_unit;  // core/unit_normals.h: the writers' one rule
        normalise_off_unit_normals(n, off_unit);
        if (off_unit.rows > 0) result.notes.push_back(gp.json_path + ": " + off_unit_normals_note(off_unit));
        attrs["NORMAL"] = add_float_accessor(out, n, 3, false, true);
      }
    } else if (attrs.contains("NORMAL")) {
      attrs.erase("NORMAL");  // the command dropped them (transform --normals drop)
      result.notes.push_back(gp.json_path + ": NORMAL removed");
    }

    // COLOR_0: per vertex or per face (then per split vertex).
    const int channels = mesh.color_channels;
    if (mesh.has_vertex_colors() || mesh.has_face_colors()) {
      const int color = source_attribute("COLOR_0");
      const bool unchanged = keep_all && mesh.has_vertex_colors() && color >= 0 &&
                             io::gltf::type_components(model->accessors[std::size_t(color)].type) == mesh.color_channels &&
                             io::gltf::accessor_equals(*source, color, mesh.vertex_colors, name);
      if (!unchanged) {
        std::vector<float> col(std::size_t(channels) * out_vertices, 1.0f);
        for (std::size_t f = 0; f < mesh.num_faces(); ++f)
          for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            const std::size_t o = corner_output[c];
            const float* src = mesh.has_face_colors() ? &mesh.face_colors[std::size_t(channels) * f]
                                                      : &mesh.vertex_colors[std::size_t(channels) * mesh.corner_vertex[c]];
            std::copy(src, src + channels, &col[std::size_t(channels) * o]);
          }
        if (mesh.has_vertex_colors() && !mesh.has_face_colors()) col = gather(mesh.vertex_colors, std::size_t(channels), split.source_vertex);
        const int ct = gp.color_component_type == kUByte || gp.color_component_type == kUShort ? gp.color_component_type : kFloat;
        std::size_t clamped = 0;
        attrs["COLOR_0"] = add_color_accessor(out, col, channels, ct, clamped);
        if (clamped > 0)
          result.notes.push_back(gp.json_path + ": " + std::to_string(clamped) + " colour values outside [0, 1] clamped: glTF's COLOR_0 holds [0, 1]");
      }
    }

    // TEXCOORD_0 (a fresh document) from the mesh's per-corner texture coordinates: v flipped
    // (t' = 1 - t; the Mesh's origin is the image's bottom left, as OBJ's, glTF's its top left);
    // a third coordinate (OBJ `vt u v w`) and corners without one are named in a note.
    if (texcoords) {
      std::vector<double> uv(2 * out_vertices, 0.0);
      const std::size_t dims = std::size_t(mesh.texcoord_dims);
      std::size_t missing = 0, w_dropped = 0;
      for (std::size_t c = 0; c < mesh.num_corners(); ++c) {
        const std::uint32_t t = mesh.corner_texcoord_index[c];
        if (t == kNoTexcoord || dims < 2 || (std::size_t(t) + 1) * dims > mesh.texcoords.size()) {
          ++missing;
          continue;
        }
        uv[2 * std::size_t(corner_output[c])] = mesh.texcoords[dims * t];
        uv[2 * std::size_t(corner_output[c]) + 1] = 1 - mesh.texcoords[dims * t + 1];
        w_dropped += dims > 2 && mesh.texcoords[dims * t + 2] != 0;
      }
      attrs["TEXCOORD_0"] = add_float_accessor(out, uv, 2, false, true);
      if (missing > 0)
        result.notes.push_back(gp.json_path + ": " + std::to_string(missing) + " corners without a texture coordinate get (0, 0) in TEXCOORD_0");
      if (w_dropped > 0)
        result.notes.push_back(gp.json_path + ": " + std::to_string(w_dropped) + " corners' third texture coordinate (w) not written: TEXCOORD_0 holds u, v");
    }

    // TANGENT from frames a command computed per corner (gltf/gltf_tangents.h), added if absent.
    if (corner_tangents) {
      std::vector<double> t(4 * out_vertices, 0.0);
      for (std::size_t c = 0; c < mesh.num_corners(); ++c)
        std::copy(&gp.corner_tangents[4 * c], &gp.corner_tangents[4 * c] + 4, &t[4 * std::size_t(corner_output[c])]);
      for (std::size_t v = 0; v < out_vertices; ++v)
        if (t[4 * v + 3] == 0.0) { t[4 * v] = 1.0; t[4 * v + 3] = 1.0; }  // a vertex no corner uses: any unit frame
      attrs["TANGENT"] = add_float_accessor(out, t, 4, false, true);
    } else if (gp.drop_tangents && attrs.contains("TANGENT")) {
      attrs.erase("TANGENT");
    }

    // TANGENT and every attribute not decoded: kept, gathered through a split, or dropped when the
    // vertices changed in a way they cannot follow.
    std::vector<std::string> dropped;
    if (model) {
      const tinygltf::Primitive& prim = model->meshes[gp.mesh_index].primitives[gp.primitive_index];
      for (const auto& [attr, index] : prim.attributes) {
        if (attr == "POSITION" || attr == "NORMAL" || (attr == "COLOR_0" && (mesh.has_vertex_colors() || mesh.has_face_colors()))) continue;
        if (attr == "TANGENT" && (corner_tangents || gp.drop_tangents)) continue;  // written or removed above
        if (attr == "TANGENT" && !gp.tangents.empty() && same_vertices) {
          if (!keep_all || !same_vertex_data(gp.tangents, gp.read_tangents))
            attrs["TANGENT"] = add_float_accessor(out, gather(gp.tangents, 4, split.source_vertex), 4, false, true);
          continue;
        }
        if (keep_all) continue;
        if (!same_vertices) {
          dropped.push_back(attr);
          attrs.erase(attr);
          continue;
        }
        attrs[attr] = add_gathered_accessor(out, *source, index, split.source_vertex, name);
      }
      write_targets(gp, jprim, prim, split, keep_all, same_vertices, dropped);
    }
    if (!dropped.empty()) {
      // Dropping them would break what refers to them (a material's texture needs its TEXCOORD, a
      // skin its JOINTS, the mesh's weights its targets): refused, nothing written.
      std::string list;
      for (const auto& d : dropped) list += (list.empty() ? "" : ", ") + d;
      fail(name, 0, gp.json_path + ": the command changed the vertex count (" + std::to_string(gp.read_vertices) + " -> " +
                        std::to_string(mesh.num_vertices()) + "); " + list +
                        " cannot follow (nothing written; without --weld the vertices are kept)");
    }

    // Indices: as read while the faces and vertices are; else a new TRIANGLES list.
    const bool faces_same = keep_all && mesh.all_triangles() &&
                            io::gltf::primitive_corners_equal(*source, src->indices, src->mode, gp.read_vertices,
                                                              mesh.corner_vertex, gp.json_path, name);
    if (!faces_same) {
      std::vector<std::uint32_t> idx, tri;
      idx.reserve(mesh.num_corners());
      for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
        tri.clear();  // a polygon's triangles inside its outline, in its winding (convex: the fan from corner 0)
        polygon_triangles(mesh.positions.data(), mesh.corner_vertex.data() + b, e - b, tri);
        for (const std::uint32_t k : tri) idx.push_back(corner_output[b + k]);
      }
      if (mesh.num_faces() == 0) {
        // A point cloud (no face; the readers keep one, e.g. a PLY with vertices only): POINTS, each
        // vertex a point, no indices (glTF 2.0, 3.7.2.1: an empty index accessor is invalid).
        jprim.erase("indices");
        jprim["mode"] = 0;
      } else {
        jprim["indices"] = add_index_accessor(out, idx, out_vertices);
        jprim["mode"] = 4;
      }
    }
  }

  void write_targets(const GltfPrimitive& gp, json& jprim, const tinygltf::Primitive& prim, const Split& split, bool keep_all,
                     bool same_vertices, std::vector<std::string>& dropped) {
    if (prim.targets.empty() || !jprim.contains("targets")) return;
    json& targets = jprim["targets"];
    for (std::size_t t = 0; t < prim.targets.size() && t < targets.size(); ++t) {
      const GltfMorphTarget& now = gp.targets[t];
      const GltfMorphTarget& was = gp.read_targets[t];
      for (const auto& [attr, index] : prim.targets[t]) {
        if (attr == "TANGENT" && gp.drop_tangents) {
          // The base TANGENT is removed (stale, not recomputable): its deltas go with it (a target
          // attribute without a base one is invalid: MESH_PRIMITIVE_MORPH_TARGET_NO_BASE_ACCESSOR).
          targets[t].erase(attr);
          continue;
        }
        const std::vector<double>* decoded = attr == "POSITION" ? &now.position_deltas
                                             : attr == "NORMAL" ? &now.normal_deltas
                                             : attr == "TANGENT" ? &now.tangent_deltas
                                                                 : nullptr;
        const std::vector<double>* before = attr == "POSITION" ? &was.position_deltas
                                            : attr == "NORMAL" ? &was.normal_deltas
                                            : attr == "TANGENT" ? &was.tangent_deltas
                                                                : nullptr;
        if (!same_vertices) {
          dropped.push_back("targets[" + std::to_string(t) + "]." + attr);
          targets[t].erase(attr);
          continue;
        }
        if (decoded && !decoded->empty()) {
          if (!keep_all || !same_vertex_data(*decoded, *before))
            targets[t][attr] = add_float_accessor(out, gather(*decoded, 3, split.source_vertex), 3, attr == "POSITION", true);
        } else if (decoded && !before->empty()) {
          targets[t].erase(attr);  // the command removed them (normals dropped)
        } else if (!keep_all) {
          targets[t][attr] = add_gathered_accessor(out, *source, index, split.source_vertex, name);
        }
      }
      // Deltas the command added (NORMAL deltas computed for a target that had none).
      if (same_vertices && now.normal_deltas.size() == 3 * gp.mesh.num_vertices() && was.normal_deltas.empty() &&
          !targets[t].contains("NORMAL"))
        targets[t]["NORMAL"] = add_float_accessor(out, gather(now.normal_deltas, 3, split.source_vertex), 3, false, true);
    }
  }
};

json fresh_document() {
  return {{"asset", {{"version", "2.0"}, {"generator", "shadetool"}}},
          {"scene", 0},
          {"scenes", json::array({{{"nodes", json::array({0})}}})},
          {"nodes", json::array({{{"mesh", 0}}})},
          {"meshes", json::array({{{"primitives", json::array({{{"attributes", json::object()}, {"mode", 4}}})}}})}};
}

}  // namespace

GltfDocument gltf_document_from_mesh(const Mesh& mesh) {
  GltfDocument doc;
  GltfPrimitive p;
  p.json_path = "meshes[0].primitives[0]";
  p.mesh = mesh;
  if (!mesh.has_vertex_colors() && !mesh.has_face_colors()) p.mesh.vertex_colors.clear();
  p.color_component_type = mesh.colors_are_float ? kFloat : kUByte;
  doc.primitives.push_back(std::move(p));
  return doc;
}

namespace {

// A file name as a URI reference (RFC 3986): every byte outside the unreserved set
// (ALPHA DIGIT - . _ ~) as %XX; '/' kept for a relative path.
std::string uri_escape(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') out += char(c);
    else out += {'%', hex[c >> 4], hex[c & 15]};
  }
  return out;
}

// KHR_materials_unlit on the materials of the document's triangle primitives; one unlit material
// (white, non-metallic: COLOR_0 is what shows) for those without a material.
void add_unlit_materials(const GltfDocument& doc, json& j, GltfWriteResult& result) {
  if (!j.contains("materials") || !j["materials"].is_array()) j["materials"] = json::array();
  json& materials = j["materials"];
  long fresh = -1;
  std::size_t marked = 0;
  for (const GltfPrimitive& gp : doc.primitives) {
    json& jprim = j["meshes"][gp.mesh_index]["primitives"][gp.primitive_index];
    if (jprim.contains("material") && jprim["material"].is_number_integer() && jprim["material"].get<long>() >= 0 &&
        jprim["material"].get<std::size_t>() < materials.size()) {
      json& m = materials[jprim["material"].get<std::size_t>()];
      if (!m.contains("extensions") || !m["extensions"].is_object()) m["extensions"] = json::object();
      if (!m["extensions"].contains("KHR_materials_unlit")) m["extensions"]["KHR_materials_unlit"] = json::object(), ++marked;
      continue;
    }
    if (fresh < 0) {
      materials.push_back({{"name", "baked colours (unlit)"},
                           {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
                           {"extensions", {{"KHR_materials_unlit", json::object()}}}});
      fresh = long(materials.size() - 1);
    }
    jprim["material"] = fresh;
  }
  if (materials.empty()) j.erase("materials");
  if (!j.contains("extensionsUsed") || !j["extensionsUsed"].is_array()) j["extensionsUsed"] = json::array();
  bool listed = false;
  for (const json& e : j["extensionsUsed"]) listed = listed || (e.is_string() && e.get<std::string>() == "KHR_materials_unlit");
  if (!listed) j["extensionsUsed"].push_back("KHR_materials_unlit");
  if (doc.source && (marked > 0 || fresh >= 0))
    result.notes.push_back("KHR_materials_unlit on " + std::to_string(marked + (fresh >= 0)) +
                           " materials (--unlit): viewers show the baked colours unlit");
}

}  // namespace

std::string gltf_buffer_path(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const std::string stem = dot != std::string::npos && (slash == std::string::npos || dot > slash) ? path.substr(0, dot) : path;
  return stem + ".bin";
}

std::string write_gltf(const GltfDocument& doc, bool binary, const std::string& name, GltfWriteResult& result,
                       const std::string& buffer_uri) {
  const GltfSource* src = doc.source.get();
  const tinygltf::Model* model = src ? &src->model : nullptr;
  json j = src ? src->json : fresh_document();
  if (!j.contains("bufferViews") || !j["bufferViews"].is_array()) j["bufferViews"] = json::array();
  if (!j.contains("accessors") || !j["accessors"].is_array()) j["accessors"] = json::array();
  OutBuffer out{std::string(), &j["bufferViews"], &j["accessors"]};

  // Every input buffer, concatenated (8-byte aligned, so every accessor keeps its alignment).
  if (model) {
    std::vector<std::size_t> base(model->buffers.size());
    std::size_t total = 28 + (std::size_t(1) << 20);  // GLB headers and room for the JSON in front
    for (std::size_t b = 0; b < model->buffers.size(); ++b) total += src->buffer_bytes(b).size() + 8;
    for (const auto& im : model->images) total += im.image.size() + 4;
    for (const GltfPrimitive& p : doc.primitives)  // room for what a command adds (position, normal, colour, indices)
      total += p.mesh.num_vertices() * 40 + p.mesh.num_corners() * 4 + 64;
    reserve_output(out.bytes, total);
    for (std::size_t b = 0; b < model->buffers.size(); ++b) {
      out.align(8);
      base[b] = out.bytes.size();
      out.bytes.append(src->buffer_bytes(b));
    }
    for (json& v : j["bufferViews"]) {
      const std::size_t b = v.value("buffer", 0);
      if (b < base.size()) {
        v["byteOffset"] = v.value("byteOffset", std::size_t(0)) + base[b];
        v["buffer"] = 0;
      }
    }
    // Images with a URI (a file or a data URI) move into the buffer, their bytes as read.
    if (j.contains("images") && j["images"].is_array())
      for (std::size_t k = 0; k < j["images"].size() && k < model->images.size(); ++k) {
        json& im = j["images"][k];
        if (!im.contains("uri")) continue;
        const std::vector<unsigned char>& bytes = model->images[k].image;
        const std::string uri = im["uri"].get<std::string>();
        if (bytes.empty()) {
          result.notes.push_back("images[" + std::to_string(k) + "]: '" + uri.substr(0, 64) + "' could not be read: kept as a reference");
          continue;
        }
        im["bufferView"] = out.add_view(bytes.data(), bytes.size(), 1, 1, 0);
        im["mimeType"] = mime_for(uri, im.value("mimeType", std::string()));
        im.erase("uri");
      }
  }

  PrimitiveWriter writer{out, src, model, name, result};
  for (const GltfPrimitive& gp : doc.primitives) {
    json& jprim = j["meshes"][gp.mesh_index]["primitives"][gp.primitive_index];
    writer.write(gp, jprim);
  }

  if (doc.unlit_materials) add_unlit_materials(doc, j, result);

  // What a command replaced leaves nothing behind; every accessor aligned, every bound exact.
  io::gltf::align_accessors(j, out.bytes, result.notes);
  io::gltf::prune_unreferenced(j, out.bytes, result.notes, src && src->compact_buffers);
  io::gltf::exact_bounds(j, out.bytes, result.notes);

  out.align(4);
  // The schema wants every top-level array non-empty (the validator's EMPTY_ENTITY): the two this
  // writer made for itself go when nothing is in them (a file with images and no mesh moves its
  // images into the buffer and has bufferViews, but no accessor).
  if (j["bufferViews"].empty()) j.erase("bufferViews");
  if (j["accessors"].empty()) j.erase("accessors");
  if (out.bytes.empty()) {
    j.erase("buffers");
  } else {
    json buffer = {{"byteLength", out.bytes.size()}};
    if (!binary && !buffer_uri.empty()) {
      buffer["uri"] = uri_escape(buffer_uri);
      result.buffer = std::move(out.bytes);
      out.bytes.clear();
    } else if (!binary) {
      buffer["uri"] = "data:application/octet-stream;base64," + base64(out.bytes);
    }
    j["buffers"] = json::array({buffer});
  }

  std::string text = j.dump(-1, ' ', false, json::error_handler_t::replace);
  if (!binary) return text + "\n";
  while (text.size() % 4) text += ' ';
  const std::uint32_t total = std::uint32_t(12 + 8 + text.size() + (out.bytes.empty() ? 0 : 8 + out.bytes.size()));
  if (12 + 8 + text.size() + 8 + out.bytes.size() > 0xFFFFFFF0ull) fail(name, 0, "the output exceeds GLB's 4 GiB limit: write .gltf");
  std::string head;
  auto put32 = [&head](std::uint32_t v) { head.append(reinterpret_cast<const char*>(&v), 4); };
  head += "glTF";
  put32(2);
  put32(total);
  put32(std::uint32_t(text.size()));
  put32(0x4E4F534Au);  // JSON
  head += text;
  if (out.bytes.empty()) return head;
  put32(std::uint32_t(out.bytes.size()));
  put32(0x004E4942u);  // BIN
  // The headers and JSON go in front of the binary chunk in place (a move within the reserved
  // block, not a second copy of the data into fresh memory).
  out.bytes.insert(0, head);
  return std::move(out.bytes);
}

}  // namespace shadetool
