// gltf_source.h (engine, not installed): what read_gltf keeps of a glTF file for the writer: the
// JSON as read (passed through) and the tinygltf model (buffers loaded, images' bytes as read).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>
#include <shadetool/gltf/engine/tinygltf.h>

#include <shadetool/gltf/gltf_document.h>
#include <shadetool/io/file_bytes.h>

namespace shadetool {

struct GltfSource {
  std::string name;             // the input's path, for messages
  nlohmann::json json;          // the document as read
  tinygltf::Model model;        // buffers[i].data loaded (but see bin_buffer); images[i].image = the file's bytes
  bool compact_buffers = false; // compressed bytes were decoded: the writer drops what no view holds
  // A GLB read from a file the reader was given (read_gltf(io::FileBytes&&)): the buffer held by
  // the BIN chunk is read where it lies in `file` (no copy into model.buffers[bin_buffer].data,
  // which stays empty); -1 when every buffer is in the model.
  io::FileBytes file;
  long bin_buffer = -1;
  std::string_view bin;         // its byteLength bytes, in `file`

  // The bytes of buffer b (b < model.buffers.size()).
  std::string_view buffer_bytes(std::size_t b) const {
    if (long(b) == bin_buffer) return bin;
    const std::vector<unsigned char>& d = model.buffers[b].data;
    return {reinterpret_cast<const char*>(d.data()), d.size()};
  }
};

}  // namespace shadetool
