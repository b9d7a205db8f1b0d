// End-to-end tests of `shadetool info`: the report, --json (one object per file), several files,
// exit codes.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "support/run_process.h"
#include "support/temp_dir.h"

namespace {

using Run = shadetool_test::ProcessResult;
Run run(const std::string& args) { return shadetool_test::run_shadetool(args); }

std::string data(const std::string& name) { return std::string(SHADETOOL_SOURCE_DIR) + "/data/" + name; }

}  // namespace

TEST_CASE("info CLI: human report of the cube", "[cli][info]") {
  const Run r = run("info " + data("cube.obj"));
  CHECK(r.code == 0);
  CHECK(r.out.find(data("cube.obj") + ": OBJ (float)\n") == 0);
  CHECK(r.out.find("  vertices               8\n") != std::string::npos);
  CHECK(r.out.find("  faces                  12 (12 triangles)\n") != std::string::npos);
  CHECK(r.out.find("  bounding box           min (-1, -1, -1)  max (1, 1, 1)\n") != std::string::npos);
  CHECK(r.out.find("  closed manifold        yes\n") != std::string::npos);
  CHECK(r.err.empty());
}

TEST_CASE("info CLI: --json prints one object per file with the statistics", "[cli][info]") {
  const Run r = run("info " + data("non_manifold.obj") + " " + data("dodecahedron.off") + " -j 1 --json");
  CHECK(r.code == 0);
  std::istringstream lines(r.out);
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    CHECK(j["status"] == "ok");
    const auto& s = j["stats"];
    if (j["input"] == data("non_manifold.obj")) {
      CHECK(s["non_manifold_edges"] == 1);
      CHECK(s["non_manifold_vertices"] == 3);
      CHECK(s["unreferenced_vertices"] == 1);
      CHECK(s["components"] == 3);
      CHECK(s["closed_manifold"] == false);
    } else {
      CHECK(s["faces_by_size"]["5"] == 12);
      CHECK(s["attributes"]["face_colors"] == true);
      CHECK(s["format"] == "OFF");
      CHECK(s["bbox"]["max"][0].get<double>() == (1 + std::sqrt(5.0)) / 2);
    }
    ++n;
  }
  CHECK(n == 2);
}

TEST_CASE("info CLI: usage errors exit 2, a bad file among good ones exits 1", "[cli][info]") {
  CHECK(run("info").code == 2);
  CHECK(run("info " + data("cube.obj") + " --no-such-flag").code == 2);
  CHECK(run("info " + data("cube.obj") + " -o x.obj").code == 2);  // info writes no mesh: no -o
  const Run r = run("info " + data("cube.obj") + " no-such-file.obj " + data("torus.obj") + " -j 1");
  CHECK(r.code == 1);
  CHECK(r.out.find("torus.obj: OBJ (double)") != std::string::npos);
  CHECK(r.err.find("shadetool: no-such-file.obj: cannot open: No such file or directory\n") != std::string::npos);
}

TEST_CASE("info CLI: stdin with --input-format", "[cli][info]") {
  const Run r = run("info - --input-format off < " + data("dodecahedron.off"));
  CHECK(r.code == 0);
  CHECK(r.out.find("-: OFF (double)") == 0);
}

TEST_CASE("info CLI: a face with a NaN corner is a degenerate face, counted as repair's library counts it", "[cli][info]") {
  // One count (geometry/degenerate_faces.h) for info and repair; info's own count used to leave a
  // NaN face out of its total: this file was "1 (0 repeated index, 1 zero area)".
  shadetool::testing::TempDir dir;
  const std::string mesh = dir.write("nan.obj",
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 2 0 0\n"
                                     "f 1 2 3\nf 1 2 4\nf 1 2 5\n");  // fine, NaN corner, collinear
  const Run text = run("info " + mesh);
  CHECK(text.code == 0);
  CHECK(text.out.find("  degenerate faces       2 (0 repeated index, 1 zero area, 1 NaN/Inf)\n") != std::string::npos);
  const Run json = run("info --json " + mesh);
  const auto s = nlohmann::json::parse(json.out)["stats"];
  CHECK(s["degenerate_faces"] == 2);
  CHECK(s["zero_area_faces"] == 1);
  CHECK(s["nonfinite_faces"] == 1);
  // Without NaN faces the line is as it was (no NaN/Inf part).
  const Run cube = run("info " + data("cube.obj"));
  CHECK(cube.out.find("  degenerate faces       0 (0 repeated index, 0 zero area)\n") != std::string::npos);
}
