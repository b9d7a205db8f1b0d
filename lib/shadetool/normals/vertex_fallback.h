// vertex_fallback.h: the normal a vertex gets when its weighted sum cannot be normalised.
//
// Inputs:  mesh       positions #V by 3, faces (a Mesh or a MeshView, core/mesh_view.h)
//          vertices   indices of the vertices whose sum was zero or not finite (ascending)
//          precision  precision of face_normals used for the fallback
// Output:  normals    #V by 3; rows listed in `vertices` are overwritten with
//                     - the unit normal of the vertex's first valid face (lowest face index),
//                       when it has one (its contributions cancelled, e.g. a two-sided sheet);
//                     - kFallbackNormal = (0, 0, 1) otherwise (isolated vertex, or every face
//                       around it is degenerate).
// Never NaN. Cost O(#corners), paid only when some vertex needs it.
#pragma once

#include <cstdint>
#include <vector>

#include <shadetool/core/fallback_normal.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

void apply_vertex_fallback(const MeshView& mesh, const std::vector<std::uint32_t>& vertices, Precision precision,
                           std::vector<double>& normals);

}  // namespace shadetool
#pragma GCC visibility pop
