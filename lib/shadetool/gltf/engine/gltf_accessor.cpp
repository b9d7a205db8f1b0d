// gltf_accessor.cpp: checked reads of glTF accessors (see gltf_accessor.h).
#include "gltf_accessor.h"
#include "gltf_source.h"

#include <cmath>
#include <cstring>

#include <shadetool/gltf/engine/tinygltf.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/error.h>

namespace shadetool::io::gltf {

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

int component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

namespace {

std::string at(int index) { return "accessors[" + std::to_string(index) + "]"; }

// The bytes [offset, offset + length) of bufferView `view`, checked against its buffer.
const unsigned char* view_span(const GltfSource& source, int view, std::size_t offset, std::size_t length,
                               const std::string& name, const std::string& path, std::size_t* stride) {
  const tinygltf::Model& model = source.model;
  if (view < 0 || std::size_t(view) >= model.bufferViews.size())
    fail(name, 0, path + ".bufferView: " + std::to_string(view) + " is not a bufferView index (the file has " +
                      std::to_string(model.bufferViews.size()) + ")");
  const tinygltf::BufferView& bv = model.bufferViews[std::size_t(view)];
  const std::string vpath = "bufferViews[" + std::to_string(view) + "]";
  if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size())
    fail(name, 0, vpath + ".buffer: " + std::to_string(bv.buffer) + " is not a buffer index");
  const std::size_t buffer_size = source.buffer_bytes(std::size_t(bv.buffer)).size();
  if (bv.byteOffset > buffer_size || bv.byteLength > buffer_size - bv.byteOffset)
    fail(name, 0, vpath + ": bytes " + std::to_string(bv.byteOffset) + ".." + std::to_string(bv.byteOffset + bv.byteLength) +
                      " overrun buffers[" + std::to_string(bv.buffer) + "] (" + std::to_string(buffer_size) + " bytes)");
  if (offset > bv.byteLength || length > bv.byteLength - offset)
    fail(name, 0, path + ": needs bytes " + std::to_string(offset) + ".." + std::to_string(offset + length) + " of " + vpath +
                      ", which has " + std::to_string(bv.byteLength) + ": the accessor overruns its buffer view");
  if (stride) *stride = bv.byteStride;
  return reinterpret_cast<const unsigned char*>(source.buffer_bytes(std::size_t(bv.buffer)).data()) + bv.byteOffset + offset;
}

}  // namespace

std::vector<unsigned char> accessor_bytes(const GltfSource& source, int index, const std::string& name) {
  const tinygltf::Model& model = source.model;
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    fail(name, 0, at(index) + ": no such accessor (the file has " + std::to_string(model.accessors.size()) + ")");
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  const int comps = type_components(a.type);
  const int cbytes = component_bytes(a.componentType);
  if (comps == 0) fail(name, 0, at(index) + ".type: unknown accessor type");
  if (cbytes == 0) fail(name, 0, at(index) + ".componentType: " + std::to_string(a.componentType) + " is not a glTF component type");
  if (a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3)
    if (cbytes < 4) fail(name, 0, at(index) + ": padded byte/short matrices are not read (no mesh attribute uses them)");
  const std::size_t elem = std::size_t(comps) * std::size_t(cbytes);
  if (a.count > (std::size_t(1) << 32)) fail(name, 0, at(index) + ".count: " + std::to_string(a.count) + " is too large");
  std::vector<unsigned char> out(a.count * elem, 0);
  if (a.bufferView >= 0 && a.count > 0) {
    std::size_t stride = 0;
    // Length needed: the last element starts (count - 1) strides in.
    const tinygltf::BufferView* bv =
        std::size_t(a.bufferView) < model.bufferViews.size() ? &model.bufferViews[std::size_t(a.bufferView)] : nullptr;
    const std::size_t s = bv && bv->byteStride ? bv->byteStride : elem;
    if (s < elem) fail(name, 0, "bufferViews[" + std::to_string(a.bufferView) + "].byteStride: " + std::to_string(s) +
                                    " is smaller than one element of " + at(index) + " (" + std::to_string(elem) + " bytes)");
    if (a.byteOffset % std::size_t(cbytes) != 0)
      fail(name, 0, at(index) + ".byteOffset: " + std::to_string(a.byteOffset) + " is not a multiple of the component size");
    const unsigned char* src = view_span(source, a.bufferView, a.byteOffset, (a.count - 1) * s + elem, name, at(index), &stride);
    if (s == elem) {
      std::memcpy(out.data(), src, out.size());
    } else {
      for (std::size_t i = 0; i < a.count; ++i) std::memcpy(&out[i * elem], src + i * s, elem);
    }
  }
  if (a.sparse.isSparse && a.sparse.count > 0) {
    const std::string sp = at(index) + ".sparse";
    const std::size_t n = std::size_t(a.sparse.count);
    if (n > a.count) fail(name, 0, sp + ".count: " + std::to_string(n) + " exceeds the accessor's count");
    const int icomp = a.sparse.indices.componentType;
    const int ib = component_bytes(icomp);
    if (!(icomp == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || icomp == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
          icomp == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      fail(name, 0, sp + ".indices.componentType: must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const unsigned char* idx = view_span(source, a.sparse.indices.bufferView, std::size_t(a.sparse.indices.byteOffset),
                                         n * std::size_t(ib), name, sp + ".indices", nullptr);
    const unsigned char* val = view_span(source, a.sparse.values.bufferView, std::size_t(a.sparse.values.byteOffset),
                                         n * elem, name, sp + ".values", nullptr);
    for (std::size_t k = 0; k < n; ++k) {
      std::uint32_t i = 0;
      if (ib == 1) i = idx[k];
      else if (ib == 2) { std::uint16_t v; std::memcpy(&v, idx + 2 * k, 2); i = v; }
      else std::memcpy(&i, idx + 4 * k, 4);
      if (i >= a.count)
        fail(name, 0, sp + ".indices: index " + std::to_string(i) + " (entry " + std::to_string(k) +
                          ") is out of range (count " + std::to_string(a.count) + ")");
      std::memcpy(&out[i * elem], val + k * elem, elem);
    }
  }
  return out;
}

namespace {

// Plain FLOAT data (no sparse values) in a buffer view: its first element and stride, after every
// check accessor_bytes makes; nullptr when the accessor is not of that kind.
const unsigned char* plain_float(const GltfSource& source, int index, const std::string& name, std::size_t& stride) {
  const tinygltf::Model& model = source.model;
  if (index < 0 || std::size_t(index) >= model.accessors.size()) return nullptr;
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.sparse.isSparse || a.bufferView < 0 || a.count == 0) return nullptr;
  const int comps = type_components(a.type);
  if (comps == 0 || std::size_t(a.bufferView) >= model.bufferViews.size()) return nullptr;
  const std::size_t elem = 4 * std::size_t(comps);
  const tinygltf::BufferView& bv = model.bufferViews[std::size_t(a.bufferView)];
  stride = bv.byteStride ? bv.byteStride : elem;
  if (stride < elem || a.byteOffset % 4 != 0) return nullptr;  // accessor_bytes reports these
  return view_span(source, a.bufferView, a.byteOffset, (a.count - 1) * stride + elem, name, at(index), nullptr);
}

}  // namespace

std::vector<double> accessor_doubles(const GltfSource& source, int index, const std::string& name) {
  const tinygltf::Model& model = source.model;
  std::size_t stride = 0;
  if (const unsigned char* src = plain_float(source, index, name, stride)) {  // no intermediate copy
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    const std::size_t comps = std::size_t(type_components(a.type));
    std::vector<double> out;
    reserve_bulk(out, a.count * comps);  // huge pages for big arrays: most of the cost is first touch
    out.resize(a.count * comps);
    for (std::size_t i = 0; i < a.count; ++i) {
      float f[16];
      std::memcpy(f, src + i * stride, 4 * comps);
      for (std::size_t k = 0; k < comps; ++k) out[i * comps + k] = f[k];
    }
    return out;
  }
  const std::vector<unsigned char> raw = accessor_bytes(source, index, name);
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  const std::size_t n = a.count * std::size_t(type_components(a.type));
  std::vector<double> out(n);
  const bool norm = a.normalized;
  // Normalised integers (glTF 2.0, 3.11 "Animations"/"Meshes" table): unsigned c / (2^b - 1),
  // signed max(c / (2^(b-1) - 1), -1). Divisors are constants, never zero.
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      for (std::size_t i = 0; i < n; ++i) { float f; std::memcpy(&f, &raw[4 * i], 4); out[i] = f; }
      break;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      for (std::size_t i = 0; i < n; ++i) {
        const double c = static_cast<signed char>(raw[i]);
        out[i] = norm ? std::max(c / 127.0, -1.0) : c;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      for (std::size_t i = 0; i < n; ++i) out[i] = norm ? raw[i] / 255.0 : raw[i];
      break;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      for (std::size_t i = 0; i < n; ++i) {
        std::int16_t v; std::memcpy(&v, &raw[2 * i], 2);
        out[i] = norm ? std::max(v / 32767.0, -1.0) : double(v);
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (std::size_t i = 0; i < n; ++i) {
        std::uint16_t v; std::memcpy(&v, &raw[2 * i], 2);
        out[i] = norm ? v / 65535.0 : double(v);
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      for (std::size_t i = 0; i < n; ++i) { std::uint32_t v; std::memcpy(&v, &raw[4 * i], 4); out[i] = v; }
      break;
    default:
      fail(name, 0, at(index) + ".componentType: " + std::to_string(a.componentType) + " cannot hold mesh data");
  }
  return out;
}

std::vector<std::uint32_t> accessor_indices(const GltfSource& source, int index, const std::string& name) {
  const tinygltf::Model& model = source.model;
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    fail(name, 0, at(index) + ": no such accessor (the file has " + std::to_string(model.accessors.size()) + ")");
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  const int ct = a.componentType;
  if (a.type != TINYGLTF_TYPE_SCALAR)
    fail(name, 0, at(index) + ".type: indices must be SCALAR");
  if (!(ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
        ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    fail(name, 0, at(index) + ".componentType: " + std::to_string(ct) +
                      " is not an index type (UNSIGNED_BYTE 5121, UNSIGNED_SHORT 5123 or UNSIGNED_INT 5125)");
  if (!a.sparse.isSparse && a.bufferView >= 0 && a.count > 0 && std::size_t(a.bufferView) < model.bufferViews.size() &&
      model.bufferViews[std::size_t(a.bufferView)].byteStride == 0 && a.byteOffset % std::size_t(component_bytes(ct)) == 0) {
    // Packed indices read straight from the buffer (no intermediate copy).
    const std::size_t cb = std::size_t(component_bytes(ct));
    const unsigned char* src = view_span(source, a.bufferView, a.byteOffset, a.count * cb, name, at(index), nullptr);
    std::vector<std::uint32_t> out;
    reserve_bulk(out, a.count);
    out.resize(a.count);
    if (cb == 4) std::memcpy(out.data(), src, a.count * 4);
    else if (cb == 2) for (std::size_t i = 0; i < a.count; ++i) { std::uint16_t v; std::memcpy(&v, src + 2 * i, 2); out[i] = v; }
    else for (std::size_t i = 0; i < a.count; ++i) out[i] = src[i];
    return out;
  }
  const std::vector<unsigned char> raw = accessor_bytes(source, index, name);
  std::vector<std::uint32_t> out(a.count);
  if (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
    for (std::size_t i = 0; i < a.count; ++i) out[i] = raw[i];
  } else if (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
    for (std::size_t i = 0; i < a.count; ++i) { std::uint16_t v; std::memcpy(&v, &raw[2 * i], 2); out[i] = v; }
  } else {
    std::memcpy(out.data(), raw.data(), raw.size());
  }
  return out;
}

bool accessor_equals(const GltfSource& source, int index, const std::vector<double>& values, const std::string& name) {
  const tinygltf::Model& model = source.model;
  if (index < 0 || std::size_t(index) >= model.accessors.size()) return false;
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  const std::size_t comps = std::size_t(type_components(a.type));
  if (values.size() != a.count * comps) return false;
  std::size_t stride = 0;
  if (const unsigned char* src = plain_float(source, index, name, stride)) {
    for (std::size_t i = 0; i < a.count; ++i) {
      float f[16];
      std::memcpy(f, src + i * stride, 4 * comps);
      for (std::size_t k = 0; k < comps; ++k)
        if (!(double(f[k]) == values[i * comps + k])) return false;
    }
    return true;
  }
  const std::vector<double> d = accessor_doubles(source, index, name);
  return d == values;
}

bool accessor_equals(const GltfSource& source, int index, const std::vector<float>& values, const std::string& name) {
  const tinygltf::Model& model = source.model;
  if (index < 0 || std::size_t(index) >= model.accessors.size()) return false;
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  if (values.size() != a.count * std::size_t(type_components(a.type))) return false;
  const std::vector<double> d = accessor_doubles(source, index, name);
  for (std::size_t i = 0; i < d.size(); ++i)
    if (!(float(d[i]) == values[i])) return false;
  return true;
}

std::vector<std::uint32_t> primitive_corners(const GltfSource& source, int indices, int mode, std::size_t vertices,
                                             const std::string& path, const std::string& name) {
  std::vector<std::uint32_t> idx;
  if (indices >= 0) {
    idx = accessor_indices(source, indices, name);
    for (std::size_t i = 0; i < idx.size(); ++i)
      if (idx[i] >= vertices)
        fail(name, 0, path + ".indices: index " + std::to_string(idx[i]) + " (element " + std::to_string(i) +
                          " of accessors[" + std::to_string(indices) + "]) is out of range: POSITION has " +
                          std::to_string(vertices) + " vertices");
  } else {
    idx.resize(vertices);
    for (std::size_t i = 0; i < vertices; ++i) idx[i] = std::uint32_t(i);
  }
  if (mode < 0 || mode == TINYGLTF_MODE_TRIANGLES) {
    if (idx.size() % 3 != 0)
      fail(name, 0, path + (indices >= 0 ? ".indices" : ".attributes.POSITION") + ": " + std::to_string(idx.size()) +
                        " vertices do not make whole triangles (TRIANGLES needs a multiple of 3)");
    return idx;
  }
  std::vector<std::uint32_t> cv;
  cv.reserve(idx.size() > 2 ? 3 * (idx.size() - 2) : 0);
  for (std::size_t i = 0; i + 2 < idx.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      cv.push_back(idx[i]);
      cv.push_back(idx[i + 1 + i % 2]);
      cv.push_back(idx[i + 2 - i % 2]);
    } else {  // TRIANGLE_FAN
      cv.push_back(idx[i + 1]);
      cv.push_back(idx[i + 2]);
      cv.push_back(idx[0]);
    }
  }
  return cv;
}

bool primitive_corners_equal(const GltfSource& source, int indices, int mode, std::size_t vertices,
                             const std::vector<std::uint32_t>& corners, const std::string& path, const std::string& name) {
  const tinygltf::Model& model = source.model;
  if ((mode < 0 || mode == TINYGLTF_MODE_TRIANGLES) && indices >= 0 && std::size_t(indices) < model.accessors.size()) {
    const tinygltf::Accessor& a = model.accessors[std::size_t(indices)];
    const int ct = a.componentType;
    if (a.count != corners.size()) return false;
    if (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && !a.sparse.isSparse && a.bufferView >= 0 && a.count > 0 &&
        std::size_t(a.bufferView) < model.bufferViews.size() && model.bufferViews[std::size_t(a.bufferView)].byteStride == 0) {
      const unsigned char* src = view_span(source, a.bufferView, a.byteOffset, a.count * 4, name, at(indices), nullptr);
      return std::memcmp(src, corners.data(), a.count * 4) == 0;
    }
  }
  return primitive_corners(source, indices, mode, vertices, path, name) == corners;
}

}  // namespace shadetool::io::gltf
