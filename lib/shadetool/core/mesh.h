// mesh.h: the mesh in memory, as indexed flat arrays (libigl-style), not a half-edge structure.
//
// Nothing read is lost: polygons of any size, non-manifold edges, duplicate faces and isolated
// vertices are kept exactly as read, in the order read. (OpenMesh's add_face refuses some of these;
// see io/openmesh_adapter.h for the bridge to OpenMesh, which is for library users, not the core.)
//
// Shapes (V = #vertices, F = #faces, C = #corners = sum of face sizes):
//   positions          V*3 doubles          x y z per vertex
//   face_start         F+1 uint32           face f uses corners [face_start[f], face_start[f+1])
//   corner_vertex      C uint32             vertex index of each corner
//   vertex_normals     0 or V*3 doubles     per-vertex normals
//   corner_normals     N*3 doubles          pool of normals referenced by corner_normal_index
//   corner_normal_index 0 or C uint32       per-corner index into corner_normals (OBJ `vn`, creases)
//   face_normals       0 or F*3 doubles     per-face normals
//   texcoords          T*texcoord_dims      pool of texture coordinates (OBJ `vt`), kept through
//   corner_texcoord_index 0 or C uint32     per-corner index into texcoords; kNoTexcoord where a
//                                           corner has none (OBJ: `f 1/1 2/2 3/3` beside `f 4 5 6`)
//   texcoord_names     0 or 2 strings       the names per-vertex texture coordinates were read under
//                                           (PLY `s t`, `u v`, `texture_u texture_v`): a PLY writer
//                                           gives them back per vertex under these names whenever
//                                           every corner of a vertex has the same coordinates
//   vertex_colors      0 or V*color_channels floats, linear, nominally in [0,1]
//   face_colors        0 or F*color_channels floats
//   group_statements   R strings            OBJ grouping lines (mtllib, usemtl, g, o, s) as read, one
//                                           run of consecutive lines per string ('\n'-terminated)
//   face_group_run     0 or F uint32        runs read before face f (non-decreasing): face f is
//                                           preceded by runs [face_group_run[f-1], face_group_run[f]),
//                                           runs from face_group_run[F-1] on follow the last face.
//                                           Steps that remove faces keep it per face, like face_colors.
//   vertex_quality     0 or V floats           a scalar per vertex (PLY `quality`, MeshLab's name)
//   face_quality       0 or F floats           a scalar per face (PLY face `quality`)
//   comments           a file's comment lines that say something about it (PLY header `comment` and
//                      `obj_info` lines as read, keyword included: MeshLab's `comment TextureFile
//                      tex.png`, a scanner's settings); written back by PLY, as `#` lines by OBJ
//   vertex_properties  scalars per vertex no array above holds, by name (a scanner's `confidence`
//   face_properties    or `intensity`, CloudCompare's `scalar_*`, a face's `flags`): V (F) values
//                      each, in double (exact for every PLY scalar type), with the declared type
//                      so a PLY writer gives them back as read.
//
// Every per-vertex array (normals, colours, quality, properties) is visited by
// for_each_vertex_array, every per-face one by for_each_face_array: a step that removes, reorders
// or duplicates vertices or faces moves them all through these, so none is forgotten.
//
// Values are stored in double so that analytic test meshes lie on their surface and float input
// (binary PLY, STL) round-trips bitwise: a float widened to double and narrowed back is unchanged.
// `precision` remembers what the input used, so writers emit the same type.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class ValuePrecision { Float, Double };
// Its vocabulary (core/vocabulary.h, mesh.cpp): "double", "float" (Python's Mesh.precision).
ValuePrecision parse_value_precision(std::string_view text, const std::string& what);
const char* value_precision_name(ValuePrecision precision);
std::vector<std::string> value_precision_names();

// corner_texcoord_index of a corner without a texture coordinate.
constexpr std::uint32_t kNoTexcoord = 0xFFFFFFFFu;

// A named scalar per vertex or per face; `type` is PLY's name for the declared type (char, uchar,
// short, ushort, int, uint, float, double).
struct MeshProperty {
  std::string name;
  std::string type = "float";
  std::vector<double> values;
};

struct Mesh {
  std::vector<double> positions;
  std::vector<std::uint32_t> face_start{0};
  std::vector<std::uint32_t> corner_vertex;

  std::vector<double> vertex_normals;
  std::vector<double> corner_normals;
  std::vector<std::uint32_t> corner_normal_index;
  std::vector<double> face_normals;

  std::vector<double> texcoords;
  int texcoord_dims = 2;
  std::vector<std::uint32_t> corner_texcoord_index;
  std::vector<std::string> texcoord_names;

  std::vector<float> vertex_colors;
  std::vector<float> face_colors;
  int color_channels = 3;  // 3 (rgb) or 4 (rgba), for both colour arrays
  bool colors_are_float = false;  // as read: PLY float colours / OBJ `v x y z r g b`; else uchar

  std::vector<std::string> group_statements;
  std::vector<std::uint32_t> face_group_run;
  std::vector<float> vertex_quality;
  std::vector<float> face_quality;
  std::vector<MeshProperty> vertex_properties;
  std::vector<MeshProperty> face_properties;
  std::vector<std::string> comments;

  ValuePrecision precision = ValuePrecision::Float;

  // f(array, width) for every per-vertex / per-face array that is not empty (width = values per
  // element). face_group_run is per face too but not a value: steps handle it themselves.
  template <class F>
  void for_each_vertex_array(F&& f) {
    if (!vertex_normals.empty()) f(vertex_normals, std::size_t(3));
    if (!vertex_colors.empty()) f(vertex_colors, std::size_t(color_channels));
    if (!vertex_quality.empty()) f(vertex_quality, std::size_t(1));
    for (MeshProperty& p : vertex_properties) f(p.values, std::size_t(1));
  }
  template <class F>
  void for_each_face_array(F&& f) {
    if (!face_normals.empty()) f(face_normals, std::size_t(3));
    if (!face_colors.empty()) f(face_colors, std::size_t(color_channels));
    if (!face_quality.empty()) f(face_quality, std::size_t(1));
    for (MeshProperty& p : face_properties) f(p.values, std::size_t(1));
  }

  std::size_t num_vertices() const { return positions.size() / 3; }
  std::size_t num_faces() const { return face_start.size() - 1; }
  std::size_t num_corners() const { return corner_vertex.size(); }
  std::size_t face_size(std::size_t f) const { return face_start[f + 1] - face_start[f]; }

  // True when every face has exactly 3 corners: kernels take the fast path (corner = 3f + k).
  bool all_triangles() const { return corner_vertex.size() == 3 * num_faces(); }

  bool has_vertex_normals() const { return !vertex_normals.empty(); }
  bool has_corner_normals() const { return !corner_normal_index.empty(); }
  bool has_face_normals() const { return !face_normals.empty(); }
  bool has_vertex_colors() const { return !vertex_colors.empty(); }
  bool has_face_colors() const { return !face_colors.empty(); }
  bool has_texcoords() const { return !corner_texcoord_index.empty(); }
  bool has_groups() const { return !group_statements.empty(); }
  bool has_vertex_quality() const { return !vertex_quality.empty(); }
  bool has_face_quality() const { return !face_quality.empty(); }

  Vec3d position(std::size_t v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
  void set_position(std::size_t v, const Vec3d& p) {
    positions[3 * v] = p.x; positions[3 * v + 1] = p.y; positions[3 * v + 2] = p.z;
  }

  // Appends a vertex / a face; used by readers and test generators.
  std::uint32_t add_vertex(const Vec3d& p) {
    positions.push_back(p.x); positions.push_back(p.y); positions.push_back(p.z);
    return static_cast<std::uint32_t>(num_vertices() - 1);
  }
  template <class Range>
  void add_face(const Range& vertices) {
    for (auto v : vertices) corner_vertex.push_back(static_cast<std::uint32_t>(v));
    face_start.push_back(static_cast<std::uint32_t>(corner_vertex.size()));
  }
  void add_face(std::initializer_list<std::uint32_t> vertices) {
    corner_vertex.insert(corner_vertex.end(), vertices.begin(), vertices.end());
    face_start.push_back(static_cast<std::uint32_t>(corner_vertex.size()));
  }
};

// Reads a 3-vector out of a flat array at element i (i*3 .. i*3+2).
inline Vec3d get3(const std::vector<double>& a, std::size_t i) { return {a[3 * i], a[3 * i + 1], a[3 * i + 2]}; }
inline void set3(std::vector<double>& a, std::size_t i, const Vec3d& v) {
  a[3 * i] = v.x; a[3 * i + 1] = v.y; a[3 * i + 2] = v.z;
}

}  // namespace shadetool
#pragma GCC visibility pop
