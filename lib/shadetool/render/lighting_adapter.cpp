// lighting_adapter.cpp: see lighting_adapter.h.
#include <shadetool/render/lighting_adapter.h>

#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {

ShadeOptions shade_options(const RenderLightingOptions& options) {
  ShadeOptions o;
  o.model = options.model;
  o.space = options.space;
  return o;
}

}  // namespace

std::vector<double> baked_vertex_colors(const Mesh& mesh, const Scene& scene, const RenderLightingOptions& options) {
  return bake_lighting(mesh, scene, ShadingFrequency::PerVertex, shade_options(options), options.shadows).rgb;
}

std::vector<double> baked_face_colors(const Mesh& mesh, const Scene& scene, const RenderLightingOptions& options) {
  return bake_lighting(mesh, scene, ShadingFrequency::PerFace, shade_options(options), options.shadows).rgb;
}

// The same choice as bake_lighting.cpp's PerVertex branch (kept in step with it by
// tests/render: Phong at a vertex equals the baked colour there).
std::vector<double> shading_vertex_normals(const Mesh& mesh) {
  const std::size_t V = mesh.num_vertices();
  if (mesh.has_vertex_normals() && mesh.vertex_normals.size() == mesh.positions.size()) return mesh.vertex_normals;
  if (mesh.has_corner_normals()) {
    std::vector<double> out(3 * V, 0.0);
    std::vector<char> seen(V, 0);
    bool one_per_vertex = true;
    for (std::size_t c = 0; c < mesh.num_corners() && one_per_vertex; ++c) {
      const std::size_t v = mesh.corner_vertex[c];
      const std::size_t k = mesh.corner_normal_index[c];
      if (v >= V || 3 * k + 2 >= mesh.corner_normals.size()) {
        one_per_vertex = false;
        break;
      }
      const Vec3d n = get3(mesh.corner_normals, k);
      if (!seen[v]) {
        set3(out, v, n);
        seen[v] = 1;
      } else if (get3(out, v) != n) {
        one_per_vertex = false;
      }
    }
    if (one_per_vertex) return out;
  }
  return vertex_normals(mesh, Weighting::Angle, Precision::Double).normals;
}

PointShader::PointShader(const Scene& scene, const RenderLightingOptions& options, const Mesh& mesh,
                         const std::vector<double>& positions_world)
    : lighting_(prepare_point_lighting(scene, options.model)), scene_(&scene), shadow_samples_(options.shadows.samples) {
  if (!options.shadows.enabled) return;
  world_.positions = positions_world;
  world_.face_start = mesh.face_start;
  world_.corner_vertex = mesh.corner_vertex;
  bvh_ = std::make_unique<VisibilityScene>(world_);
}

PointShader::~PointShader() = default;

std::vector<double> PointShader::visibility(const std::vector<double>& points_world,
                                            const std::vector<double>& normals_world,
                                            const std::vector<std::uint64_t>& ids) const {
  return light_visibility(*bvh_, *scene_, lighting_.plan, points_world, normals_world, ids, shadow_samples_);
}

std::size_t PointShader::bvh_bytes() const {
  return bvh_ ? bvh_->stats().bvh_bytes + bvh_->stats().buffer_bytes : 0;
}

Vec3d scene_eye_world(const Scene& scene) { return eye_world(scene); }

std::uint8_t encode_srgb_8bit(double linear) { return quantize_8bit(srgb_encode(linear)); }

}  // namespace shadetool
