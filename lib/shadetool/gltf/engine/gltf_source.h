// gltf_source.h (engine, not installed): what read_gltf keeps of a glTF file for the writer: the
// JSON as read (passed through) and the tinygltf model (buffers loaded, images' bytes as read).
#pragma once

#include <string>

#include <nlohmann/json.hpp>
#include <shadetool/gltf/engine/tinygltf.h>

#include <shadetool/gltf/gltf_document.h>

namespace shadetool {

struct GltfSource {
  std::string name;             // the input's path, for messages
  nlohmann::json json;          // the document as read
  tinygltf::Model model;        // buffers[i].data loaded; images[i].image = the file's bytes
  bool compact_buffers = false; // compressed bytes were decoded: the writer drops what no view holds
};

}  // namespace shadetool
