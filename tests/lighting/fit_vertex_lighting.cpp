// Tests for lighting/fit_vertex_lighting.h: the least-squares Gouraud colours against the point
// colours, measured by a finer quadrature (12 points, degree 6) than the fit used (3 points), so
// the error is not the fit's own objective; and the case where both must agree (f linear).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <shadetool/lighting/fit_vertex_lighting.h>

#include "lighting/lighting_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

struct Errors {
  double fit, point;
};

// Fit with 3 points per triangle (HDR bounds), then both colour sets measured by the 12-point rule.
Errors errors_of(const Mesh& mesh, const Scene& scene, bool shadows_on, const std::vector<std::uint32_t>* only_faces = nullptr) {
  ShadowOptions shadows;
  shadows.enabled = shadows_on;
  const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  const VertexLightingFit lsq = fit_vertex_lighting(mesh, scene, point, {}, shadows, fit);
  const std::vector<double> world = world_positions(mesh, scene);
  const FitElements e = fit_elements(mesh);
  const FitQuadrature q = fit_quadrature(e, world, 12);
  const std::vector<double> f = lighting_at_quadrature(mesh, scene, q, world, point.vertex_normals, {}, shadows);
  if (!only_faces) return {relative_l2_error(q, f, lsq.rgb, 3), relative_l2_error(q, f, point.rgb, 3)};
  // The same relative L2 distance over the points of the listed faces only.
  const auto error_over_faces = [&](const std::vector<double>& rgb) {
    double num = 0, den = 0;
    for (std::size_t s = 0; s < q.size(); ++s) {
      const FitPoint p = q.point(s);
      if (std::find(only_faces->begin(), only_faces->end(), p.face) == only_faces->end()) continue;
      for (int k = 0; k < 3; ++k) {
        double g = 0;
        for (int j = 0; j < p.corners; ++j) g += p.phi[j] * rgb[3 * p.node[j] + k];
        num += p.weight * (g - f[3 * s + k]) * (g - f[3 * s + k]);
        den += p.weight * f[3 * s + k] * f[3 * s + k];
      }
    }
    return den > 0 ? std::sqrt(num / den) : 0.0;  // divisor checked
  };
  return {error_over_faces(lsq.rgb), error_over_faces(point.rgb)};
}

}  // namespace

TEST_CASE("Planar mesh, directional Lambert light: f is linear on every face, so the fit is the point colours",
          "[lighting][fit]") {
  Mesh m;
  for (int j = 0; j <= 5; ++j)
    for (int i = 0; i <= 5; ++i) m.add_vertex({i + 0.2 * std::sin(5.0 * j), j + 0.1 * std::cos(2.0 * i), 0});
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const std::uint32_t a = std::uint32_t(j * 6 + i);
      m.add_face({a, a + 1, a + 7});
      m.add_face({a, a + 7, a + 6});
    }
  Scene scene = dark_scene(ShadingModel::Lambert);
  scene.material.diffuse = {0.8, 0.6, 0.4};
  scene.lights.push_back(directional({0.3, -0.2, -1}));
  const BakeResult point = bake_lighting(m, scene, ShadingFrequency::PerVertex);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  fit.solve.regularization = 0.1;  // zero on a linear signal of a plane
  const VertexLightingFit lsq = fit_vertex_lighting(m, scene, point, {}, {}, fit);
  REQUIRE(lsq.solve.clamped == 0);
  for (std::size_t i = 0; i < point.rgb.size(); ++i) CHECK(lsq.rgb[i] == Approx(point.rgb[i]).epsilon(1e-8));
  CHECK(lsq.error_fit < 1e-8);
  CHECK(lsq.error_point < 1e-12);
}

TEST_CASE("Coarse sphere under a point light with a Phong highlight: the fitted error is below the point error",
          "[lighting][fit]") {
  const Mesh sphere = icosphere(2).mesh;  // 162 vertices
  REQUIRE(sphere.num_vertices() <= 500);
  Scene scene = dark_scene(ShadingModel::Phong);
  scene.material.diffuse = {0.6, 0.6, 0.6};
  scene.material.specular = {0.5, 0.5, 0.5};
  scene.material.shininess = 40;
  scene.material.ambient = {0.1, 0.1, 0.1};
  scene.global_ambient = {1, 1, 1};
  scene.lights.push_back(point_light({2.5, 1.5, 3}));
  scene.camera_from_world = camera_at({0, 0, 4});
  scene.has_camera = true;
  const Errors e = errors_of(sphere, scene, false);
  WARN("sphere, Phong highlight: relative L2 error, least squares " << e.fit << ", point " << e.point);
  CHECK(e.fit < e.point);
}

TEST_CASE("Shadow edge on a ground plane: the fitted error is below the point error", "[lighting][fit]") {
  // a 12 x 12 ground grid (z = 0) and a closed box above it, lit from above at an angle
  Mesh m;
  const int n = 12;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.add_vertex({-3 + 6.0 * i / n, -3 + 6.0 * j / n, 0});
  std::vector<std::uint32_t> ground;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = std::uint32_t(j * (n + 1) + i);
      ground.push_back(std::uint32_t(m.num_faces()));
      m.add_face({a, a + 1, a + std::uint32_t(n) + 2});
      ground.push_back(std::uint32_t(m.num_faces()));
      m.add_face({a, a + std::uint32_t(n) + 2, a + std::uint32_t(n) + 1});
    }
  const std::uint32_t b = std::uint32_t(m.num_vertices());
  for (int k = 0; k < 8; ++k) m.add_vertex({k & 1 ? 0.9 : -0.7, k & 2 ? 0.8 : -0.9, k & 4 ? 2.0 : 1.0});
  const std::uint32_t box[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : box) m.add_face({b + f[0], b + f[1], b + f[2], b + f[3]});
  Scene scene = dark_scene(ShadingModel::Lambert);
  scene.material.diffuse = {0.8, 0.8, 0.8};
  scene.material.ambient = {0.2, 0.2, 0.2};
  scene.global_ambient = {1, 1, 1};
  scene.lights.push_back(directional({0.45, 0.3, -1}));
  const Errors e = errors_of(m, scene, true, &ground);
  WARN("ground plane, shadow edge: relative L2 error, least squares " << e.fit << ", point " << e.point);
  CHECK(e.fit < e.point);
}

TEST_CASE("Skipping the error measure (no --stats) leaves the fitted colours bit for bit", "[lighting][fit]") {
  // Truth: the same fit with the errors measured; the errors are NaN when not measured and finite
  // (the fit's below the point colours') when they are.
  const Mesh mesh = shadetool::testing::icosphere(2).mesh;
  Scene scene = dark_scene(ShadingModel::Phong);  // the highlight of the sphere test above
  scene.material.diffuse = {0.6, 0.6, 0.6};
  scene.material.specular = {0.5, 0.5, 0.5};
  scene.material.shininess = 40;
  scene.lights.push_back(point_light({2.5, 1.5, 3}));
  scene.camera_from_world = camera_at({0, 0, 4});
  scene.has_camera = true;
  const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  fit.solve.upper = 1;
  fit.solve.accuracy = kEightBitFitAccuracy;
  const VertexLightingFit measured = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
  fit.measure_error = false;
  const VertexLightingFit quiet = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
  CHECK(quiet.rgb == measured.rgb);
  CHECK(quiet.solve.iterations == measured.solve.iterations);
  CHECK(std::isnan(quiet.error_fit));
  CHECK(std::isnan(quiet.error_point));
  CHECK(std::isfinite(measured.error_fit));
  CHECK(measured.error_fit < measured.error_point);
}

TEST_CASE("Without the point colours (VertexColors::None) the fit is the same bits; its fallback vertices are lit as the "
          "full bake lights them",
          "[lighting][fit]") {
  // Truth: the fit given the full point bake (every vertex shaded by shade_points), whose colours
  // are also the fallback vertices' expected values. The mesh has two fallback vertices: an isolated
  // one and one whose only face has no area (its three corners on a line).
  Mesh mesh = shadetool::testing::icosphere(2).mesh;
  mesh.add_vertex({0.1, 0.0, 1.2});  // isolated
  const std::uint32_t a = std::uint32_t(mesh.num_vertices());
  mesh.add_vertex({1.2, 0.0, 0.1});
  mesh.add_vertex({1.3, 0.0, 0.1});
  mesh.add_vertex({1.4, 0.0, 0.1});
  mesh.add_face({a, a + 1, a + 2});  // collinear: no area
  // The input's normals (the sphere's radial ones; the extra vertices' facing the sphere sideways):
  // the fallback vertices are lit, and the sphere hides part of their sky (rays seeded with their ids).
  mesh.vertex_normals = mesh.positions;
  set3(mesh.vertex_normals, a - 1, {1, 0, 0.2});
  for (std::uint32_t v = a; v < a + 3; ++v) set3(mesh.vertex_normals, v, {-1, 0, 0.5});
  Scene scene = dark_scene(ShadingModel::Phong);
  scene.material.diffuse = {0.6, 0.6, 0.6};
  scene.material.specular = {0.5, 0.5, 0.5};
  scene.material.shininess = 40;
  scene.lights.push_back(point_light({2.5, 1.5, 3}));
  scene.lights.push_back(directional({-0.3, 0.2, -1}));
  scene.lights.push_back(sky_light({0, 0, 1}, {0.3, 0.3, 0.4}, {0.1, 0.1, 0.1}));  // sampled: its rays' seeds matter
  scene.camera_from_world = camera_at({0, 0, 4});
  scene.has_camera = true;
  for (bool shadows_on : {false, true}) {
    INFO("shadows " << shadows_on);
    ShadowOptions shadows;
    shadows.enabled = shadows_on;
    const BakeResult full = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows);
    const BakeResult bare = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, shadows, VertexColors::None);
    CHECK(bare.rgb.empty());
    CHECK(bare.vertex_normals == full.vertex_normals);
    CHECK(bare.report.plan.lights.size() == full.report.plan.lights.size());
    VertexFitOptions fit;
    fit.method = VertexFit::LeastSquares;
    fit.solve.upper = 1;
    fit.solve.accuracy = kEightBitFitAccuracy;
    fit.measure_error = false;
    const VertexLightingFit with = fit_vertex_lighting(mesh, scene, full, {}, shadows, fit);
    const VertexLightingFit without = fit_vertex_lighting(mesh, scene, bare, {}, shadows, fit);
    CHECK(with.solve.fallback_nodes == 4);  // the isolated vertex and the three of the flat face
    CHECK(without.solve.fallback_nodes == 4);
    CHECK(without.rgb == with.rgb);
    CHECK(without.fallback_counters.points == 4);
    if (shadows_on) CHECK(without.fallback_counters.shadowed > 0);  // the sky partly hidden: the seeds matter
    for (std::uint32_t v : {a - 1, a, a + 1, a + 2})
      for (int k = 0; k < 3; ++k) CHECK(without.rgb[3 * v + k] == std::min(std::max(full.rgb[3 * v + k], 0.0), 1.0));
  }
}

TEST_CASE("f clamped as it is shaded (lighting_at_sites' bounds) is the unclamped f clamped after, bit for bit, "
          "with and without shadows",
          "[lighting][fit]") {
  // Truth: the unbounded f (the default bounds change nothing: every value compared with the
  // unbounded call's) with std::min(std::max(v, lower), upper) applied here afterwards. A bright
  // point light with a highlight puts values above 1, a dark side below 0.2; bounds [0.2, 1].
  const Mesh sphere = icosphere(2).mesh;
  Scene scene = dark_scene(ShadingModel::Phong);
  scene.material.diffuse = {0.9, 0.9, 0.9};
  scene.material.specular = {0.9, 0.9, 0.9};
  scene.material.shininess = 20;
  scene.lights.push_back(point_light({2.5, 1.5, 3}, {1, 0, 0}, {3, 3, 3}));
  scene.camera_from_world = camera_at({0, 0, 4});
  scene.has_camera = true;
  const BakeResult point = bake_lighting(sphere, scene, ShadingFrequency::PerVertex, {}, {});
  const std::vector<double> world = world_positions(sphere, scene);
  const FitElements e = fit_elements(sphere);
  for (int samples : {1, 3}) {
    const FitQuadrature q = fit_quadrature(e, world, samples);
    for (bool shadows_on : {false, true}) {
      ShadowOptions shadows;
      shadows.enabled = shadows_on;
      const std::vector<double> raw = lighting_at_sites(sphere, scene, q, world, point.vertex_normals, {}, shadows);
      const std::vector<double> bounded =
          lighting_at_sites(sphere, scene, q, world, point.vertex_normals, {}, shadows, nullptr, 0.2, 1.0);
      REQUIRE(bounded.size() == raw.size());
      std::size_t above = 0, below = 0, differ = 0;
      for (std::size_t i = 0; i < raw.size(); ++i) {
        above += raw[i] > 1.0;
        below += raw[i] < 0.2;
        const double expected = std::min(std::max(raw[i], 0.2), 1.0);
        differ += std::memcmp(&expected, &bounded[i], sizeof expected) != 0;
      }
      INFO(samples << " points, shadows " << shadows_on << ": " << above << " values above 1, " << below << " below 0.2");
      CHECK(above > 0);
      CHECK(below > 0);
      CHECK(differ == 0);
    }
  }
}
