// scene.cpp: see scene.h.
#include <shadetool/lighting/scene.h>

#include <shadetool/core/affine.h>
#include <shadetool/core/vocabulary.h>

namespace shadetool {

namespace {
const NamedValue<ShadingModel> kShadingModels[] = {
    {ShadingModel::Lambert, "lambert"},
    {ShadingModel::Phong, "phong"},
    {ShadingModel::BlinnPhong, "blinn-phong"},
};
}  // namespace

ShadingModel parse_shading_model(std::string_view text, const std::string& what) {
  return parse_named(kShadingModels, text, what);
}
const char* shading_model_name(ShadingModel model) { return name_of(kShadingModels, model); }
std::vector<std::string> shading_model_names() { return names_of(kShadingModels); }

Vec3d eye_world(const Scene& scene) {
  if (!scene.has_camera) return {0, 0, 0};
  Affine3d world_from_camera;
  if (!invert_affine(scene.camera_from_world, world_from_camera)) return {0, 0, 0};  // validated on read
  return world_from_camera.t;  // V^-1 (0,0,0)
}

}  // namespace shadetool
