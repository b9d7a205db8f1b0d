// ply_properties.h (engine, not installed): which PLY properties become which Mesh arrays.
//
// Inputs:  elements  the header's elements (PlyHeader::elements); each property's `target` is set
//          name      for messages
// Output:  PlyLayout: the first `vertex` and `face` elements, what they carry (normals, colours,
//          texcoords: an attribute is kept only when all its components are declared), the colour
//          channel count, whether colours are float, and whether any kept vertex value is declared
//          double (or a 32-bit integer): Mesh::precision.
//   vertex:  x y z; nx ny nz; red green blue alpha (also diffuse_*, r g b a); s t / u v /
//            texture_u texture_v / texture_s texture_t
//            quality (MeshLab's per-vertex scalar; the first such property)
//            every other scalar (and the parts of an incompletely declared attribute): an extra
//            property by name and type
//   face:    list vertex_indices or vertex_index (integer items; the first one), list texcoord
//            (float items: per-corner u v), nx ny nz, red green blue alpha (also diffuse_*), quality;
//            every other scalar: an extra property. Other lists of either element are skipped
//            (the body reader names them in a note).
//   tristrips: (Stanford's Cyberware-era files, igea.ply; only when there is no face element)
//            list vertex_indices: triangle strips, -1 restarts a strip; read as triangles.
// Errors:  a vertex element without x, y and z; a face element without an index list; faces but
//          no vertex element.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <shadetool/io/engine/ply_types.h>

namespace shadetool::io::ply {

struct PlyLayout {
  Element* vertex = nullptr;  // into the elements passed in
  Element* face = nullptr;
  Element* strips = nullptr;  // `tristrips` with a vertex_indices list, when there is no face element
  bool vnormal[3] = {false, false, false}, fnormal[3] = {false, false, false};
  bool vcolor[4] = {false, false, false, false}, fcolor[4] = {false, false, false, false};
  bool vtex[2] = {false, false};
  bool colors_float = false;
  bool face_texcoords = false;
  bool any_double = false;
  bool vquality = false, fquality = false;  // `quality`: MeshLab's per-vertex / per-face scalar (float)
  // Scalars no array above takes (Target::Extra; Property::extra numbers them in declaration
  // order): kept as Mesh::vertex_properties / face_properties.
  std::size_t vertex_extras = 0, face_extras = 0;

  bool has_vnormals() const { return vnormal[0] && vnormal[1] && vnormal[2]; }
  bool has_fnormals() const { return fnormal[0] && fnormal[1] && fnormal[2]; }
  bool has_vcolors() const { return vcolor[0] && vcolor[1] && vcolor[2]; }
  bool has_fcolors() const { return fcolor[0] && fcolor[1] && fcolor[2]; }
  bool has_vtex() const { return vtex[0] && vtex[1]; }
  int channels() const { return ((has_vcolors() && vcolor[3]) || (has_fcolors() && fcolor[3])) ? 4 : 3; }
  std::uint64_t num_vertices() const { return vertex ? vertex->count : 0; }
};

PlyLayout map_ply_properties(std::vector<Element>& elements, const std::string& name);

}  // namespace shadetool::io::ply
