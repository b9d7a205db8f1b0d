// gltf_scene.h: a glTF document's scene graph, and its triangle primitives as one mesh in world
// space (what assimp's and Blender's exporters write when a glTF scene becomes an OBJ or a PLY).
//
// gltf_scene_nodes: the nodes of the document's scene (`scene`, else scenes[0]; a document
// without scenes: every node that is nobody's child), depth first in scene order, each with its
// world matrix = parent's world * local, local = `matrix` (column-major 4x4) or T * R * S (glTF
// 2.0, 3.5.2-3.5.3; the rotation quaternion is divided by its length, so a quaternion rounded
// off unit length stays a rotation). Error `FILE: nodes[i].KEY: what` for a matrix, translation,
// rotation or scale that is not an array of finite numbers of the right size, or a zero
// quaternion. The graph was checked to be a forest on reading (gltf_read.cpp).
//
// gltf_world_mesh: every triangle primitive of every node that shows its mesh, placed by that
// node's world matrix through lib/transform's transform_mesh (positions A p + t, normals
// sign(det A) cof(A) n, the winding reversed where det A < 0: glTF 2.0, 3.7.2.1, a mirrored node
// draws its triangles clockwise, so the faces keep facing out), then concatenated in scene order:
//   - a node with EXT_mesh_gpu_instancing places its mesh once per instance, by world_from_node
//     * T_i R_i S_i (the extension's TRANSLATION, ROTATION, SCALE accessors, read as a node's
//     T R S; an attribute absent: identity; counts that differ: an Error naming the JSON path);
//   - a mesh shown by K nodes is written K times; a mesh no node of the scene shows is written
//     once in its object space; a node with a singular matrix (scale 0: hidden) places nothing;
//     a skinned node is placed by its node's matrix (the bind pose: joints are not applied);
//     morph targets are not applied (the base shape). Each of these is named in one note.
//   - normals: every primitive's vertex normals -> vertex normals; otherwise, when any primitive
//     has normals, corner normals for all (a primitive's own corner normals, else its vertex
//     normals, else its face normals, else its faces' normals from the geometry, with a note);
//     face normals are kept when every primitive has them.
//   - colours and quality (vertex and face): kept when any primitive has them; the others get
//     white (alpha 1) or quality 0, with a note. rgb and rgba together: rgba (alpha 1 added).
//   - TEXCOORD_0 as the mesh's texture coordinates, v flipped (t' = 1 - t: glTF's origin is the
//     image's top left, OBJ's and the Mesh's its bottom left, as assimp and Blender import them).
//     A primitive whose vertex count a command changed keeps no texture coordinates (note).
//   - POINTS / LINES primitives are not in the mesh (note).
// Precision: double, as the Mesh.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/core/mesh.h>
#include <shadetool/gltf/gltf_document.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct GltfNodePlacement {
  std::size_t node = 0;  // index into the document's "nodes"
  Affine3d world;        // world_from_node
};

// Empty for a document not read from a file (gltf_document_from_mesh) or without nodes.
std::vector<GltfNodePlacement> gltf_scene_nodes(const GltfDocument& document);

// Per document primitive (document.primitives[i]), the nodes of the scene that place it, in scene
// order: `nodes` those with an invertible world matrix, `singular_nodes` those with a singular one
// (scale 0: hidden; they place nothing), `skinned_nodes` those of `nodes` with a skin. in_scene is
// false when no node of the scene shows the primitive's mesh (gltf_world_mesh then writes it once
// in its object space). A node with EXT_mesh_gpu_instancing gives one entry per instance (its
// world matrix times the instance's T R S; the same node index each time), gpu_instances counts them.
struct GltfPrimitivePlacements {
  bool in_scene = false;
  std::size_t gpu_instances = 0;
  std::vector<GltfNodePlacement> nodes;
  std::vector<std::size_t> singular_nodes, skinned_nodes;
};
std::vector<GltfPrimitivePlacements> gltf_primitive_placements(const GltfDocument& document);

// The primitive's mesh placed by `placement` (transform_mesh: the bits gltf_world_mesh writes for
// that instance); null: as read (object space).
Mesh gltf_placed_mesh(const GltfDocument& document, const GltfPrimitive& primitive, const GltfNodePlacement* placement);

// notes: what the flattening did or could not carry, one line each (appended).
Mesh gltf_world_mesh(const GltfDocument& document, std::vector<std::string>& notes);

}  // namespace shadetool
#pragma GCC visibility pop
