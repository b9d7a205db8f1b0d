// End-to-end tests of `shadetool repair`: the built binary on files, its exit codes, messages,
// report JSON, and that nothing is written when it fails.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace fs = std::filesystem;

namespace {

using shadetool::testing::TempDir;

using shadetool_test::read_file;
using shadetool_test::run_shadetool;

void write_text(const std::string& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

// Runs `shadetool ARGS` (tests/support/run_process.h); its stderr into `err`, returns the exit code.
int run(const std::string& args, std::string& err) {
  const shadetool_test::ProcessResult r = run_shadetool(args);
  err = r.err;
  return r.code;
}

std::string data(const std::string& name) { return std::string(SHADETOOL_SOURCE_DIR) + "/data/" + name; }

// Unit cube as 12 triangles, all wound outward except the two listed.
std::string cube_obj(bool flip_two) {
  std::string s;
  for (int i = 0; i < 8; ++i) s += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string((i >> 2) & 1) + "\n";
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  int f = 0;
  for (auto& s4 : q)
    for (int t = 0; t < 2; ++t, ++f) {
      int a = s4[0] + 1, b = s4[t + 1] + 1, c = s4[t + 2] + 1;
      if (flip_two && (f == 3 || f == 8)) std::swap(b, c);
      s += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    }
  return s;
}

}  // namespace

TEST_CASE("repair: report JSON fields and one stderr line per step that changed something", "[repair][cli]") {
  TempDir tmp;
  const std::string out = tmp / "fixed.ply", report = tmp / "report.json";
  std::string err;
  // data/inconsistent_winding.obj: an 80-face icosphere with faces 0, 7, ..., 77 (12) reversed.
  REQUIRE(run("repair '" + data("inconsistent_winding.obj") + "' -o '" + out + "' --report '" + report + "'", err) == 0);
  REQUIRE(fs::exists(out));
  const nlohmann::json j = nlohmann::json::parse(read_file(report));
  CHECK(j["faces_in"] == 80);
  CHECK(j["faces_out"] == 80);
  CHECK(j["components"] == 1);
  CHECK(j["closed_components"] == 1);
  CHECK(j["open_components"] == 0);
  CHECK(j["faces_flipped"] == 12);
  CHECK(j["components_inverted"] == 0);
  CHECK(j["non_manifold_edges"] == 0);
  CHECK(j["duplicate_faces"] == 0);
  CHECK(j["non_orientable_components"] == 0);
  CHECK(j["boundary_loops"] == 0);
  CHECK(j["degenerate_faces"] == 0);
  CHECK(j["vertices_welded"] == 0);
  CHECK(j["normals_recomputed"]["missing"] == 42);
  CHECK(j["normals_recomputed"]["nan"] == 0);
  CHECK(j["normals_recomputed"]["zero"] == 0);
  CHECK(j["normals_recomputed"]["flipped"] == 0);
  CHECK(j["orientation"]["open_component_method"] == "generalized winding number");
  const std::string e = err;  // the first run's
  CHECK(e.find("winding: reversed 12 faces") != std::string::npos);
  CHECK(e.find("normals: computed 42 vertex normals") != std::string::npos);
  CHECK(e.find("orientation:") == std::string::npos);  // nothing was inverted as a whole

  SECTION("repairing the output again changes nothing and prints nothing") {
    const std::string out2 = tmp / "again.ply", report2 = tmp / "again.json";
    REQUIRE(run("repair '" + out + "' -o '" + out2 + "' --report '" + report2 + "'", err) == 0);
    const nlohmann::json k = nlohmann::json::parse(read_file(report2));
    CHECK(k["changes"] == 0);
    CHECK(k["faces_flipped"] == 0);
    CHECK(k["normals_recomputed"]["total"] == 0);
    CHECK(err.empty());
  }
}

TEST_CASE("repair: data/non_manifold.obj (a fin, a bow-tie, a duplicated triangle) is left as it is", "[repair][cli]") {
  TempDir tmp;
  const std::string out = tmp / "nm.obj", report = tmp / "nm.json";
  std::string err;
  REQUIRE(run("repair '" + data("non_manifold.obj") + "' -o '" + out + "' --report '" + report + "'", err) == 0);
  const nlohmann::json j = nlohmann::json::parse(read_file(report));
  CHECK(j["faces_in"] == 7);
  CHECK(j["faces_out"] == 7);
  CHECK(j["non_manifold_edges"] == 1);  // the fin's edge
  CHECK(j["duplicate_faces"] == 1);
  CHECK(j["components"] == 6);          // 3 fin triangles, 2 bow-tie triangles, 1 (+ its duplicate)
  CHECK(j["open_components"] == 6);
  CHECK(j["boundary_loops"] == 6);
  CHECK(j["faces_flipped"] == 0);       // flat pieces: no evidence, nothing reversed
  CHECK(j["orientation"]["by_majority"] == 6);
}

TEST_CASE("repair: a wholly inverted cube, --remove-degenerate, --weld", "[repair][cli]") {
  TempDir tmp;
  const std::string in = tmp / "cube.obj", out = tmp / "cube_fixed.obj", report = tmp / "r.json";
  std::string err;
  // Inverted cube (every face reversed) plus one zero-area face on collinear points 1, 2, (2,0,0).
  std::string s = cube_obj(false);
  std::string inverted;
  std::istringstream lines(s);
  for (std::string line; std::getline(lines, line);) {
    if (line[0] == 'f') {
      std::istringstream f(line.substr(2));
      int a, b, c;
      f >> a >> b >> c;
      line = "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b);
    }
    inverted += line + "\n";
  }
  inverted += "v 2 0 0\nf 1 2 9\n";
  write_text(in, inverted);
  REQUIRE(run("repair '" + in + "' -o '" + out + "' --report '" + report + "'", err) == 0);
  nlohmann::json j = nlohmann::json::parse(read_file(report));
  CHECK(j["faces_flipped"] == 12);
  CHECK(j["components_inverted"] == 1);
  CHECK(j["degenerate_faces"] == 1);
  CHECK(j["degenerate_by_kind"]["zero_area"] == 1);
  CHECK(j["faces_out"] == 13);  // reported, kept
  CHECK(j["components"] == 2);   // the sliver on the cube's edge (1, 2) makes it non-manifold
  CHECK(j["non_manifold_edges"] == 1);
  CHECK(err.find("orientation: reversed 1 of 2 components as a whole") != std::string::npos);

  REQUIRE(run("repair '" + in + "' -o '" + out + "' --report '" + report + "' --remove-degenerate", err) == 0);
  j = nlohmann::json::parse(read_file(report));
  CHECK(j["degenerate_faces_removed"] == 1);
  CHECK(j["faces_out"] == 12);
  CHECK(err.find("degenerate: removed 1 face (") != std::string::npos);

  // Split the cube's faces apart (each face its own 3 vertices), then weld them back.
  std::string soup;
  std::istringstream cube(cube_obj(true));
  std::vector<std::string> vs;
  int next = 1;
  for (std::string line; std::getline(cube, line);) {
    if (line[0] == 'v') { vs.push_back(line); continue; }
    std::istringstream f(line.substr(2));
    int a, b, c;
    f >> a >> b >> c;
    soup += vs[a - 1] + "\n" + vs[b - 1] + "\n" + vs[c - 1] + "\n";
    soup += "f " + std::to_string(next) + " " + std::to_string(next + 1) + " " + std::to_string(next + 2) + "\n";
    next += 3;
  }
  write_text(in, soup);
  REQUIRE(run("repair '" + in + "' -o '" + out + "' --report '" + report + "' --weld 1e-9", err) == 0);
  j = nlohmann::json::parse(read_file(report));
  CHECK(j["vertices_welded"] == 36 - 8);
  CHECK(j["components"] == 1);
  CHECK(j["closed_components"] == 1);
  CHECK(j["faces_flipped"] == 2);
  CHECK(j["weld_eps"] == 1e-9);
  CHECK(err.find("weld: merged 28 vertices within") != std::string::npos);
}

TEST_CASE("repair: bad input exits 1 with a located message and writes nothing", "[repair][cli]") {
  TempDir tmp;
  const std::string in = tmp / "nan.obj", out = tmp / "out.obj", report = tmp / "r.json";
  std::string err;
  write_text(in, "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  CHECK(run("repair '" + in + "' -o '" + out + "' --report '" + report + "'", err) == 1);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(report));
  CHECK(err.find("shadetool: " + in + ": 1 vertex has NaN or Inf coordinates") != std::string::npos);

  // An existing output is left untouched by a failed run.
  write_text(out, "previous contents");
  CHECK(run("repair '" + in + "' -o '" + out + "'", err) == 1);
  CHECK(read_file(out) == "previous contents");

  // A mesh without faces.
  write_text(in, "v 0 0 0\n");
  fs::remove(out);
  CHECK(run("repair '" + in + "' -o '" + out + "'", err) == 1);
  CHECK(err.find("no faces") != std::string::npos);
  CHECK(!fs::exists(out));

  // A report in a directory that does not exist: refused before any output is written.
  write_text(in, cube_obj(true));
  CHECK(run("repair '" + in + "' -o '" + out + "' --report '" + tmp / "missing/r.json" + "'", err) == 1);
  CHECK(!fs::exists(out));
  CHECK(err.find("cannot write the report") != std::string::npos);
}

TEST_CASE("repair: usage errors exit 2 and write nothing", "[repair][cli]") {
  TempDir tmp;
  const std::string in = tmp / "cube.obj", out = tmp / "out.obj";
  std::string err;
  write_text(in, cube_obj(true));
  CHECK(run("repair '" + in + "' -o '" + out + "' --weld -1", err) == 2);
  CHECK(run("repair '" + in + "' -o '" + out + "' --weight median", err) == 2);
  CHECK(run("repair '" + in + "' '" + in + "' --output-dir '" + tmp.path.string() + "' --report '" + tmp / "r.json" + "'", err) == 2);
  CHECK(err.find("--report takes one input") != std::string::npos);
  // No output given, stdout not a terminal (captured): one mesh goes to stdout, several are refused.
  CHECK(run("repair '" + in + "' '" + in + "'", err) == 2);
  CHECK(err.find("--output-dir") != std::string::npos);
  CHECK(err.find("--in-place") != std::string::npos);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(tmp / "r.json"));
}

TEST_CASE("repair: --json carries the counts", "[repair][cli]") {
  TempDir tmp;
  const std::string in = tmp / "cube.obj", out = tmp / "out.obj";
  write_text(in, cube_obj(true));
  const shadetool_test::ProcessResult r = run_shadetool("repair '" + in + "' -o '" + out + "' --json");
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["status"] == "ok");
  CHECK(j["stats"]["faces_flipped"] == 2);
  CHECK(j["stats"]["components"] == 1);
  CHECK(j["stats"]["faces"] == 12);
}

namespace {

// A cube as a game exporter writes it for flat shading with UVs: every face its own 4 vertices
// (24 in all, positions repeated bitwise), per-vertex normals and texture coordinates, two
// triangles per face. The triangles of faces `inverted` are wound inside out (the normals still
// say outward, as authored).
std::string seam_split_cube_ply(const std::vector<int>& inverted) {
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const double n[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  std::string s = "ply\nformat ascii 1.0\ncomment exported with per-face vertices (UV seams)\nelement vertex 24\n"
                  "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                  "property float nz\nproperty float s\nproperty float t\nelement face 12\n"
                  "property list uchar int vertex_indices\nend_header\n";
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k) {
      const int i = q[f][k];
      s += std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string((i >> 2) & 1) + " " +
           std::to_string(n[f][0]) + " " + std::to_string(n[f][1]) + " " + std::to_string(n[f][2]) + " " +
           std::to_string(k == 1 || k == 2) + " " + std::to_string(k >= 2) + "\n";
    }
  for (int f = 0; f < 6; ++f) {
    const bool flip = std::find(inverted.begin(), inverted.end(), f) != inverted.end();
    for (int t = 0; t < 2; ++t) {
      int a = 4 * f, b = 4 * f + t + 1, c = 4 * f + t + 2;
      if (flip) std::swap(b, c);
      s += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    }
  }
  return s;
}

}  // namespace

TEST_CASE("repair orients a cube split at its UV seams as one closed surface (issue 21 item 12)", "[repair][cli][seams]") {
  TempDir tmp;
  write_text(tmp / "cube.ply", seam_split_cube_ply({1, 4}));
  std::string err;
  REQUIRE(run("repair '" + tmp / "cube.ply" + "' -o '" + tmp / "out.ply" + "' --ascii --report '" + tmp / "r.json" + "'", err) == 0);
  const nlohmann::json r = nlohmann::json::parse(read_file(tmp / "r.json"));
  CHECK(r["seam_vertices_joined"] == 16);  // 24 vertices at 8 positions
  CHECK(r["closed_components"] == 1);
  CHECK(r["faces_flipped"] == 4);  // the two inverted faces' triangles, nothing else
  // The output keeps its 24 vertices (and their UVs) and every triangle faces outward.
  std::istringstream out(read_file(tmp / "out.ply"));
  std::string line;
  int vertices = 0;
  while (std::getline(out, line) && line != "end_header")
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoi(line.substr(15));
  CHECK(vertices == 24);
  std::vector<std::array<double, 3>> p(vertices);
  for (auto& v : p) {
    std::getline(out, line);
    std::istringstream(line) >> v[0] >> v[1] >> v[2];
  }
  int outward = 0;
  for (int f = 0; f < 12; ++f) {
    std::getline(out, line);
    int k, a, b, c;
    std::istringstream(line) >> k >> a >> b >> c;
    double e1[3], e2[3], centre[3];
    for (int i = 0; i < 3; ++i) {
      e1[i] = p[b][i] - p[a][i];
      e2[i] = p[c][i] - p[a][i];
      centre[i] = (p[a][i] + p[b][i] + p[c][i]) / 3 - 0.5;
    }
    const double N[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    outward += N[0] * centre[0] + N[1] * centre[1] + N[2] * centre[2] > 0;
  }
  CHECK(outward == 12);
}

TEST_CASE("repair --remove-unreferenced: NaN in vertices no face uses (Open3D) has a way out, named by every refusal",
          "[repair][cli][issue27]") {
  // issue 27, item 8: Open3D writes NaN into the vertices its subdivision leaves unused; every
  // command refused the file and no option removed them.
  TempDir tmp;
  const std::string in = tmp / "open3d.ply", out = tmp / "out.ply", moved = tmp / "moved.ply";
  write_text(in, "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\nnan nan nan\n1 0 0\n0 1 0\nnan 0 0\n1 1 0\n3 0 2 3\n3 2 5 3\n");
  std::string err;
  // A refusal names the fix.
  CHECK(run("transform '" + in + "' -o '" + moved + "' --translate 1,0,0", err) == 1);
  CHECK(err.find("2 vertices have NaN or Inf coordinates (first: vertex 1); no face uses them: "
                 "`shadetool repair --remove-unreferenced` removes them") != std::string::npos);
  CHECK(run("repair '" + in + "' -o '" + out + "'", err) == 1);
  CHECK(err.find("--remove-unreferenced") != std::string::npos);
  // info reports them.
  const auto info = run_shadetool("info '" + in + "' --json");
  CHECK(info.code == 0);
  const auto j = nlohmann::json::parse(info.out);
  CHECK(j["stats"]["nonfinite_vertices"] == 2);
  CHECK(j["stats"]["nonfinite_unreferenced_vertices"] == 2);
  // The way out: both removed, counted; the faces keep their corners' positions.
  CHECK(run("repair '" + in + "' -o '" + out + "' --remove-unreferenced", err) == 0);
  CHECK(err.find("unreferenced: removed 2 vertices no face used") != std::string::npos);
  const auto after = run_shadetool("info '" + out + "' --json");
  const auto k = nlohmann::json::parse(after.out);
  CHECK(k["stats"]["vertices"] == 4);
  CHECK(k["stats"]["faces"] == 2);
  CHECK(k["stats"]["nonfinite_vertices"] == 0);
  CHECK(k["stats"]["bbox"]["max"] == nlohmann::json::array({1.0, 1.0, 0.0}));
  // A NaN that a face uses is not this case: the message says so.
  const std::string in_obj = tmp / "used.obj";
  write_text(in_obj, "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  CHECK(run("repair '" + in_obj + "' -o '" + out + "' --remove-unreferenced", err) == 1);
  CHECK(err.find("1 vertex has NaN or Inf coordinates (first: vertex 2)\n") != std::string::npos);
}

TEST_CASE("repair keeps a valley terrain its vn agree with, and says why in orientation.by (issue 27 items 1-2)",
          "[repair][cli][authored]") {
  // A bowl z = x^2 + y^2 on a 12 x 12 grid, wound to face up (into the bowl, as a valley is seen
  // from above) with vn = the exact upward surface normal: the winding-number vote alone would
  // turn it over (it wraps the region above it). Written by hand, read back by hand.
  const int n = 12;
  std::string obj;
  auto id = [&](int i, int j) { return j * (n + 1) + i + 1; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      const double len = std::sqrt(4 * x * x + 4 * y * y + 1);
      obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(x * x + y * y) + "\n";
      obj += "vn " + std::to_string(-2 * x / len) + " " + std::to_string(-2 * y / len) + " " + std::to_string(1 / len) + "\n";
    }
  auto corner = [&](int k) { return std::to_string(k) + "//" + std::to_string(k); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      obj += "f " + corner(id(i, j)) + " " + corner(id(i + 1, j)) + " " + corner(id(i + 1, j + 1)) + "\n";
      obj += "f " + corner(id(i, j)) + " " + corner(id(i + 1, j + 1)) + " " + corner(id(i, j + 1)) + "\n";
    }
  TempDir tmp;
  write_text(tmp / "valley.obj", obj);
  std::string err;
  REQUIRE(run("repair '" + tmp / "valley.obj" + "' -o '" + tmp / "out.obj" + "' --report '" + tmp / "r.json" + "'", err) == 0);
  const nlohmann::json r = nlohmann::json::parse(read_file(tmp / "r.json"));
  CHECK(r["faces_flipped"] == 0);
  const nlohmann::json& by = r["orientation"]["by"];
  CHECK(by["winding_and_normals"]["components"] == 1);
  CHECK(by["winding_and_normals"]["faces"] == 2 * n * n);
  CHECK(by["winding_and_normals"]["faces_reversed"] == 0);
  CHECK(by["surface_vote"]["components"] == 0);
  CHECK(by["evidence"]["faces_agreeing_with_normals"] == 2 * n * n);
  CHECK(by["evidence"]["faces_agreeing_reversed"] == 0);
  CHECK(by["evidence"]["components_geometry_overruled"] == 1);  // the vote said: turn it over
  CHECK(err.find("kept 1 component as authored") != std::string::npos);
  // The faces as written are the input's (no face reversed): the same `f` lines.
  std::istringstream in(obj), out(read_file(tmp / "out.obj"));
  std::vector<std::string> fin, fout;
  for (std::string line; std::getline(in, line);) if (line.rfind("f ", 0) == 0) fin.push_back(line);
  for (std::string line; std::getline(out, line);) if (line.rfind("f ", 0) == 0) fout.push_back(line);
  CHECK(fin == fout);
  // Without the vn lines the vote decides and turns it over: the difference is the normals.
  std::string bare;
  std::istringstream again(obj);
  for (std::string line; std::getline(again, line);) {
    if (line.rfind("vn ", 0) == 0) continue;
    if (line.rfind("f ", 0) == 0) {
      std::string f = "f";
      std::istringstream t(line.substr(2));
      for (std::string c; t >> c;) f += " " + c.substr(0, c.find('/'));
      line = f;
    }
    bare += line + "\n";
  }
  write_text(tmp / "bare.obj", bare);
  REQUIRE(run("repair '" + tmp / "bare.obj" + "' -o '" + tmp / "bare_out.obj" + "' --report '" + tmp / "b.json" + "'", err) == 0);
  const nlohmann::json b = nlohmann::json::parse(read_file(tmp / "b.json"));
  CHECK(b["faces_flipped"] == 2 * n * n);
  CHECK(b["orientation"]["by"]["surface_vote"]["inverted"] == 1);
}
