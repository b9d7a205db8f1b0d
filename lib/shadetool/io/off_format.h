// off_format.h: Geomview OFF reader and writer (OFF, COFF, NOFF, CNOFF, STOFF...).
//
// Reading: an optional header keyword [ST][C][N]OFF (4OFF and nOFF are refused; `[ST][C][N]OFF
// BINARY` on the first line is read by io/off_binary.h, Geomview's and pmp-library's layouts),
// then `#V #F [#E]` (on the keyword's line or the next; a digit right after the keyword, `OFF8 6 12`,
// starts the counts, as trimesh reads it: no variant's keyword ends in a digit), #V vertex lines `x y z [nx ny nz] [r g b [a]] [s t]` and #F face lines
// `k i_1 ... i_k [r g b [a]]` (0-based indices, polygons kept; a line with k < 3 is not a face:
// its indices are checked, then it is dropped with its colour, and a note counts such lines). Colours written as integers are
// 0..255 and divided by 255; colours with a decimal point or exponent are taken as floats in [0,1].
// Four components whose alpha is 1 everywhere read as rgb (Mesh::color_channels 3): the writer
// gives rgb colours alpha 1.
// Comments (#) and blank lines are skipped anywhere. CR, LF and CRLF line endings, a UTF-8 BOM. Each vertex and face is one line,
// except that a face's indices may go on over the following lines (Geomview's OFF is free-format;
// libigl's readOFF reads indices with fscanf; libigl-tutorial-data writes some files one index a
// line), its colour then following the last index on that line; a line with
// the wrong number of values, or content after the last face, means the header counts disagree
// with the body and is an error. Counts are bounded by the file size before allocation.
// Precision: as OBJ (obj_format.h): values stored as parsed, never rounded; Mesh::precision is
// Double when a number has more than 9 significant digits (the binary writers' value-type hint).
//
// Writing: values in the shortest text that reads back to them (io/engine/number_text.h); `[C][N]OFF`
// (C with vertex colours, N with vertex normals; per-corner normals are split into vertices,
// WriteInfo::split_vertices); face colours after the indices (native in any OFF: no split).
// Colours as floats when Mesh::colors_are_float, always with a decimal point ("1.0") so that they
// cannot read back as 0..255 integers; else integers 0..255. Always four components r g b a
// (alpha 1 for rgb meshes): assimp and MeshLab read COFF colours as four. Face normals and
// texcoords have no OFF form (notes).
#pragma once

#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/byte_sink.h>
#include <shadetool/io/mesh_io.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

Mesh read_off(std::string_view bytes, const std::string& name, ReadInfo& info);
void write_off(const Mesh& mesh, ByteSink& out, WriteInfo& info);

}  // namespace shadetool::io
#pragma GCC visibility pop
