// degenerate_faces.h: removal of the faces that have no area or no well-defined winding. Which
// faces those are, and their counts, is geometry/degenerate_faces.h (the one count, which info
// uses too), included here for repair's callers.
//
// remove_faces: deletes the flagged faces, keeping the order of the others and every per-face and
// per-corner attribute (face normals and colours, corner normal and texcoord indices). Vertices
// are kept, even when no face uses them any more.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/geometry/degenerate_faces.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Returns the number of faces removed.
std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove);

}  // namespace shadetool
#pragma GCC visibility pop
