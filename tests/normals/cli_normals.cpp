// End-to-end tests of `shadetool normals`: flags, notes, exit codes, files written or not.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include <shadetool/files/mesh_files.h>
#include "normals_test_util.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

using namespace shadetool;
using namespace shadetool::testing;
namespace fs = std::filesystem;

namespace {

using Run = shadetool_test::ProcessResult;
using shadetool_test::read_file;
using shadetool_test::run_shadetool;
using shadetool::testing::TempDir;


std::string data(const std::string& name) { return std::string(SHADETOOL_SOURCE_DIR) + "/data/" + name; }

void write_double_ply(const Mesh& m, const std::string& path) {
  Mesh copy = m;
  copy.precision = ValuePrecision::Double;
  WriteOptions o;
  o.format = Format::Ply;
  write_mesh(copy, path, o);
}

}  // namespace

TEST_CASE("cli normals: default computes angle-weighted vertex normals (cube: diagonals)", "[cli]") {
  TempDir d;
  const Run r = run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "out.ply") + "' --stats");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("weight=angle") != std::string::npos);
  CHECK(r.err.find("fallback_vertices=0") != std::string::npos);
  const Mesh out = read_mesh(d / "out.ply");
  REQUIRE(out.has_vertex_normals());
  for (std::size_t v = 0; v < out.num_vertices(); ++v) {
    const Vec3d p = out.position(v), n = get3(out.vertex_normals, v);
    CHECK(angle_degrees(n, p) < 1e-5);  // cube centred at 0: the diagonal is the position (float file)
  }
}

TEST_CASE("cli normals: existing normals are written back bitwise, with a note", "[cli]") {
  TempDir d;
  Mesh m = cube(false);
  // Unit length to rounding (a normal off unit length by more than 1e-3 is written divided by its
  // length: files/mesh_files.h), with bits a float or a short decimal would lose.
  for (std::size_t v = 0; v < 8; ++v) {
    const double x = 0.1 * double(v) + 1e-17;
    m.vertex_normals.push_back(x);
    m.vertex_normals.push_back(-3.0e-300);
    m.vertex_normals.push_back(std::nextafter(std::sqrt(1 - x * x), 0.0));
  }
  write_double_ply(m, d / "in.ply");
  const Run r = run_shadetool("normals '" + (d / "in.ply") + "' -o '" + (d / "out.ply") + "'");
  REQUIRE(r.code == 0);
  CHECK(r.err.find("kept unchanged") != std::string::npos);
  CHECK(r.err.find("--recompute") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line
  const Mesh out = read_mesh(d / "out.ply");
  CHECK(out.vertex_normals == m.vertex_normals);  // bitwise, through a double PLY
  // --recompute replaces them.
  const Run r2 = run_shadetool("normals '" + (d / "in.ply") + "' -o '" + (d / "out2.ply") + "' --recompute");
  REQUIRE(r2.code == 0);
  const Mesh out2 = read_mesh(d / "out2.ply");
  CHECK(out2.vertex_normals != m.vertex_normals);
  CHECK(std::fabs(out2.vertex_normals[0] + 1 / std::sqrt(3.0)) < 1e-15);
}

TEST_CASE("cli normals: invalid existing normals: exit 1, count named, --recompute asked, no output", "[cli]") {
  TempDir d;
  Mesh m = cube(false);
  m.vertex_normals.assign(24, 0.5);
  m.vertex_normals[0] = std::numeric_limits<double>::quiet_NaN();
  m.vertex_normals[9] = m.vertex_normals[10] = m.vertex_normals[11] = 0.0;
  write_double_ply(m, d / "in.ply");
  const Run r = run_shadetool("normals '" + (d / "in.ply") + "' -o '" + (d / "out.ply") + "'");
  CHECK(r.code == 1);
  CHECK(r.err.find("shadetool: " + (d / "in.ply") + ": 2 of 8 vertex normals are invalid") != std::string::npos);
  CHECK(r.err.find("--recompute") != std::string::npos);
  CHECK_FALSE(fs::exists(d / "out.ply"));
  const Run ok = run_shadetool("normals '" + (d / "in.ply") + "' -o '" + (d / "out.ply") + "' --recompute");
  CHECK(ok.code == 0);
  CHECK(fs::exists(d / "out.ply"));
}

TEST_CASE("cli normals: --crease writes per-corner vn in OBJ and splits vertices in PLY", "[cli]") {
  TempDir d;
  const Run r = run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "out.obj") + "' --crease 30");
  REQUIRE(r.code == 0);
  const Mesh obj = read_mesh(d / "out.obj");
  REQUIRE(obj.has_corner_normals());
  CHECK(obj.num_vertices() == 8);
  CHECK(obj.corner_normals.size() == 3 * 24);
  // Every corner's normal is one of the six axes.
  for (std::size_t c = 0; c < obj.num_corners(); ++c) {
    REQUIRE(obj.corner_normal_index[c] < obj.corner_normals.size() / 3);
    const Vec3d n = get3(obj.corner_normals, obj.corner_normal_index[c]);
    CHECK(std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z) == 1.0);
  }
  const Run p = run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "out.ply") + "' --crease 30 --stats");
  REQUIRE(p.code == 0);
  CHECK(p.err.find("split_vertices=16") != std::string::npos);
  CHECK(p.err.find("corner_normals=24") != std::string::npos);
  CHECK(read_mesh(d / "out.ply").num_vertices() == 24);
  // --crease 180: one normal per vertex again.
  const Run q = run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "flat.obj") + "' --crease 180");
  REQUIRE(q.code == 0);
  CHECK(read_mesh(d / "flat.obj").corner_normals.size() == 3 * 8);
}

TEST_CASE("cli normals: --faces writes one normal per face", "[cli]") {
  TempDir d;
  REQUIRE(run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "f.ply") + "' --faces").code == 0);
  const Mesh ply = read_mesh(d / "f.ply");
  REQUIRE(ply.has_face_normals());
  CHECK_FALSE(ply.has_vertex_normals());
  REQUIRE(run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "f.obj") + "' --faces").code == 0);
  const Mesh obj = read_mesh(d / "f.obj");
  REQUIRE(obj.has_corner_normals());
  CHECK(obj.corner_normals.size() == 3 * obj.num_faces());
  for (std::size_t f = 0; f < obj.num_faces(); ++f)
    for (std::uint32_t c = obj.face_start[f]; c < obj.face_start[f + 1]; ++c) CHECK(obj.corner_normal_index[c] == f);
  // The face normals are the cube's axes (OBJ written in float: exact for 0 and +-1).
  for (std::size_t f = 0; f < ply.num_faces(); ++f) {
    const Vec3d n = get3(ply.face_normals, f);
    CHECK(std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z) == 1.0);
  }
}

TEST_CASE("cli normals: every weighting and precision runs; float is within 1e-3 deg of double", "[cli]") {
  TempDir d;
  for (const char* w : {"uniform", "area", "angle", "max"}) {
    const std::string base = std::string("normals '") + data("torus.obj") + "' --weight " + w + " -o '";
    REQUIRE(run_shadetool(base + (d / "dbl.ply") + "'").code == 0);
    REQUIRE(run_shadetool(base + (d / "flt.ply") + "' --precision float").code == 0);
    const Mesh a = read_mesh(d / "dbl.ply"), b = read_mesh(d / "flt.ply");
    double worst = 0;
    for (std::size_t v = 0; v < a.num_vertices(); ++v)
      worst = std::max(worst, angle_degrees(get3(a.vertex_normals, v), get3(b.vertex_normals, v)));
    CHECK(worst < 1e-3);
  }
}

TEST_CASE("cli normals: isolated vertices and degenerate faces are counted, never NaN", "[cli]") {
  TempDir d;
  std::ofstream(d / "in.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nv 2 0 0\nf 1 2 3\nf 1 2 5\n";
  const Run r = run_shadetool("normals '" + (d / "in.obj") + "' -o '" + (d / "out.obj") + "' --stats");
  REQUIRE(r.code == 0);
  CHECK(r.err.find("fallback_vertices=2") != std::string::npos);  // v4 isolated, v5 only on a degenerate face
  CHECK(r.err.find("degenerate_faces=1") != std::string::npos);
  CHECK(r.err.find("given a fallback normal") != std::string::npos);
  const Mesh out = read_mesh(d / "out.obj");
  for (double x : out.corner_normals) CHECK(std::isfinite(x));
}

TEST_CASE("cli normals: usage errors exit 2, bad input exits 1, with no output", "[cli]") {
  TempDir d;
  const std::string in = "'" + data("cube.obj") + "'", out = " -o '" + (d / "o.ply") + "'";
  CHECK(run_shadetool("normals " + in + out + " --crease 200").code == 2);
  CHECK(run_shadetool("normals " + in + out + " --crease -1").code == 2);
  CHECK(run_shadetool("normals " + in + out + " --faces --crease 30").code == 2);
  CHECK(run_shadetool("normals " + in + out + " --faces --weight area").code == 2);
  CHECK(run_shadetool("normals " + in + out + " --weight cotan").code == 2);
  CHECK(run_shadetool("normals " + in + out + " --precision half").code == 2);
  CHECK_FALSE(fs::exists(d / "o.ply"));
  std::ofstream(d / "nan.obj") << "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n";
  const Run r = run_shadetool("normals '" + (d / "nan.obj") + "'" + out);
  CHECK(r.code == 1);
  CHECK(r.err.find("NaN or Inf coordinates") != std::string::npos);
  CHECK_FALSE(fs::exists(d / "o.ply"));
}

TEST_CASE("cli normals: --json reports the stats", "[cli]") {
  TempDir d;
  const Run r = run_shadetool("normals '" + data("cube.obj") + "' -o '" + (d / "o.obj") + "' --json --crease 45");
  REQUIRE(r.code == 0);
  CHECK(r.out.find("\"normals\":\"corner\"") != std::string::npos);
  CHECK(r.out.find("\"fallback_corners\":0") != std::string::npos);
}

TEST_CASE("cli normals: the man page documents every flag of --help", "[cli][man]") {
  TempDir d;
  const Run r = run_shadetool("normals --help");
  REQUIRE(r.code == 0);
  const std::string man = read_file(fs::path(SHADETOOL_SOURCE_DIR) / "man" / "shadetool-normals.1");
  REQUIRE_FALSE(man.empty());
  // Long flags in the help text: "--" followed by lower-case letters and hyphens.
  std::set<std::string> flags;
  for (std::size_t i = r.out.find("--"); i != std::string::npos; i = r.out.find("--", i + 2)) {
    std::size_t e = i + 2;
    while (e < r.out.size() && ((r.out[e] >= 'a' && r.out[e] <= 'z') || r.out[e] == '-')) ++e;
    if (e > i + 2 && r.out[i + 2] != '-') flags.insert(r.out.substr(i, e - i));
  }
  CHECK(flags.size() >= 15);
  for (const auto& f : flags) {
    INFO(f);
    // roff escapes '-' as '\-'
    std::string escaped;
    for (char c : f) escaped += c == '-' ? std::string("\\-") : std::string(1, c);
    CHECK((man.find(escaped) != std::string::npos || man.find(f) != std::string::npos));
  }
}

TEST_CASE("normals --recompute --crease 30 gives a vertex no face uses the fallback, never 0 0 0, and its output is "
          "accepted again (issue 27 item 4: the Stanford bun_zipper.ply case)", "[cli][normals]") {
  TempDir tmp;
  const std::string in = tmp / "unref.ply", out = tmp / "out.ply", again = tmp / "again.ply";
  std::ofstream(in) << "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                       "0 0 0\n1 0 0\n0 1 0\n5 5 5\n0 0 1\n3 0 1 2\n3 0 4 1\n";
  for (const std::string& mode : {std::string("--crease 30"), std::string(""), std::string("--crease 180")}) {
    const Run r = run_shadetool("normals --recompute " + mode + " --ascii '" + in + "' -o '" + out + "'");
    REQUIRE(r.code == 0);
    const Mesh m = read_mesh(out);
    REQUIRE(m.has_vertex_normals());
    for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(length(get3(m.vertex_normals, v)) > 0.5);
    // Vertex 3 (5, 5, 5) is used by no face: the documented fallback (0, 0, 1).
    CHECK(get3(m.vertex_normals, 3) == Vec3d{0, 0, 1});
    CHECK(run_shadetool("normals '" + out + "' -o '" + again + "'").code == 0);  // its own output is not refused
  }
}
