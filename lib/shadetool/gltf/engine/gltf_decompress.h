// gltf_decompress.h (engine, not installed): compressed glTF geometry decoded into plain
// accessors, so that every command reads it and the writer writes it uncompressed.
//
//   KHR_draco_mesh_compression (Draco, Debian libdraco-dev): a primitive's extension names a
//     bufferView holding one Draco mesh and maps each attribute name to a Draco attribute by its
//     unique id (`attributes: {"POSITION": 2, ...}`: the map decides, not the order). The decoded
//     corners fill the primitive's `indices` accessor and each attribute its accessor, in the
//     accessor's own componentType and type (Draco converts), one element per Draco point; the
//     accessors' counts must agree with the decoded mesh.
//   EXT_meshopt_compression (meshoptimizer, Debian libmeshoptimizer-dev): a bufferView's
//     extension names the compressed bytes (buffer, byteOffset, byteLength), the element size
//     (byteStride), `count`, `mode` (ATTRIBUTES: meshopt_decodeVertexBuffer; TRIANGLES:
//     meshopt_decodeIndexBuffer; INDICES: meshopt_decodeIndexSequence) and `filter` (NONE,
//     OCTAHEDRAL, QUATERNION, EXPONENTIAL: meshopt_decodeFilter*); the decoded bytes replace the
//     view's own (in its "fallback" buffer, which may have no uri and no bytes).
//
// After decoding, both extensions are gone from the JSON (primitives, bufferViews,
// extensionsUsed, extensionsRequired); the compressed bytes are left unreferenced for the writer
// to prune. Bad data: Error naming the file and the JSON path and the decoder's reason.
#pragma once

#include <string>
#include <vector>

#include "gltf_source.h"

namespace shadetool::io::gltf {

// What prepare_compressed changed for the loader, for decode_compressed to undo.
struct CompressedPlan {
  std::vector<std::size_t> fallback_lengths;  // per buffer: a meshopt fallback's true byteLength, or 0
  struct DracoIndices {
    std::size_t mesh, primitive;
    int accessor;
  };
  std::vector<DracoIndices> draco_indices;  // per Draco primitive: its `indices` when hidden from the
                                            // loader (an accessor without a bufferView), else -1
};

// Before tinygltf loads the JSON: a meshopt fallback buffer without a uri gets a 4-byte data URI
// in source.json (tinygltf refuses a buffer without bytes); a Draco primitive's extension and its
// `indices` (an accessor without a bufferView, which tinygltf refuses) are left out of the text
// given to the loader (a tinygltf built with Draco support would otherwise decode it itself). Returns that text, or "" when the JSON as read can be loaded as it is.
std::string prepare_compressed(GltfSource& source, CompressedPlan& plan);

// After loading: decodes every meshopt bufferView and every Draco primitive in source.model and
// source.json; notes: one line per extension decoded.
void decode_compressed(GltfSource& source, const CompressedPlan& plan, std::vector<std::string>& notes);

}  // namespace shadetool::io::gltf
