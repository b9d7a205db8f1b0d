// vertex_normals.h: one unit normal per vertex from the normals of its faces.
//
// n_v = normalise( sum over the corners of v of w_c n_f ), contributions per normals/weighting.h
// (Gouraud 1971; area; Thuermer & Wuethrich 1998; Max 1999). Polygons use
// their Newell normal and their own corner at v. Degenerate faces contribute nothing.
// Precision: contributions are computed in double either way. Double (default) sums in double;
// Float rounds each contribution once to float (area and max weights after one exact power-of-two
// scale per mesh, so meshes scaled to 1e-30 or 1e30 work) and sums in float; measured within 1e-3
// degree of Double (about 1e-5).
// Scale: a mesh scaled by any power of two that keeps its coordinates finite and normal gives
// bitwise the same normals, under every weighting and precision (2^-1000 .. 2^1000 tested): a mesh
// whose largest sampled coordinate lies outside [2^-32, 2^32) is computed on a copy scaled exactly by a
// power of two into [1, 2) (engine/mesh_scale.h), so no product of coordinates over- or underflows. Threads: for meshes of 32768+ faces the sum is split over TBB
// threads; the plain call plans the split itself for the angle and Max weightings (one bitmap
// pass over the corners per thread; it would cost half the area kernel, so area and uniform sum
// serially), a VertexNormalsPlan (vertex_normals_plan.h) made once splits every weighting and
// saves the planning on repeated calls. The result is bitwise the same either way
// and for any thread count (accumulate_by_vertex.h).
//
// Inputs:  mesh      positions #V by 3, faces (triangles or polygons): a Mesh, or a MeshView of
//                    arrays held elsewhere (core/mesh_view.h: e.g. NumPy arrays, used in place;
//                    the same code, so the same bits as a Mesh holding the same arrays)
//          weighting see normals/weighting.h (default Angle)
//          precision accumulation precision
// Output:  normals   #V by 3 flat array of unit normals
//          fallback_vertices  how many vertices had no valid face (isolated, or only degenerate
//          faces) or whose weighted sum cancelled, and got the documented fallback instead
//          (never NaN; see vertex_fallback.h)
//          degenerate_faces  faces that contributed nothing: without area by the one rule of
//          geometry/degenerate_face.h (face_area_kind: fewer than 3 corners, non-finite position,
//          zero area to 64 eps), the rule info counts and repair removes by (they also count
//          faces with a repeated index, which contribute here while they have area)
#pragma once

#include <cstddef>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/vertex_normals_plan.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct VertexNormals {
  std::vector<double> normals;
  std::size_t fallback_vertices = 0;
  std::size_t degenerate_faces = 0;
};

VertexNormals vertex_normals(const Mesh& mesh, Weighting weighting = Weighting::Angle,
                             Precision precision = Precision::Double);
VertexNormals vertex_normals(const MeshView& mesh, Weighting weighting = Weighting::Angle,
                             Precision precision = Precision::Double);

// The same into `out`, reusing the storage of out.normals when its capacity suffices (no
// allocation and no fresh pages to fault in: for callers that compute normals repeatedly, as
// OpenMesh's update_normals writes into its preallocated normal property). Every field of `out`
// is overwritten.
void vertex_normals(const Mesh& mesh, Weighting weighting, Precision precision, VertexNormals& out);
void vertex_normals(const MeshView& mesh, Weighting weighting, Precision precision, VertexNormals& out);

// The same with a plan of the mesh's connectivity made once (vertex_normals_plan.h): repeated calls
// on 2+ threads skip the per-call planning of the parallel sum. Same result bit for bit. Throws
// Error when the plan was built for other vertex/face/corner counts.
void vertex_normals(const Mesh& mesh, const VertexNormalsPlan& plan, Weighting weighting, Precision precision,
                    VertexNormals& out);
void vertex_normals(const MeshView& mesh, const VertexNormalsPlan& plan, Weighting weighting, Precision precision,
                    VertexNormals& out);

}  // namespace shadetool
#pragma GCC visibility pop
