// shadetool render from the command line: outputs, exit codes, no partial files.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "support/temp_dir.h"
#include "support/run_process.h"

using shadetool_test::run_shadetool;
namespace fs = std::filesystem;

namespace {

const std::string src = SHADETOOL_SOURCE_DIR;
const std::string torus = src + "/data/torus.obj";
const std::string studio = src + "/data/scenes/studio.json";

// A fresh directory per test inside this process's own TempDir (mkdtemp: test runs side by side,
// from other checkouts too, never share one), removed when the process ends.
fs::path scratch(const std::string& name) {
  static const shadetool::testing::TempDir root;
  const fs::path d = root.path / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("render writes an sRGB PNG, or a PFM with --hdr", "[render][cli]") {
  const fs::path d = scratch("ok");
  const auto r = run_shadetool("render " + torus + " -o " + (d / "t.png").string() + " --scene " + studio +
                               " --shading gouraud --size 64,48 --stats");
  CHECK(r.code == 0);
  CHECK(r.err.find("culled_faces=") != std::string::npos);
  CHECK(r.err.find("faces_outside_view=0") != std::string::npos);
  const std::string png = shadetool_test::read_file((d / "t.png").string());
  REQUIRE(png.size() > 50);
  CHECK(png.compare(1, 3, "PNG") == 0);
  CHECK(png.find("sRGB") != std::string::npos);
  const auto h = run_shadetool("render " + torus + " -o " + (d / "t.pfm").string() + " --scene " + studio + " --hdr --size 8,6");
  CHECK(h.code == 0);
  const std::string pfm = shadetool_test::read_file((d / "t.pfm").string());
  CHECK(pfm.compare(0, 9, "PF\n8 6\n-1") == 0);
  CHECK(pfm.size() == std::string("PF\n8 6\n-1.0\n").size() + 8 * 6 * 12);
}

TEST_CASE("render: bad input is one line, exit 1, and no output file", "[render][cli]") {
  const fs::path d = scratch("bad");
  const std::string out = (d / "o.png").string();
  // A flag value outside the library's limit is a usage error (exit 2), as every other (issue 26).
  auto r = run_shadetool("render " + torus + " -o " + out + " --scene " + studio + " --size 0,10");
  CHECK(r.code == 2);
  CHECK(r.err.find("each side must be 1..16384") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(out));
  // --space under phong is refused (exit 2), not accepted and ignored; flat and gouraud take it.
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + studio + " --size 8,8 --space object");
  CHECK(r.code == 2);
  CHECK(r.err.find("space 'object' applies to flat and gouraud shading") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + studio + " --size 8,8 --space object --shading flat");
  CHECK(r.code == 0);
  fs::remove(out);
  CHECK_FALSE(fs::exists(out));

  r = run_shadetool("render " + torus + " -o " + (d / "missing" / "o.png").string() + " --scene " + studio + " --size 8,8");
  CHECK(r.code == 1);
  CHECK(r.err.find("cannot write") != std::string::npos);

  std::ofstream(d / "up.json") << R"({"camera": {"eye": [0,5,0], "target": [0,0,0], "up": [0,1,0]}})";
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + (d / "up.json").string());
  CHECK(r.code == 1);
  CHECK(r.err.find("$.camera.up: is parallel to the view direction") != std::string::npos);

  std::ofstream(d / "inside.json") << R"({"camera": {"eye": [1,0,0], "target": [0,1,0]}})";  // in the tube
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + (d / "inside.json").string() + " --size 8,8");
  CHECK(r.code == 1);
  CHECK(r.err.find("is inside the mesh") != std::string::npos);
  CHECK_FALSE(fs::exists(out));

  // An existing output is not touched by a failed render.
  std::ofstream(out) << "keep";
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + (d / "inside.json").string() + " --size 8,8");
  CHECK(r.code == 1);
  CHECK(shadetool_test::read_file(out) == "keep");

  r = run_shadetool("render " + torus + " --scene " + studio);  // no output: usage
  CHECK(r.code == 2);
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + studio + " --shading toon");
  CHECK(r.code == 2);
  r = run_shadetool("render " + torus + " -o " + out + " --scene " + studio + " --samples 0");
  CHECK(r.code == 2);
}

TEST_CASE("render --shadows: shadowed pixels, --shadow-samples only with --shadows", "[render][cli][shadows]") {
  const fs::path d = scratch("shadows");
  const std::string knot = src + "/data/torus_knot.ply", sun = src + "/data/scenes/sun.json";
  const auto plain = run_shadetool("render " + knot + " -o " + (d / "a.pfm").string() + " --scene " + sun + " --hdr --size 64,48");
  const auto shadowed = run_shadetool("render " + knot + " -o " + (d / "b.pfm").string() + " --scene " + sun +
                                      " --hdr --size 64,48 --shadows --stats");
  REQUIRE(plain.code == 0);
  REQUIRE(shadowed.code == 0);
  CHECK(shadowed.err.find("shadows=on") != std::string::npos);
  // The knot's strands shade each other under the sun: some pixels darker, none brighter.
  const std::string a = shadetool_test::read_file((d / "a.pfm").string()), b = shadetool_test::read_file((d / "b.pfm").string());
  REQUIRE(a.size() == b.size());
  const std::size_t header = std::string("PF\n64 48\n-1.0\n").size();
  std::size_t darker = 0, brighter = 0;
  for (std::size_t i = header; i + 4 <= a.size(); i += 4) {
    float x, y;
    std::memcpy(&x, a.data() + i, 4);
    std::memcpy(&y, b.data() + i, 4);
    darker += y < x;
    brighter += y > x;
  }
  CHECK(darker > 0);
  CHECK(brighter == 0);
  const auto r = run_shadetool("render " + knot + " -o " + (d / "c.png").string() + " --scene " + sun + " --shadow-samples 4");
  CHECK(r.code == 2);
  CHECK_FALSE(fs::exists(d / "c.png"));
}

TEST_CASE("render uses an OBJ's corner normals: the same image as the same normals from a PLY", "[render][cli][issue27]") {
  // issue 27, item 6: `normals --crease 30` writes per-corner vn to OBJ (one vn pool, shared
  // vertices) and split vertices with vertex normals to PLY. Both files hold the same normals; the
  // OBJ rendered smooth (computed normals) and the PLY crisp. The ascii PLY keeps every value
  // exactly (shortest text), so the two meshes are equal after the split and the images must be
  // equal byte for byte, under Gouraud and Phong alike.
  const fs::path d = scratch("corner_normals");
  const std::string cube = src + "/data/cube.obj";
  const std::string obj = (d / "c.obj").string(), ply = (d / "c.ply").string();
  REQUIRE(run_shadetool("normals " + cube + " --crease 30 -o " + obj).code == 0);
  REQUIRE(run_shadetool("normals " + cube + " --crease 30 --ascii -o " + ply).code == 0);
  REQUIRE(shadetool_test::read_file(obj).find("//") != std::string::npos);  // corner normals: f v//vn
  for (const char* shading : {"gouraud", "phong"}) {
    const std::string a = (d / (std::string("obj_") + shading + ".png")).string();
    const std::string b = (d / (std::string("ply_") + shading + ".png")).string();
    const std::string flags = std::string(" --scene ") + studio + " --shading " + shading + " --size 48,40";
    REQUIRE(run_shadetool("render " + obj + " -o " + a + flags).code == 0);
    REQUIRE(run_shadetool("render " + ply + " -o " + b + flags).code == 0);
    const std::string pa = shadetool_test::read_file(a), pb = shadetool_test::read_file(b);
    REQUIRE(pa.size() > 50);
    CHECK(pa == pb);
  }
  // And the crease is visible: a smooth-shaded cube (normals averaged over the corner) differs.
  const std::string smooth = (d / "smooth.obj").string();
  REQUIRE(run_shadetool("normals " + cube + " --recompute -o " + smooth).code == 0);
  const std::string s = (d / "s.png").string(), c = (d / "c.png").string();
  REQUIRE(run_shadetool("render " + smooth + " -o " + s + " --scene " + studio + " --shading phong --size 48,40").code == 0);
  REQUIRE(run_shadetool("render " + obj + " -o " + c + " --scene " + studio + " --shading phong --size 48,40").code == 0);
  CHECK(shadetool_test::read_file(s) != shadetool_test::read_file(c));
}

TEST_CASE("render of a mesh without faces is an error, not a background-only PNG", "[render][cli][issue27]") {
  // issue 27, item 9: a faceless input rendered as a black PNG with exit 0.
  const fs::path d = scratch("faceless");
  std::ofstream(d / "points.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string out = (d / "p.png").string();
  const auto r = run_shadetool("render " + (d / "points.ply").string() + " -o " + out + " --scene " + studio + " --size 8,8");
  CHECK(r.code == 1);
  CHECK(r.err.find("mesh is empty (no faces)") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

// Issue 28, item 12: without --scene, a 0.2-unit model far from the origin fills the picture (the
// default scene's framing camera), and --camera frame rescues a scene whose fixed camera looks
// elsewhere. Coverage is counted in the PFM (background exactly 0): more than 10% of the pixels lit
// (the torus ring seen face on covers 16% of a 64x48 frame; a scene's fixed camera 0%, a dot 0.1%).
namespace {
double lit_fraction(const std::string& pfm_path) {
  const std::string pfm = shadetool_test::read_file(pfm_path);
  const std::size_t header = pfm.find("-1.0\n");
  REQUIRE(header != std::string::npos);
  std::size_t lit = 0, pixels = (pfm.size() - header - 5) / 12;
  for (std::size_t p = 0; p < pixels; ++p) {
    float rgb[3];
    std::memcpy(rgb, pfm.data() + header + 5 + 12 * p, 12);
    lit += rgb[0] > 0 || rgb[1] > 0 || rgb[2] > 0;
  }
  return pixels ? double(lit) / double(pixels) : 0.0;
}
}  // namespace

TEST_CASE("render without --scene frames a small, far model; --camera frame replaces a scene's camera", "[render][cli]") {
  const fs::path d = scratch("default_scene");
  // The torus (radius about 1.3) scaled to 0.2 units and moved 1000 units away.
  auto r = run_shadetool("transform " + torus + " -o " + (d / "small.ply").string() + " --scale 0.08 --translate 1000,-500,300");
  REQUIRE(r.code == 0);
  r = run_shadetool("render " + (d / "small.ply").string() + " -o " + (d / "a.pfm").string() + " --hdr --size 64,48");
  CHECK(r.code == 0);
  CHECK(r.err.find("no --scene: the default scene") != std::string::npos);
  CHECK(lit_fraction((d / "a.pfm").string()) > 0.1);
  // studio.json's camera at (0,0,5) looking at the origin does not see it at all ...
  r = run_shadetool("render " + (d / "small.ply").string() + " -o " + (d / "b.pfm").string() + " --hdr --size 64,48 --scene " + studio);
  CHECK(r.code == 0);
  CHECK(lit_fraction((d / "b.pfm").string()) == 0.0);
  // ... and --camera frame does.
  r = run_shadetool("render " + (d / "small.ply").string() + " -o " + (d / "c.pfm").string() +
                    " --hdr --size 64,48 --camera frame --scene " + studio);
  CHECK(r.code == 0);
  CHECK(lit_fraction((d / "c.pfm").string()) > 0.1);
}
