// camera.cpp: see camera.h.
#include <shadetool/render/camera.h>

#include <algorithm>
#include <cmath>

#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/look_at.h>

namespace shadetool {

void Bounds3d::add(const Vec3d& p) {
  if (empty) {
    lo = hi = p;
    empty = false;
    return;
  }
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min(lo[i], p[i]);
    hi[i] = std::max(hi[i], p[i]);
  }
}

RenderCamera make_render_camera(const Scene& scene, const Bounds3d& bounds, int width, int height) {
  RenderCamera cam;
  const CameraLens& lens = scene.lens;
  const double aspect = double(width) / double(height);  // sizes checked > 0 by render_mesh
  const Vec3d centre = bounds.empty ? Vec3d{0, 0, 0} : (bounds.lo + bounds.hi) * 0.5;
  double radius = bounds.empty ? 0.0 : 0.5 * length(bounds.hi - bounds.lo);
  if (!(radius > 0)) radius = 1;
  const double fov_y = lens.fov_y_degrees * kRadiansPerDegree;  // (0, pi), checked on read
  const double f = 1.0 / std::tan(0.5 * fov_y);                 // tan > 0 in (0, pi/2)

  if (scene.has_camera) {
    cam.camera_from_world = scene.camera_from_world;
  } else {
    cam.framed = true;
    // The bounding sphere fits the smaller field: half-angle a with tan a = min(1, aspect) / f.
    const double tan_half = std::min(1.0, aspect) / f;
    const double sin_half = tan_half / std::sqrt(1 + tan_half * tan_half);
    const double distance = lens.orthographic_height > 0 ? 2 * radius : 1.1 * radius / sin_half;
    look_at(centre + Vec3d{0, 0, distance}, centre, {0, 1, 0}, cam.camera_from_world);  // never degenerate
  }
  Affine3d world_from_camera;
  invert_affine(cam.camera_from_world, world_from_camera);  // V invertible: checked on read
  cam.eye_world = world_from_camera.t;

  // Depth range of the bounds along the view direction (distance = -z in camera space).
  double d_min = 0, d_max = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3d corner{(k & 1) ? bounds.hi.x : bounds.lo.x, (k & 2) ? bounds.hi.y : bounds.lo.y,
                       (k & 4) ? bounds.hi.z : bounds.lo.z};
    const double d = -transform_point(cam.camera_from_world, corner).z;
    d_min = k == 0 ? d : std::min(d_min, d);
    d_max = k == 0 ? d : std::max(d_max, d);
  }
  const double margin = 1e-3 * std::max(d_max - d_min, 1e-6 * radius);
  double far = lens.far > 0 ? lens.far : d_max + margin;
  double near;
  if (lens.near > 0) {
    near = lens.near;
  } else if (lens.orthographic_height > 0) {
    near = d_min - margin;  // an orthographic near plane may lie behind the eye
  } else {
    near = std::max(d_min - margin, far * 1e-4);
  }
  if (!(far > near)) far = near + std::max(margin, std::fabs(near) * 1e-3);  // whole mesh behind the eye
  cam.near = near;
  cam.far = far;

  if (lens.orthographic_height > 0) {
    cam.orthographic = true;
    cam.scale_y = 2.0 / lens.orthographic_height;  // > 0, checked on read
    cam.scale_x = cam.scale_y / aspect;
    cam.depth_a = -2.0 / (far - near);             // far > near
    cam.depth_b = -(far + near) / (far - near);
  } else {
    cam.scale_y = f;
    cam.scale_x = f / aspect;
    cam.depth_a = -(far + near) / (far - near);    // far > near
    cam.depth_b = -2.0 * far * near / (far - near);
  }
  return cam;
}

}  // namespace shadetool
