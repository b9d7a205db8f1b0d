// render --shadows: the rasterizer's lighting through lib/lighting's light visibility (Embree rays).
// Truth the code does not compute: a unit ground grid z = 0 over [0, 16]^2 and a square occluder
// [4, 8] x [4, 12] at height 4 under a directional light travelling (1, 0, -1): by similar
// triangles the shadow on the ground is [8, 12] x [4, 12], and in it exactly the light's Lambert
// term kd * d * n.l = 0.8 * 1 / sqrt(2) goes missing, nothing else changes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include <shadetool/render/render_mesh.h>
#include "render_test_util.h"

using namespace shadetool;
using namespace shadetool::render_testing;

namespace {

constexpr int kSide = 16;

// Unit squares of the plane z = height over [x0, x1] x [y0, y1], two triangles each, facing +z.
void add_grid(Mesh& m, int x0, int x1, int y0, int y1, double height) {
  const std::uint32_t base = std::uint32_t(m.num_vertices());
  const int nx = x1 - x0 + 1;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) m.positions.insert(m.positions.end(), {double(x), double(y), height});
  for (int y = 0; y < y1 - y0; ++y)
    for (int x = 0; x < x1 - x0; ++x) {
      const std::uint32_t a = base + std::uint32_t(y * nx + x), b = a + 1, c = a + std::uint32_t(nx), d = c + 1;
      m.add_face({a, b, d});
      m.add_face({a, d, c});
    }
}

Scene shadow_scene() {
  Scene s = pixel_exact_scene(kSide);
  s.model = ShadingModel::Lambert;
  s.lights = {directional_light({1, 0, -1})};  // toward +x and down: shadows fall 4 to the right of a height-4 occluder
  return s;
}

RenderResult render(const Mesh& m, RenderShading shading, bool shadows, int threads = 0) {
  RenderOptions o;
  o.shading = shading;
  o.width = o.height = kSide;
  o.threads = threads;
  o.lighting.shadows.enabled = shadows;
  return render_mesh(m, shadow_scene(), o);
}

bool in_shadow(int col, int row) { return col >= 8 && col < 12 && row >= kSide - 12 && row < kSide - 4; }

}  // namespace

TEST_CASE("A shadowed point is darker by exactly the light's unshadowed term, every other pixel is unchanged",
          "[render][shadows]") {
  Mesh m;
  add_grid(m, 0, kSide, 0, kSide, 0.0);
  add_grid(m, 4, 8, 4, 12, 4.0);
  const double term = 0.8 / std::sqrt(2.0);  // kd * d * n.l, n = +z, l = (-1, 0, 1)/sqrt 2
  for (RenderShading shading : {RenderShading::Phong, RenderShading::Flat}) {
    const RenderResult lit = render(m, shading, false), shadowed = render(m, shading, true);
    int dark = 0;
    for (int row = 0; row < kSide; ++row)
      for (int col = 0; col < kSide; ++col) {
        const float* a = lit.image.pixel(col, row);
        const float* b = shadowed.image.pixel(col, row);
        if (in_shadow(col, row)) {
          ++dark;
          for (int k = 0; k < 3; ++k) REQUIRE(std::fabs((double(a[k]) - double(b[k])) - term) < 1e-6);
          for (int k = 0; k < 3; ++k) REQUIRE(std::fabs(double(b[k]) - 0.2 * 0.2) < 1e-6);  // ka * global ambient only
        } else {
          REQUIRE(std::memcmp(a, b, 3 * sizeof(float)) == 0);
        }
      }
    REQUIRE(dark == 32);
  }
  // Gouraud: vertex colours, so only pixels whose four corners are all inside the shadow.
  const RenderResult lit = render(m, RenderShading::Gouraud, false), shadowed = render(m, RenderShading::Gouraud, true);
  for (int k = 0; k < 3; ++k) REQUIRE(std::fabs(double(lit.image.pixel(10, 7)[k] - shadowed.image.pixel(10, 7)[k]) - term) < 1e-6);
  REQUIRE(std::memcmp(lit.image.pixel(14, 7), shadowed.image.pixel(14, 7), 3 * sizeof(float)) == 0);
}

TEST_CASE("With nothing in the way, --shadows leaves the image bitwise unchanged", "[render][shadows]") {
  Mesh m;
  add_grid(m, 0, kSide, 0, kSide, 0.0);
  for (RenderShading shading : {RenderShading::Phong, RenderShading::Gouraud, RenderShading::Flat}) {
    const RenderResult a = render(m, shading, false), b = render(m, shading, true);
    REQUIRE(a.image.rgb.size() == b.image.rgb.size());
    REQUIRE(std::memcmp(a.image.rgb.data(), b.image.rgb.data(), a.image.rgb.size() * sizeof(float)) == 0);
  }
}

TEST_CASE("Shadowed Phong renders are the same bits for 1 and 2 threads", "[render][shadows]") {
  Mesh m;
  add_grid(m, 0, kSide, 0, kSide, 0.0);
  add_grid(m, 4, 8, 4, 12, 4.0);
  Scene s = shadow_scene();
  Light sky;
  sky.type = LightType::Sky;
  sky.up = {0, 0, 1};
  sky.diffuse = sky.specular = {0.5, 0.5, 0.5};
  s.lights.push_back(sky);
  RenderOptions o;
  o.width = o.height = kSide;
  o.samples = 2;
  o.lighting.shadows.enabled = true;
  o.lighting.shadows.samples = 8;
  o.threads = 1;
  const RenderResult one = render_mesh(m, s, o);
  o.threads = 2;
  const RenderResult two = render_mesh(m, s, o);
  REQUIRE(std::memcmp(one.image.rgb.data(), two.image.rgb.data(), one.image.rgb.size() * sizeof(float)) == 0);
  // The sky is partly hidden under the occluder: those ground pixels get less than the open ground.
  REQUIRE(one.image.pixel(6, 15)[0] > one.image.pixel(10, 7)[0]);
}
