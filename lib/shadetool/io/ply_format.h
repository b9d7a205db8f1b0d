// ply_format.h: Stanford PLY reader and writer (ascii, binary little- and big-endian).
//
// Reading: element `vertex` with x y z, nx ny nz, red green blue [alpha] (uchar -> c/255, or
// float as is; also diffuse_red...), texture coordinates s t / u v / texture_u texture_v;
// element `face` with list vertex_indices or vertex_index (any integer count and item types),
// nx ny nz (face normals), red green blue [alpha] (face colours), list texcoord (per-corner
// u v pairs, MeshLab's wedge texcoords); a face of fewer than 3 vertices is skipped with its
// properties (a note counts them). Any other element or property is skipped by its
// declared type. Counts in the header are checked against the size of the body before anything
// is allocated, so a header claiming 2^40 vertices fails at once.
// Precision: Mesh::precision is Double if any kept vertex value (x y z, normals, texcoords) is
// declared double (or a 32-bit integer), else Float. Binary values are the declared type's values;
// ascii values are stored as parsed (the double nearest to the text), never rounded to the
// declared float: the text is what the file says.
//
// Writing: binary little-endian (default) or ascii; x y z and normals as float or double after
// Mesh::precision (binary float narrows each value to float; ascii prints the shortest text that
// reads back to the stored value, io/engine/number_text.h), colours as uchar or float after Mesh::colors_are_float; per-corner normals are
// split into vertices (WriteInfo::split_vertices); face normals and face colours as face
// properties; per-corner texcoords as a face list `texcoord` (as MeshLab writes them), except
// that coordinates read per vertex (Mesh::texcoord_names) are written per vertex under the same
// names whenever every corner of each vertex has the same coordinates (no vertex to split).
// read_ply also reads a `tristrips` element (list vertex_indices, -1 restarting a strip) when the
// file has no face element, as MeshLab does: see io/engine/ply_properties.h and ply_body.h.
// A file whose faces are in an element it cannot read (faceless otherwise) is refused.
// write_ply's steps: plan (what is written, notes), header, vertex records, face records.
#pragma once

#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/byte_sink.h>
#include <shadetool/io/mesh_io.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

Mesh read_ply(std::string_view bytes, const std::string& name, ReadInfo& info);
void write_ply(const Mesh& mesh, bool binary, ByteSink& out, WriteInfo& info);

}  // namespace shadetool::io
#pragma GCC visibility pop
