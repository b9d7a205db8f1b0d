// Tests of lighting/default_scene.h: the framing camera puts every vertex of any mesh, at any
// scale and position, inside the picture with the promised margin (checked by projecting with the
// camera's own matrix, written out here), and the default scene is valid and lights the side of a
// mesh that faces a viewer on +z.
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/default_scene.h>
#include <shadetool/lighting/validate_scene.h>

using namespace shadetool;

namespace {

// A box's 8 corners at `centre` with half extents h.
Mesh box(Vec3d centre, Vec3d h) {
  Mesh m;
  for (int k = 0; k < 8; ++k) {
    m.positions.push_back(centre.x + (k & 1 ? h.x : -h.x));
    m.positions.push_back(centre.y + (k & 2 ? h.y : -h.y));
    m.positions.push_back(centre.z + (k & 4 ? h.z : -h.z));
  }
  m.corner_vertex = {0, 1, 3};
  m.face_start = {0, 3};
  return m;
}

// The largest |y/z| and |x/z| (tangent of the angle off the view axis) over the mesh's vertices in
// camera space, and whether every vertex is in front of the camera.
void extent_in_view(const Mesh& m, const Scene& s, double& tan_max, bool& in_front) {
  tan_max = 0;
  in_front = true;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d p = transform_point(s.camera_from_world, Vec3d{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]});
    in_front = in_front && p.z < 0;
    tan_max = std::fmax(tan_max, std::fmax(std::fabs(p.y / p.z), std::fabs(p.x / p.z)));
  }
}

}  // namespace

TEST_CASE("The framing camera shows every vertex of a mesh at any scale and place", "[lighting][default_scene]") {
  for (double scale : {1e-6, 0.2, 1.0, 1e5})
    for (Vec3d centre : {Vec3d{0, 0, 0}, Vec3d{3e3, -2, 7}}) {
      const Mesh m = box(scale * centre, Vec3d{scale, 2 * scale, 0.5 * scale});
      Scene s = default_scene();
      CHECK_FALSE(s.has_camera);  // render frames the mesh itself
      frame_camera(m, s, "t");
      REQUIRE(s.has_camera);
      double tan_max;
      bool in_front;
      extent_in_view(m, s, tan_max, in_front);
      CHECK(in_front);
      const double half_fov = s.lens.fov_y_degrees / 2 * kRadiansPerDegree;
      // inside the vertical half field of view ...
      CHECK(tan_max < std::tan(half_fov));
      // ... and filling a good part of it: the bounding sphere (radius r) is seen under asin(1/1.1)
      // of the half-angle, so the farthest corner is beyond a third of it whatever the box's shape.
      CHECK(tan_max > std::tan(half_fov) / 3);
    }
}

TEST_CASE("The default scene is valid and lights the side of a mesh that faces the viewer", "[lighting][default_scene]") {
  const Mesh m = box(Vec3d{0, 0, 0}, Vec3d{1, 1, 1});
  Scene s = default_scene();
  CHECK_NOTHROW(validate_scene(s, "default scene"));
  frame_camera(m, s, "t");
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].type == LightType::Sky);
  CHECK(s.lights[1].type == LightType::Directional);
  // The key light travels toward the scene from the viewer's side: against the direction to the eye.
  const Affine3d& V = s.camera_from_world;
  const Vec3d eye_dir = transform_vector(V, s.lights[1].direction);  // in camera space: into the screen is -z
  CHECK(eye_dir.z < 0);
}

TEST_CASE("Framing refuses a mesh with no finite position and takes a unit sphere around one point", "[lighting][default_scene]") {
  Mesh m = box(Vec3d{0, 0, 0}, Vec3d{0, 0, 0});
  Scene s = default_scene();
  frame_camera(m, s, "one point");
  double tan_max;
  bool in_front;
  extent_in_view(m, s, tan_max, in_front);
  CHECK(in_front);
  CHECK(tan_max == Approx(0).margin(1e-12));
  for (double& x : m.positions) x = std::nan("");
  CHECK_THROWS_WITH(frame_camera(m, s, "nan.obj"), Catch::Contains("nan.obj: no finite vertex position"));
}
