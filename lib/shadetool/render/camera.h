// camera.h: the camera a mesh is rendered with: view, projection, near and far planes.
//
// Inputs:  scene            camera_from_world V and scene.lens (fov_y, near, far, orthographic);
//                           without a camera (has_camera false) one that frames the mesh
//          bounds_world     the mesh's axis-aligned bounds in world space (world_from_object applied)
//          width, height    image size in pixels (aspect = width / height)
// Output:  RenderCamera: V, the projection's scales, near and far (camera-space distances along
//          the view direction -z, OpenGL convention), and clip_from_camera applied by to_clip.
//
// Projection (OpenGL's glFrustum / glOrtho with a symmetric frustum):
//   perspective   x_c = (f / aspect) x,  y_c = f y,  w = -z,  f = 1 / tan(fov_y / 2)
//   orthographic  x_c = (2 / (h aspect)) x, y_c = (2 / h) y, w = 1,  h = the orthographic height
//   z_c = a z + b with the OpenGL near/far mapping, so z_c / w is -1 at near and +1 at far.
//
// Near and far, unless the scene gives them: fitted to the eight corners of bounds_world in camera
// space, widened by 1/1000 of the depth range; near is at least far / 10^4 (a depth range of
// 10^4 keeps 1/w's spacing far above double's resolution).
//
// Framing camera (no camera in the scene): looks along -z (world) at the bounds' centre, up +y,
// from the distance at which the bounding sphere (radius r = half the diagonal) fills the smaller
// of the two fields of view, times 1.1. A point-sized mesh (r = 0) uses r = 1.
//
// Errors (shadetool::Error naming `scene_name`): an empty bounds (no vertices), a given near/far
// that leaves the whole mesh outside [near, far] is allowed (an empty image, counted in --stats).
#pragma once

#include <string>

#include <shadetool/core/affine.h>
#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct Bounds3d {
  Vec3d lo{0, 0, 0}, hi{0, 0, 0};
  bool empty = true;
  void add(const Vec3d& p);
};

struct ClipPoint {
  double x, y, z, w;
};

struct RenderCamera {
  Affine3d camera_from_world;
  bool orthographic = false;
  double scale_x = 1, scale_y = 1;  // x_c = scale_x x, y_c = scale_y y
  double depth_a = -1, depth_b = 0; // z_c = depth_a z + depth_b
  double near = 0.1, far = 100;
  bool framed = false;              // the scene had no camera: one framing the mesh was made
  Vec3d eye_world{0, 0, 0};

  ClipPoint to_clip(const Vec3d& p_camera) const {
    return {scale_x * p_camera.x, scale_y * p_camera.y, depth_a * p_camera.z + depth_b,
            orthographic ? 1.0 : -p_camera.z};
  }
};

RenderCamera make_render_camera(const Scene& scene, const Bounds3d& bounds_world, int width, int height);

}  // namespace shadetool
#pragma GCC visibility pop
