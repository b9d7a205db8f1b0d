// crease_paths.h: corner_normals with its path chosen by the caller (internal to lib/normals; for
// tests and benchmarks, which must reach each path whatever the mesh and the thread count).
//
// corner_normals (corner_normals.h) has two paths that give the same results bit for bit:
//   General    the vertex fans, grouped vertex by vertex (any mesh, any thread count);
//   OneThread  one pass in face order with a fixed slot per vertex; only the vertices it cannot
//              prove to be one smooth group go through General, on the sub-mesh of their faces.
//              Applies to triangle meshes without smoothing groups, Angle or Uniform weighting,
//              and crease angles where SmoothCone can pass a vertex (corner_normals.cpp); elsewhere
//              General runs.
// Auto (what corner_normals does): OneThread on one thread, for meshes of 50,000 faces or more,
// when a probe of a few windows of faces
// finds few vertices it would leave to General (and it did not find more than half of them hard
// after its pass), else General. OneThread here skips the probe and that limit (and ignores the
// thread count), so that tests can check it on every mesh.
// Inputs and outputs as corner_normals (no smoothing groups).
#pragma once

#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/weighting.h>

namespace shadetool::normals_detail {

enum class CreasePath { Auto, General, OneThread };

CornerNormals corner_normals_by(const MeshView& mesh, double crease_angle, Weighting weighting, Precision precision,
                                CreasePath path);

}  // namespace shadetool::normals_detail
