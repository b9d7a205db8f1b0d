// gltf_transform.h: what transform_mesh (lib/transform) cannot see of a glTF primitive: its
// TANGENT attribute and its morph targets' deltas, mapped by the same affine map.
//
// Inputs:  primitive  a GltfPrimitive (gltf/gltf_document.h): tangents #V by 4, targets' deltas
//                     #V by 3; primitive.mesh.vertex_normals #V by 3 = the base normals BEFORE the
//                     map (call this before transform_mesh)
//          M          the map p -> A p + t (t does not act on tangents or deltas: they are vectors)
//          drop_normals  the command drops normals: NORMAL deltas are dropped too, and a TANGENT
//                        beside a NORMAL is removed with it (drop_tangents; glTF 2.0 3.7.2.1: a
//                        reader ignores tangents without normals)
// Output:  primitive, in place. Formulas (the functions of lib/transform, not copies):
//   TANGENT xyz   t' = A t (transform_vector), renormalised (length checked; a zero or non-finite
//                 tangent is left as read); w' = -w when det A < 0 (a mirror swaps handedness:
//                 with n' = sign(det A) cof(A) n, n' x t' = -A (n x t) for an orthogonal mirror)
//   POSITION delta d' = A d
//   TANGENT delta  d' = A d
//   NORMAL delta   d' = N(n + d) - N(n), N = the normal map of transform_normals.h (sign(det A)
//                  cof(A), normalised on the general path): the displaced normal maps as a normal.
// Double precision throughout; the singular map leaves tangents and normal deltas as read (the
// command refuses it where normals are transformed).
//
// mapped_tangents_stay_mikktspace(path): whether the mapped frame (A t, w flipped under a mirror)
//   of a MikkTSpace frame is the MikkTSpace frame of the mapped mesh, so that the mapped TANGENT
//   may be kept. True for the similarities (Identity, Translation, Rotation with or without a
//   mirror, UniformScale): MikkTSpace's steps (projection of dP/du onto the plane of the vertex
//   normal, normalisation, corner-angle-weighted sums) commute with s Q. False for General: it
//   changes corner angles, and A does not keep the projection onto the normal's plane (A n is not
//   along cof(A) n), so the frames must be recomputed from the mapped normals (the transform
//   command does, with a note; tests/gltf/gltf_tangents.cpp checks both against the reference
//   MikkTSpace). False for Singular (no frame survives).
#pragma once

#include <cstddef>

#include <shadetool/core/affine.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/transform/classify_affine.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct GltfTransformReport {
  std::size_t tangents = 0;        // tangents mapped
  std::size_t tangents_left = 0;   // zero or non-finite tangents left as read
  std::size_t target_deltas = 0;   // delta vectors mapped
  bool tangents_dropped = false;   // TANGENT removed with NORMAL (drop_normals)
};

GltfTransformReport transform_gltf_extras(GltfPrimitive& primitive, const Affine3d& M, bool drop_normals);

bool mapped_tangents_stay_mikktspace(TransformPath path);

}  // namespace shadetool
#pragma GCC visibility pop
