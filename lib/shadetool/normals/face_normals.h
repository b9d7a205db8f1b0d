// face_normals.h: one unit normal per face.
//
// Inputs:  mesh      positions #V by 3, faces (triangles or polygons): a Mesh, or a MeshView of
//                    arrays held elsewhere (core/mesh_view.h; used in place, the same code and bits)
//          precision accumulation precision
// Output:  #F by 3 flat array of unit normals. Triangles: cross product of the two shortest edges
//          (best conditioned for slivers); polygons: Newell's method. A face without area (geometry/degenerate_face.h,
//          face_area_kind: zero area to 64 eps, non-finite position, fewer than 3 corners) gets
//          (0, 0, 0), never NaN.
#pragma once

#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::vector<double> face_normals(const Mesh& mesh, Precision precision = Precision::Double);
std::vector<double> face_normals(const MeshView& mesh, Precision precision = Precision::Double);
// The same normals written into out (#F by 3 doubles, every entry written): for a caller that
// holds scratch memory of its own (corner_normals: unzeroed huge pages, core/bulk_reserve.h).
void face_normals(const MeshView& mesh, Precision precision, double* out);

}  // namespace shadetool
#pragma GCC visibility pop
