// bake_lighting.h: per-vertex (Gouraud) or per-face (flat) lit colours of a mesh.
//
// Inputs:  mesh       positions #V by 3 (object space), faces; normals if it has them
//          scene      lighting/scene.h; scene.world_from_object places the mesh in the world
//          frequency  PerVertex: one colour per vertex, from its vertex normal at its position.
//                     PerFace: one colour per face, from its face normal at its centroid (the
//                     mean of its corners' positions).
//          options    model, space, skips, threads (lighting/shade_points.h)
// Output:  rgb        #V by 3 (PerVertex) or #F by 3 (PerFace) linear doubles, unclamped
//          report     what shade_points did, and where the normals came from
//
// Normals, PerVertex: lighting/lit_normals.h (the mesh's vertex normals; else its corner normals
// when every corner of a vertex carries the same normal; else computed with normals/
// vertex_normals.h, angle-weighted, double), and `normals_source` says which. PerFace: the mesh's face normals, else
// normals/face_normals.h. A vertex or face whose normal is zero (isolated vertex, degenerate face)
// gets only the emission and ambient terms, and is counted (report.counters.zero_normals).
//
// Shadows (shadows.enabled, lighting/light_visibility.h): the mesh's non-degenerate faces, placed in
// the world by world_from_object, go into one VisibilityScene (lighting/world_occluders.h; or shadows.occluders, a scene the
// caller built: a glTF document's whole scene); each point's visibility of each
// kept light (rays from its world position, offset along its world normal) multiplies that
// light's diffuse and specular terms. Seeds: the vertex id (PerVertex) or face id (PerFace).
// report.shadows counts the rays; with shadows off nothing of this runs.
//
// store_baked_colors puts encoded colours into the mesh: vertex_colors (PerVertex) or face_colors
// (PerFace), the other array cleared, 3 channels, colors_are_float = hdr. Positions and faces are
// not touched. It returns one note for each thing of the input's that this drops (its colours of the
// other frequency, its colour alpha), so that nothing vanishes silently.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/lighting/light_visibility.h>
#include <shadetool/lighting/shade_points.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class ShadingFrequency { PerVertex, PerFace };
// Its vocabulary (core/vocabulary.h): "vertex", "face" (bake-lighting's and occlusion's --per).
ShadingFrequency parse_shading_frequency(std::string_view text, const std::string& what);
const char* shading_frequency_name(ShadingFrequency frequency);
std::vector<std::string> shading_frequency_names();

struct BakeResult {
  std::vector<double> rgb;
  ShadeReport report;
  std::string normals_source;          // e.g. "input vertex normals", "computed (angle-weighted)"
  std::size_t normal_fallback_vertices = 0;  // computed normals that needed the fallback
  ShadowStats shadows;                 // zero unless shadows.enabled
  std::vector<double> vertex_normals;  // PerVertex: the normals lit with, #V by 3 object space (the
                                       // normals lighting/fit_vertex_lighting.h interpolates)
};

// What a mesh must carry to be baked at `frequency` (Error "NAME: what"): per face, faces
// (core/validate.h require_faces); per vertex, vertex normals or faces to compute them from (a
// mesh of bare vertices has no normal to light). The CLI and Python call it before baking.
void require_bakeable(const Mesh& mesh, ShadingFrequency frequency, const std::string& name);

// What a per-vertex bake shades. All: every vertex (rgb #V by 3). None: no vertex (rgb empty;
// report: model, space and plan, counters 0; shadows: none cast): the normals only, for a caller
// whose output replaces the point colours and reports nothing of them (lighting/
// fit_vertex_lighting.h's least squares without --stats or --json; it shades only its fallback
// vertices, with bake_vertex_colors). PerFace bakes ignore it.
enum class VertexColors { All, None };

BakeResult bake_lighting(const Mesh& mesh, const Scene& scene, ShadingFrequency frequency,
                         const ShadeOptions& options = {}, const ShadowOptions& shadows = {},
                         VertexColors colors = VertexColors::All);

// The per-vertex colours of `vertices` (#vertices by 3, in their order) exactly as bake_lighting
// (PerVertex, All) computes them there: lit with normals_bake.vertex_normals, shadow rays seeded
// with the vertex ids. Their shading counts are added to `counters`. Error for a vertex id out of
// range or normals of another mesh.
std::vector<double> bake_vertex_colors(const Mesh& mesh, const Scene& scene, const BakeResult& normals_bake,
                                       const std::vector<std::uint32_t>& vertices, const ShadeOptions& options,
                                       const ShadowOptions& shadows, ShadeCounters& counters);

std::vector<std::string> store_baked_colors(Mesh& mesh, std::vector<float> colors, ShadingFrequency frequency, bool hdr);

}  // namespace shadetool
#pragma GCC visibility pop
