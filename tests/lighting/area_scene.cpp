// Area and sky lights through the whole pipeline (shade_points, read_scene): the small-light limit
// against the point light, scale and rotation invariance, the three shading spaces, and bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <iomanip>
#include <random>
#include <string>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/lighting/shade_points.h>
#include "lighting_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

Light rect_light(const Vec3d& c, const Vec3d& u, const Vec3d& v, const Vec3d& radiance, bool two_sided = false) {
  Light L;
  L.type = LightType::Area;
  L.shape = AreaShape::Polygon;
  L.vertices = {c - u - v, c + u - v, c + u + v, c - u + v};
  L.two_sided = two_sided;
  L.diffuse = L.specular = radiance;
  L.ambient = {0, 0, 0};
  return L;
}
Light sphere_light(const Vec3d& c, double r, const Vec3d& radiance) {
  Light L;
  L.type = LightType::Area;
  L.shape = AreaShape::Sphere;
  L.center = c;
  L.radius = r;
  L.diffuse = L.specular = radiance;
  L.ambient = {0, 0, 0};
  return L;
}

void check_rel(const Vec3d& a, const Vec3d& b, double rel) {
  for (int k = 0; k < 3; ++k) {
    INFO(std::setprecision(17) << "channel " << k << ": " << a[k] << " vs " << b[k]);
    CHECK(std::fabs(a[k] - b[k]) <= rel * std::fmax(std::fabs(a[k]), std::fabs(b[k])));
  }
}

Scene lit_scene(ShadingModel model) {
  Scene s = dark_scene(model);
  s.material.diffuse = {0.8, 0.6, 0.4};
  s.material.specular = {0.5, 0.5, 0.5};
  s.material.shininess = 12;
  s.has_camera = true;
  s.camera_from_world = camera_at({0.3, 0.5, 4});
  return s;
}

}  // namespace

TEST_CASE("a small rect or sphere light is, in the limit, the point light with L A cos(theta_light)", "[lighting][area]") {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1, 1);
  for (ShadingModel model : {ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    for (int trial = 0; trial < 40; ++trial) {
      const Vec3d p{u(rng), u(rng), u(rng)};
      const Vec3d n = normalized_or(Vec3d{u(rng), 1.5, u(rng)}, Vec3d{0, 1, 0});
      const Vec3d c{2 * u(rng), 3, 2 * u(rng)};
      const double eps = 1e-5;
      const Vec3d uu = normalized_or(Vec3d{1, u(rng) * 0.3, u(rng)}, Vec3d{1, 0, 0}) * eps;
      const Vec3d vv = normalized_or(cross(uu, Vec3d{0, 1, 0.2 * u(rng)}), Vec3d{0, 0, 1}) * (0.5 * eps);
      Vec3d emit = normalized_or(cross(uu, vv), Vec3d{0, 0, 0});
      const bool flip = dot(emit, p - c) < 0;  // make it face p
      Light area = flip ? rect_light(c, vv, uu, {1, 0.9, 0.7}) : rect_light(c, uu, vv, {1, 0.9, 0.7});
      if (flip) emit = -emit;
      const double A = 4 * length(cross(uu, vv));
      const double cos_l = dot(emit, normalized_or(p - c, Vec3d{0, 0, 0}));
      Light point = point_light(c, {0, 0, 1}, Vec3d{1, 0.9, 0.7} * (A * cos_l));
      Scene with_area = lit_scene(model), with_point = lit_scene(model);
      with_area.lights = {area};
      with_point.lights = {point};
      INFO("model " << int(model) << " trial " << trial);
      check_rel(shade_one(with_area, p, n), shade_one(with_point, p, n), 1e-6);
      // sphere of radius eps: a disc of area pi eps^2 facing p
      Scene with_sphere = lit_scene(model);
      with_sphere.lights = {sphere_light(c, eps, {1, 0.9, 0.7})};
      with_point.lights = {point_light(c, {0, 0, 1}, Vec3d{1, 0.9, 0.7} * (kPi * eps * eps))};
      check_rel(shade_one(with_sphere, p, n), shade_one(with_point, p, n), 1e-6);
    }
  }
}

TEST_CASE("sky = ground gives the uniform pi L; zero normals get only the ambient terms", "[lighting][area]") {
  Scene s = lit_scene(ShadingModel::Lambert);
  s.lights = {sky_light({0.3, 1, 0.2}, {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5})};
  const Vec3d c = shade_one(s, {1, 2, 3}, {0.2, -0.7, 0.1});
  check_rel(c, Vec3d{0.8, 0.6, 0.4} * (kPi * 0.5), 1e-15);
  ShadeReport report;
  const Vec3d zero = shade_one(s, {1, 2, 3}, {0, 0, 0}, {}, &report);
  CHECK(zero == Vec3d{0, 0, 0});
  CHECK(report.counters.zero_normals == 1);
}

namespace {

// Points, normals and a scene with one light of each new kind, then the same scene mapped by a
// similarity x -> s Q x (Q a rotation): colours must not change (P and S are scale-free).
Scene mixed_scene(ShadingModel model, double s, const Mat3d& Q) {
  auto P = [&](const Vec3d& x) { return (Q * x) * s; };
  auto D = [&](const Vec3d& x) { return Q * x; };
  Scene sc = lit_scene(model);
  Affine3d world_from_camera;
  world_from_camera.A = Q;
  world_from_camera.t = P({0.3, 0.5, 4});
  invert_affine(world_from_camera, sc.camera_from_world);
  sc.lights = {rect_light(P({-1, 2.5, 0}), D({0, 0, 0.8}) * s, D({0.6, -0.4, 0}) * s, {3, 2.9, 2.7}),
               sphere_light(P({1.5, 1, 1}), 0.4 * s, {2, 2, 2}),
               sky_light(D({0, 1, 0}), {0.5, 0.7, 1}, {0.3, 0.25, 0.2})};
  Light poly;
  poly.type = LightType::Area;
  poly.vertices = {P({-0.5, -3, -0.5}), P({0.3, -3, -0.8}), P({0.8, -3, 0}), P({0.3, -3, 0.8}), P({-0.5, -3, 0.5})};
  poly.diffuse = poly.specular = {1, 1, 1};
  poly.ambient = {0, 0, 0};
  sc.lights.push_back(poly);
  return sc;
}

Mat3d rotation(double angle, Vec3d axis) {
  axis = normalized_or(axis, Vec3d{0, 0, 1});
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  Mat3d R;
  R.m[0][0] = c + t * axis.x * axis.x;
  R.m[0][1] = t * axis.x * axis.y - s * axis.z;
  R.m[0][2] = t * axis.x * axis.z + s * axis.y;
  R.m[1][0] = t * axis.x * axis.y + s * axis.z;
  R.m[1][1] = c + t * axis.y * axis.y;
  R.m[1][2] = t * axis.y * axis.z - s * axis.x;
  R.m[2][0] = t * axis.x * axis.z - s * axis.y;
  R.m[2][1] = t * axis.y * axis.z + s * axis.x;
  R.m[2][2] = c + t * axis.z * axis.z;
  return R;
}

void sample_points(std::vector<double>& pts, std::vector<double>& nrm, double s, const Mat3d& Q, int count) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < count; ++i) {
    const Vec3d p = (Q * Vec3d{u(rng), u(rng), u(rng)}) * s;
    const Vec3d n = Q * Vec3d{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) pts.push_back(p[k]), nrm.push_back(n[k]);
  }
}

}  // namespace

TEST_CASE("a scene scaled by 1e-100 or 1e100, or rotated, gives the same colours (1e-12)", "[lighting][area]") {
  Mat3d I;
  const Mat3d Q = rotation(0.7, {1, 2, 3});
  for (ShadingModel model : {ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    std::vector<double> p0, n0;
    sample_points(p0, n0, 1, I, 200);
    const std::vector<double> ref = shade_points(mixed_scene(model, 1, I), p0, n0);
    for (double s : {1e-100, 1e100, 1.0}) {
      const Mat3d R = s == 1.0 ? Q : I;
      std::vector<double> p, n;
      sample_points(p, n, s, R, 200);
      const std::vector<double> got = shade_points(mixed_scene(model, s, R), p, n);
      INFO("model " << int(model) << " scale " << s << (s == 1.0 ? " rotated" : ""));
      for (std::size_t i = 0; i < ref.size(); ++i) REQUIRE(got[i] == Approx(ref[i]).epsilon(1e-12).margin(1e-300));
    }
  }
}

TEST_CASE("world, camera and object spaces agree to 1e-9 with shear, non-uniform scale and a mirror", "[lighting][area]") {
  Mat3d I;
  for (ShadingModel model : {ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    Scene sc = mixed_scene(model, 1, I);
    sc.two_sided = true;
    sc.world_from_object.A.m[0][0] = 2;
    sc.world_from_object.A.m[0][1] = 0.7;  // shear
    sc.world_from_object.A.m[1][1] = -0.5;  // mirror
    sc.world_from_object.A.m[2][2] = 1.3;
    sc.world_from_object.t = {0.2, -0.1, 0.3};
    std::vector<double> p, n;
    sample_points(p, n, 1, I, 300);
    ShadeOptions world, camera, object, automatic;
    world.space = ShadingSpace::World;
    camera.space = ShadingSpace::Camera;
    object.space = ShadingSpace::Object;
    const std::vector<double> w = shade_points(sc, p, n, world);
    const std::vector<double> c = shade_points(sc, p, n, camera);
    const std::vector<double> o = shade_points(sc, p, n, object);
    const std::vector<double> a = shade_points(sc, p, n, automatic);
    for (std::size_t i = 0; i < w.size(); ++i) {
      REQUIRE(c[i] == Approx(w[i]).epsilon(1e-9).margin(1e-12));
      REQUIRE(o[i] == Approx(w[i]).epsilon(1e-9).margin(1e-12));
      REQUIRE(a[i] == Approx(w[i]).epsilon(1e-9).margin(1e-12));
    }
  }
}

TEST_CASE("a light wholly below the horizon is skipped and counted", "[lighting][area]") {
  Scene s = lit_scene(ShadingModel::Lambert);
  s.lights = {rect_light({0, -3, 0}, {1, 0, 0}, {0, 0, -1}, {1, 1, 1})};  // below, facing up
  ShadeReport r;
  const Vec3d c = shade_one(s, {0, 0, 0}, {0, 1, 0}, {}, &r);
  CHECK(c == Vec3d{0, 0, 0});
  CHECK(r.counters.below_horizon == 1);
}

namespace {
std::string error_of(const std::string& json) {
  try {
    parse_scene(json, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
std::string with_light(const std::string& light) { return "{\"lights\": [" + light + "]}"; }
}  // namespace

TEST_CASE("bad area and sky lights: one line with the JSON path", "[lighting][area][read_scene]") {
  CHECK(error_of(with_light(R"({"type": "area", "shape": "polygon", "vertices": [[0,0,0],[1,0,0],[1,1,0.1],[0,1,0]]})")) ==
        "s.json: $.lights[0].vertices[1]: not planar: 0.0351794418501 of the polygon's size off the plane of the others");
  CHECK(error_of(with_light(R"({"type": "area", "shape": "polygon", "vertices": [[0,0,0],[2,0,0],[1,0.2,0],[2,2,0],[0,2,0]]})"))
            .rfind("s.json: $.lights[0].vertices[", 0) == 0);
  CHECK(error_of(with_light(R"({"type": "area", "shape": "polygon", "vertices": [[0,0,0],[2,0,0],[1,0.2,0],[2,2,0],[0,2,0]]})"))
            .find("not convex") != std::string::npos);
  CHECK(error_of(with_light(R"({"type": "area", "shape": "polygon", "vertices": [[0,0,0],[1,1,1],[2,2,2]]})")) ==
        "s.json: $.lights[0].vertices: degenerate polygon: its vertices are collinear (zero area)");
  CHECK(error_of(with_light(R"({"type": "area", "shape": "polygon", "vertices": [[0,0,0],[1,0,0],["NaN",1,0]]})")) ==
        "s.json: $.lights[0].vertices[2][0]: must be a number, got a string");
  CHECK(error_of(with_light(R"({"type": "area", "shape": "sphere", "center": [0,0,0], "radius": -1})")) ==
        "s.json: $.lights[0].radius: must be > 0, got -1");
  CHECK(error_of(with_light(R"({"type": "sky", "up": [0,0,0]})")) == "s.json: $.lights[0].up: zero-length direction");
  CHECK(error_of(with_light(R"({"type": "area", "shape": "rect", "center": [0,0,0], "u": [1,0,0], "v": [2,0,0]})")) ==
        "s.json: $.lights[0].v: is parallel to u: the rect has no area");
  CHECK(error_of(with_light(R"({"type": "area", "shape": "disc"})")) ==
        "s.json: $.lights[0].shape: must be \"rect\", \"polygon\" or \"sphere\", got \"disc\"");
  CHECK(error_of(with_light(R"({"type": "area", "shape": "sphere", "center": [0,0,0], "radius": 1, "u": [1,0,0]})")) ==
        "s.json: $.lights[0].u: unknown key in a sphere area light (expected one of: type, shape, center, radius, color, "
        "intensity, ambient)");
  CHECK(error_of(with_light(R"({"type": "lamp"})")) ==
        "s.json: $.lights[0].type: must be \"ambient\", \"directional\", \"point\", \"spot\", \"area\", \"sky\" or \"environment\", got \"lamp\"");
}

TEST_CASE("issue 21: colour x intensity that overflows is refused when read, naming the JSON path", "[lighting][read_scene]") {
  CHECK(error_of(with_light(R"({"type": "ambient", "color": [5.2,0.2,0.3], "intensity": 0.51e308})")) ==
        "s.json: $.lights[0].intensity: color x intensity overflows (5.2 x 5.1e+307 is beyond double's range)");
  CHECK(error_of(with_light(R"({"type": "sky", "sky": [1,1,1], "ground": [4,1,1], "intensity": 1e308})")) ==
        "s.json: $.lights[0].intensity: color x intensity overflows (4 x 1e+308 is beyond double's range)");
}

TEST_CASE("the example scenes of data/scenes read and light", "[lighting][area]") {
  for (const char* name : {"window.json", "area_polygon.json", "area_sphere.json", "sky.json"}) {
    const Scene s = read_scene(std::string(SHADETOOL_SOURCE_DIR) + "/data/scenes/" + name);
    const Vec3d c = shade_one(s, {0, 0, 0}, {0, 1, 0});
    INFO(name);
    CHECK((c.x > 0 && std::isfinite(c.x)));
  }
}
