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
        const double expected = baked[3 * v + c];
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
