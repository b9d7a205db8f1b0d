// lighting_adapter.cpp: see lighting_adapter.h.
#include <shadetool/render/lighting_adapter.h>

#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include <shadetool/lighting/lit_normals.h>

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

std::vector<double> shading_vertex_normals(const Mesh& mesh) { return lit_vertex_normals(mesh).normals; }

PointShader::PointShader(const Scene& scene, const RenderLightingOptions& options, const Mesh& mesh,
                         const std::vector<double>& positions_world)
    : lighting_(prepare_point_lighting(scene, options.model)), scene_(&scene), shadow_samples_(options.shadows.samples) {
  if (options.shadows.enabled) occluders_ = world_occluders(positions_world, mesh);
}

PointShader::~PointShader() = default;

std::vector<double> PointShader::visibility(const std::vector<double>& points_world,
                                            const std::vector<double>& normals_world,
                                            const std::vector<std::uint64_t>& ids) const {
  return light_visibility(*occluders_->bvh, *scene_, lighting_.plan, points_world, normals_world, ids, shadow_samples_);
}

std::size_t PointShader::bvh_bytes() const {
  return occluders_ ? occluders_->bvh->stats().bvh_bytes + occluders_->bvh->stats().buffer_bytes : 0;
}

Vec3d scene_eye_world(const Scene& scene) { return eye_world(scene); }

std::uint8_t encode_srgb_8bit(double linear) { return quantize_8bit(srgb_encode(linear)); }

}  // namespace shadetool
