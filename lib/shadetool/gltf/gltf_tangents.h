// gltf_tangents.h: a primitive's TANGENT kept in step with its NORMAL (glTF 2.0, 3.7.2.1: "When
// tangents are not specified, client implementations SHOULD calculate tangents using default
// MikkTSpace algorithms"; a normal map baked against MikkTSpace shades correctly only with them).
//
// gltf_texcoords: TEXCOORD_0 of a primitive as read (#V by 2, glTF's v down), or empty when it has
//   none or a command changed its vertex count (then `changed` is set). Error when it is not one
//   VEC2 per vertex.
// gltf_update_tangents: after a command changed a primitive's normals, its tangent frames by
//   MikkTSpace (normals/tangents.h) from the new normals, POSITION and TEXCOORD_0 as read, when the
//   primitive has TANGENT, or its material a normalTexture, or `add` (--tangents). The frames go to
//   GltfPrimitive::corner_tangents (#C by 4; the writer splits vertices where a vertex's corners
//   differ and writes TANGENT). w is the reference's negated: MikkTSpace runs on TEXCOORD_0 as
//   read, whose v runs down, and glTF's bitangent points along +v of the image's bottom-left
//   convention (checked on Khronos samples whose tangents Blender wrote: every authored w is the
//   negated raw w).
//   Returns a note for the user, without the primitive's path ("" when nothing was needed): recomputed, added, or why not
//   (no TEXCOORD_0: no tangents; a stale TANGENT is then removed, never written beside new normals).
// gltf_world_tangents: a document written to another format becomes one world-space mesh
//   (gltf_world_mesh); when any of its primitives carries tangents (TANGENT as read, or frames a
//   command computed), `world` gets MikkTSpace frames of its own (computed on the merged, placed
//   mesh with its texture coordinates as Mesh holds them, v up: the w a PLY reader expects) stored
//   as per-vertex tx ty tz tw (normals/tangent_vertices.h, vertices split where corners differ)
//   when `holds_tangents` (PLY); otherwise nothing is stored. Recomputed rather than mapped: the
//   placement may be no similarity (then mapped tangents are no MikkTSpace frame, see
//   gltf_transform.h), and merged primitives are one mesh. Returns the note for the user ("" when
//   no primitive had tangents).
#pragma once

#include <string>
#include <vector>

#include <shadetool/gltf/gltf_document.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::vector<double> gltf_texcoords(const GltfDocument& doc, const GltfPrimitive& p, bool& changed);

std::string gltf_update_tangents(const GltfDocument& doc, GltfPrimitive& p, bool add);

std::string gltf_world_tangents(const GltfDocument& doc, Mesh& world, bool holds_tangents);

}  // namespace shadetool
#pragma GCC visibility pop
