// End-to-end tests of `shadetool info`: the report, --json (one object per file), several files,
// exit codes.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <sstream>
#include <algorithm>

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

TEST_CASE("info CLI: a glTF primitive's TEXCOORD_0 counts as texture coordinates", "[cli][info][issue27]") {
  // issue 27, item 13: "texcoords": false on the Khronos Duck, whose primitive has TEXCOORD_0
  // (they pass through beside the mesh). data/scene.gltf's primitives have TEXCOORD_0 too.
  const Run r = run("info " + data("scene.gltf") + " --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  int with_texcoord0 = 0, without = 0;
  for (const auto& [path, p] : j["stats"]["per_primitive"].items()) {
    const auto& attrs = p["gltf_attributes"];
    const bool has = std::find(attrs.begin(), attrs.end(), "TEXCOORD_0") != attrs.end();
    (has ? with_texcoord0 : without) += 1;
    INFO(path);
    CHECK(p["attributes"]["texcoords"] == has);
  }
  CHECK(with_texcoord0 == 2);  // data/scene.gltf: meshes[0] and [1] have TEXCOORD_0, [2] and [3] not
  CHECK(without == 2);
  const Run t = run("info " + data("scene.gltf"));
  CHECK(t.out.find("texcoords (TEXCOORD_0)") != std::string::npos);
}

TEST_CASE("info CLI: sizes print without the subtraction's rounding digits", "[cli][info][issue27]") {
  // issue 27, item 13: 0.036306 - (-0.036306) printed as 0.07261200000000001.
  const shadetool::testing::TempDir tmp;
  const std::string dir = tmp.path.string();
  std::ofstream(dir + "/d.obj") << "v -0.036306 0 0\nv 0.036306 0.1 0\nv 0 0.3 0.2\nf 1 2 3\n";
  const Run d = run("info " + dir + "/d.obj");
  CHECK(d.out.find("  size                   0.072612 x 0.3 x 0.2\n") != std::string::npos);
  CHECK(d.out.find("0.07261200000000001") == std::string::npos);
  // Float data (binary STL, PLY float): the float's shortest digits, not the widened double's.
  const Run f = run("info " + data("torus_knot.ply"));
  CHECK(f.code == 0);
  const std::size_t at = f.out.find("  bounding box");
  REQUIRE(at != std::string::npos);
  const std::string box = f.out.substr(at, f.out.find('\n', at) - at);
  for (std::size_t p = 0; (p = box.find_first_of("0123456789", p)) != std::string::npos;) {
    const std::size_t e = box.find_first_not_of("0123456789.e-", p);
    CHECK(box.substr(p, e - p).size() <= 14);  // a float needs at most 9 significant digits (and e-XX)
    p = e;
  }
}
