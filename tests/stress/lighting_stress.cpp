// Numerical stress tests of lib/lighting: a light exactly at a shaded point, lights extremely near
// and far, shininess 0 and 1e4, spot cutoffs 0, 90 and 180, zero-length and subnormal light
// directions. Scenes are parsed from JSON (the path users take). Every expected colour is
// computed by hand below from the equation of lighting_equation.h (OpenGL 2.1, section 2.14.1):
//
//   c = e + ka a_global + sum_i att_i spot_i (ka a_i + max(n.L, 0) kd d_i + [n.L > 0] spec_i ks s_i)
//
// with the defaults used throughout unless a case says otherwise: e = 0, ka = 0.2, a_global = 0.2
// (so the base term is 0.04), kd = 0.8, light colour 1 (d_i = s_i = 1), light ambient a_i = 0,
// attenuation (1, 0, 0). The shaded point is the origin with normal +z unless stated.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/lighting/shade_points.h>
#include "stress/stress_util.h"
#include "support/run_process.h"

using namespace shadetool;
using namespace shadetool::stress;

namespace {

struct Shaded {
  std::vector<double> rgb;
  ShadeReport report;
};

Shaded shade(const std::string& json, const std::vector<double>& points, const std::vector<double>& normals) {
  const Scene scene = parse_scene(json, "stress.json");
  ShadeOptions options;
  options.parallel = false;
  Shaded s;
  s.rgb = shade_points(scene, points, normals, options, &s.report);
  return s;
}

// The red channel at the origin with normal +z (all channels are equal in these scenes).
double at_origin(const std::string& json) {
  const Shaded s = shade(json, {0, 0, 0}, {0, 0, 1});
  REQUIRE(s.rgb.size() == 3);
  CHECK(s.rgb[0] == s.rgb[1]);
  CHECK(s.rgb[1] == s.rgb[2]);
  return s.rgb[0];
}

std::string point_light_at(const std::string& position, const std::string& extra = "") {
  return R"({"lights": [{"type": "point", "position": )" + position + extra + "}]}";
}

// A small mesh around the origin, for "the whole bake is finite" checks.
Mesh tetra_with_isolated_vertex() {
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0, 1, 0});
  m.add_vertex({0, 0, 1});
  m.add_vertex({7, 7, 7});
  m.add_face({0, 2, 1});
  m.add_face({0, 1, 3});
  m.add_face({0, 3, 2});
  m.add_face({1, 2, 3});
  m.add_face({1, 1, 2});  // degenerate
  return m;
}

void check_bake_finite(const std::string& json) {
  const Scene scene = parse_scene(json, "stress.json");
  for (auto freq : {ShadingFrequency::PerVertex, ShadingFrequency::PerFace})
    for (auto model : {ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
      ShadeOptions o;
      o.model = model;
      const BakeResult r = bake_lighting(tetra_with_isolated_vertex(), scene, freq, o);
      CHECK(all_finite(r.rgb));
    }
}

}  // namespace

TEST_CASE("stress: a point light exactly at the shaded point adds nothing, and nothing is NaN", "[stress][lighting]") {
  // d = 0: L, the spot cosine and the attenuation are undefined. Documented choice
  // (lighting_equation.h): the light adds 0 there, even its ambient term. Expected 0.04, counted.
  const Shaded s = shade(point_light_at("[0, 0, 0]", R"(, "ambient": [0.5, 0.5, 0.5])"), {0, 0, 0}, {0, 0, 1});
  CHECK(s.rgb == std::vector<double>{0.2 * 0.2, 0.2 * 0.2, 0.2 * 0.2});
  CHECK(s.report.counters.at_light == 1);
  // A spot light there too, and the whole mesh (the light sits on vertex 0).
  CHECK(at_origin(R"({"lights": [{"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1], "cutoff": 30}]})") ==
        0.2 * 0.2);
  check_bake_finite(point_light_at("[0, 0, 0]"));
  check_bake_finite(R"({"lights": [{"type": "spot", "position": [1, 0, 0], "direction": [0, 0, -1], "cutoff": 0}]})");
}

TEST_CASE("stress: a point light 1e-3 .. 1e-150 above the point lights it fully", "[stress][lighting]") {
  // Light at (0, 0, h): L = +z, n.L = 1, att = 1 / (1 + 0 + 0) = 1: c = 0.04 + 0.8 * 1 = 0.84,
  // whatever h > 0 is, as long as h^2 does not underflow (1e-150^2 = 1e-300 is still normal).
  for (const char* h : {"1e-3", "1e-100", "1e-150"}) {
    INFO("h = " << h);
    CHECK(at_origin(point_light_at(std::string("[0, 0, ") + h + "]")) == Approx(0.84).epsilon(1e-15));
  }
}

TEST_CASE("stress: a point light 1e-200 above the point, or 1e200 away, lights it like any other",
          "[stress][lighting]") {
  // The distance is |to_light| computed without squaring out of range (lighting_equation.h
  // metric_length: scaled by a power of two when |to_light|^2 would underflow or overflow), and an
  // attenuation term with coefficient 0 is left out (0 * d is NaN for d = Inf). Expected, as for
  // any h: light at (0, 0, h), n.L = 1, att = 1 with attenuation (1, 0, 0): c = 0.04 + 0.8 = 0.84;
  // with attenuation (0, 0, 1) at h = 1e200: att = 1 / 1e400 = 0 in double, c = 0.04 exactly;
  // at h = 1e-100 with (0, 0, 1): att = 1e200, c = 0.04 + 0.8e200.
  for (const char* h : {"1e-200", "1e-300", "4.9e-324", "1e200", "1e300"}) {
    INFO("h = " << h);
    CHECK(at_origin(point_light_at(std::string("[0, 0, ") + h + "]")) == Approx(0.84).epsilon(1e-15));
  }
  CHECK(at_origin(point_light_at("[0, 0, 1e200]", R"(, "attenuation": [0, 0, 1])")) == 0.2 * 0.2);
  CHECK(at_origin(point_light_at("[0, 0, 1e-100]", R"(, "attenuation": [0, 0, 1])")) == Approx(0.04 + 0.8e200).epsilon(1e-15));
  // A light at distance sqrt(3) 1e300 with an ambient term (att 1): c = 0.04 + 0.2 * 1 + 0.8 n.L,
  // n.L = 1e300 / (sqrt(3) 1e300) = 1 / sqrt(3).
  CHECK(at_origin(point_light_at("[1e300, -1e300, 1e300]", R"(, "ambient": [1, 1, 1])")) ==
        Approx(0.04 + 0.2 + 0.8 / std::sqrt(3.0)).epsilon(1e-15));
  // The eye that far: V is still a unit vector. Eye at (0, 0, 1e300), directional light along -z:
  // Blinn-Phong n.H = 1, c = 0.04 + 0.8 + 1 (ks = 1, shininess 10).
  CHECK(at_origin(R"({"camera": {"eye": [0, 0, 1e300], "target": [0, 0, 0]},
                      "material": {"specular": [1, 1, 1], "shininess": 10},
                      "lights": [{"type": "directional", "direction": [0, 0, -1]}]})") == Approx(1.84).epsilon(1e-15));
}

TEST_CASE("stress: shininess 0 makes the specular term 1 wherever the light reaches", "[stress][lighting]") {
  // Eye at (0, 0, 5): V = +z. Directional light travelling along -(sin 60, 0, cos 60), so
  // L = (sin 60, 0, cos 60) = (0.8660254, 0, 0.5): n.L = 0.5, diffuse 0.8 * 0.5 = 0.4.
  // Blinn-Phong: n.H = cos 30 deg (H halves the 60 deg between L and V), and 0.866^0 = 1:
  // c = 0.04 + 0.4 + 1 (ks = 1) = 1.44. Phong: R.V = cos 60 = 0.5, 0.5^0 = 1: c = 1.44 as well.
  const double s60 = std::sqrt(3.0) / 2;
  const std::string dir = "[" + std::to_string(-s60) + ", 0, -0.5]";
  for (const char* model : {"blinn-phong", "phong"}) {
    const std::string scene = std::string(R"({"model": ")") + model +
                              R"(", "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
        "material": {"specular": [1, 1, 1], "shininess": 0},
        "lights": [{"type": "directional", "direction": )" + dir + "}]}";
    INFO(model);
    CHECK(at_origin(scene) == Approx(1.44).epsilon(1e-6));  // 1e-6: the direction printed with 6 digits
    check_bake_finite(scene);
  }
  // Back-facing (n.L < 0): no specular even though x^0 = 1: c = 0.04.
  CHECK(at_origin(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}, "material": {"specular": [1, 1, 1], "shininess": 0},
                      "lights": [{"type": "directional", "direction": [0, 0, 1]}]})") == 0.2 * 0.2);
}

TEST_CASE("stress: shininess 1e4 gives a narrow, finite highlight", "[stress][lighting]") {
  // Eye at (0, 0, 5), V = +z; light at angle a = 0.02 rad from the normal: L = (sin a, 0, cos a).
  // Blinn-Phong: n.H = cos(a / 2); spec = cos(0.01)^1e4 = exp(1e4 ln cos 0.01) = exp(-0.500004167)
  //   = 0.606528...; c = 0.04 + 0.8 cos(0.02) + spec.
  // Phong: R.V = cos(2 * 0) ... R is L mirrored about n, at angle a on the other side: R.V = cos a;
  //   spec = cos(0.02)^1e4 = exp(-2.0000667) = 0.135326...
  // Light along the normal: spec = 1^1e4 = 1. Light 60 deg off: 0.866^1e4 underflows to 0 (not NaN).
  const double a = 0.02;
  char dir[128];
  std::snprintf(dir, sizeof dir, "[%.17g, 0, %.17g]", -std::sin(a), -std::cos(a));
  auto scene = [&](const char* model, const std::string& direction) {
    return std::string(R"({"model": ")") + model + R"(", "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
        "material": {"specular": [1, 1, 1], "shininess": 10000},
        "lights": [{"type": "directional", "direction": )" + direction + "}]}";
  };
  const long double diffuse = 0.8L * std::cos((long double)a);
  const long double blinn = std::pow(std::cos((long double)a / 2), 10000.0L);
  const long double phong = std::pow(std::cos((long double)a), 10000.0L);
  // d(spec)/da is about 1e4 tan(a) spec < 200: the direction's rounding (1e-17) costs < 1e-14.
  CHECK(at_origin(scene("blinn-phong", dir)) == Approx(double(0.04L + diffuse + blinn)).epsilon(1e-12));
  CHECK(at_origin(scene("phong", dir)) == Approx(double(0.04L + diffuse + phong)).epsilon(1e-12));
  CHECK(at_origin(scene("blinn-phong", "[0, 0, -1]")) == Approx(1.84).epsilon(1e-15));
  const double s60 = std::sqrt(3.0) / 2;
  CHECK(at_origin(scene("blinn-phong", "[" + std::to_string(-s60) + ", 0, -0.5]")) == Approx(0.44).epsilon(1e-6));
  check_bake_finite(scene("phong", dir));
}

TEST_CASE("stress: spot cutoff 0 lights only its axis, 90 a half-space (boundary included), 180 is a point light",
          "[stress][lighting]") {
  // Cutoff 0, light at (0, 0, 4) aiming down (-z): the origin is on the axis, cos_t = 1 >= cos 0 = 1,
  // spot = 1 (exponent 0), att = 1, n.L = 1: c = 0.84. A point 1e-3 off the axis: cos_t < 1, c = 0.04.
  const std::string cut0 = R"({"lights": [{"type": "spot", "position": [0, 0, 4], "direction": [0, 0, -1], "cutoff": 0}]})";
  const Shaded s0 = shade(cut0, {0, 0, 0, 1e-3, 0, 0}, {0, 0, 1, 0, 0, 1});
  CHECK(s0.rgb[0] == Approx(0.84).epsilon(1e-15));
  CHECK(s0.rgb[3] == 0.2 * 0.2);
  // Cutoff 90, light at (0, 0, 1) aiming along +x: the cone is the half-space x >= 0 (cos 90 = 0
  // exactly). The origin lies exactly on its boundary plane: cos_t = 0 >= 0 -> inside (OpenGL:
  // outside only when the angle exceeds the cutoff), spot = 0^0 = 1, n.L = 1: c = 0.84.
  // (0.5, 0, 0): inside, n.L = 1 / sqrt(1.25): c = 0.04 + 0.8 / sqrt(1.25) = 0.7555418.
  // (-0.5, 0, 0): outside: c = 0.04.
  const std::string cut90 = R"({"lights": [{"type": "spot", "position": [0, 0, 1], "direction": [1, 0, 0], "cutoff": 90}]})";
  const Shaded s90 = shade(cut90, {0, 0, 0, 0.5, 0, 0, -0.5, 0, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1});
  CHECK(s90.rgb[0] == Approx(0.84).epsilon(1e-15));
  CHECK(s90.rgb[3] == Approx(0.04 + 0.8 / std::sqrt(1.25)).epsilon(1e-15));
  CHECK(s90.rgb[6] == 0.2 * 0.2);
  // Cutoff 180 is OpenGL's "no cone": spot = 1 whatever the exponent and direction, so the colours
  // equal a point light's at the same place, bit for bit, on points all around it.
  std::vector<double> P, N;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      P.insert(P.end(), {double(i), double(j), -1.0});
      N.insert(N.end(), {0.0, 0.0, 1.0});
    }
  const Shaded spot = shade(R"({"lights": [{"type": "spot", "position": [0.5, 0, 2], "direction": [1, 1, 1], "cutoff": 180, "exponent": 50}]})", P, N);
  const Shaded point = shade(point_light_at("[0.5, 0, 2]"), P, N);
  CHECK(spot.rgb == point.rgb);
  for (const std::string& s : {cut0, cut90}) check_bake_finite(s);
}

TEST_CASE("stress: zero-length light directions are refused; subnormal ones act as their unit direction", "[stress][lighting]") {
  for (const char* json : {R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})",
                           R"({"lights": [{"type": "spot", "position": [0, 0, 1], "direction": [0, -0, 0], "cutoff": 45}]})"}) {
    INFO(json);
    try {
      parse_scene(json, "stress.json");
      FAIL("accepted a zero-length direction");
    } catch (const Error& e) {
      const std::string what = e.what();
      CHECK(what.find("stress.json") == 0);
      CHECK(what.find("zero-length direction") != std::string::npos);
    }
  }
  // A direction of length 1e-320 (subnormal) is not zero: it must act exactly as (0, 0, -1)
  // (normalised by scaling first: its squared length, 1e-640, is 0 in double).
  const double tiny = at_origin(R"({"lights": [{"type": "directional", "direction": [0, 0, -1e-320]}]})");
  const double unit = at_origin(R"({"lights": [{"type": "directional", "direction": [0, 0, -1]}]})");
  CHECK(unit == Approx(0.84).epsilon(1e-15));
  CHECK(tiny == Approx(unit).epsilon(1e-15));
  // Likewise a huge one (1e300: squared, Inf).
  CHECK(at_origin(R"({"lights": [{"type": "directional", "direction": [0, 0, -1e300]}]})") == Approx(unit).epsilon(1e-15));
  // And a spot's axis.
  CHECK(at_origin(R"({"lights": [{"type": "spot", "position": [0, 0, 4], "direction": [0, 0, -1e-320], "cutoff": 10}]})") ==
        Approx(unit).epsilon(1e-15));
}

TEST_CASE("stress: bake-lighting never writes a NaN or Inf colour: it refuses instead", "[stress][lighting][cli]") {
  // Where the true colour exceeds double's or float's range, the command must not write NaN or
  // Inf: an intensity of 1e300 behind an attenuation of 1e-300 (colour 8e599: Inf in double) and
  // an intensity of 1e300 alone (finite in double, Inf as the float an --hdr file holds) both exit
  // 1, one line, no output.
  namespace fs = std::filesystem;
  char tmpl[] = "/tmp/shadetool-light-XXXXXX";
  const fs::path dir = ::mkdtemp(tmpl);
  const fs::path far = dir / "far.json", bright = dir / "bright.json", out = dir / "out.ply";
  std::ofstream(far) << R"({"lights": [{"type": "point", "position": [0, 0, 5], "intensity": 1e300, "attenuation": [1e-300, 0, 0]}]})";
  std::ofstream(bright) << R"({"lights": [{"type": "point", "position": [0, 0, 5], "intensity": 1e300}]})";
  const std::string cube = std::string(SHADETOOL_SOURCE_DIR) + "/data/cube.obj";
  for (const auto& [scene, hdr] : std::vector<std::pair<fs::path, bool>>{{far, false}, {far, true}, {bright, true}}) {
    std::vector<std::string> argv = {SHADETOOL_BIN, "bake-lighting", cube, "-o", out.string(), "--scene", scene.string()};
    if (hdr) argv.push_back("--hdr");
    const auto r = shadetool_test::run_process(argv);
    INFO(scene.filename().string() << (hdr ? " --hdr" : "") << ": " << r.err);
    CHECK(r.code == 1);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find("NaN or infinite") != std::string::npos);
    CHECK(!fs::exists(out));
  }
  // The same light far but not beyond double (1e100): finite colours, written.
  const fs::path ok = dir / "ok.json";
  std::ofstream(ok) << R"({"lights": [{"type": "point", "position": [1e100, -1e100, 1e100], "ambient": [1, 1, 1]}]})";
  const auto r = shadetool_test::run_process({SHADETOOL_BIN, "bake-lighting", cube, "-o", out.string(), "--scene", ok.string(), "--hdr", "-q"});
  CHECK(r.code == 0);
  const Mesh baked = read_mesh(out.string());
  CHECK(baked.has_vertex_colors());
  CHECK(all_finite(baked.vertex_colors));
  fs::remove_all(dir);
}
