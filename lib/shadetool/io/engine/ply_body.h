// ply_body.h (engine, not installed): the PLY body, element by element, by declared type.
//
// Inputs:  bytes   the whole file; header  parse_ply_header's result; layout  map_ply_properties's
//          name    for messages
// Output:  the Mesh: positions, faces and the attributes the layout keeps; every other element
//          is skipped by its declared types (a note counts it). Claimed counts are bounded by the
//          bytes left before anything is allocated. Binary vertex records of scalars and binary
//          triangle lists take fast paths (plain loads at fixed offsets) that read the same values.
//          Mesh::precision, colour channels and float-ness are set from the layout.
//          A `tristrips` element (PlyLayout::strips) becomes triangles: a -1 restarts a strip; odd
//          triangles of a strip are reordered to wind like the first (as VCG/MeshLab read them);
//          a triangle with a repeated index (a join between strips) is not kept; one note counts.
// Ascii:   read by tokens (an item is its properties' next values, wherever lines break: the
//          format's rule); when that fails, read again by lines (ply.c, Turk's reference reader,
//          reads an ascii item per line and ignores extra words: VCGLIB writes such files), and
//          that result kept if it reads, with one note per element naming how many lines held
//          values past the header's properties and the first; else the token reading's error.
//          The failed reading's notes are dropped. A file the token reading reads is unchanged.
// Faces:   a face item whose index list has fewer than 3 entries (0, 1 or 2) is not a face (Blender
//          drops it, assimp makes it a point or line): its indices are checked, then it is dropped
//          with its other properties (colours, normals, quality, extras, texcoord list), the kept
//          faces' values staying aligned; one note counts them.
// Errors:  truncated or malformed data, indices out of range,
//          data after the last element (`NAME:LINE: what` in ascii, `NAME: what` in binary); a
//          result without faces while another element holds a vertex_indices list (faces this
//          reader does not take).
#pragma once

#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/engine/ply_header.h>
#include <shadetool/io/engine/ply_properties.h>
#include <shadetool/io/mesh_io.h>

namespace shadetool::io::ply {

Mesh read_ply_body(std::string_view bytes, const PlyHeader& header, const PlyLayout& layout, const std::string& name,
                   ReadInfo& info);

}  // namespace shadetool::io::ply
