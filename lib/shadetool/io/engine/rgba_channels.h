// rgba_channels.h: colours gathered as 4 floats per element (r g b a, alpha 1 where the file gave
// none) packed into a Mesh's colour array of `channels` values per element (3: r g b; 4: r g b a),
// as Mesh::vertex_colors and Mesh::face_colors hold them. Shared by the readers that gather rgba
// first and decide the channel count after the last element (OBJ `v x y z r g b [a]`, OFF text
// and binary).
//
// Inputs:  rgba  4 floats per element; channels 3 or 4.
// Outputs: out   resized to (rgba.size() / 4) * channels, each element's first `channels` values.
// Degenerate input: an empty rgba gives an empty out.
#pragma once

#include <cstddef>
#include <vector>

namespace shadetool::io {

inline void pack_rgba(const std::vector<float>& rgba, int channels, std::vector<float>& out) {
  const std::size_t n = rgba.size() / 4, c = std::size_t(channels);
  out.resize(n * c);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < c; ++k) out[i * c + k] = rgba[4 * i + k];
}

}  // namespace shadetool::io
