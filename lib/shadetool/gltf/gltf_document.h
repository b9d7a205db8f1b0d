// gltf_document.h: a glTF 2.0 file (.gltf or .glb) in memory, kept whole so that whatever a
// command does not change leaves unchanged.
//
// Reading (read_gltf, through tinygltf, libtinygltf-dev): the JSON is kept as read (nodes,
// cameras, materials, textures, images, animations, skins, extensions, extras, everything) and
// so are the buffers. Each mesh primitive of mode TRIANGLES (4), TRIANGLE_STRIP (5) or
// TRIANGLE_FAN (6) becomes one GltfPrimitive whose `mesh` is in the primitive's own object space:
//   positions       POSITION (float, or KHR_mesh_quantization's normalised/integer types)
//   faces           triangles: the indices (any index type) or 0..V-1; strips and fans as their
//                   triangles (spec 3.7.2.1: strip i -> {i, i+1+i%2, i+2-i%2}, fan i -> {i+1, i+2, 0})
//   vertex_normals  NORMAL, when present
//   vertex_colors   COLOR_0, when present (VEC3/VEC4; float or normalised ubyte/ushort)
// TANGENT and morph-target POSITION/NORMAL/TANGENT deltas are decoded beside it (transform maps
// them); every other attribute stays in the buffers. POINTS and LINES primitives are not decoded
// and pass through untouched.
//
// Writing (write_gltf): the JSON as read, with one buffer (GLB: the BIN chunk; .gltf: a data URI)
// holding every input buffer's bytes, every image moved into a bufferView byte for byte (no
// re-encoding; GLB cannot reference loose files), and, per primitive, new accessors only for
// what changed: POSITION (min/max recomputed), NORMAL, COLOR_0, TANGENT, target deltas, indices.
// When a command splits vertices (corner or face normals, face colours), every other vertex
// attribute is gathered through the split; when it changes the vertex count otherwise (repair's
// welding) and the primitive has attributes or morph targets that cannot follow, nothing is
// written (Error naming them: dropping them would break the materials, skins and weights that
// refer to them). Last (engine/gltf_tidy.h): accessors not aligned to their component size are
// copied to aligned views, accessors and views nothing refers to any more are removed with their
// bytes (unless an unknown extension could refer to them: a note), every min/max is made exact.
// With unlit_materials (baked colours, gltf/gltf_baked.h), materials get KHR_materials_unlit.
//
// Bad input (Error `FILE: JSON.PATH: what`): a property whose JSON type is not the schema's (a
// number for a name, -1 for an index, an array for an object: engine/gltf_schema.h), a missing buffer file, a view or accessor beyond its
// buffer, an index out of range, component types the spec forbids for an attribute, NaN/Inf in
// POSITION, a node graph that is not a forest (recursion), compressed data that does not decode.
// KHR_draco_mesh_compression and EXT_meshopt_compression are decoded on reading (libdraco,
// libmeshoptimizer: engine/gltf_decompress.h) and written uncompressed, with a note.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/io/file_bytes.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct GltfSource;  // the tinygltf model, the JSON and the buffers as read (gltf_read.cpp)

// One morph target's decoded deltas (#V by 3 each; empty when the target has none of that kind).
struct GltfMorphTarget {
  std::vector<double> position_deltas, normal_deltas, tangent_deltas;
};

struct GltfPrimitive {
  std::size_t mesh_index = 0, primitive_index = 0;
  std::string json_path;              // "meshes[0].primitives[1]"
  Mesh mesh;                          // what commands change, in object space
  std::vector<double> tangents;       // #V by 4 (xyz, w = handedness +-1), or empty
  // Tangent frames per corner (#C by 4) a command computed (gltf_tangents.h): when not empty the
  // writer writes TANGENT from them (vertices split where a vertex's corners differ), added if absent.
  std::vector<double> corner_tangents;
  bool drop_tangents = false;         // TANGENT is stale and cannot be recomputed: not written
  std::vector<GltfMorphTarget> targets;
  int color_component_type = 0;       // COLOR_0 as read (5126 float, 5121, 5123); 0: none
  std::vector<std::string> attributes;  // every attribute name as read (POSITION, TEXCOORD_0, ...)
  int mode = 4;                       // as read: 4 TRIANGLES, 5 TRIANGLE_STRIP, 6 TRIANGLE_FAN
  // As read, to write only what changed (positions, normals, colours and corners are compared
  // with their accessors in the source, without a copy).
  std::size_t read_vertices = 0;
  std::vector<double> read_tangents;
  std::vector<GltfMorphTarget> read_targets;
};

struct GltfDocument {
  std::shared_ptr<const GltfSource> source;  // null for a document made from a plain Mesh
  std::vector<GltfPrimitive> primitives;     // triangle primitives, in file order
  std::size_t passed_through_primitives = 0; // POINTS / LINES primitives left as they are
  std::size_t passed_through_vertices = 0;   // their POSITION accessors' counts (what info reports)
  bool was_binary = false;                   // read from a .glb
  std::vector<std::string> notes;            // what reading changed (compressed geometry decoded)
  // Written with KHR_materials_unlit (baked colours, gltf/gltf_baked.h): a fresh document gets one
  // unlit material; a document as read gets the extension on its triangle primitives' materials
  // (one unlit material for those without).
  bool unlit_materials = false;
};

// Parses a .glb or .gltf (told apart by the bytes: "glTF" magic). `name` is the file's path:
// external buffers and images are resolved relative to its directory; messages name it.
GltfDocument read_gltf(std::string_view bytes, const std::string& name);
// The same from a file read whole (io/file_bytes.h), which the document then keeps: a GLB's
// binary chunk is read where it lies in the file's bytes instead of being copied (a mapped file
// stays mapped while the document lives). Same document, same errors.
GltfDocument read_gltf(io::FileBytes&& file, const std::string& name);

// A one-primitive document holding `mesh` (positions, normals, colours, texture coordinates;
// polygons as the triangles of geometry/polygon_triangles.h) for writing a non-glTF mesh as glTF: corner and face normals, face
// colours and per-corner texture coordinates split vertices; texture coordinates become
// TEXCOORD_0 with v flipped (t' = 1 - t: glTF's origin is the image's top left).
GltfDocument gltf_document_from_mesh(const Mesh& mesh);

// Every triangle primitive in one Mesh, placed by the scene's nodes: gltf/gltf_scene.h's
// gltf_world_mesh (what read_mesh returns for a glTF file).

struct GltfWriteResult {
  std::vector<std::string> notes;  // what could not be carried (one line each)
  std::size_t split_vertices = 0;  // vertices added to carry corner/face normals or face colours
  std::string buffer;              // .gltf with a buffer_uri: the buffer's bytes, for the caller to write there
};

// Serialises the document: GLB when `binary`, else .gltf JSON whose one buffer is a data URI, or,
// when `buffer_uri` is given (a relative file name, percent-encoded here: RFC 3986 as glTF 2.0,
// 2.8 asks), a reference to that file, its bytes left in result.buffer (the caller writes them
// beside the .gltf, as Blender's "glTF Separate" and gltf-transform do). `name` is the output's
// name for messages.
std::string write_gltf(const GltfDocument& document, bool binary, const std::string& name, GltfWriteResult& result,
                       const std::string& buffer_uri = "");

// buffer_uri for a .gltf written to `path`: the file name with its extension replaced by .bin.
std::string gltf_buffer_path(const std::string& path);

// The name the document was read under (its path, or "stdin"); "<glTF>" for one made from a Mesh.
std::string gltf_source_name(const GltfDocument& document);

// The files the document was read with besides itself (external buffers and images), as paths
// relative to the working directory: a writer must not overwrite them.
std::vector<std::string> gltf_external_files(const GltfDocument& document);

// True when `name` ends in .gltf (any case): JSON output; anything else is written as GLB.
bool gltf_name_is_text(const std::string& name);

}  // namespace shadetool
#pragma GCC visibility pop
