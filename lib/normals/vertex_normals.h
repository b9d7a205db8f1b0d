// vertex_normals.h: one unit normal per vertex from the normals of its faces.
//
// n_v = normalise( sum over the corners of v of w_c n_f ), weights per normals/weighting.h and
// corner_contributions.h (Gouraud 1971; area; Thuermer & Wuethrich 1998; Max 1999). Polygons use
// their Newell normal and their own corner at v. Degenerate faces contribute nothing.
// Precision: Double (default) computes and sums in double. Float forms each edge vector in double,
// rounds it once, and computes and sums in float (angles: double in both); measured within 1e-3
// degree of Double (about 1e-5). Threads: TBB over face chunks for meshes of 32768+ faces; the
// result is bitwise the same for any thread count (accumulate_by_vertex.h).
//
// Inputs:  mesh      positions #V by 3, faces (triangles or polygons)
//          weighting see normals/weighting.h (default Angle)
//          precision accumulation precision
// Output:  normals   #V by 3 flat array of unit normals
//          fallback_vertices  how many vertices had no valid face (isolated, or only degenerate
//          faces) or whose weighted sum cancelled, and got the documented fallback instead
//          (never NaN; see vertex_fallback.h)
//          degenerate_faces  faces that contributed nothing (zero area, repeated index, fewer than
//          3 corners, non-finite position)
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh.h"
#include "normals/weighting.h"

namespace shadetool {

struct VertexNormals {
  std::vector<double> normals;
  std::size_t fallback_vertices = 0;
  std::size_t degenerate_faces = 0;
};

VertexNormals vertex_normals(const Mesh& mesh, Weighting weighting = Weighting::Angle,
                             Precision precision = Precision::Double);

}  // namespace shadetool
