// bake_lighting.cpp: see bake_lighting.h.
#include <shadetool/lighting/bake_lighting.h>

#include <memory>

#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {

// True when every corner of each vertex references the same normal value; fills `normals`.
bool corner_normals_per_vertex(const Mesh& mesh, std::vector<double>& normals) {
  const std::size_t V = mesh.num_vertices();
  std::vector<double> out(3 * V, 0.0);
  std::vector<char> seen(V, 0);
  for (std::size_t c = 0; c < mesh.num_corners(); ++c) {
    const std::size_t v = mesh.corner_vertex[c];
    const std::size_t k = mesh.corner_normal_index[c];
    if (v >= V || 3 * k + 2 >= mesh.corner_normals.size()) return false;
    const Vec3d n = get3(mesh.corner_normals, k);
    if (!seen[v]) {
      set3(out, v, n);
      seen[v] = 1;
    } else if (get3(out, v) != n) {
      return false;  // a crease: this vertex has several normals
    }
  }
  normals = std::move(out);
  return true;
}

// Shades object-space points and normals, with shadows when asked: the visibility is computed
// from world-space copies (the lights' space) and handed to shade_points.
std::vector<double> shade_with_shadows(const Mesh& mesh, const Scene& scene, const std::vector<double>& points,
                                       const std::vector<double>& normals, const ShadeOptions& options,
                                       const ShadowOptions& shadows, BakeResult& result) {
  if (!shadows.enabled) return shade_points(scene, points, normals, options, &result.report);
  const Affine3d& M = scene.world_from_object;
  const Mat3d cof = signed_cofactor(M.A);
  Mesh world;  // the mesh's own occluders, unless the caller built the scene's
  std::unique_ptr<VisibilityScene> own;
  if (!shadows.occluders) {
    world.positions.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v) set3(world.positions, v, transform_point(M, mesh.position(v)));
    world.face_start = mesh.face_start;
    world.corner_vertex = mesh.corner_vertex;
    own = std::make_unique<VisibilityScene>(world);
  }
  const VisibilityScene& bvh = shadows.occluders ? *shadows.occluders : *own;

  const std::size_t P = points.size() / 3;
  std::vector<double> wp(3 * P), wn(3 * P);
  for (std::size_t i = 0; i < P; ++i) {
    set3(wp, i, transform_point(M, get3(points, i)));
    set3(wn, i, Vec3d(transform_normal(cof, Normal3d(get3(normals, i)))));
  }
  const ShadingModel model = options.model ? *options.model : scene.model;
  const LightingPlan plan = plan_lighting(scene, model, options.skips);
  const std::vector<double> visibility = light_visibility(bvh, scene, plan, wp, wn, {}, shadows.samples, &result.shadows);
  ShadeOptions with = options;
  with.visibility = &visibility;
  return shade_points(scene, points, normals, with, &result.report);
}

}  // namespace

BakeResult bake_lighting(const Mesh& mesh, const Scene& scene, ShadingFrequency frequency, const ShadeOptions& options,
                         const ShadowOptions& shadows) {
  BakeResult result;
  if (frequency == ShadingFrequency::PerVertex) {
    std::vector<double> normals;
    if (mesh.has_vertex_normals() && mesh.vertex_normals.size() == mesh.positions.size()) {
      result.normals_source = "input vertex normals";
      normals = mesh.vertex_normals;
    } else if (mesh.has_corner_normals() && corner_normals_per_vertex(mesh, normals)) {
      result.normals_source = "input corner normals (one per vertex)";
    } else {
      VertexNormals computed = vertex_normals(mesh, Weighting::Angle, Precision::Double);
      result.normals_source = mesh.has_corner_normals()
                                  ? "computed (angle-weighted): the input's corner normals differ at some vertices"
                                  : "computed (angle-weighted)";
      result.normal_fallback_vertices = computed.fallback_vertices;
      normals = std::move(computed.normals);
    }
    result.rgb = shade_with_shadows(mesh, scene, mesh.positions, normals, options, shadows, result);
    result.vertex_normals = std::move(normals);
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

void store_baked_colors(Mesh& mesh, std::vector<float> colors, ShadingFrequency frequency, bool hdr) {
  mesh.color_channels = 3;
  mesh.colors_are_float = hdr;
  if (frequency == ShadingFrequency::PerVertex) {
    mesh.vertex_colors = std::move(colors);
    mesh.face_colors.clear();
  } else {
    mesh.face_colors = std::move(colors);
    mesh.vertex_colors.clear();
  }
}

}  // namespace shadetool
