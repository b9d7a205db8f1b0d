// Near-plane clipping, mirrors in world_from_object, thread-count independence, quads without a
// diagonal seam.
#include <catch2/catch.hpp>

#include <random>

#include <shadetool/render/clip_polygon.h>
#include <shadetool/render/inverse_bilinear.h>
#include "render_test_util.h"

using namespace shadetool;
using namespace shadetool::render_testing;

TEST_CASE("a ground plane reaching behind the camera is clipped at the near plane, not dropped", "[render][clip]") {
  // Two huge triangles (the plane y = 0, |x|, |z| <= 1000) and a camera 1 above it looking along
  // -z: both triangles cross the near plane. Below the horizon every pixel must show the plane,
  // in its exact colour (lambert, light straight down: ambient + kd * 1).
  Mesh m;
  m.add_vertex({-1000, 0, 1000});
  m.add_vertex({1000, 0, 1000});
  m.add_vertex({1000, 0, -1000});
  m.add_vertex({-1000, 0, -1000});
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  Scene s = lit_scene({0, 1, 0}, {0, 1, -1});
  s.model = ShadingModel::Lambert;
  s.lights = {directional_light({0, -1, 0})};
  s.lens.fov_y_degrees = 90;
  RenderOptions o;
  o.width = 64;
  o.height = 48;
  for (RenderShading shading : {RenderShading::Flat, RenderShading::Gouraud, RenderShading::Phong}) {
    o.shading = shading;
    const RenderResult r = render_mesh(m, s, o);
    INFO(render_shading_name(shading));
    CHECK(r.stats.triangles_near_clipped == 2);
    CHECK(r.stats.faces_outside_view == 0);
    const double expected_r = 0.2 * 0.05 + 0.7;
    for (int row = 26; row < 48; ++row)  // the horizon is at row 24; the far edge is < 1/40 pixel above it
      for (int col = 0; col < 64; ++col) {
        INFO("pixel " << col << "," << row);
        REQUIRE(r.image.pixel(col, row)[0] == Approx(expected_r).margin(1e-5));
      }
    for (int row = 0; row < 23; ++row)
      for (int col = 0; col < 64; ++col) REQUIRE(r.image.pixel(col, row)[0] == 0.0f);
  }
}

TEST_CASE("a clipped edge shared by two triangles is cut at the same point in both", "[render][clip]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-5, 5);
  for (int i = 0; i < 1000; ++i) {
    ClipVertex a{U(rng), U(rng), U(rng), U(rng), {1, 0, 0}}, b{U(rng), U(rng), U(rng), U(rng), {0, 1, 0}};
    const double da = clip_distance(a, 0, 2), db = clip_distance(b, 0, 2);
    if (!((da < 0) != (db < 0)) || da == 0 || db == 0) continue;
    const ClipVertex p = clip_intersection(a, b, da, db), q = clip_intersection(b, a, db, da);
    CHECK(p.x == q.x);
    CHECK(p.y == q.y);
    CHECK(p.z == q.z);
    CHECK(p.w == q.w);
    CHECK(std::fabs(clip_distance(p, 0, 2)) < 1e-12 * (std::fabs(da) + std::fabs(db)));
  }
}

TEST_CASE("a mirror in world_from_object renders as the mirrored mesh with the identity", "[render][mirror]") {
  Mesh mesh = testing::irregular(testing::torus(24, 12)).mesh;
  Scene s = lit_scene({1, 2, 5});
  s.world_from_object.A = Mat3d::diagonal(-1, 1, 1);
  s.world_from_object.t = {0.2, 0, 0};
  Mesh mirrored = mesh;
  for (std::size_t v = 0; v < mirrored.num_vertices(); ++v) {
    const Vec3d p = mirrored.position(v);
    mirrored.set_position(v, {0.2 - p.x, p.y, p.z});
  }
  for (std::size_t f = 0; f < mirrored.num_faces(); ++f)  // a mirror reverses the winding
    std::reverse(mirrored.corner_vertex.begin() + mirrored.face_start[f], mirrored.corner_vertex.begin() + mirrored.face_start[f + 1]);
  Scene identity = s;
  identity.world_from_object = Affine3d{};
  for (RenderShading shading : {RenderShading::Flat, RenderShading::Gouraud, RenderShading::Phong}) {
    RenderOptions o;
    o.shading = shading;
    o.width = 120;
    o.height = 90;
    o.samples = 2;
    const RenderResult a = render_mesh(mesh, s, o), b = render_mesh(mirrored, identity, o);
    INFO(render_shading_name(shading));
    CHECK(a.stats.samples_covered == b.stats.samples_covered);
    CHECK(a.stats.faces_culled == b.stats.faces_culled);
    CHECK(max_abs_difference(a.image, b.image) < 1e-5);
    CHECK(a.stats.samples_covered > 1000);
  }
}

TEST_CASE("the image is bitwise the same for 1, 2 and 3 threads", "[render][threads]") {
  Mesh mesh = testing::irregular(testing::torus(40, 20)).mesh;
  Scene s = lit_scene({0.5, 1, 3.5});
  RenderOptions o;
  o.width = 150;
  o.height = 110;
  o.samples = 2;
  o.threads = 1;
  const RenderResult one = render_mesh(mesh, s, o);
  for (int t : {2, 3}) {
    o.threads = t;
    const RenderResult r = render_mesh(mesh, s, o);
    CHECK(r.image.rgb == one.image.rgb);
  }
}

TEST_CASE("the inverse bilinear map returns the (u, v) the bilinear map was given", "[render][quad]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    // a convex-ish quad: corners jittered from a square, non-planar by a little
    const Vec3d q[4] = {{0 + 0.3 * U(rng), 0 + 0.3 * U(rng), 0.1 * U(rng)},
                        {1 + 0.3 * U(rng), 0 + 0.3 * U(rng), 0.1 * U(rng)},
                        {1 + 0.3 * U(rng), 1 + 0.3 * U(rng), 0.1 * U(rng)},
                        {0 + 0.3 * U(rng), 1 + 0.3 * U(rng), 0.1 * U(rng)}};
    const double u = U(rng), v = U(rng);
    const Vec3d p = q[0] * ((1 - u) * (1 - v)) + q[1] * (u * (1 - v)) + q[2] * (u * v) + q[3] * ((1 - u) * v);
    QuadUV uv;
    REQUIRE(inverse_bilinear_3d(p, q, uv));
    CHECK(uv.u == Approx(u).margin(1e-9));
    CHECK(uv.v == Approx(v).margin(1e-9));
    ++checked;
  }
  CHECK(checked == 2000);
  const Vec3d flat[4] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};  // zero area: no map
  QuadUV uv;
  CHECK_FALSE(inverse_bilinear_3d({1, 0, 0}, flat, uv));
}

TEST_CASE("a quad shows no diagonal seam: both diagonals give the same image", "[render][quad]") {
  // A planar trapezoid (not a parallelogram) with four different vertex normals, lit by a near
  // point light, seen in perspective from an angle. Fanned along either diagonal the triangles'
  // interpolation differs (a visible seam), the bilinear interpolation of the corners does not:
  // a pixel's ray meets the plane at the same point on either fan, so (u, v) is the same.
  // (A non-planar quad's two fans are different surfaces; a slanted ray then meets them at
  // points a little apart: the residual is proportional to the non-planarity.)
  Mesh a;
  a.add_vertex({-1, -1, 0});
  a.add_vertex({1.3, -1, 0});
  a.add_vertex({0.7, 1, 0});
  a.add_vertex({-0.8, 1, 0});
  a.add_face({0, 1, 2, 3});
  a.vertex_normals = {-0.3, -0.2, 1, 0.4, -0.1, 1, 0.2, 0.5, 1, -0.5, 0.3, 1};  // distinct normals
  Mesh b = a;
  b.corner_vertex = {1, 2, 3, 0};
  Scene s = lit_scene({0.8, -1.5, 4});
  s.lights = {point_light({0.5, 0.5, 1.5})};
  for (RenderShading shading : {RenderShading::Gouraud, RenderShading::Phong}) {
    RenderOptions o;
    o.shading = shading;
    o.width = o.height = 80;
    const RenderResult ra = render_mesh(a, s, o), rb = render_mesh(b, s, o);
    INFO(render_shading_name(shading));
    CHECK(ra.stats.quad_fallbacks == 0);
    CHECK(ra.stats.samples_covered == rb.stats.samples_covered);
    CHECK(max_abs_difference(ra.image, rb.image) < 1e-4);  // rounding of the ray-plane point (measured 4e-5)
    // The same corners as two triangle faces, fanned both ways: the seam is there.
    Mesh fan = a;
    fan.face_start = {0};
    fan.corner_vertex.clear();
    fan.add_face({0, 1, 2});
    fan.add_face({0, 2, 3});
    Mesh other = fan;
    other.face_start = {0};
    other.corner_vertex.clear();
    other.add_face({1, 2, 3});
    other.add_face({1, 3, 0});
    const RenderResult fa = render_mesh(fan, s, o), fb = render_mesh(other, s, o);
    CHECK(max_abs_difference(fa.image, fb.image) > 0.01);
  }
}

TEST_CASE("back faces are culled, or lit from behind with two_sided", "[render][two_sided]") {
  // A triangle facing +z seen from -z, a light travelling +z (shining onto its back, from the
  // camera's side). Not two-sided: culled, background only. Two-sided: n -> -n, n.L = 1, so the
  // colour is global ambient * ka + kd, exactly.
  Mesh m;
  m.add_vertex({-1, -1, 0});
  m.add_vertex({1, -1, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  Scene s = lit_scene({0, 0, -5});
  s.model = ShadingModel::Lambert;
  s.lights = {directional_light({0, 0, 1})};
  RenderOptions o;
  o.width = o.height = 41;
  for (RenderShading shading : {RenderShading::Flat, RenderShading::Gouraud, RenderShading::Phong}) {
    o.shading = shading;
    INFO(render_shading_name(shading));
    s.two_sided = false;
    const RenderResult culled = render_mesh(m, s, o);
    CHECK(culled.stats.faces_culled == 1);
    CHECK(culled.stats.samples_covered == 0);
    s.two_sided = true;
    const RenderResult lit = render_mesh(m, s, o);
    CHECK(lit.stats.faces_culled == 0);
    REQUIRE(lit.stats.samples_covered > 100);
    const float* c = lit.image.pixel(20, 20);
    CHECK(c[0] == Approx(0.2 * 0.05 + 0.7).margin(1e-6));
    CHECK(c[1] == Approx(0.2 * 0.05 + 0.5).margin(1e-6));
  }
}
