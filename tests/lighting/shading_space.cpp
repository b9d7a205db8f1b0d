// Shading spaces: world, camera and object space give the same colours (to 1e-6 per channel in
// float output) for random scenes whose M has non-uniform scale, shear, rotation, translation and
// mirrors; object space equals an independently built world-space mesh; auto picks the cheapest.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include <shadetool/lighting/encode_color.h>
#include <shadetool/lighting/look_at.h>
#include <shadetool/lighting/shade_points.h>
#include <shadetool/lighting/shading_space.h>
#include "lighting_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

Mat3d rotation(const Vec3d& axis_in, double angle) {  // Rodrigues
  const Vec3d k = normalized_or(axis_in, Vec3d{0, 0, 1});
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  Mat3d R;
  R.m = {{{t * k.x * k.x + c, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y},
          {t * k.x * k.y + s * k.z, t * k.y * k.y + c, t * k.y * k.z - s * k.x},
          {t * k.x * k.z - s * k.y, t * k.y * k.z + s * k.x, t * k.z * k.z + c}}};
  return R;
}

struct Rng {
  std::mt19937 gen;
  explicit Rng(unsigned seed) : gen(seed) {}
  double u(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
  Vec3d v(double a, double b) { return {u(a, b), u(a, b), u(a, b)}; }
  Vec3d dir() { return normalized_or(v(-1, 1), Vec3d{0, 0, 1}); }
};

// A = R * Shear * diag(scales), possibly a mirror; t random.
Affine3d random_affine(Rng& r, bool mirror) {
  Mat3d H;  // shear: unit upper triangle
  H.m = {{{1, r.u(-0.8, 0.8), r.u(-0.8, 0.8)}, {0, 1, r.u(-0.8, 0.8)}, {0, 0, 1}}};
  const Mat3d S = Mat3d::diagonal(r.u(0.3, 3) * (mirror ? -1 : 1), r.u(0.3, 3), r.u(0.3, 3));
  Affine3d M;
  M.A = rotation(r.v(-1, 1), r.u(0, 6.28)) * H * S;
  M.t = r.v(-2, 2);
  return M;
}

Scene random_scene(Rng& r, ShadingModel model, bool mirror, bool general_camera) {
  Scene s;
  s.model = model;
  s.world_from_object = random_affine(r, mirror);
  const Vec3d center = s.world_from_object.t;
  s.has_camera = true;
  if (general_camera) {
    s.camera_from_world = random_affine(r, false);  // a "view" with scale and shear
  } else {
    REQUIRE(look_at(center + r.dir() * r.u(5, 9), center + r.v(-0.5, 0.5), {0, 1, 0}, s.camera_from_world));
  }
  s.global_ambient = r.v(0, 0.2);
  s.two_sided = r.u(0, 1) < 0.5;
  s.material.ambient = r.v(0, 1);
  s.material.diffuse = r.v(0, 1);
  s.material.specular = r.v(0, 1);
  s.material.emission = r.v(0, 0.05);
  const double shininess[] = {1, 8, 32, 128, r.u(1, 64)};
  s.material.shininess = shininess[std::uniform_int_distribution<int>(0, 4)(r.gen)];

  s.lights.push_back(directional(r.dir(), r.v(0.2, 1)));
  for (int k = 0; k < 2; ++k) {
    Light p = point_light(center + r.dir() * r.u(3, 6), {r.u(0.2, 1), r.u(0, 0.2), r.u(0, 0.05)}, r.v(0.5, 2));
    p.ambient = r.v(0, 0.1);
    s.lights.push_back(p);
  }
  for (int k = 0; k < 2; ++k) {
    const Vec3d pos = center + r.dir() * r.u(3, 6);
    Light sp = spot_light(pos, center - pos + r.v(-0.5, 0.5), r.u(25, 80), r.u(0, 10));
    sp.attenuation = {r.u(0.5, 1), r.u(0, 0.1), r.u(0, 0.02)};
    sp.diffuse = sp.specular = r.v(0.5, 2);
    s.lights.push_back(sp);
  }
  Light ambient;
  ambient.type = LightType::Ambient;
  ambient.ambient = r.v(0, 0.1);
  s.lights.push_back(ambient);
  return s;
}

// Positions and normals of an ellipsoid (object space), flat arrays.
struct Points {
  std::vector<double> p, n;
};
Points ellipsoid_points(double a, double b, double c, const Mat3d& R = Mat3d::identity(), const Vec3d& t = {0, 0, 0},
                        double mirror_x = 1) {
  AnalyticMesh e = uv_ellipsoid(24, 16, a, b, c);
  Points out;
  for (std::size_t v = 0; v < e.mesh.num_vertices(); ++v) {
    Vec3d p = e.mesh.position(v), n = e.exact_normals[v];
    p.x *= mirror_x;
    n.x *= mirror_x;
    p = R * p + t;
    n = R * n;
    out.p.insert(out.p.end(), {p.x, p.y, p.z});
    out.n.insert(out.n.end(), {n.x, n.y, n.z});
  }
  return out;
}

std::vector<float> shade_float(const Scene& scene, const Points& pts, ShadingSpace space, ShadeReport* report = nullptr) {
  ShadeOptions o;
  o.space = space;
  ColorEncoding hdr;
  hdr.hdr = true;
  return encode_colors(shade_points(scene, pts.p, pts.n, o, report), hdr);
}

double max_abs_difference(const std::vector<float>& a, const std::vector<float>& b) {
  REQUIRE(a.size() == b.size());
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(double(a[i]) - double(b[i])));
  return m;
}

}  // namespace

TEST_CASE("world, camera and object space agree to 1e-6 on random scenes", "[lighting][space]") {
  Rng r(20240607);
  const Points pts = ellipsoid_points(1, 0.6, 0.8);
  std::size_t lit_evaluations = 0, cone_tests = 0;
  double spread = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const ShadingModel model = trial % 3 == 0 ? ShadingModel::Lambert
                                              : trial % 3 == 1 ? ShadingModel::Phong : ShadingModel::BlinnPhong;
    const bool mirror = trial % 4 == 3;
    const bool general_camera = trial % 5 == 4;
    const Scene scene = random_scene(r, model, mirror, general_camera);
    INFO("trial " << trial << " model " << shading_model_name(model) << " mirror " << mirror << " general camera "
                  << general_camera);
    ShadeReport report;
    const auto world = shade_float(scene, pts, ShadingSpace::World, &report);
    const auto camera = shade_float(scene, pts, ShadingSpace::Camera);
    const auto object = shade_float(scene, pts, ShadingSpace::Object);
    const auto chosen = shade_float(scene, pts, ShadingSpace::Auto);
    CHECK(max_abs_difference(world, camera) <= 1e-6);
    CHECK(max_abs_difference(world, object) <= 1e-6);
    CHECK(max_abs_difference(world, chosen) <= 1e-6);

    lit_evaluations += report.counters.vertex_light_evaluations - report.counters.back_facing -
                       report.counters.outside_cone;
    cone_tests += report.counters.outside_cone;
    const auto [lo, hi] = std::minmax_element(world.begin(), world.end());
    spread += *hi - *lo;
  }
  // The comparison is not vacuous: lights reach the points, cones cut some off, colours vary.
  CHECK(lit_evaluations > 10000);
  CHECK(cone_tests > 100);
  CHECK(spread / 60 > 0.3);
}

TEST_CASE("object space with a non-uniform, mirrored M equals the mesh built in world space", "[lighting][space]") {
  // The ellipsoid x^2/a^2 + ... mapped by diag(sx, sy, sz) is the ellipsoid with semi-axes
  // (sx a, sy b, sz c): its exact normals at the same parameters are the truth in world space,
  // computed without any normal transform. Then rotate and translate both (rigid: exact for normals).
  const Mat3d R = rotation({1, 2, 3}, 0.7);
  const Vec3d t{0.5, -1, 2};
  for (double mirror : {1.0, -1.0}) {
    INFO("mirror " << mirror);
    Scene scene;
    scene.model = ShadingModel::BlinnPhong;
    scene.material.specular = {0.8, 0.8, 0.8};
    scene.material.shininess = 20;
    scene.has_camera = true;
    REQUIRE(look_at({4, 3, 6}, t, {0, 1, 0}, scene.camera_from_world));
    scene.lights = {directional({-1, -2, -0.5}), point_light(t + Vec3d{2, 3, 1}, {1, 0.2, 0.05}),
                    spot_light(t + Vec3d{-3, 2, 2}, Vec3d{3, -2, -2}, 50, 3)};

    // world-space truth: M = identity, mesh already in the world
    const Points world_mesh = ellipsoid_points(2 * 1, 0.5 * 1.5, 1.5 * 0.7, R, t, mirror);
    const auto truth = shade_float(scene, world_mesh, ShadingSpace::World);

    // object mesh, placed by M = (R diag(mirror*2, 0.5, 1.5), t)
    const Points object_mesh = ellipsoid_points(1, 1.5, 0.7);
    scene.world_from_object.A = R * Mat3d::diagonal(mirror * 2, 0.5, 1.5);
    scene.world_from_object.t = t;
    for (ShadingSpace space : {ShadingSpace::World, ShadingSpace::Camera, ShadingSpace::Object}) {
      INFO("space " << shading_space_name(space));
      CHECK(max_abs_difference(truth, shade_float(scene, object_mesh, space)) <= 1e-6);
    }
    const auto [lo, hi] = std::minmax_element(truth.begin(), truth.end());
    CHECK(*hi - *lo > 0.5);  // lit, with highlights
  }
}

TEST_CASE("lambert does not depend on the camera", "[lighting][space]") {
  Rng r(7);
  const Points pts = ellipsoid_points(1, 0.6, 0.8);
  for (int trial = 0; trial < 10; ++trial) {
    Scene a = random_scene(r, ShadingModel::Lambert, trial % 2 == 1, false);
    a.two_sided = false;  // two-sided lighting reads the eye by definition
    Scene b = a;
    REQUIRE(look_at({-7, 1, 2}, {0, 0, 0}, {0, 0, 1}, b.camera_from_world));
    for (ShadingSpace space : {ShadingSpace::World, ShadingSpace::Object, ShadingSpace::Auto}) {
      CHECK(shade_float(a, pts, space) == shade_float(b, pts, space));  // bitwise
    }
    CHECK(max_abs_difference(shade_float(a, pts, ShadingSpace::Camera), shade_float(b, pts, ShadingSpace::Camera)) <=
          1e-6);
  }
}

TEST_CASE("metric classification: rotation, similarity, general", "[lighting][space]") {
  const Mat3d R = rotation({0.3, -1, 2}, 1.1);
  CHECK(metric_of(R).kind == MetricKind::Identity);
  const SpaceMetric s = metric_of(R * Mat3d::diagonal(2, 2, 2));
  CHECK(s.kind == MetricKind::Scaled);
  CHECK(s.scale2 == Approx(4).epsilon(1e-14));
  const SpaceMetric mirror = metric_of(R * Mat3d::diagonal(-1, 1, 1));
  CHECK(mirror.kind == MetricKind::Identity);
  Mat3d shear;
  shear.m = {{{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}}};
  const SpaceMetric g = metric_of(R * shear);
  REQUIRE(g.kind == MetricKind::General);
  const Mat3d I = transpose(g.B_inverse_transpose) * g.B;  // B^-1 B
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) CHECK(I.m[i][j] == Approx(i == j ? 1.0 : 0.0).margin(1e-14));
}

TEST_CASE("auto picks the cheapest space", "[lighting][space]") {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.diffuse = {1, 1, 1};
  s.material.specular = {1, 1, 1};
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 0, 5});
  s.lights = {point_light({1, 2, 3}), point_light({-1, 2, 3})};

  ShadeReport report;
  // M = identity: nothing to transform anywhere; object space (tie broken toward object).
  shade_one(s, {0, 0, 0}, {0, 0, 1}, {}, &report);
  CHECK(report.space == ShadingSpace::Object);
  CHECK(report.transforms_skipped);

  // A similarity (rotation, uniform scale 3, translation): object space with G = 9 I.
  s.world_from_object.A = rotation({1, 1, 0}, 0.4) * Mat3d::diagonal(3, 3, 3);
  s.world_from_object.t = {1, 2, 3};
  shade_one(s, {0, 0, 0}, {0, 0, 1}, {}, &report);
  CHECK(report.space == ShadingSpace::Object);

  // A shear with two point lights and specular: object space would pay the metric per light
  // (15 + 45 + 2*15 = 90) against world space's transforms (15 + 18 = 33).
  s.world_from_object.A.m = {{{1, 0.7, 0}, {0, 1, 0}, {0, 0, 2}}};
  shade_one(s, {0, 0, 0}, {0, 0, 1}, {}, &report);
  CHECK(report.space == ShadingSpace::World);
  CHECK_FALSE(report.transforms_skipped);

  // The same shear lit by one directional light, lambert: no positions needed; the normal
  // costs the same either way (15), and object space avoids the per-point matrix work.
  s.model = ShadingModel::Lambert;
  s.lights = {directional({0, 0, -1})};
  shade_one(s, {0, 0, 0}, {0, 0, 1}, {}, &report);
  CHECK(report.space == ShadingSpace::Object);

  // Whatever it picks, auto's cost is the least of the three.
  const SpaceChoice choice = choose_space(s, plan_lighting(s, s.model));
  CHECK(choice.cost[2] <= std::min(choice.cost[0], choice.cost[1]));
}

TEST_CASE("spaces agree also for a badly conditioned M (cond 1e5)", "[lighting][space]") {
  // Object space measures with the metric of A; its error must grow like cond(A), as world space's
  // normal transform does, not like cond(A)^2 (which forming G = A^T A would give).
  Rng r(99);
  const Points pts = ellipsoid_points(1, 0.6, 0.8);
  for (int trial = 0; trial < 10; ++trial) {
    Scene s = random_scene(r, trial % 2 ? ShadingModel::Phong : ShadingModel::BlinnPhong, false, false);
    Mat3d H;
    H.m = {{{1, 0.9, 0.5}, {0, 1, -0.7}, {0, 0, 1}}};
    s.world_from_object.A = rotation(r.v(-1, 1), r.u(0, 6)) * H * Mat3d::diagonal(300, 1, 1.0 / 300);
    // lights and eye around the (now very flat, very long) object
    const auto world = shade_float(s, pts, ShadingSpace::World);
    const auto object = shade_float(s, pts, ShadingSpace::Object);
    const auto camera = shade_float(s, pts, ShadingSpace::Camera);
    INFO("trial " << trial);
    CHECK(max_abs_difference(world, object) <= 1e-6);
    CHECK(max_abs_difference(world, camera) <= 1e-6);
  }
}
