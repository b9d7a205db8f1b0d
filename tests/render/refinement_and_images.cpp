// Phong and Gouraud converge as a sphere is refined; the image writers; the camera.
#include <catch2/catch.hpp>

#include <cstring>

#include <png.h>

#include <shadetool/core/error.h>
#include <shadetool/io/image_png.h>
#include <shadetool/lighting/read_scene.h>
#include "render_test_util.h"

using namespace shadetool;
using namespace shadetool::render_testing;

TEST_CASE("the Phong-Gouraud difference falls as a sphere is refined", "[render][refinement]") {
  // Gouraud's error in the interpolated colour is O(h^2) on a smooth surface (linear
  // interpolation of a smooth function); each icosphere level halves h: the difference should
  // fall by about 4 per level. Measured over the covered pixels of a 200 x 200 image.
  Scene s = lit_scene({0, 0, 3.2});
  s.material.shininess = 12;
  std::vector<double> diffs;
  for (int level = 1; level <= 5; ++level) {
    const Mesh m = testing::icosphere(level).mesh;
    RenderOptions o;
    o.width = o.height = 200;
    o.samples = 2;
    o.clamp_vertex_colors = false;  // the linear values converge; clamped ones differ where a vertex saturates
    o.shading = RenderShading::Gouraud;
    const RenderResult g = render_mesh(m, s, o);
    o.shading = RenderShading::Phong;
    const RenderResult p = render_mesh(m, s, o);
    double sum = 0;
    std::size_t covered = 0;
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 200; ++x) {
        const float* a = g.image.pixel(x, y);
        const float* b = p.image.pixel(x, y);
        if (a[0] == 0 && b[0] == 0) continue;
        ++covered;
        for (int c = 0; c < 3; ++c) sum += std::fabs(double(a[c]) - double(b[c]));
      }
    diffs.push_back(sum / double(3 * covered));
  }
  for (std::size_t i = 1; i < diffs.size(); ++i) {
    const double rate = diffs[i - 1] / diffs[i];
    WARN("icosphere level " << i + 1 << ": mean |phong - gouraud| = " << diffs[i] << ", fell by " << rate);
    CHECK(diffs[i] < diffs[i - 1]);
  }
  CHECK(diffs.back() < diffs.front() / 20);  // ~4^4 = 256 ideal; sampling noise at the limb caps it
}

TEST_CASE("the PNG is 8-bit RGB with an sRGB chunk and decodes to the bytes written", "[render][png]") {
  const int w = 5, h = 3;
  std::vector<std::uint8_t> px(w * h * 3);
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = std::uint8_t(i * 17);
  const std::string bytes = io::encode_png_srgb8(w, h, px, "t.png");
  REQUIRE(bytes.compare(1, 3, "PNG") == 0);
  CHECK(bytes.find("sRGB") != std::string::npos);
  CHECK(bytes.find("IHDR") == 12);
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  REQUIRE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()));
  image.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> back(PNG_IMAGE_SIZE(image));
  REQUIRE(png_image_finish_read(&image, nullptr, back.data(), 0, nullptr));
  CHECK(image.width == 5);
  CHECK(image.height == 3);
  CHECK(back == px);
  CHECK_THROWS_AS(io::encode_png_srgb8(w, h, std::vector<std::uint8_t>(7), "t.png"), Error);
}

TEST_CASE("scene cameras: fov_y, near, far and orthographic are read and checked", "[render][camera]") {
  const Scene s = parse_scene(R"({"camera": {"eye": [0,0,5], "target": [0,0,0], "fov_y": 30, "near": 1, "far": 9}})", "c.json");
  CHECK(s.lens.fov_y_degrees == 30);
  CHECK(s.lens.near == 1);
  CHECK(s.lens.far == 9);
  const Scene o = parse_scene(R"({"camera": {"eye": [0,0,5], "target": [0,0,0], "orthographic": 4}})", "c.json");
  CHECK(o.lens.orthographic_height == 4);
  CHECK_THROWS_WITH(parse_scene(R"({"camera": {"eye": [0,0,5], "target": [0,0,0], "fov_y": 180}})", "c.json"),
                    Catch::Contains("c.json: $.camera.fov_y: must be in (0, 180)"));
  CHECK_THROWS_WITH(parse_scene(R"({"camera": {"eye": [0,0,5], "target": [0,0,0], "near": 2, "far": 1}})", "c.json"),
                    Catch::Contains("$.camera.far: must be greater than near"));
  CHECK_THROWS_WITH(parse_scene(R"({"camera": {"eye": [0,0,5], "target": [0,0,0], "up": [0,0,1]}})", "c.json"),
                    Catch::Contains("$.camera.up: is parallel to the view direction"));

  // The projection: a point at distance d on the view axis maps to z/w = -1 at near, +1 at far.
  Bounds3d b;
  b.add({-1, -1, -1});
  b.add({1, 1, 1});
  const RenderCamera cam = make_render_camera(s, b, 40, 20);
  const ClipPoint n = cam.to_clip(Vec3d{0, 0, -1}), f = cam.to_clip(Vec3d{0, 0, -9});
  CHECK(n.z / n.w == Approx(-1));
  CHECK(f.z / f.w == Approx(1));
  CHECK(cam.scale_y == Approx(1 / std::tan(15 * testing::kPi / 180)));
  CHECK(cam.scale_x == Approx(cam.scale_y / 2));
  // Fitted: near/far just around the bounds' depth range [4, 6] seen from z = 5.
  Scene fitted = s;
  fitted.lens = CameraLens{};
  const RenderCamera fc = make_render_camera(fitted, b, 40, 20);
  CHECK(fc.near < 4);
  CHECK(fc.near > 3.99);
  CHECK(fc.far > 6);
  CHECK(fc.far < 6.01);
}

TEST_CASE("without a camera the mesh is framed: every vertex inside the image", "[render][camera]") {
  Mesh m = testing::torus(30, 12).mesh;
  Scene s = lit_scene({0, 0, 5});
  s.has_camera = false;
  s.camera_from_world = Affine3d{};
  s.world_from_object.t = {10, -3, 2};
  RenderOptions o;
  o.width = 120;
  o.height = 60;
  const RenderResult r = render_mesh(m, s, o);
  CHECK(r.camera.framed);
  CHECK(r.stats.faces_outside_view == 0);
  CHECK(r.stats.samples_covered > 500);  // the ring fills about 0.64 of the half-height
}

TEST_CASE("bad input: zero size, samples out of range, the eye inside a closed mesh", "[render][bad]") {
  Mesh m = testing::icosphere(2).mesh;
  Scene s = lit_scene({0, 0, 5});
  RenderOptions o;
  o.width = 0;
  CHECK_THROWS_WITH(render_mesh(m, s, o, "m.obj"), Catch::Contains("m.obj: image size 0x600: each side must be 1..16384"));
  o.width = 10;
  o.samples = 0;
  CHECK_THROWS_WITH(render_mesh(m, s, o, "m.obj"), Catch::Contains("m.obj: samples must be 1..16"));
  o.samples = 1;
  o.threads = 1025;
  CHECK_THROWS_WITH(render_mesh(m, s, o, "m.obj"), Catch::Contains("m.obj: threads must be 0..1024"));
  o.threads = 0;
  o.lighting.shadows.enabled = true;
  o.lighting.shadows.samples = 0;
  CHECK_THROWS_WITH(render_mesh(m, s, o, "m.obj"), Catch::Contains("m.obj: shadow samples must be 1..1048576, got 0"));
  o.lighting.shadows = {};
  o.background = {0, -1, 0};
  CHECK_THROWS_WITH(render_mesh(m, s, o, "m.obj"), Catch::Contains("m.obj: background channels must be finite and >= 0"));
  o.background = {0, 0, 0};
  o.lighting.shadows = {};
  // Phong evaluates per sample in world space: a space asked of it is refused, not ignored.
  o.lighting.space = ShadingSpace::Object;
  CHECK_THROWS_WITH(render_mesh(m, s, o, "m.obj"), Catch::Contains("m.obj: space 'object' applies to flat and gouraud"));
  o.shading = RenderShading::Gouraud;
  CHECK_NOTHROW(check_render_options(o, "m.obj"));
  o = RenderOptions();
  o.width = 10;
  Scene inside = lit_scene({0.1, 0.2, 0.3}, {1, 0, 0});
  CHECK_THROWS_WITH(render_mesh(m, inside, o, "m.obj"), Catch::Contains("m.obj: the camera's eye") &&
                                                            Catch::Contains("is inside the mesh"));
  // An open mesh has no inside: a camera above a disc is fine.
  Scene outside = lit_scene({0, 0, 1.5});
  CHECK_NOTHROW(render_mesh(m, outside, o, "m.obj"));
}
