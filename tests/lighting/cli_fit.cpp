// `bake-lighting --fit` and `occlusion --error/--fit` end to end: the binary's output against the
// library called on the same file (the CLI only plumbs), its --json counts, and its usage errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include <shadetool/files/mesh_files.h>
#include <shadetool/lighting/fit_vertex_lighting.h>
#include <shadetool/lighting/read_scene.h>
#include "support/run_process.h"
#include "support/temp_dir.h"

using namespace shadetool;
using shadetool::testing::TempDir;

TEST_CASE("bake-lighting --fit least-squares writes the library's fit and reports both errors", "[lighting][cli][fit]") {
  TempDir dir;
  const std::string src = SHADETOOL_SOURCE_DIR;
  const std::string mesh_path = src + "/data/icosphere.ply", scene_path = src + "/data/scenes/studio.json";
  const auto r = shadetool_test::run_shadetool("bake-lighting " + mesh_path + " -o " + dir.file("lsq.ply") +
                                               " --scene " + scene_path + " --fit least-squares --fit-samples 6 --hdr --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto& s = j["stats"];
  CHECK(s["fit"] == "least-squares");
  CHECK(s["fit_samples"] == 6);
  CHECK(s["fit_regularization"] == 0.0);
  CHECK(s["fit_error"].get<double>() < s["point_error"].get<double>());
  CHECK(s["fit_quadrature_points"] == 6 * 1280);

  const Mesh in = read_mesh(mesh_path);
  const Scene scene = read_scene(scene_path);
  const BakeResult point = bake_lighting(in, scene, ShadingFrequency::PerVertex);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  fit.samples = 6;
  const VertexLightingFit lsq = fit_vertex_lighting(in, scene, point, {}, {}, fit);
  const Mesh out = read_mesh(dir.file("lsq.ply"));
  REQUIRE(out.vertex_colors.size() == lsq.rgb.size());
  for (std::size_t i = 0; i < lsq.rgb.size(); ++i) CHECK(out.vertex_colors[i] == float(lsq.rgb[i]));

  // the default stays the point colours: the same bytes as without --fit
  const auto a = shadetool_test::run_shadetool("bake-lighting " + mesh_path + " -o " + dir.file("a.ply") + " --scene " + scene_path);
  const auto b = shadetool_test::run_shadetool("bake-lighting " + mesh_path + " -o " + dir.file("b.ply") + " --scene " + scene_path + " --fit point");
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  CHECK(shadetool_test::read_file(dir.file("a.ply")) == shadetool_test::read_file(dir.file("b.ply")));
}

TEST_CASE("--fit and --error refuse values outside their vocabulary (exit 2, no output)", "[lighting][cli][fit]") {
  TempDir dir;
  const std::string src = SHADETOOL_SOURCE_DIR;
  const std::string mesh = src + "/data/icosphere.ply", scene = " --scene " + src + "/data/scenes/studio.json";
  for (const std::string& bad : {std::string("--fit least_squares"), std::string("--fit-samples 4"),
                                 std::string("--fit-regularization -1")}) {
    const auto r = shadetool_test::run_shadetool("bake-lighting " + mesh + " -o " + dir.file("x.ply") + scene + " " + bad);
    CHECK(r.code == 2);
  }
  for (const std::string& bad : {std::string("--error 0"), std::string("--error 0.01 --samples 16")}) {
    const auto r = shadetool_test::run_shadetool("occlusion " + mesh + " -o " + dir.file("x.ply") + " " + bad);
    INFO(bad << ": " << r.err);
    CHECK(r.code == 2);
  }
  CHECK_FALSE(std::ifstream(dir.file("x.ply")).good());
}

TEST_CASE("occlusion --error reports rays per vertex as a histogram; --fit least-squares clamps to [0, 1]",
          "[visibility][cli][fit]") {
  TempDir dir;
  const std::string knot = std::string(SHADETOOL_SOURCE_DIR) + "/data/torus_knot.ply";
  const auto r = shadetool_test::run_shadetool("occlusion " + knot + " -o " + dir.file("ao.ply") +
                                               " --error 0.03 --samples 1024 --fit least-squares --fit-samples 1 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto s = nlohmann::json::parse(r.out)["stats"];
  std::size_t points = 0, rays = 0;
  for (const auto& [count, n] : s["rays_histogram"].items()) {
    points += n.get<std::size_t>();
    rays += std::stoul(count) * n.get<std::size_t>();
    CHECK(std::stoul(count) <= 1024);
  }
  CHECK(points == s["vertices"].get<std::size_t>());
  CHECK(rays == s["rays"].get<std::size_t>());
  CHECK(s["max_samples"] == 1024);
  CHECK(s["fit_error"].get<double>() < s["point_error"].get<double>());
  const Mesh out = read_mesh(dir.file("ao.ply"));
  for (float q : out.vertex_quality) {
    CHECK(q >= 0.0f);
    CHECK(q <= 1.0f);
  }
}

TEST_CASE("bake-lighting --fit least-squares without --stats or --json (no point colours computed) writes the same "
          "bytes and the same notes as with --json",
          "[lighting][cli][fit]") {
  // Truth: the run with --json, which computes the point colours (their error is reported). With
  // shadows under window.json (an area light and a sky: sampled lights), the note about --samples
  // must not claim that the scene has no sampled light.
  TempDir dir;
  const std::string src = SHADETOOL_SOURCE_DIR;
  const std::string base = "bake-lighting " + src + "/data/icosphere.ply --scene " + src +
                           "/data/scenes/window.json --shadows --samples 4 --fit least-squares --fit-samples 1";
  const auto quiet = shadetool_test::run_shadetool(base + " -o " + dir.file("quiet.ply"));
  const auto json = shadetool_test::run_shadetool(base + " -o " + dir.file("json.ply") + " --json");
  INFO(quiet.err);
  REQUIRE(quiet.code == 0);
  REQUIRE(json.code == 0);
  CHECK(shadetool_test::read_file(dir.file("quiet.ply")) == shadetool_test::read_file(dir.file("json.ply")));
  CHECK(quiet.err.find("--samples ignored") == std::string::npos);
  CHECK(std::isfinite(nlohmann::json::parse(json.out)["stats"]["point_error"].get<double>()));
}
