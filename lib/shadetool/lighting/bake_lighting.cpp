// bake_lighting.cpp: see bake_lighting.h.
#include <shadetool/lighting/bake_lighting.h>

#include <memory>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include <shadetool/core/vocabulary.h>
#include <shadetool/lighting/lit_normals.h>
#include <shadetool/lighting/world_occluders.h>
#include <shadetool/normals/face_normals.h>

namespace shadetool {

namespace {
const NamedValue<ShadingFrequency> kShadingFrequencies[] = {
    {ShadingFrequency::PerVertex, "vertex"},
    {ShadingFrequency::PerFace, "face"},
};
}  // namespace

ShadingFrequency parse_shading_frequency(std::string_view text, const std::string& what) {
  return parse_named(kShadingFrequencies, text, what);
}
const char* shading_frequency_name(ShadingFrequency frequency) { return name_of(kShadingFrequencies, frequency); }
std::vector<std::string> shading_frequency_names() { return names_of(kShadingFrequencies); }

namespace {

// Shades object-space points and normals, with shadows when asked: the visibility is computed
// from world-space copies (the lights' space) and handed to shade_points.
// ids: the points' seeds (empty: their index).
std::vector<double> shade_with_shadows(const Mesh& mesh, const Scene& scene, const std::vector<double>& points,
                                       const std::vector<double>& normals, const ShadeOptions& options,
                                       const ShadowOptions& shadows, BakeResult& result,
                                       const std::vector<std::uint64_t>& ids = {}) {
  if (!shadows.enabled) return shade_points(scene, points, normals, options, &result.report);
  const Affine3d& M = scene.world_from_object;
  const Mat3d cof = signed_cofactor(M.A);
  std::unique_ptr<const WorldOccluders> own;  // the mesh's own occluders, unless the caller built the scene's
  if (!shadows.occluders) own = world_occluders(world_positions(mesh, M), mesh);
  const VisibilityScene& bvh = shadows.occluders ? *shadows.occluders : *own->bvh;

  const std::size_t P = points.size() / 3;
  std::vector<double> wp(3 * P), wn(3 * P);
  for (std::size_t i = 0; i < P; ++i) {
    set3(wp, i, transform_point(M, get3(points, i)));
    set3(wn, i, Vec3d(transform_normal(cof, Normal3d(get3(normals, i)))));
  }
  const ShadingModel model = options.model ? *options.model : scene.model;
  const LightingPlan plan = plan_lighting(scene, model);
  const std::vector<double> visibility = light_visibility(bvh, scene, plan, wp, wn, ids, shadows.samples, &result.shadows,
                                                                shadows.progress);
  ShadeOptions with = options;
  with.visibility = &visibility;
  return shade_points(scene, points, normals, with, &result.report);
}

}  // namespace

void require_bakeable(const Mesh& mesh, ShadingFrequency frequency, const std::string& name) {
  switch (frequency) {
    case ShadingFrequency::PerFace:
      require_faces(mesh, name);
      break;
    case ShadingFrequency::PerVertex:
      if (mesh.num_faces() == 0 && !mesh.has_vertex_normals() && mesh.num_vertices() > 0)
        fail(name, 0, "no vertex normals and no faces to compute them from");
      break;
  }
}

BakeResult bake_lighting(const Mesh& mesh, const Scene& scene, ShadingFrequency frequency, const ShadeOptions& options,
                         const ShadowOptions& shadows, VertexColors colors) {
  check_shadow_options(shadows, "bake_lighting: shadow samples");
  BakeResult result;
  if (frequency == ShadingFrequency::PerVertex) {
    LitVertexNormals lit = lit_vertex_normals(mesh);
    result.normals_source = std::move(lit.source);
    result.normal_fallback_vertices = lit.fallback_vertices;
    switch (colors) {
      case VertexColors::All:
        result.rgb = shade_with_shadows(mesh, scene, mesh.positions, lit.normals, options, shadows, result);
        break;
      case VertexColors::None:  // no point: the report's model, space and plan, no counts
        shade_points(scene, {}, {}, options, &result.report);
        break;
    }
    result.vertex_normals = std::move(lit.normals);
    return result;
  }

  // PerFace: face normal at the centroid of the face's corners.
  const std::size_t F = mesh.num_faces();
  std::vector<double> normals;
  if (mesh.has_face_normals() && mesh.face_normals.size() == 3 * F) {
    result.normals_source = "input face normals";
    normals = mesh.face_normals;
  } else {
    result.normals_source = "computed face normals";
    normals = face_normals(mesh, Precision::Double);
  }
  std::vector<double> centroids(3 * F, 0.0);
  for (std::size_t f = 0; f < F; ++f) {
    const std::size_t size = mesh.face_size(f);
    if (size == 0) {  // no corners: no position; the zero normal below leaves only ambient terms
      set3(normals, f, {0, 0, 0});
      continue;
    }
    Vec3d sum{0, 0, 0};
    for (std::size_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) sum += mesh.position(mesh.corner_vertex[c]);
    set3(centroids, f, sum * (1.0 / double(size)));  // size > 0 checked above
  }
  result.rgb = shade_with_shadows(mesh, scene, centroids, normals, options, shadows, result);
  return result;
}

std::vector<double> bake_vertex_colors(const Mesh& mesh, const Scene& scene, const BakeResult& normals_bake,
                                       const std::vector<std::uint32_t>& vertices, const ShadeOptions& options,
                                       const ShadowOptions& shadows, ShadeCounters& counters) {
  check_shadow_options(shadows, "bake_lighting: shadow samples");
  if (normals_bake.vertex_normals.size() != mesh.positions.size())
    throw Error("bake_vertex_colors: " + std::to_string(normals_bake.vertex_normals.size() / 3) + " vertex normals for " +
                std::to_string(mesh.num_vertices()) + " vertices");
  if (vertices.empty()) return {};
  std::vector<double> points(3 * vertices.size()), normals(3 * vertices.size());
  std::vector<std::uint64_t> ids(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (vertices[i] >= mesh.num_vertices())
      throw Error("bake_vertex_colors: vertex " + std::to_string(vertices[i]) + " of " + std::to_string(mesh.num_vertices()));
    set3(points, i, mesh.position(vertices[i]));
    set3(normals, i, get3(normals_bake.vertex_normals, vertices[i]));
    ids[i] = vertices[i];  // the full bake's seed of this vertex: the same shadow rays
  }
  BakeResult part;
  std::vector<double> rgb = shade_with_shadows(mesh, scene, points, normals, options, shadows, part, ids);
  counters += part.report.counters;
  return rgb;
}

std::vector<std::string> store_baked_colors(Mesh& mesh, std::vector<float> colors, ShadingFrequency frequency, bool hdr) {
  std::vector<std::string> notes;
  const bool per_vertex = frequency == ShadingFrequency::PerVertex;
  if (per_vertex ? mesh.has_face_colors() : mesh.has_vertex_colors())
    notes.push_back(std::string("the input's ") + (per_vertex ? "face" : "vertex") + " colours dropped: the lighting is baked per " +
                    (per_vertex ? "vertex" : "face") + " (--per " + (per_vertex ? "face" : "vertex") + " bakes into them instead)");
  if (mesh.color_channels == 4 && (mesh.has_vertex_colors() || mesh.has_face_colors()))
    notes.push_back("the input's colour alpha dropped: baked colours are rgb");
  mesh.color_channels = 3;
  mesh.colors_are_float = hdr;
  if (frequency == ShadingFrequency::PerVertex) {
    mesh.vertex_colors = std::move(colors);
    mesh.face_colors.clear();
  } else {
    mesh.face_colors = std::move(colors);
    mesh.vertex_colors.clear();
  }
  return notes;
}

}  // namespace shadetool
