// obj_format.h: Wavefront OBJ reader and writer.
//
// Reading keeps: `v x y z [w]` (w, a curve's rational weight, is not read: positions are x y z
// as written, as Blender reads them; a note counts w other than 1) and `v x y z r g b [a]`
// (vertex colours, float in [0,1]),
// `vn` (pool of corner normals, per-corner index), `vt u [v [w]]` (texcoord pool, per-corner
// index), `f` in the forms i, i/j, i//k, i/j/k with negative (relative) indices, polygons of any
// size, in order. An empty vt or vn field (`1/`, `1//`, `1/1/`) is absent (tinyobjloader, assimp,
// trimesh). Accepted and skipped: o, g, s, usemtl, mtllib, comments, blank lines, CRLF,
// trailing whitespace; other keywords (l, p, curves...), `f` with no index and `f` with 1 or 2
// vertices (not a face; nothing of it kept) are skipped with one note counting each kind. vt or
// vn lines no face references are not read (a note counts them).
// A line ending in `\` (spaces after it allowed) continues its statement on the next line (the
// OBJ spec; trimesh and Blender read it so), comment lines included; messages count every line.
// The test is made only where a reader finds a `\` where it wanted a token (its error path) or
// in text a reader left on its line, so ordinary lines pay nothing. Continued grouping
// statements are kept as one line.
// A `vt` or `vn` index on a face corner while the file has defined no `vt` (`vn`) line before it
// (OpenSubdiv's shapes write `f v/vt/vn` with neither) is ignored, counted in one note, as assimp
// does; an index beyond a pool that does have entries is still an error naming the line.
// Reading in parallel: files of 4 MiB or more are cut into chunks at line feeds; a counting pass
// (io/engine/obj_statement_counts.h: bit masks of 64-byte blocks, which also find CR and NUL bytes:
// text with a CR is converted to LF and counted again, a NUL refused with its line) gives each
// chunk the number of v, vt, vn, faces, corners and lines before it, then every chunk is
// parsed into its place in the mesh's arrays at once, relative (negative) indices and ranges
// resolved against the whole file's counts; grouping statements, colours and per-corner vn/vt are
// merged in file order. The mesh is the same bit for bit as one pass gives, and so is the error
// (the first in the file, with its line). Chunks are never cut after a line ending in `\`. Text
// the two passes count differently (a face continued on the next line, an `f` of 2 vertices) is
// read in one pass instead.
// Steps: read the lines (read_lines), validate, build the corner normals, texture coordinates and
// vertex colours from the pools, then note what was skipped.
// Precision: every value is stored as parsed, the double nearest to the text, never rounded to
// float: `v 123456.789 0 0` keeps 123456.789. Mesh::precision is Float when no number has more
// significant digits than a float carries (9), else Double; it is only the hint for the value type
// binary writers use (PLY float or double properties).
//
// Writing: each value in the shortest text that reads back to it (io/engine/number_text.h: a value that
// is exactly a float prints as the shortest float, 0.1f as "0.1"; any other as the shortest
// double, at most 17 significant digits). v [rgb(a)], vt, vn and f v/t/n. Normals: corner normals
// as a pool, else vertex normals (one vn per vertex), else face normals (one vn per face).
// Face colours (flat shading) have no OBJ form of their own: vertices are split so that every
// corner's vertex carries its face's colour as `v x y z r g b [a]` (io/split_face_colors.h; a
// vertex whose faces share one colour is not split). Faces, their order and corner order are
// unchanged, normals and texcoords stay per corner; WriteInfo::split_vertices counts the vertices
// added, and a note says so. Vertex colours, if the mesh also has them, give way (note).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/byte_sink.h>
#include <shadetool/io/mesh_io.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

// How the reader splits its work; the mesh read never depends on it (tests/io/obj_format.cpp reads
// every file with chunks forced small and compares).
struct ObjReadOptions {
  // Bytes per chunk of lines read in parallel (cut at line feeds); 0: the file in one pass on one
  // thread or below 4 MiB, else chunks of decreasing size for the threads of the current TBB arena
  // (each a 1 / (2 * threads) share of what is left, at least 1 MiB).
  std::size_t chunk_bytes = 0;
};

Mesh read_obj(std::string_view bytes, const std::string& name, ReadInfo& info);
Mesh read_obj(std::string_view bytes, const std::string& name, ReadInfo& info, const ObjReadOptions& options);
void write_obj(const Mesh& mesh, ByteSink& out, WriteInfo& info);

}  // namespace shadetool::io
#pragma GCC visibility pop
