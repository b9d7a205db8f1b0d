// recompute_normals.h: replaces the normals a mesh carries by normals computed from its faces
// (`--normals recompute`: after a transform the faces are the truth, the old normals are not).
//
// Input/Output (in place), only the kinds present in the input are recomputed:
//   face_normals   #F by 3   normals/face_normals.h (unit; a degenerate face gets 0 0 0)
//   vertex_normals #V by 3   normals/vertex_normals.h, angle weighting (the library's default:
//                            independent of how the surface is triangulated)
//   corner normals           the smoothing groups of the input are kept: corners of one vertex
//                            that shared one pool normal still share one. Each group's normal is
//                            normals/corner_normals.h's corner_group_normals, angle weighting
//                            (Thuermer & Wuethrich 1998, as for vertex normals). The pool is
//                            rebuilt with one entry per (vertex, old pool index) group, in order
//                            of first use; corner_normal_index is renumbered accordingly.
// Returns the number of vertices / corner groups that had no valid face (degenerate faces only:
// geometry/degenerate_face.h) and got the fallback: for a vertex, the normals library's
// documented fallback; for a corner group, its vertex's recomputed normal.
//
// Precision: double accumulation (the normals library's Precision::Double).
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::size_t recompute_normals(Mesh& mesh);

}  // namespace shadetool
#pragma GCC visibility pop
