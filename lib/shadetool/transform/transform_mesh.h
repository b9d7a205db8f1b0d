// transform_mesh.h: applies an affine map p -> A p + t to a mesh: positions, normals (vertex,
// corner and face), and the winding of a mirror's faces, doing only the work the map needs.
//
// Inputs:  mesh     positions #V by 3 (finite: Error otherwise; Error too when the map sends a
//                   position beyond double's range, the mesh then left partly transformed),
//                   faces, optional normals
//          M        the map (A 3 by 3, t 3 by 1), finite
//          options  normals: Transform (default) | Recompute | Drop
//          name     the input's name for messages
// Output:  mesh, in place; TransformReport (the path taken and counts)
//
// Formulas (see transform_normals.h for the derivation and its sources):
//   positions  p' = A p + t                               (double; A p skipped when A = I)
//   normals    n' = sign(det A) cof(A) n, normalised      (cof(A) = det(A) A^-T)
//   winding    reversed (reverse_winding.h) when det A < 0, so that faces keep their orientation
//              and the transformed normals agree with normals recomputed from the new faces.
// Paths (classify_affine.h states the tolerances):
//   identity       nothing is touched (a copy)
//   translation    positions only; normals and faces untouched, their bytes equal
//   rotation       normals multiplied by A, not renormalised
//   uniform-scale  normals multiplied by A / s, not renormalised
//   general        signed cofactor, normalised
//   singular       Error unless normals are dropped or recomputed (no reliable normal transform;
//                  the winding is still reversed when det A < 0)
// Recompute: after positions and winding, the normals present are recomputed from the new faces
// (recompute_normals.h). Drop: every normal array is cleared.
// Tangents held as vertex properties tx ty tz tw (normals/tangent_vertices.h, PLY) follow the map
// as tangents do: t' = A t, normalised, w' = sign(det A) w (a mirror flips the bitangent). With
// normals transformed, t' stays orthogonal to n' = sign(det A) cof(A) n, since
// (A t) . (cof(A) n) = det(A) (t . n) = 0; after a map that is no similarity it is no longer the
// MikkTSpace frame of the new mesh (the CLI says so). When the normals are recomputed or dropped,
// or the map is singular, the tangents no longer belong to the normals: they are removed
// (tangents = "dropped"). A zero or non-finite tangent, or one A sends to zero, is left as read.
// A zero or non-finite input normal is left exactly as read (and counted), never turned into NaN.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/core/mesh.h>
#include <shadetool/transform/classify_affine.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class NormalsPolicy { Transform, Recompute, Drop };
// Its vocabulary (core/vocabulary.h): "transform", "recompute", "drop" (--normals).
NormalsPolicy parse_normals_policy(std::string_view text, const std::string& what);
const char* normals_policy_name(NormalsPolicy policy);
std::vector<std::string> normals_policy_names();

struct TransformOptions {
  NormalsPolicy normals = NormalsPolicy::Transform;
};

struct TransformReport {
  AffineClass affine;                 // path, mirror, det, relative_det
  bool winding_reversed = false;      // det A < 0 and the mesh has faces: every face re-wound
                                      // (false for a mesh without faces: nothing was reversed)
  const char* normals = "none";       // "none" (the mesh had none), "untouched", "transformed",
                                      // "recomputed", "dropped"
  std::size_t normals_mapped = 0;     // normal vectors multiplied (vertex + corner pool + face)
  std::size_t normals_left = 0;       // zero or non-finite input normals left as read
  std::size_t fallback_normals = 0;   // Recompute: vertices / corner groups with no valid face
  const char* tangents = "none";      // vertex properties tx ty tz tw: "none", "untouched",
                                      // "mapped", "dropped"
  std::size_t tangents_mapped = 0;
};

TransformReport transform_mesh(Mesh& mesh, const Affine3d& M, const TransformOptions& options = {},
                               const std::string& name = "");

// The Error message for a singular map (shared with the command line, which checks the flags
// before reading any file).
std::string singular_map_message(const AffineClass& c);

}  // namespace shadetool
#pragma GCC visibility pop
