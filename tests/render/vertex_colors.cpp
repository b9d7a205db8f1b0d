// A pixel centre that projects exactly onto a vertex shows that vertex's baked colour: Gouraud
// interpolates bake-lighting's colours, Phong evaluates the same equation with the same normal.
#include <catch2/catch.hpp>

#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include "render_test_util.h"

using namespace shadetool;
using namespace shadetool::render_testing;

namespace {

std::uint8_t code(double linear) { return quantize_8bit(srgb_encode(linear)); }

}  // namespace

TEST_CASE("a pixel centre on a vertex gets the vertex's baked colour (gouraud and phong)", "[render][vertex]") {
  // Irregular sphere under a non-trivial world map; for several vertices, a camera on the line
  // through the vertex along its (world) normal, aimed at the vertex: the vertex projects to the
  // image centre, which is a pixel centre for an odd size.
  Mesh mesh = testing::irregular(testing::uv_sphere(24, 12)).mesh;
  Scene base = lit_scene({0, 0, 6});
  base.world_from_object.A = Mat3d::diagonal(1.5, 1.2, 1.0);
  base.world_from_object.t = {0.25, -0.5, 0.125};

  for (std::uint32_t v : {5u, 40u, 77u, 150u, 211u}) {
    const Vec3d p_world = transform_point(base.world_from_object, mesh.position(v));
    const Vec3d n_world = normalized_or(Vec3d(transform_normal(signed_cofactor(base.world_from_object.A), Normal3d(mesh.position(v)))),
                                        Vec3d{0, 0, 1});
    Scene s = base;
    const Vec3d up = std::fabs(n_world.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
    REQUIRE(look_at(p_world + n_world * 4.0, p_world, up, s.camera_from_world));
    const std::vector<double> baked = bake_lighting(mesh, s, ShadingFrequency::PerVertex).rgb;  // same eye
    for (RenderShading shading : {RenderShading::Gouraud, RenderShading::Phong}) {
      RenderOptions o;
      o.shading = shading;
      o.width = o.height = 101;
      const RenderResult r = render_mesh(mesh, s, o);
      const float* px = r.image.pixel(50, 50);
      INFO("vertex " << v << ", " << render_shading_name(shading));
      for (int c = 0; c < 3; ++c) {
        // Gouraud: OpenGL 2.1 clamps the vertex colour to [0, 1] before interpolating (issue 28)
        const double expected =
            shading == RenderShading::Gouraud ? std::min(1.0, std::max(0.0, baked[3 * v + c])) : baked[3 * v + c];
        CHECK(std::abs(int(code(px[c])) - int(code(expected))) <= 1);  // to 1/255 as stored in the PNG
        CHECK(px[c] == Approx(expected).margin(1e-6));                  // and in fact to float rounding
      }
    }
  }
}

TEST_CASE("flat, gouraud and phong agree on a planar mesh under a directional light", "[render][planar]") {
  // On a plane every normal is the plane's; with a light at infinity and no specular the colour is
  // constant, whichever way it is interpolated.
  Mesh mesh;
  const int n = 6;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.add_vertex({-1 + 2.0 * i / n + 0.03 * ((i * 7 + j * 3) % 5 - 2) * (i > 0 && i < n),
                       -1 + 2.0 * j / n + 0.03 * ((i * 2 + j * 5) % 5 - 2) * (j > 0 && j < n), 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if ((i + j) % 3 == 0) {
        mesh.add_face({a, b, d, c});  // some quads, the rest triangles
      } else {
        mesh.add_face({a, b, d});
        mesh.add_face({a, d, c});
      }
    }
  Scene s = lit_scene({0.5, -1, 4});
  s.model = ShadingModel::Lambert;
  s.lights = {directional_light({-1, -2, -3})};
  RenderOptions o;
  o.width = 96;
  o.height = 80;
  o.samples = 2;
  o.shading = RenderShading::Flat;
  const ImageRGB flat = render_mesh(mesh, s, o).image;
  o.shading = RenderShading::Gouraud;
  const ImageRGB gouraud = render_mesh(mesh, s, o).image;
  o.shading = RenderShading::Phong;
  const ImageRGB phong = render_mesh(mesh, s, o).image;
  CHECK(max_abs_difference(flat, gouraud) < 1e-6);
  CHECK(max_abs_difference(flat, phong) < 1e-6);
  // and the colour is the hand-computed one: ambient 0.05 * 0.2 + kd * n.L, L = (1,2,3)/sqrt(14)
  const double nl = 3 / std::sqrt(14.0);
  const float* centre = flat.pixel(48, 40);
  CHECK(centre[0] == Approx(0.2 * 0.05 + 0.7 * nl).margin(1e-6));
  CHECK(centre[2] == Approx(0.2 * 0.05 + 0.3 * nl).margin(1e-6));
}

TEST_CASE("gouraud clamps each vertex colour to [0, 1] before interpolating, as OpenGL 2.1 (--hdr: unclamped)",
          "[render][vertex][issue28]") {
  // issue 28, item 4: interpolating unclamped colours and clamping per pixel made highlights
  // brighter than OpenGL draws them. Truth: the same triangle rendered from colours clamped by
  // hand first, pixel by pixel.
  const int side = 64;
  Mesh mesh;
  mesh.add_vertex({4, 4, 0});
  mesh.add_vertex({60, 8, 0});
  mesh.add_vertex({20, 60, 0});
  mesh.add_face({0, 1, 2});
  const Scene s = pixel_exact_scene(side);
  const std::vector<double> over = {3.0, 0.2, 0.5, 0.1, 2.0, -0.25, 0.5, 0.5, 1.5};  // channels beyond 1 (and below 0)
  const std::vector<double> clamped = {1.0, 0.2, 0.5, 0.1, 1.0, 0.0, 0.5, 0.5, 1.0};  // by hand
  RenderOptions o;
  o.width = o.height = side;
  o.samples = 2;
  o.shading = RenderShading::Gouraud;
  o.vertex_rgb = &over;
  const ImageRGB from_over = render_mesh(mesh, s, o).image;
  o.clamp_vertex_colors = false;  // --hdr
  const ImageRGB hdr = render_mesh(mesh, s, o).image;
  o.vertex_rgb = &clamped;
  const ImageRGB from_clamped = render_mesh(mesh, s, o).image;
  REQUIRE(from_over.rgb.size() == from_clamped.rgb.size());
  std::size_t covered = 0;
  for (std::size_t i = 0; i < from_over.rgb.size(); ++i) {
    CHECK(from_over.rgb[i] == from_clamped.rgb[i]);
    covered += from_over.rgb[i] > 0;
  }
  CHECK(covered > 1000);  // the triangle covers about 1500 pixels: the comparison saw it
  CHECK(max_abs_difference(hdr, from_clamped) > 0.5);  // --hdr keeps the unclamped interpolation
  float brightest = 0;
  for (float c : hdr.rgb) brightest = std::max(brightest, c);
  CHECK(brightest > 1.5f);
}
