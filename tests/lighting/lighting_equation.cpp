// Hand-computed single-point cases of the lighting equation (lighting/lighting_equation.h), one
// per light type and model, with the arithmetic written out. Each case is checked in all three
// shading spaces (with M = identity and a camera that is a pure translation, the spaces' maps
// are trivial, so the expected value is the same number).
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/lighting/shade_points.h>
#include "lighting_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

constexpr double kTol = 1e-12;

void check(const Scene& scene, const Vec3d& p, const Vec3d& n, const Vec3d& expected) {
  for (ShadingSpace space : {ShadingSpace::World, ShadingSpace::Camera, ShadingSpace::Object}) {
    ShadeOptions o;
    o.space = space;
    const Vec3d c = shade_one(scene, p, n, o);
    INFO("space " << shading_space_name(space));
    CHECK(c.x == Approx(expected.x).margin(kTol));
    CHECK(c.y == Approx(expected.y).margin(kTol));
    CHECK(c.z == Approx(expected.z).margin(kTol));
  }
}

}  // namespace

TEST_CASE("directional light, lambert: emission + ka*ambient + (n.L) kd d", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.emission = {0.01, 0.02, 0.03};
  s.global_ambient = {0.1, 0.2, 0.3};
  s.material.ambient = {0.5, 0.5, 0.5};
  s.material.diffuse = {0.8, 0.5, 0.2};
  s.lights = {directional({0, -3, -4})};  // travels down-and-back: L = (0, 3, 4)/5 = (0, .6, .8)
  // n = (0,0,1): n.L = 0.8.  diffuse = 0.8 * kd = (0.64, 0.40, 0.16)
  // ka * ambient = 0.5 * (0.1, 0.2, 0.3) = (0.05, 0.10, 0.15); emission (0.01, 0.02, 0.03)
  // sum: (0.64+0.05+0.01, 0.40+0.10+0.02, 0.16+0.15+0.03) = (0.70, 0.52, 0.34)
  check(s, {0, 0, 0}, {0, 0, 1}, {0.70, 0.52, 0.34});
  // The normal's length does not matter: n = (0,0,7) gives the same.
  check(s, {0, 0, 0}, {0, 0, 7}, {0.70, 0.52, 0.34});
}

TEST_CASE("point light with attenuation [1, 0.1, 0.01] and a light ambient term", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.ambient = {1, 1, 1};
  s.material.diffuse = {0.5, 0.5, 0.5};
  Light L = point_light({0, 3, 4}, {1, 0.1, 0.01}, {2, 2, 2});  // color (1,1,1) * intensity 2
  L.ambient = {0.2, 0.2, 0.2};
  s.lights = {L};
  // p = 0: d = |(0,3,4)| = 5, L = (0, .6, .8), n.L = 0.8
  // att = 1 / (1 + 0.1*5 + 0.01*25) = 1 / 1.75
  // ambient  att * ka * a  = 0.2 / 1.75
  // diffuse  att * 0.8 * kd * d = 0.8 * 0.5 * 2 / 1.75 = 0.8 / 1.75
  // total (0.2 + 0.8) / 1.75 = 0.571428571428...
  const double e = 1.0 / 1.75;
  check(s, {0, 0, 0}, {0, 0, 1}, {e, e, e});

  // Facing away (n = (0,0,-1)): n.L = -0.8, no diffuse; the ambient term stays: 0.2 / 1.75.
  check(s, {0, 0, 0}, {0, 0, -1}, {0.2 / 1.75, 0.2 / 1.75, 0.2 / 1.75});
}

TEST_CASE("spot light: exponent, and the cone's edge", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {1, 1, 1};
  s.lights = {spot_light({0, 0, 4}, {0, 0, -1}, 30, 2)};  // 4 above the plane z = 0, pointing down

  // Under the light: cos_t = 1, spot = 1, n.L = 1, att = 1: colour 1.
  check(s, {0, 0, 0}, {0, 0, 1}, {1, 1, 1});

  // p = (2,0,0): to light (-2,0,4), d = sqrt(20); cos_t = 4/sqrt(20) = 0.894427... (26.57 deg < 30)
  // spot = cos_t^2 = 16/20 = 0.8; n.L = 4/sqrt(20); colour = 0.8 * 4/sqrt(20) = 0.7155417527999327
  check(s, {2, 0, 0}, {0, 0, 1}, {0.7155417527999327, 0.7155417527999327, 0.7155417527999327});

  // The edge at 30 degrees: x = 4 tan(29.9 deg) = 2.300102014990301 is inside, with
  // cos_t = n.L = cos(29.9 deg) = 0.8668967489356028: colour = cos^2 * cos = 0.6514815526595569;
  // x = 4 tan(30.1 deg) = 2.318718898151777 is outside: colour exactly 0.
  check(s, {2.300102014990301, 0, 0}, {0, 0, 1}, {0.6514815526595569, 0.6514815526595569, 0.6514815526595569});
  const Vec3d outside = shade_one(s, {2.318718898151777, 0, 0}, {0, 0, 1});
  CHECK(outside == Vec3d{0, 0, 0});

  // Cutoff 180 is OpenGL's "no cone": spot = 1 whatever the direction and exponent. The light
  // points away from the point (+z) and has exponent 8, yet the point gets n.L * kd = 1.
  s.lights = {spot_light({0, 0, 4}, {0, 0, 1}, 180, 8)};
  check(s, {0, 0, 0}, {0, 0, 1}, {1, 1, 1});
}

TEST_CASE("blinn-phong specular, shininess 1 and 128", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.diffuse = {0.5, 0.5, 0.5};
  s.material.specular = {1, 1, 1};
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 0, 5});
  s.lights = {directional({0, -3, -4})};  // L = (0, .6, .8)
  // p = 0, n = (0,0,1), V = (0,0,1).  diffuse = 0.8 * 0.5 = 0.4
  // H = normalize(L + V) = (0, .6, 1.8)/sqrt(3.6); n.H = 1.8/sqrt(3.6) = 3/sqrt(10) = 0.9486832980505138
  s.material.shininess = 1;
  check(s, {0, 0, 0}, {0, 0, 1}, Vec3d{1, 1, 1} * 1.348683298050514);  // 0.4 + 0.94868...
  // shininess 128: (3/sqrt(10))^128 = 0.9^64 = 0.0011790184577738603
  s.material.shininess = 128;
  check(s, {0, 0, 0}, {0, 0, 1}, Vec3d{1, 1, 1} * 0.4011790184577739);
}

TEST_CASE("phong specular, shininess 1 and 128", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::Phong);
  s.material.specular = {1, 1, 1};
  s.lights = {directional({0, -3, -4})};  // L = (0, .6, .8)
  // R = 2 (n.L) n - L = 1.6 (0,0,1) - (0,.6,.8) = (0, -.6, .8). Put the eye at 10 V with V at
  // angle theta from R, cos theta = 0.99: V = 0.99 R + sin(theta) T, T = (0, .8, .6) (unit, T.R = 0),
  // sin(theta) = sqrt(1 - 0.99^2) = 0.14106735979665894.
  const double sin_t = 0.14106735979665894;
  const Vec3d V = Vec3d{0, -0.6, 0.8} * 0.99 + Vec3d{0, 0.8, 0.6} * sin_t;
  s.has_camera = true;
  s.camera_from_world = camera_at(V * 10.0);
  // R.V = 0.99: shininess 1 -> 0.99; shininess 128 -> 0.99^128 = 0.2762516676992083
  s.material.shininess = 1;
  check(s, {0, 0, 0}, {0, 0, 1}, {0.99, 0.99, 0.99});
  s.material.shininess = 128;
  check(s, {0, 0, 0}, {0, 0, 1}, Vec3d{1, 1, 1} * 0.2762516676992083);
}

TEST_CASE("specular needs n.L > 0: a light behind the surface gives no highlight", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.specular = {1, 1, 1};
  s.material.shininess = 0;  // spec = max(n.H, 0)^0 = 1 whenever the term is on
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 0, 5});
  s.lights = {directional({0, 0, 1})};  // L = (0,0,-1): n.L = -1
  check(s, {0, 0, 0}, {0, 0, 1}, {0, 0, 0});
  s.lights = {directional({0, 0, -1})};  // L = (0,0,1): n.L = 1, H = V = n: spec = 1^0 = 1
  check(s, {0, 0, 0}, {0, 0, 1}, {1, 1, 1});
}

TEST_CASE("lambert has no specular term even with a specular material", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {0.5, 0.5, 0.5};
  s.material.specular = {1, 1, 1};
  s.material.shininess = 1;
  s.lights = {directional({0, 0, -1})};  // n.L = 1: diffuse 0.5, and blinn-phong would add 1
  check(s, {0, 0, 0}, {0, 0, 1}, {0.5, 0.5, 0.5});
}

TEST_CASE("two-sided: where n.V < 0 the normal is flipped", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {0.25, 0.5, 1};
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 0, -5});  // the eye looks at the back (n.V = -1)
  s.lights = {directional({0, 0, 1})};          // from below: L = (0,0,-1), n.L = -1
  // one-sided: n.L < 0, colour 0
  check(s, {0, 0, 0}, {0, 0, 1}, {0, 0, 0});
  // two-sided: n -> (0,0,-1), n.L = 1: colour = kd = (0.25, 0.5, 1)
  s.two_sided = true;
  check(s, {0, 0, 0}, {0, 0, 1}, {0.25, 0.5, 1});
  // from the front (eye at +z) two-sided changes nothing: the light is still behind: 0
  s.camera_from_world = camera_at({0, 0, 5});
  check(s, {0, 0, 0}, {0, 0, 1}, {0, 0, 0});
}

TEST_CASE("ambient lights and the global ambient add ka * colour everywhere", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.ambient = {0.5, 1, 0.25};
  s.global_ambient = {0.2, 0.2, 0.2};
  Light a;
  a.type = LightType::Ambient;
  a.ambient = {0.4, 0.4, 0.4};  // color (1,1,1) * intensity 0.4
  s.lights = {a};
  // ka * (0.2 + 0.4) = (0.3, 0.6, 0.15), whatever the normal (also a zero normal)
  check(s, {1, 2, 3}, {0, 0, 1}, {0.3, 0.6, 0.15});
  check(s, {1, 2, 3}, {0, 0, 0}, {0.3, 0.6, 0.15});
}

TEST_CASE("spot light with attenuation and blinn-phong specular together", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.diffuse = {1, 1, 1};
  s.material.specular = {1, 1, 1};
  s.material.shininess = 2;
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 3, 4});  // the eye where the light is: V = L
  Light L = spot_light({0, 3, 4}, {0, -3, -4}, 45, 3);
  L.attenuation = {0, 0, 1};  // inverse square
  s.lights = {L};
  // p = 0, n = (0,0,1): d = 5, L = (0,.6,.8), cos_t = 1 (on the axis), spot = 1^3 = 1
  // att = 1/25 = 0.04; n.L = 0.8; V = L so H = L, n.H = 0.8, spec = 0.8^2 = 0.64
  // colour = 0.04 * (0.8 + 0.64) = 0.0576
  check(s, {0, 0, 0}, {0, 0, 1}, {0.0576, 0.0576, 0.0576});
}

TEST_CASE("degenerate points: at the light, zero normal, at the eye", "[lighting][equation]") {
  Scene s = dark_scene(ShadingModel::BlinnPhong);
  s.material.ambient = {1, 1, 1};
  s.material.diffuse = {1, 1, 1};
  s.material.specular = {1, 1, 1};
  s.material.shininess = 4;
  Light L = point_light({1, 1, 1});
  L.ambient = {0.5, 0.5, 0.5};
  s.lights = {L};
  s.has_camera = true;
  s.camera_from_world = camera_at({0, 0, 3});

  // At the light: L and att are undefined; the light adds nothing (not even its ambient term).
  ShadeReport report;
  Vec3d c = shade_one(s, {1, 1, 1}, {0, 0, 1}, {}, &report);
  CHECK(c == Vec3d{0, 0, 0});
  CHECK(report.counters.at_light == 1);

  // Zero normal at p = (1,1,0): d = 1, att = 1: only the light's ambient term ka*a = 0.5.
  c = shade_one(s, {1, 1, 0}, {0, 0, 0}, {}, &report);
  CHECK(c.x == Approx(0.5).margin(kTol));
  CHECK(report.counters.zero_normals == 1);

  // At the eye (0,0,3) with n = (0,0,1): to light (1,1,-2), d = sqrt(6), n.L = -2/sqrt(6) < 0: only
  // ambient 0.5. Move the light to (0,0,4): L = n, V = 0 so H = L, n.H = 1: 0.5 + 1 + 1 = 2.5.
  s.lights[0].position = {0, 0, 4};
  c = shade_one(s, {0, 0, 3}, {0, 0, 1});
  CHECK(c.x == Approx(2.5).margin(kTol));
}
