// obj_format.h: Wavefront OBJ reader and writer.
//
// Reading keeps: `v x y z [w]` and `v x y z r g b [a]` (vertex colours, float in [0,1]),
// `vn` (pool of corner normals, per-corner index), `vt u [v [w]]` (texcoord pool, per-corner
// index), `f` in the forms i, i/j, i//k, i/j/k with negative (relative) indices, polygons of any
// size, in order. Accepted and skipped: o, g, s, usemtl, mtllib, comments, blank lines, CRLF,
// trailing whitespace; other keywords (l, p, curves...) are skipped with a note.
// Precision: values are parsed in double; when no number has more significant digits than a float
// carries (9), the file is float data: values are rounded to float and Mesh::precision = Float.
//
// Writing: v [rgb(a)], vt, vn and f v/t/n. Normals: corner normals as a pool, else vertex normals
// (one vn per vertex), else face normals (one vn per face). Face colours have no OBJ form (note).
#pragma once

#include <string>
#include <string_view>

#include "core/mesh.h"
#include "io/mesh_io.h"

namespace shadetool::io {

Mesh read_obj(std::string_view bytes, const std::string& name, ReadInfo& info);
void write_obj(const Mesh& mesh, std::string& out, WriteInfo& info);

}  // namespace shadetool::io
