// scene.cpp: see scene.h.
#include <shadetool/lighting/scene.h>

#include <shadetool/core/affine.h>

namespace shadetool {

Vec3d eye_world(const Scene& scene) {
  if (!scene.has_camera) return {0, 0, 0};
  Affine3d world_from_camera;
  if (!invert_affine(scene.camera_from_world, world_from_camera)) return {0, 0, 0};  // validated on read
  return world_from_camera.t;  // V^-1 (0,0,0)
}

}  // namespace shadetool
