// stl_format.h: STL reader and writer (ascii and binary).
//
// Reading: binary when the size is exactly 84 + 50 * (triangle count in the header); ascii when
// the file starts with `solid` (several solids, and loops of more than 3 vertices, are kept);
// any other file is refused, a binary file whose size disagrees with its count as truncated, and a
// file that starts as ascii (lines of text with a facet) and then holds a control byte, at the
// line of that byte (an ascii file cut or overwritten; OpenSCAD's unparseable.stl).
// STL stores a triangle soup: corners with identical positions (equal as values; -0 equals 0,
// NaN equals nothing) are merged into one vertex, in order of first appearance; the number merged
// is ReadInfo::merged_vertices (and a note). Facet normals are kept as face normals unless all are
// zero; zero, NaN/Inf and against-the-winding ones are replaced by the triangle's own (a note);
// all are when the median facet is more than 45 degrees from its triangle's own (normals in
// another frame: Meshmixer's Y-up), with a note. Binary STL is float (Mesh::precision = Float); ascii values are stored as parsed, never
// rounded, and Mesh::precision follows the digit rule of OBJ (a hint for binary writers).
// Merging uses an open-addressing hash table in flat arrays (no per-vertex allocation).
// Binary colours: the attribute bytes are read as face colours when the header marks Materialise's
// convention ("COLOR=" + default R G B A; bit 15 clear: own colour R bits 0-4, G 5-9, B 10-14 of 31;
// set: the default); unmarked non-zero attribute bytes are not read, and a note counts them.
//
// Writing: binary (default) or ascii; polygons are split into triangles inside their outline
// (geometry/polygon_triangles.h: ear clipping; a convex polygon gives the fan from corner 0; a note
// says how many polygons); each facet normal is the face normal if the mesh has them, else the unit normal of
// the triangle (cross product of its edges, (0,0,0) for a zero-area triangle). Vertex normals,
// colours and texcoords have no STL form (notes). No vertices are split (split_vertices = 0).
#pragma once

#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/byte_sink.h>
#include <shadetool/io/mesh_io.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

Mesh read_stl(std::string_view bytes, const std::string& name, ReadInfo& info);
void write_stl(const Mesh& mesh, bool binary, ByteSink& out, WriteInfo& info);

}  // namespace shadetool::io
#pragma GCC visibility pop
