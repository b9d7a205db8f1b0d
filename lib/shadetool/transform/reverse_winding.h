// reverse_winding.h: reverses the corner order of every face (a mirror's faces keep their
// orientation only if re-wound), with the per-corner attributes following their corners.
//
// Input/Output (in place):
//   mesh.corner_vertex          C uint32   corners of face f are [face_start[f], face_start[f+1])
//   mesh.corner_normal_index    0 or C     permuted exactly like corner_vertex
//   mesh.corner_texcoord_index  0 or C     permuted exactly like corner_vertex
// Every face (v0, v1, ..., v_{k-1}) becomes (v0, v_{k-1}, ..., v1): the cyclic order is reversed
// and the first corner stays first, so a face keeps its leading vertex (what a renderer's
// provoking-vertex convention and a reader of face lists see first); libigl's
// F.rowwise().reverse() gives (v_{k-1}, ..., v0), the same cycle rotated. Per-vertex and per-face arrays are not touched: they are not attached to corners.
// Faces with fewer than 3 corners (not produced by the readers) are reversed the same way.
// Corner-attribute arrays of a size other than 0 or C are an inconsistent mesh: Error.
#pragma once

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

void reverse_winding(Mesh& mesh);

}  // namespace shadetool
#pragma GCC visibility pop
