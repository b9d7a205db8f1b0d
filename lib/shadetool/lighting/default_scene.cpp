// default_scene.cpp: see default_scene.h.
#include <shadetool/lighting/default_scene.h>

#include <cmath>
#include <limits>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/core/vocabulary.h>
#include <shadetool/lighting/look_at.h>

namespace shadetool {

namespace {

const Vec3d kUp{0, 1, 0};

// The direction from the target to the eye: +z, as render's framing camera (render/camera.cpp).
const Vec3d kViewFromTarget{0, 0, 1};

const NamedValue<CameraChoice> kCameraChoices[] = {
    {CameraChoice::Scene, "scene"},
    {CameraChoice::Frame, "frame"},
};

}  // namespace

CameraChoice parse_camera_choice(const std::string& text, const std::string& what) {
  return parse_named(kCameraChoices, text, what);
}
const char* camera_choice_name(CameraChoice choice) { return name_of(kCameraChoices, choice); }
std::vector<std::string> camera_choice_names() { return names_of(kCameraChoices); }

void frame_camera(const MeshView& mesh, Scene& scene, const std::string& what) {
  const double inf = std::numeric_limits<double>::infinity();
  Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  std::size_t finite = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = mesh.positions + 3 * v;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
    // The box of the placed mesh: each point through world_from_object (an affine map keeps the
    // hull, so the placed points' box is the placed mesh's box).
    const Vec3d w = transform_point(scene.world_from_object, Vec3d{p[0], p[1], p[2]});
    lo = {std::fmin(lo.x, w.x), std::fmin(lo.y, w.y), std::fmin(lo.z, w.z)};
    hi = {std::fmax(hi.x, w.x), std::fmax(hi.y, w.y), std::fmax(hi.z, w.z)};
    ++finite;
  }
  if (finite == 0) fail(what, 0, "no finite vertex position: nothing to frame with the camera");
  const Vec3d centre{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
  const Vec3d half{(hi.x - lo.x) / 2, (hi.y - lo.y) / 2, (hi.z - lo.z) / 2};
  double r = length(half);
  if (!std::isfinite(r)) fail(what, 0, "the mesh's extent overflows double: nothing to frame");
  if (r == 0) r = 1;  // one point: a unit sphere around it
  const Vec3d v = kViewFromTarget;
  double distance;
  if (scene.lens.orthographic_height > 0) {
    distance = 2 * r;  // outside the sphere; near/far are fitted
  } else {
    const double half_fov = scene.lens.fov_y_degrees * kRadiansPerDegree / 2;  // (0, 90) degrees: sin > 0
    distance = 1.1 * r / std::sin(half_fov);
  }
  const Vec3d eye{centre.x + distance * v.x, centre.y + distance * v.y, centre.z + distance * v.z};
  Affine3d view;
  if (!look_at(eye, centre, kUp, view)) fail(what, 0, "cannot place the framing camera");  // +z is never parallel to +Y
  scene.camera_from_world = view;
  scene.has_camera = true;
  scene.lens.near = scene.lens.far = 0;  // fitted to the mesh's bounds
}

Scene default_scene() {
  Scene scene;
  scene.model = ShadingModel::Phong;  // Arvo's closed form for the sky's lobe (Blinn-Phong's needs a quadrature: 300x slower)
  scene.global_ambient = {0, 0, 0};
  scene.material.ambient = {0, 0, 0};
  scene.material.diffuse = {0.8, 0.8, 0.8};
  scene.material.specular = {0.25, 0.25, 0.25};
  scene.material.shininess = 32;

  Light sky;
  sky.type = LightType::Sky;
  sky.up = kUp;
  sky.ambient = {0, 0, 0};
  sky.diffuse = {0.1, 0.1, 0.1};     // radiance: a surface facing up gets kd * 0.1 * pi = 0.25
  sky.specular = {0, 0, 0};          // no sky highlight (it would cost a quadrature per point)
  sky.ground = {0.03, 0.03, 0.03};
  scene.lights.push_back(sky);

  Light key;  // from over the right shoulder of a viewer on +z: right +x, up +y, behind +z
  key.type = LightType::Directional;
  key.direction = normalized_or(Vec3d{-0.5, -0.5, -1.0}, Vec3d{0, 0, -1});
  key.ambient = {0, 0, 0};
  key.diffuse = key.specular = {0.75, 0.75, 0.75};
  scene.lights.push_back(key);
  return scene;
}

}  // namespace shadetool
