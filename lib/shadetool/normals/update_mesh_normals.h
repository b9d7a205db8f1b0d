// update_mesh_normals.h: what `shadetool normals` does to one mesh, as a library call: keep the
// normals a mesh already has, or compute the kind asked for and store it in the mesh.
//
// Inputs:  mesh     positions, faces, and any normals read from the file
//          request  kind (vertex, corner with crease angle, face), weighting, precision, recompute
// Output:  mesh     normals stored (see below)
//          report   what happened, with counts
//
// Policy (the command's contract, issue 4):
//   - "Existing normals" are those of the kind asked for: shading normals (vertex or corner
//     normals, e.g. OBJ `vn`, PLY vertex nx ny nz) for kinds Vertex and Corner; face normals
//     (e.g. STL facets, PLY face nx ny nz) for kind Face.
//   - Without `recompute`, existing normals are kept bitwise and nothing is computed
//     (report.kept). If any of them is invalid (NaN, Inf or zero length; count_invalid_normals),
//     nothing is changed and report.invalid_existing says how many: the caller refuses the input.
//     For corner normals, a corner whose index points outside the pool also counts as invalid.
//   - Otherwise the kind asked for is computed and stored: Vertex -> mesh.vertex_normals (corner
//     normals removed); Corner -> mesh.corner_normals + corner_normal_index (vertex normals
//     removed); Face -> mesh.face_normals, with kFallbackNormal (0,0,1) for degenerate faces
//     (counted in report.fallback), and any shading normals are removed (report.dropped)
//     because OBJ can carry only one kind and `--faces` asks for face normals.
//   - With `recompute`, every normal in the input (all kinds) is discarded first.
//   - A two-sided surface (two_sided_faces.h: a face and its reverse on the same vertices) would
//     sum to noise: Vertex normals are computed from the front faces only (the earlier face of
//     each pair), so both sides' corners share the front's normal; Corner normals are computed
//     from the front faces and each back face's corner gets its front's corner normal reversed
//     (each side shades as itself; PLY/OFF writers split those vertices). report.two_sided_faces
//     counts the back faces.
//   - Normals of the other kind that are not in the way (face normals when shading normals are
//     computed) are passed through unchanged.
#pragma once

#include <cstddef>
#include <string>

#include <shadetool/core/mesh.h>
#include <shadetool/normals/ranked_normals.h>
#include <shadetool/normals/smoothing_groups.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class NormalKind { Vertex, Corner, Face };

struct NormalsRequest {
  NormalKind kind = NormalKind::Vertex;
  Weighting weighting = Weighting::Angle;
  double crease_angle = 0.0;  // radians, kind Corner only
  Precision precision = Precision::Double;
  bool recompute = false;
  // Honour: when the mesh's file has smoothing groups that matter (normals/smoothing_groups.h),
  // kinds Vertex and Corner compute corner normals that never join faces of different groups and
  // keep `s off` faces flat (crease_angle splits further inside a group; pi for kind Vertex).
  SmoothingGroups smoothing_groups = SmoothingGroups::Honour;
  // Blender's Weighted Normal modes instead of `weighting` (normals/ranked_normals.h): kind Vertex
  // one normal per vertex, kind Corner keep sharp at crease_angle (its crease_angle is set here).
  // Smoothing groups are not honoured with them.
  bool ranked = false;
  RankedWeightingOptions ranked_options;
  // Kinds Vertex and Corner: a vertex (smooth group) whose faces all lie in one plane gets exactly
  // that plane's normal (normals/flat_patches.h).
  bool flat_patches = false;
};

struct NormalsReport {
  bool kept = false;                  // existing normals kept, nothing computed
  std::string kept_what;              // "vertex normals", "corner normals", "face normals"
  std::size_t existing = 0;           // how many existing normals of the asked kind (rows)
  std::size_t invalid_existing = 0;   // of those, NaN/Inf/zero (mesh left unchanged if > 0)
  std::size_t computed = 0;           // normals computed (rows stored)
  std::size_t fallback = 0;           // vertices (Vertex), corners (Corner), faces (Face) given the fallback
  std::size_t degenerate_faces = 0;   // faces with no normal (zero area, repeated index, NaN)
  std::size_t dropped = 0;            // shading normals removed for kind Face
  std::size_t discarded = 0;          // normals discarded by `recompute` (rows, all kinds)
  std::size_t two_sided_faces = 0;    // back faces of a two-sided surface (two_sided_faces.h)
  std::size_t flat_patches = 0;       // normals replaced by their plane's (flat_patches)
  bool honoured_groups = false;       // corner normals split by the file's smoothing groups
  std::size_t smoothing_groups = 0;   // distinct groups (s N), when honoured
  std::size_t flat_faces = 0;         // faces in no group (s off, s 0), when honoured
};

NormalsReport update_mesh_normals(Mesh& mesh, const NormalsRequest& request);

}  // namespace shadetool
#pragma GCC visibility pop
