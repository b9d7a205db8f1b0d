// off_binary.h: the body of a binary OFF file (`[ST][C][N]OFF BINARY`), in the two layouts that
// programs write.
//
// What it computes: the Mesh held by the bytes that follow the header line, read by read_off
// (off_format.h) when the keyword is followed by BINARY.
//
// Layouts. Geomview's OFF specification (geomview.org/docs/html/OFF.html, "binary format"): after
// the header line, 32-bit big-endian integers #V #F #E; per vertex 32-bit floats x y z, then
// nx ny nz (N), then r g b a (C), then s t (ST); per face an integer k, k integer vertex indices
// (0-based), an integer ncolors and ncolors values (0: none; 1: a colormap index, an integer;
// 3 or 4: floats r g b [a] in [0,1]). pmp-library writes faces without ncolors (k and the
// indices only), big-endian since 3.0 and in the machine's byte order (little-endian) before
// (pmp's read_off_binary reads both; its data/off/beetle.off and fairing-cross.off are the
// little-endian kind).
// The four readings (big/little-endian, with/without ncolors) are tried in that order; the first
// that ends exactly at the end of the file with every index in range and every face size and colour
// count valid is the file's layout. Different layouts cannot both pass on a real file: the vertex
// block and every face's size tie the body's length to its counts. None passing: an error naming
// the file, and the byte offset and reason of the big-endian specification reading.
//
// Inputs:  body  the bytes after the header line's '\n'; header_bytes its length (for offsets in
//          messages); has_st/has_c/has_n the keyword's flags; name the file for messages.
// Outputs: Mesh with positions (#V by 3), vertex_normals (N), vertex_colors (C, 4 floats read as
//          rgba, alpha 1 everywhere read as rgb), texcoords per corner (ST), face_colors (3 or 4
//          floats), precision Float (every value is a 32-bit float). Notes in info: faces of fewer
//          than 3 indices dropped (as the text reader), colormap-index face colours not read.
// Precision: float32 values widened to double exactly.
// Degenerate input: counts are bounded by the body's size before any allocation; a face of k < 3
// indices is checked, then dropped with its colour and counted in a note.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/mesh_io.h>

namespace shadetool::io {

struct OffBinaryFlags {
  bool has_st = false, has_c = false, has_n = false;
};

Mesh read_off_binary_body(std::string_view body, std::size_t header_bytes, OffBinaryFlags flags, const std::string& name,
                          ReadInfo& info);

}  // namespace shadetool::io
