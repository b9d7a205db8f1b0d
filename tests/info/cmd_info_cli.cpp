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
