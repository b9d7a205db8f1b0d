// gltf_tidy.h (engine, not installed): the last two passes of the glTF writer over the output's
// JSON and its single buffer (every bufferView in buffer 0, `bytes`).
//
// prune_unreferenced: accessors no property refers to (a command's replaced NORMAL, POSITION,
// indices; an input's own leftovers), then bufferViews no accessor, sparse block or image refers
// to, then their bytes: the buffer is rebuilt from the views kept, in order, each at a 4-byte
// boundary plus its old offset mod 4 (so that every accessor keeps its alignment, glTF 2.0
// 3.6.2.4). Every index is remapped: primitives' attributes, indices and targets, skins'
// inverseBindMatrices, animation samplers, accessors' bufferView and sparse views, images'
// bufferView, EXT_mesh_gpu_instancing's attributes, EXT_structural_metadata's property tables'
// views (values, arrayOffsets, stringOffsets; these keep their offset mod 8, as their components
// may be 8 bytes long). CESIUM_RTC and EXT_mesh_features hold no such index. An extension it does
// not know (in extensionsUsed) could hold such an index: then nothing is pruned and a note says so;
// unless the
// extension holds no number in any of its `extensions` objects (FB_ngon_encoding's are empty; an
// extension may be listed with no object at all): with no number it names no index. Nothing
// unreferenced and no `compact`: nothing changes (bytes identical); `compact` rebuilds the buffer
// from the views all the same (bytes no view holds: a decoded file's compressed data).
//
// align_accessors: an accessor whose data does not start on a multiple of its component size
// (glTF 2.0 3.6.2.4; files that other programs wrote have them, and the validator rejects them)
// gets its elements copied to a new bufferView at a 4-byte boundary (the view's byteStride kept
// when it had one, else packed); the old view is left for prune_unreferenced. So does an accessor
// that a primitive or a morph target reads as a vertex attribute whose elements do not each start
// on a multiple of 4 bytes (3.6.2.4 again; the validator's MESH_PRIMITIVE_ACCESSOR_UNALIGNED):
// draco's BoxMeta.gltf packs its UNSIGNED_BYTE and UNSIGNED_SHORT _FEATURE_ID_n tightly; copied
// with a byteStride of the element size rounded up to 4 (the padding bytes zero). Sparse accessors
// and data outside buffer 0 are left alone.
//
// exact_bounds: every accessor that has `min`/`max` gets the exact bounds of its values (raw
// component values: integers as stored, also when `normalized`; floats as float32; sparse
// substitutions applied), glTF 2.0 3.6.2.5; values already equal at the component's precision are
// left as written. Bounds of an accessor whose data lies outside buffer 0 are left alone.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadetool::io::gltf {

// Returns the number of accessors removed; notes: one line when something was pruned or could not be.
std::size_t prune_unreferenced(nlohmann::json& document, std::string& bytes, std::vector<std::string>& notes,
                               bool compact = false);

// Returns the number of accessors moved (named in one note per rule).
std::size_t align_accessors(nlohmann::json& document, std::string& bytes, std::vector<std::string>& notes);

// Returns the number of accessors whose min/max were corrected (named in one note).
std::size_t exact_bounds(nlohmann::json& document, const std::string& bytes, std::vector<std::string>& notes);

}  // namespace shadetool::io::gltf
