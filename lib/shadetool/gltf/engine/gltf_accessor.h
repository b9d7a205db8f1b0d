// gltf_accessor.h (engine, not installed): reading glTF accessors into flat arrays, every check
// on the way, and appending new accessors to an output buffer.
//
// A glTF accessor is `count` elements of `type` (SCALAR, VEC2..4, MAT*) made of `componentType`
// numbers (5120 BYTE, 5121 UNSIGNED_BYTE, 5122 SHORT, 5123 UNSIGNED_SHORT, 5125 UNSIGNED_INT,
// 5126 FLOAT) at bufferView.byteOffset + accessor.byteOffset, `byteStride` apart (0: packed),
// optionally `normalized` (integers mapped to [0,1] or [-1,1], glTF 2.0 section 3.11:
// f = max(c / (2^(b-1) - 1), -1) for signed, c / (2^b - 1) for unsigned), optionally `sparse`
// (a dense base, or zeros, then `count` (index, value) substitutions). An accessor without a
// bufferView is all zeros (plus its sparse values).
//
// Everything read is checked against the document and the buffer sizes before one byte is
// loaded: a view beyond its buffer, an accessor beyond its view, a stride smaller than an element,
// sparse indices out of range; the Error names the file and the JSON path (`accessors[3]`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf { class Model; }
namespace shadetool { struct GltfSource; }

namespace shadetool::io::gltf {

// Components of one element of an accessor `type` ("VEC3" -> 3); 0 for an unknown type.
int type_components(int tinygltf_type);
// Bytes of one component (5126 -> 4); 0 for an unknown component type.
int component_bytes(int component_type);

// The raw element bytes of accessor `index`, tightly packed (count * components * component
// bytes), sparse substitutions applied. `name` is the file, for messages.
std::vector<unsigned char> accessor_bytes(const GltfSource& source, int index, const std::string& name);

// Accessor `index` as doubles, count * components, normalized integers mapped as in the spec.
std::vector<double> accessor_doubles(const GltfSource& source, int index, const std::string& name);

// Accessor `index` as unsigned indices (SCALAR of UNSIGNED_BYTE/SHORT/INT; Error otherwise).
std::vector<std::uint32_t> accessor_indices(const GltfSource& source, int index, const std::string& name);

// True when accessor `index` decodes (as accessor_doubles would) to exactly `values`; compares
// in place, without a copy, for tightly or stride-packed FLOAT data without sparse values.
bool accessor_equals(const GltfSource& source, int index, const std::vector<double>& values, const std::string& name);
// The same for colours held as float: each decoded value rounded to float equals values[i].
bool accessor_equals(const GltfSource& source, int index, const std::vector<float>& values, const std::string& name);

// The triangle corners of a TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN primitive: its indices (or
// 0..count-1), strips and fans unrolled (glTF 2.0, 3.7.2.1: strip i -> {i, i+1+i%2, i+2-i%2},
// fan i -> {i+1, i+2, 0}). `vertices` is POSITION's count (indices are checked against it);
// `path` names the primitive in messages.
std::vector<std::uint32_t> primitive_corners(const GltfSource& source, int indices, int mode, std::size_t vertices,
                                             const std::string& path, const std::string& name);
// True when primitive_corners(...) would equal `corners` (TRIANGLES with plain indices: compared
// in place).
bool primitive_corners_equal(const GltfSource& source, int indices, int mode, std::size_t vertices,
                             const std::vector<std::uint32_t>& corners, const std::string& path, const std::string& name);

}  // namespace shadetool::io::gltf
