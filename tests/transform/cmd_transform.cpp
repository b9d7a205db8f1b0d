// End-to-end tests of `shadetool transform` (the built binary): flag order, the path named by
// --stats, normal bytes kept through translations, mirrors re-wound in the file, and the messages,
// exit codes and absent outputs of malformed, singular and projective input.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_process.h"

namespace fs = std::filesystem;

namespace {

using Run = shadetool_test::ProcessResult;

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = fs::temp_directory_path() / ("shadetool_transform_" + std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

Run run(const std::string& args) { return shadetool_test::run_shadetool(args); }

std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> r;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) r.push_back(line);
  return r;
}

// A triangle with per-corner normals, written by hand (not by shadetool). The vn numbers are the
// shortest text of floats, as the OBJ writer prints them, so that unchanged values give unchanged
// bytes (a longer spelling such as 0.267261237 would be re-spelt by any reader/writer pair).
const char* kTriangleObj =
    "v 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "vn 0.26726124 0.5345225 0.8017837\nvn 0.1 0.2 0.9746794\nvn -0.6 0 0.8\n"
    "f 1//1 2//2 3//3\n";

// Binary little-endian PLY, float x y z nx ny nz, two triangles, built byte by byte.
std::string binary_ply_with_normals(std::vector<float>& normals_out) {
  std::string h =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nelement face 2\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float v[4][6] = {{0, 0, 0, 0.1f, 0.2f, 0.9746794f},
                         {1, 0, 0, -0.3333333f, 0.6666667f, 0.6666667f},
                         {1, 1, 0.5f, 0.f, 0.f, 1.f},
                         {0, 1, 0.25f, 0.5773503f, -0.5773503f, 0.5773503f}};
  std::string b = h;
  for (auto& r : v) {
    b.append(reinterpret_cast<const char*>(r), sizeof r);
    normals_out.insert(normals_out.end(), r + 3, r + 6);
  }
  const std::int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (auto& f : faces) {
    b.push_back(char(3));
    b.append(reinterpret_cast<const char*>(f), sizeof f);
  }
  return b;
}

// The bytes of nx ny nz of every vertex in a binary little-endian PLY whose vertex element comes
// first and has only scalar properties (what shadetool writes): parsed from the header.
std::string ply_normal_bytes(const std::string& file, std::size_t& vertex_count) {
  const std::size_t end = file.find("end_header\n");
  REQUIRE(end != std::string::npos);
  std::istringstream header(file.substr(0, end));
  std::string line;
  bool in_vertex = false;
  std::size_t offset = 0, stride = 0, n_offset = std::string::npos, n_size = 0;
  vertex_count = 0;
  while (std::getline(header, line)) {
    std::istringstream w(line);
    std::string kw, a, b;
    w >> kw >> a >> b;
    if (kw == "element") {
      in_vertex = a == "vertex";
      if (in_vertex) vertex_count = std::stoul(b);
    } else if (kw == "property" && in_vertex) {
      const std::size_t size = (a == "double" || a == "float64") ? 8 : (a == "uchar" || a == "uint8" || a == "char") ? 1 : 4;
      if (b == "nx") n_offset = offset, n_size = size;
      offset += size;
      stride = offset;
    }
  }
  REQUIRE(n_offset != std::string::npos);
  std::string bytes;
  const char* body = file.data() + end + std::strlen("end_header\n");
  for (std::size_t v = 0; v < vertex_count; ++v) bytes.append(body + v * stride + n_offset, 3 * n_size);
  return bytes;
}

}  // namespace

TEST_CASE("cmd transform: translation keeps the normals' file bytes (OBJ text and binary PLY)", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "out.obj" + "' --translate 10,-2.5,1e3 --stats");
  CHECK(r.code == 0);
  CHECK(r.err.find("path=translation") != std::string::npos);
  CHECK(lines_starting(slurp(dir / "out.obj"), "vn ") == lines_starting(kTriangleObj, "vn "));
  CHECK(lines_starting(slurp(dir / "out.obj"), "v ") ==
        std::vector<std::string>{"v 11 -2.5 1000", "v 10 -1.5 1000", "v 10 -2.5 1001"});

  std::vector<float> normals;
  spit(dir / "in.ply", binary_ply_with_normals(normals));
  r = run("transform '" + dir / "in.ply" + "' -o '" + dir / "out.ply" + "' --translate 0.1,0.2,0.3");
  REQUIRE(r.code == 0);
  std::size_t nv = 0;
  const std::string got = ply_normal_bytes(slurp(dir / "out.ply"), nv);
  CHECK(nv == 4);
  CHECK(got == std::string(reinterpret_cast<const char*>(normals.data()), normals.size() * sizeof(float)));
}

TEST_CASE("cmd transform: flags act in command-line order", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  // Vertex (1,0,0): rotate then translate -> (1,1,0); translate then rotate -> (0,2,0).
  Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "a.obj" + "' --rotate 90,0,0,1 --translate 1,0,0");
  REQUIRE(r.code == 0);
  CHECK(lines_starting(slurp(dir / "a.obj"), "v ")[0] == "v 1 1 0");
  r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "b.obj" + "' --translate 1,0,0 --rotate 90,0,0,1");
  REQUIRE(r.code == 0);
  CHECK(lines_starting(slurp(dir / "b.obj"), "v ")[0] == "v 0 2 0");
  // Repeated flags: (1 * 2 + 1) * 3 = 9 versus (1 + 1) * 2 * 3 = 12.
  run("transform '" + dir / "tri.obj" + "' -o '" + dir / "c.obj" + "' --scale 2 --translate 1,0,0 --scale 3");
  CHECK(lines_starting(slurp(dir / "c.obj"), "v ")[0] == "v 9 0 0");
  run("transform '" + dir / "tri.obj" + "' -o '" + dir / "d.obj" + "' --translate 1,0,0 --scale 2 --scale=3");
  CHECK(lines_starting(slurp(dir / "d.obj"), "v ")[0] == "v 12 0 0");
  // A matrix from a file, 3x4 with a comment: x' = 2x + 1.
  spit(dir / "m.txt", "# scale x by 2, then move by 1\n2 0 0 1\n0 1 0 0\n0 0 1 0\n");
  r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "e.obj" + "' --matrix @'" + dir / "m.txt" + "' --stats");
  REQUIRE(r.code == 0);
  CHECK(lines_starting(slurp(dir / "e.obj"), "v ")[0] == "v 3 0 0");
  CHECK(r.err.find("path=general") != std::string::npos);
}

TEST_CASE("cmd transform: --stats names the path", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  struct Case { const char* flags; const char* path; };
  for (Case c : {Case{"", "path=identity"}, Case{"--translate 1,2,3", "path=translation"},
                 Case{"--rotate 30,1,1,0", "path=rotation"}, Case{"--rotate 30,1,1,0 --scale 2", "path=uniform-scale"},
                 Case{"--scale 1,2,3", "path=general"}, Case{"--scale 1,1,0 --normals drop", "path=singular"},
                 Case{"--scale -1,1,1", "path=rotation"}}) {
    const Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "o.obj" + "' --stats " + c.flags);
    CAPTURE(c.flags, r.err);
    CHECK(r.code == 0);
    CHECK(r.err.find(c.path) != std::string::npos);
  }
}

TEST_CASE("cmd transform: --json carries the path, the mirror flag and what happened to the normals", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  const Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "j.obj" + "' --scale 1,-2,3 --json");
  REQUIRE(r.code == 0);
  CHECK(r.out.find("\"path\":\"general\"") != std::string::npos);
  CHECK(r.out.find("\"mirror\":true") != std::string::npos);
  CHECK(r.out.find("\"normals\":\"transformed\"") != std::string::npos);
}

TEST_CASE("cmd transform: --scale -1,1,1 re-winds the faces in the file and says so", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  const Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "m.obj" + "' --scale -1,1,1 --stats");
  REQUIRE(r.code == 0);
  CHECK(r.err.find("mirror=true") != std::string::npos);
  CHECK(r.err.find("winding reversed") != std::string::npos);
  const auto f = lines_starting(slurp(dir / "m.obj"), "f ");
  REQUIRE(f.size() == 1);
  // Corners (1,2,3) become (1,3,2), each corner keeping its own normal index.
  CHECK(f[0] == "f 1//1 3//3 2//2");
  CHECK(lines_starting(slurp(dir / "m.obj"), "vn ")[2] == "vn 0.6 0 0.8");
}

TEST_CASE("cmd transform: a mirror of a point cloud (no faces) says nothing about winding; with faces it does",
          "[cmd_transform]") {
  // The same vertices as points only (a PLY with no face element, as scanners write) and with one
  // face: only the second has a face whose winding the mirror reverses.
  TempDir dir;
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string verts = "1 0 0\n0 1 0\n0 0 1\n";
  spit(dir / "points.ply", head + "end_header\n" + verts);
  spit(dir / "face.ply", head + "element face 1\nproperty list uchar int vertex_indices\nend_header\n" + verts + "3 0 1 2\n");
  const Run points = run("transform '" + dir / "points.ply" + "' -o '" + dir / "p.ply" + "' --scale -1,1,1 --stats --ascii");
  REQUIRE(points.code == 0);
  CHECK(points.err.find("mirror=true") != std::string::npos);  // the map is still a mirror
  CHECK(points.err.find("winding") == std::string::npos);
  CHECK(slurp(dir / "p.ply").find("-1 0 0\n0 1 0\n0 0 1\n") != std::string::npos);
  const Run face = run("transform '" + dir / "face.ply" + "' -o '" + dir / "f.ply" + "' --scale -1,1,1 --stats --ascii");
  REQUIRE(face.code == 0);
  CHECK(face.err.find("det(A) < 0 (a mirror): face winding reversed so that faces keep their orientation") != std::string::npos);
  CHECK(slurp(dir / "f.ply").find("\n3 0 2 1\n") != std::string::npos);
}

TEST_CASE("cmd transform: malformed numbers are usage errors with a clear line and no output", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  struct Case { const char* flags; const char* message; };
  for (Case c : {Case{"--scale 1,x,3", "shadetool: --scale '1,x,3': 'x' is not a number\n"},
                 Case{"--scale 1,2", "shadetool: --scale '1,2': give S or SX,SY,SZ (1 or 3 numbers), got 2\n"},
                 Case{"--translate 1,,3", "shadetool: --translate '1,,3': item 2 is empty"},
                 Case{"--rotate 90,0,0", "shadetool: --rotate '90,0,0': give DEG,AX,AY,AZ (4 numbers), got 3\n"},
                 Case{"--rotate 90,0,0,0", "shadetool: --rotate: the rotation axis has zero length\n"},
                 Case{"--scale 1e999", "shadetool: --scale '1e999': '1e999' is out of the range of double\n"},
                 Case{"--translate nan,0,0", "'nan' is not a finite number"},
                 Case{"--matrix 1,2,3", "shadetool: --matrix: expected 12 or 16 numbers"},
                 Case{"--matrix 1,0,0,0,0,1,0,0,0,0,1,0,0,0,0.5,1",
                      "shadetool: --matrix: the last row of a 4x4 matrix must be 0 0 0 1, got 0 0 0.5 1"},
                 Case{"--scale 1,1,0", "shadetool: the transform is singular or nearly so"},
                 Case{"--scale 1,1,1e-12 --normals transform", "--normals drop | --normals recompute"},
                 Case{"--normals sideways", "--normals"},
                 Case{"--scale 1e200 --scale 1e200", "shadetool: the composed transform has an entry that overflows"}}) {
    const Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "never.obj" + "' " + c.flags);
    CAPTURE(c.flags, r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "never.obj"));
  }
}

TEST_CASE("cmd transform: a bad matrix file is an input error naming FILE:LINE", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  spit(dir / "bad.txt", "1 0 0 0\n0 1 zero 0\n0 0 1 0\n");
  spit(dir / "proj.txt", "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 -1 0\n");
  spit(dir / "short.txt", "1 0 0 0\n0 1 0 0\n");
  struct Case { std::string flags, message; };
  for (const Case& c : {Case{"--matrix @'" + dir / "bad.txt" + "'", dir / "bad.txt" + ":2: 'zero' is not a number\n"},
                        Case{"--matrix @'" + dir / "proj.txt" + "'", dir / "proj.txt" + ": the last row of a 4x4 matrix"},
                        Case{"--matrix @'" + dir / "short.txt" + "'", dir / "short.txt" + ": expected 12 or 16 numbers"},
                        Case{"--matrix @'" + dir / "missing.txt" + "'", dir / "missing.txt" + ": cannot open the matrix file"}}) {
    const Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "never.obj" + "' " + c.flags);
    CAPTURE(c.flags, r.err);
    CHECK(r.code == 1);
    CHECK(r.err.find("shadetool: " + c.message) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "never.obj"));
  }
}

TEST_CASE("cmd transform: singular maps run with --normals drop or recompute", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "tri.obj", kTriangleObj);
  Run r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "flat.obj" + "' --scale 1,1,0 --normals drop");
  CHECK(r.code == 0);
  CHECK(lines_starting(slurp(dir / "flat.obj"), "vn ").empty());
  CHECK(lines_starting(slurp(dir / "flat.obj"), "v ")[2] == "v 0 0 0");
  r = run("transform '" + dir / "tri.obj" + "' -o '" + dir / "re.obj" + "' --scale 1,2,3 --normals recompute");
  CHECK(r.code == 0);
  // Mapped triangle (1,0,0), (0,2,0), (0,0,3): plane x + y/2 + z/3 = 1, normal (6,3,2)/7.
  for (const auto& line : lines_starting(slurp(dir / "re.obj"), "vn ")) {
    std::istringstream w(line.substr(3));
    double x, y, z;
    w >> x >> y >> z;
    CHECK(x == Approx(6.0 / 7).epsilon(1e-7));  // OBJ in float precision: written as floats
    CHECK(y == Approx(3.0 / 7).epsilon(1e-7));
    CHECK(z == Approx(2.0 / 7).epsilon(1e-7));
  }
}

TEST_CASE("cmd transform: every flag in --help is documented in the man page", "[cmd_transform]") {
  TempDir dir;
  const Run r = run("transform --help");
  CHECK(r.code == 0);
  const std::string man = slurp(std::string(SHADETOOL_SOURCE_DIR) + "/man/shadetool-transform.1");
  REQUIRE(!man.empty());
  for (const char* flag : {"--scale", "--rotate", "--translate", "--matrix", "--normals", "--stats", "--output",
                           "--output-dir", "--format", "--json", "--quiet", "--jobs", "--ascii", "--binary",
                           "--input-format"}) {
    CAPTURE(flag);
    CHECK(r.out.find(flag) != std::string::npos);
    // roff escapes '-' as '\-'.
    std::string escaped;
    for (const char* p = flag; *p; ++p) escaped += *p == '-' ? std::string("\\-") : std::string(1, *p);
    CHECK(man.find(escaped) != std::string::npos);
  }
}

TEST_CASE("cmd transform: a zero input normal (assimp's spider.obj) is replaced by the computed one with a counted "
          "note, not refused (issue 27 item 14)", "[cmd_transform]") {
  TempDir dir;
  spit(dir / "in.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 0\nf 1//1 2//1 3//2\nf 2//1 4//1 3//1\n");
  const Run r = run("transform --translate 1,0,0 '" + dir / "in.obj" + "' -o '" + dir / "out.obj" + "'");
  CHECK(r.code == 0);
  CHECK(r.err.find("1 input normal had no direction (zero, NaN or Inf): replaced by the computed one (1 corner)") != std::string::npos);
  // Both written normals are the plane's +z (translation leaves them as they are); none is zero.
  CHECK(lines_starting(slurp(dir / "out.obj"), "vn ") == std::vector<std::string>{"vn 0 0 1", "vn 0 0 1"});
  // `normals` without --recompute keeps asking, as documented.
  const Run keep = run("normals '" + dir / "in.obj" + "' -o '" + dir / "kept.obj" + "'");
  CHECK(keep.code == 1);
  CHECK(keep.err.find("use --recompute") != std::string::npos);
}
