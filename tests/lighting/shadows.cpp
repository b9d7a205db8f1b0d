// bake-lighting with shadows (issue 18): light_visibility.h's rays through bake_lighting.h, checked
// against values the shadow code does not produce: the equation's unshadowed terms written out,
// the same scene without shadows (bitwise where nothing is in the way), and a symmetric half-blocked
// area light (visible fraction 1/2 by symmetry, within the sampling error).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include <tbb/global_control.h>

#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/light_visibility.h>
#include "lighting_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using shadetool::testing::dark_scene;
using shadetool::testing::directional;
using shadetool::testing::point_light;

namespace {

// Appends a convex polygon (counter-clockwise seen from where its normal points) as one face.
void add_polygon(Mesh& m, const std::vector<Vec3d>& polygon) {
  const auto first = std::uint32_t(m.num_vertices());
  for (const Vec3d& p : polygon) m.positions.insert(m.positions.end(), {p.x, p.y, p.z});
  for (std::uint32_t k = 0; k < polygon.size(); ++k) m.corner_vertex.push_back(first + k);
  m.face_start.push_back(std::uint32_t(m.corner_vertex.size()));
}

std::vector<Vec3d> square(double half, double z, double cx = 0) {
  return {{cx - half, -half, z}, {cx + half, -half, z}, {cx + half, half, z}, {cx - half, half, z}};
}

// A floor (z = 0, half width 5), a square occluder of half width 0.5 at height `occluder_z`, and
// two isolated probe vertices on the floor: 0 at the origin (under the occluder), 1 at (3, 0, 0).
// Every vertex has normal +z (given, so nothing is computed).
Mesh floor_with_occluder(double occluder_z) {
  Mesh m;
  m.positions = {0, 0, 0, 3, 0, 0};
  add_polygon(m, square(5, 0));
  add_polygon(m, square(0.5, occluder_z));
  m.vertex_normals.clear();
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.vertex_normals.insert(m.vertex_normals.end(), {0, 0, 1});
  return m;
}

// Emission e, material ka/kd/ks, global ambient and one light with an ambient part: every term of
// the equation is present, so the test sees which are shadowed.
Scene lit_scene(const Light& light) {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.global_ambient = {0.2, 0.2, 0.2};
  s.material.emission = {0.125, 0, 0};
  s.material.ambient = {0.25, 0.5, 0.5};
  s.material.diffuse = {0.5, 0.25, 0.75};
  s.material.specular = {0.5, 0.5, 0.5};
  s.material.shininess = 8;
  s.has_camera = true;
  s.camera_from_world = testing::camera_at({0.5, 0.25, 4});
  Light l = light;
  l.ambient = {0.5, 0.5, 0.25};
  s.lights.push_back(l);
  return s;
}

Vec3d rgb(const BakeResult& b, std::size_t v) { return {b.rgb[3 * v], b.rgb[3 * v + 1], b.rgb[3 * v + 2]}; }

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

ShadowOptions shadows_on(std::uint32_t samples = 16) {
  ShadowOptions s;
  s.enabled = true;
  s.samples = samples;
  return s;
}

}  // namespace

TEST_CASE("a directional light straight above: the point under the occluder gets ambient and emission only",
          "[lighting][shadows]") {
  const Scene scene = lit_scene(directional({0, 0, -1}));
  const Mesh mesh = floor_with_occluder(1.0);
  const BakeResult shadowed = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows_on());
  const BakeResult plain = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);

  // Under the occluder: e + ka * (global ambient + the light's ambient), nothing else.
  const Vec3d ka = scene.material.ambient;
  const Vec3d expected = scene.material.emission + mul(ka, scene.global_ambient) + mul(ka, scene.lights[0].ambient);
  const Vec3d under = rgb(shadowed, 0);
  CHECK(under.x == Approx(expected.x).epsilon(1e-15));
  CHECK(under.y == Approx(expected.y).epsilon(1e-15));
  CHECK(under.z == Approx(expected.z).epsilon(1e-15));
  // Without shadows it is lit (n.L = 1): the test can tell the two apart.
  CHECK(rgb(plain, 0).x > expected.x + 0.4);

  // Outside the shadow: exactly the unshadowed colour (same bits).
  const Vec3d outside = rgb(shadowed, 1), outside_plain = rgb(plain, 1);
  CHECK(std::memcmp(&outside, &outside_plain, sizeof outside) == 0);
  // ... which is e + ka*(a_g + a_l) + kd*d*1 + ks*s*spec (n.L = 1; checked for the diffuse part).
  CHECK(outside.y >= expected.y + scene.material.diffuse.y - 1e-15);

  CHECK(shadowed.shadows.hard_lights == 1);
  CHECK(shadowed.shadows.shadow_rays == mesh.num_vertices());
  CHECK(shadowed.report.counters.shadowed >= 1);
}

TEST_CASE("a point light with the occluder beyond it casts no shadow; above the occluder it does",
          "[lighting][shadows]") {
  const Mesh mesh = floor_with_occluder(2.0);
  SECTION("light between the point and the occluder") {
    const Scene scene = lit_scene(point_light({0, 0, 1}, {1, 0, 0.5}));
    const BakeResult shadowed = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows_on());
    const BakeResult plain = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
    const Vec3d a = rgb(shadowed, 0), b = rgb(plain, 0);
    CHECK(std::memcmp(&a, &b, sizeof a) == 0);
  }
  SECTION("light above the occluder") {
    const Scene scene = lit_scene(point_light({0, 0, 3}, {1, 0, 0.5}));
    const BakeResult shadowed = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows_on());
    const Vec3d ka = scene.material.ambient;
    const double att = 1.0 / (1.0 + 0.5 * 9.0);  // the ambient term is attenuated, never shadowed
    const Vec3d expected =
        scene.material.emission + mul(ka, scene.global_ambient) + mul(ka, scene.lights[0].ambient) * att;
    const Vec3d a = rgb(shadowed, 0);
    CHECK(a.x == Approx(expected.x).epsilon(1e-15));
    CHECK(a.z == Approx(expected.z).epsilon(1e-15));
  }
}

TEST_CASE("a closed convex mesh is not shadowed by itself: bitwise the unshadowed colours",
          "[lighting][shadows]") {
  Scene scene = lit_scene(directional({-0.3, -0.5, -1}));
  scene.lights.push_back(point_light({2, 1, 3}, {1, 0.1, 0.05}));
  scene.lights.push_back(testing::spot_light({-2, 0, 2}, {1, 0, -1}, 40, 2));
  for (const double scale : {1e-3, 1.0, 1e6}) {
    for (const double offset : {0.0, 1e8}) {
      DYNAMIC_SECTION("scale " << scale << " offset " << offset) {
        Scene s = scene;
        for (int k = 0; k < 3; ++k) s.world_from_object.A.m[k][k] = scale;
        s.world_from_object.t = {offset, -offset, offset};
        for (Light& l : s.lights) l.position = l.position * scale + s.world_from_object.t;
        const Mesh mesh = testing::icosphere(3).mesh;
        for (const auto per : {ShadingFrequency::PerVertex, ShadingFrequency::PerFace}) {
          const BakeResult shadowed = bake_lighting(mesh, s, per, {}, shadows_on());
          const BakeResult plain = bake_lighting(mesh, s, per);
          CHECK(same_bits(shadowed.rgb, plain.rgb));
          CHECK(shadowed.report.counters.shadowed == 0);
        }
      }
    }
  }
}

TEST_CASE("area, sphere and sky lights with nothing in the way: bitwise the unoccluded closed forms",
          "[lighting][shadows]") {
  Scene scene = lit_scene(directional({0, 0, -1}));
  scene.lights.clear();
  Light rect;
  rect.type = LightType::Area;
  rect.shape = AreaShape::Polygon;
  rect.vertices = {{-1, -1, 3}, {-1, 1, 3}, {1, 1, 3}, {1, -1, 3}};  // counter-clockwise seen from below
  rect.diffuse = rect.specular = {2, 2, 2};
  rect.ambient = {0.1, 0.1, 0.1};
  scene.lights.push_back(rect);
  Light ball;
  ball.type = LightType::Area;
  ball.shape = AreaShape::Sphere;
  ball.center = {2, 1, 2};
  ball.radius = 0.5;
  scene.lights.push_back(ball);
  Light sky;
  sky.type = LightType::Sky;
  sky.up = {0, 0, 1};
  sky.diffuse = sky.specular = {0.25, 0.5, 1};
  sky.ground = {0.3, 0.2, 0.1};
  scene.lights.push_back(sky);
  const Mesh mesh = testing::icosphere(3).mesh;
  for (const auto model : {ShadingModel::Lambert, ShadingModel::BlinnPhong}) {
    ShadeOptions options;
    options.model = model;
    const BakeResult shadowed = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, options, shadows_on(8));
    const BakeResult plain = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, options);
    CHECK(same_bits(shadowed.rgb, plain.rgb));
    CHECK(shadowed.report.counters.shadowed == 0);
    CHECK(shadowed.shadows.sampled_lights == 3);
    CHECK(shadowed.shadows.shadow_rays > 0);
  }
}

TEST_CASE("a rect light half hidden by a symmetric occluder: the diffuse term halves, within sampling error",
          "[lighting][shadows]") {
  // Light: square of half width 1 at z = 2 above the probe at the origin; occluder: the x < 0 half
  // of its projection, at z = 1 (x in [-0.5, 0], y in [-0.5, 0.5] hides exactly the directions of
  // the light's x < 0 half). By symmetry the weighted visible fraction is exactly 1/2.
  Scene scene = dark_scene(ShadingModel::Lambert);
  scene.material.diffuse = {1, 1, 1};
  Light rect;
  rect.type = LightType::Area;
  rect.shape = AreaShape::Polygon;
  rect.vertices = {{-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}};
  rect.diffuse = {1, 1, 1};
  scene.lights.push_back(rect);
  Mesh mesh;
  mesh.positions = {0, 0, 0};
  add_polygon(mesh, {{-0.5, -0.5, 1}, {0, -0.5, 1}, {0, 0.5, 1}, {-0.5, 0.5, 1}});
  mesh.vertex_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const double unshadowed = bake_lighting(mesh, scene, ShadingFrequency::PerVertex).rgb[0];
  REQUIRE(unshadowed > 0);
  double previous_error = 1;
  for (const std::uint32_t n : {16u, 256u}) {
    const double f = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows_on(n)).rgb[0] / unshadowed;
    const double error = std::fabs(f - 0.5);
    INFO("samples " << n << " fraction " << f);
    // Scrambled Sobol on a discontinuous integrand: error O(N^-1/2) at worst; 2/sqrt(N) bounds it.
    CHECK(error <= 2.0 / std::sqrt(double(n)));
    CHECK(error <= previous_error + 1e-12);
    previous_error = error;
  }
}

TEST_CASE("shadows: the same bits for 1 and 2 threads", "[lighting][shadows]") {
  // A sphere above a floor under a rect, a sky and a directional light: real shadows on the floor.
  Mesh mesh = testing::icosphere(5).mesh;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) mesh.positions[3 * v + 2] += 1.5;
  add_polygon(mesh, square(4, 0));
  Scene scene = lit_scene(directional({0.2, 0.1, -1}));
  Light rect;
  rect.type = LightType::Area;
  rect.vertices = {{-1, -1, 4}, {-1, 1, 4}, {1, 1, 4}, {1, -1, 4}};
  scene.lights.push_back(rect);
  Light sky;
  sky.type = LightType::Sky;
  sky.up = {0, 0, 1};
  sky.ground = {0.2, 0.2, 0.2};
  scene.lights.push_back(sky);
  std::vector<double> results[2];
  std::size_t shadowed[2] = {0, 0};
  for (int t = 0; t < 2; ++t) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(t + 1));
    const BakeResult b = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows_on(16));
    results[t] = b.rgb;
    shadowed[t] = b.report.counters.shadowed;
  }
  CHECK(mesh.num_vertices() > 4096);  // large enough for the parallel path
  CHECK(shadowed[0] > 0);
  CHECK(shadowed[0] == shadowed[1]);
  CHECK(same_bits(results[0], results[1]));
}

TEST_CASE("shadows on a mesh without faces (points with normals): nothing casts a shadow", "[lighting][shadows]") {
  Mesh cloud;
  cloud.positions = {0, 0, 0, 1, 2, 3, -1, 0.5, 0};
  cloud.vertex_normals = {0, 0, 1, 0, 1, 0, 0, 0, 0};  // the last one zero: ambient and emission only
  Scene scene = lit_scene(directional({0, -0.5, -1}));
  scene.lights.push_back(point_light({0, 3, 3}));
  const BakeResult shadowed = bake_lighting(cloud, scene, ShadingFrequency::PerVertex, {}, shadows_on());
  const BakeResult plain = bake_lighting(cloud, scene, ShadingFrequency::PerVertex);
  CHECK(same_bits(shadowed.rgb, plain.rgb));
  CHECK(shadowed.report.counters.shadowed == 0);
}

TEST_CASE("a sphere light and a sky half hidden by a half-plane occluder: the diffuse term halves",
          "[lighting][shadows]") {
  // The occluder covers x < 0 at z = 1 (a square 2000 wide: the directions it misses are below
  // 0.06 degrees of elevation, a fraction < 1e-6 of the cosine-weighted hemisphere). The probe at
  // the origin faces +z; both lights are symmetric about x = 0, so the visible fraction is 1/2.
  Mesh mesh;
  mesh.positions = {0, 0, 0};
  add_polygon(mesh, {{-1000, -1000, 1}, {0, -1000, 1}, {0, 1000, 1}, {-1000, 1000, 1}});
  mesh.vertex_normals.assign(3 * mesh.num_vertices(), 0.0);
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) mesh.vertex_normals[3 * v + 2] = 1;
  Scene scene = dark_scene(ShadingModel::Lambert);
  scene.material.diffuse = {1, 1, 1};
  Light light;
  light.diffuse = {1, 1, 1};
  SECTION("sphere") {
    light.type = LightType::Area;
    light.shape = AreaShape::Sphere;
    light.center = {0, 0, 3};
    light.radius = 0.5;
  }
  SECTION("sky") {
    light.type = LightType::Sky;
    light.up = {0, 0, 1};
  }
  scene.lights.push_back(light);
  const double unshadowed = bake_lighting(mesh, scene, ShadingFrequency::PerVertex).rgb[0];
  REQUIRE(unshadowed > 0);
  for (const std::uint32_t n : {16u, 256u}) {
    const double f = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows_on(n)).rgb[0] / unshadowed;
    INFO("samples " << n << " fraction " << f);
    CHECK(std::fabs(f - 0.5) <= 2.0 / std::sqrt(double(n)));
  }
}
