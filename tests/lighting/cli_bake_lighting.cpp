// `shadetool bake-lighting` end to end: the binary is run, its exit code, messages and output
// files checked (output read back with io/mesh_io.h).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <shadetool/files/mesh_files.h>
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace fs = std::filesystem;
using namespace shadetool;

namespace {

using Run = shadetool_test::ProcessResult;

using shadetool::testing::TempDir;

Run run(const std::string& args) { return shadetool_test::run_shadetool("bake-lighting " + args); }

// A 2 x 1 quad in z = 0, as two triangles, normal +z.
const char* kQuadObj = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

// Lambert, no ambient, kd = (0.5, 0.25, 1), light straight down: every colour is kd.
const char* kFlatScene = R"({
  "model": "lambert", "ambient": [0, 0, 0],
  "material": {"ambient": [0, 0, 0], "diffuse": [0.5, 0.25, 1]},
  "lights": [{"type": "directional", "direction": [0, 0, -1]}]
})";

// kd's bytes as an 8-bit output stores them by default (man shadetool, COLOUR): IEC 61966-2-1,
// worked by hand: 1.055 * 0.5^(1/2.4) - 0.055 = 0.735357 -> 255 * 0.735357 = 187.52 -> 188;
// 1.055 * 0.25^(1/2.4) - 0.055 = 0.537099 -> 136.96 -> 137; 1 -> 255.
const long kKdSrgbBytes[3] = {188, 137, 255};
// ... and with --linear: round(255 * 0.5) = round(127.5) = 128, round(63.75) = 64, 255.
const long kKdLinearBytes[3] = {128, 64, 255};

}  // namespace

TEST_CASE("bake-lighting writes 8-bit vertex colours sRGB-encoded by default, linear with --linear", "[lighting][cli][issue28]") {
  // issue 28, item 1: viewers read 8-bit colours as sRGB; the lighting (kd here) is linear.
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  dir.write("scene.json", kFlatScene);
  struct Case {
    const char* flags;
    const long* bytes;
  };
  for (const Case& c : {Case{"", kKdSrgbBytes}, Case{" --srgb", kKdSrgbBytes}, Case{" --linear", kKdLinearBytes}}) {
    INFO("flags:" << c.flags);
    for (const char* out : {"lit.ply", "lit.off", "lit.obj"}) {
      INFO(out);
      const Run r = run(dir.file("quad.obj") + " -o " + dir.file(out) + " --scene " + dir.file("scene.json") + c.flags);
      INFO(r.err);
      REQUIRE(r.code == 0);
      CHECK((r.err.find("--srgb is the default now") != std::string::npos) == (std::string(c.flags) == " --srgb"));
      const Mesh m = read_mesh(dir.file(out));
      REQUIRE(m.vertex_colors.size() == 12);
      for (int v = 0; v < 4; ++v)
        for (int k = 0; k < 3; ++k) CHECK(std::lround(255 * m.vertex_colors[3 * v + k]) == c.bytes[k]);
      CHECK(m.positions == std::vector<double>{0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0});
      CHECK(m.num_faces() == 2);
    }
  }
  CHECK(run(dir.file("quad.obj") + " -o " + dir.file("x.ply") + " --scene " + dir.file("scene.json") + " --linear --srgb")
            .code == 2);
  CHECK_FALSE(fs::exists(dir.file("x.ply")));
}

TEST_CASE("bake-lighting to glTF writes linear COLOR_0 with and without --srgb", "[lighting][cli][issue28]") {
  // glTF 2.0, 3.7.2.1: COLOR_0 is linear in every component type. ubyte, normalized: kd's
  // linear bytes 128, 64, 255 whatever --srgb says.
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  dir.write("scene.json", kFlatScene);
  for (const char* flags : {"", " --srgb", " --linear"}) {
    INFO("flags:" << flags);
    const Run r = run(dir.file("quad.obj") + " -o " + dir.file("lit.glb") + " --scene " + dir.file("scene.json") + flags);
    INFO(r.err);
    REQUIRE(r.code == 0);
    const Mesh m = read_mesh(dir.file("lit.glb"));
    REQUIRE(m.vertex_colors.size() >= 12);
    const std::size_t ch = std::size_t(m.color_channels);
    for (std::size_t v = 0; v < m.num_vertices(); ++v)
      for (std::size_t k = 0; k < 3; ++k) CHECK(std::lround(255 * m.vertex_colors[ch * v + k]) == kKdLinearBytes[k]);
  }
}

TEST_CASE("bake-lighting --hdr --srgb --per face --model --space: float colours stay linear", "[lighting][cli]") {
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  dir.write("scene.json", kFlatScene);
  const Run r = run(dir.file("quad.obj") + " -o " + dir.file("lit.ply") + " --scene " + dir.file("scene.json") +
                             " --per face --hdr --srgb --model blinn-phong --space object --stats");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const Mesh m = read_mesh(dir.file("lit.ply"));
  REQUIRE(m.face_colors.size() == 6);
  CHECK(m.vertex_colors.empty());
  CHECK(m.colors_are_float);
  // float outputs are linear (man shadetool, COLOUR; issue 28): kd itself; --srgb is a no-op now
  CHECK(m.face_colors[0] == 0.5f);
  CHECK(m.face_colors[1] == 0.25f);
  CHECK(m.face_colors[2] == 1.0f);
  CHECK(r.err.find("--srgb is the default now") != std::string::npos);
  // --stats names the model, the space and what was skipped (material specular defaults to 0)
  CHECK(r.err.find("model=blinn-phong") != std::string::npos);
  CHECK(r.err.find("space=object") != std::string::npos);
  CHECK(r.err.find("skipped=specular,view_vector,transforms") != std::string::npos);
  CHECK(r.err.find("vertex_light_evaluations=2") != std::string::npos);  // 2 faces x 1 light
}

TEST_CASE("bake-lighting with the example scenes", "[lighting][cli]") {
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  for (const char* scene : {"studio.json", "sun.json", "stretched.json"}) {
    INFO(scene);
    const Run r = run(dir.file("quad.obj") + " -o " + dir.file("lit.obj") + " --scene " +
                               std::string(SHADETOOL_SOURCE_DIR) + "/data/scenes/" + scene + " --stats");
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.err.find("space=") != std::string::npos);
    CHECK(fs::exists(dir.file("lit.obj")));
  }
}

TEST_CASE("bake-lighting errors: exit codes, one-line messages, no output", "[lighting][cli]") {
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  dir.write("bad.json", R"({"lights": [{"type": "spot", "position": [0,3,0], "direction": [0,-1,0], "cutoff": 95}]})");
  const std::string out = dir.file("lit.ply");

  // a bad scene: exit 1, the file, the JSON path and the problem, no output
  Run r = run(dir.file("quad.obj") + " -o " + out + " --scene " + dir.file("bad.json"));
  CHECK(r.code == 1);
  CHECK(r.err == "shadetool: " + dir.file("bad.json") +
                     ": $.lights[0].cutoff: must be in [0, 90] degrees or 180 (no cone), got 95\n");
  CHECK_FALSE(fs::exists(out));

  // a missing scene file: exit 1
  r = run(dir.file("quad.obj") + " -o " + out + " --scene " + dir.file("none.json"));
  CHECK(r.code == 1);
  CHECK(r.err.find("none.json: cannot read scene file") != std::string::npos);
  CHECK_FALSE(fs::exists(out));

  // usage errors: exit 2
  dir.write("scene.json", kFlatScene);
  // no --scene: the default scene (issue 28 item 12), said in a note
  r = run(dir.file("quad.obj") + " -o " + out);
  CHECK(r.code == 0);
  CHECK(r.err.find("no --scene: the default scene") != std::string::npos);
  fs::remove(out);
  r = run(dir.file("quad.obj") + " -o " + out + " --scene " + dir.file("scene.json") + " --model gouraud");
  CHECK(r.code == 2);
  r = run(dir.file("quad.obj") + " -o " + out + " --scene " + dir.file("scene.json") + " --per corner");
  CHECK(r.code == 2);
  CHECK_FALSE(fs::exists(out));

  // a missing input mesh: exit 1, no output
  r = run(dir.file("none.obj") + " -o " + out + " --scene " + dir.file("scene.json"));
  CHECK(r.code == 1);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("bake-lighting --shadows: the face under an occluder gets only its ambient terms", "[lighting][cli][shadows]") {
  TempDir dir;
  // Face 1: a floor tile under face 3 (an occluder at z = 1); face 2: a floor tile in the open;
  // all facing +z, light straight down, no ambient: lit faces are kd, the shadowed one black.
  dir.write("scene.obj",
            "v -0.25 -0.25 0\nv 0.25 -0.25 0\nv 0.25 0.25 0\nv -0.25 0.25 0\n"
            "v 2.75 -0.25 0\nv 3.25 -0.25 0\nv 3.25 0.25 0\nv 2.75 0.25 0\n"
            "v -0.5 -0.5 1\nv 0.5 -0.5 1\nv 0.5 0.5 1\nv -0.5 0.5 1\n"
            "f 1 2 3 4\nf 5 6 7 8\nf 9 10 11 12\n");
  dir.write("scene.json", kFlatScene);
  const std::string base = dir.file("scene.obj") + " --scene " + dir.file("scene.json") + " --per face";

  Run r = run(base + " -o " + dir.file("plain.ply"));
  REQUIRE(r.code == 0);
  r = run(base + " -o " + dir.file("shadows.ply") + " --shadows --stats");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("shadow_rays=3") != std::string::npos);
  CHECK(r.err.find("occluded_light_terms=1") != std::string::npos);
  const Mesh plain = read_mesh(dir.file("plain.ply"));
  const Mesh shadows = read_mesh(dir.file("shadows.ply"));
  REQUIRE(shadows.face_colors.size() == 9);
  const long* kd = kKdSrgbBytes;  // kd's bytes (8-bit: sRGB), read back as channel / 255
  for (int c = 0; c < 3; ++c) {
    CHECK(plain.face_colors[c] * 255.0 == Approx(kd[c]));   // without shadows the tile is lit
    CHECK(shadows.face_colors[c] == 0);                     // with them it is black (no ambient)
    CHECK(shadows.face_colors[3 + c] * 255.0 == Approx(kd[c]));  // the open tile and the occluder's top
    CHECK(shadows.face_colors[6 + c] * 255.0 == Approx(kd[c]));
  }

  // --samples with only a directional light: ignored, with a note; without --shadows: exit 2.
  r = run(base + " -o " + dir.file("s.ply") + " --shadows --samples 8");
  CHECK(r.code == 0);
  CHECK(r.err.find("--samples ignored") != std::string::npos);
  r = run(base + " -o " + dir.file("u.ply") + " --samples 8");
  CHECK(r.code == 2);
  CHECK_FALSE(fs::exists(dir.file("u.ply")));
  r = run(base + " -o " + dir.file("z.ply") + " --shadows --samples 0");
  CHECK(r.code == 2);
  CHECK_FALSE(fs::exists(dir.file("z.ply")));
}

TEST_CASE("bake-lighting with an environment light: data/scenes/environment.json lights; a bad image fails before "
          "the mesh is read", "[lighting][cli][environment]") {
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  const std::string example = std::string(SHADETOOL_SOURCE_DIR) + "/data/scenes/environment.json";
  const Run ok = run(dir.file("quad.obj") + " -o " + dir.file("lit.ply") + " --scene " + example + " --hdr");
  INFO(ok.err);
  REQUIRE(ok.code == 0);
  const Mesh m = read_mesh(dir.file("lit.ply"));
  REQUIRE(m.vertex_colors.size() == 12);
  CHECK(m.vertex_colors[0] > 0);  // lit by the sky above the quad (normal +z, the map rotated about y)

  // A scene whose image is not an HDR, and a mesh that does not exist: the scene's error wins
  // (it is read first), exit 1, one line, no output file.
  dir.write("fake.hdr", "P3\n1 1\n255\n0 0 0\n");
  dir.write("bad.json", R"({"lights": [{"type": "environment", "image": "fake.hdr"}]})");
  const Run bad = run(dir.file("missing.obj") + " -o " + dir.file("out.ply") + " --scene " + dir.file("bad.json"));
  CHECK(bad.code == 1);
  CHECK(bad.err == "shadetool: " + dir.file("bad.json") + ": $.lights[0].image: '" + dir.file("fake.hdr") +
                       "': not a Radiance .hdr (RGBE) image\n");
  CHECK_FALSE(fs::exists(dir.file("out.ply")));
}

TEST_CASE("bake-lighting and occlusion to a format that cannot hold their result: usage error before any work",
          "[lighting][cli][issue27]") {
  // issue 27, item 11: `bake-lighting -o x.stl` exited 0 with nothing it computed in the file. STL
  // holds no colours (files/format_table.h); OBJ holds no quality.
  TempDir dir;
  dir.write("quad.obj", kQuadObj);
  dir.write("scene.json", kFlatScene);
  const Run r = run(dir.file("quad.obj") + " -o " + dir.file("lit.stl") + " --scene " + dir.file("scene.json"));
  CHECK(r.code == 2);
  CHECK(r.err.find(dir.file("lit.stl") + ": stl cannot hold bake-lighting's result (vertex colours): write obj, ply, off or gltf") !=
        std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("lit.stl")));
  // --per face: face colours; OBJ converts them (split vertices), so it is accepted.
  CHECK(run(dir.file("quad.obj") + " -o " + dir.file("lit.obj") + " --per face --scene " + dir.file("scene.json")).code == 0);
  // occlusion: grey colours and quality (both by default); quality alone to OBJ has nowhere to go.
  auto occ = shadetool_test::run_shadetool("occlusion " + dir.file("quad.obj") + " -o " + dir.file("ao.stl") + " --samples 4");
  CHECK(occ.code == 2);
  CHECK(occ.err.find("stl cannot hold occlusion's result (grey colours and quality per vertex)") != std::string::npos);
  occ = shadetool_test::run_shadetool("occlusion " + dir.file("quad.obj") + " -o " + dir.file("ao.obj") + " --as quality --samples 4");
  CHECK(occ.code == 2);
  CHECK(occ.err.find("write ply") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("ao.obj")));
  CHECK(shadetool_test::run_shadetool("occlusion " + dir.file("quad.obj") + " -o " + dir.file("ao.obj") + " --samples 4").code == 0);
}

TEST_CASE("bake-lighting lights each corner with the OBJ's own corner normal (creases kept)", "[lighting][cli][issue27]") {
  // issue 27, item 6: corner normals that differ at a vertex (a cube with its edges creased) were
  // replaced by computed smooth normals. Lambert, light straight down, kd = (0.5, 0.25, 1): a
  // corner of the top face (normal +z) is kd exactly, every other corner black (n.l <= 0).
  TempDir dir;
  dir.write("scene.json", kFlatScene);
  const std::string cube = std::string(SHADETOOL_SOURCE_DIR) + "/data/cube.obj";
  REQUIRE(shadetool_test::run_shadetool("normals " + cube + " --crease 30 -o " + dir.file("c.obj")).code == 0);
  const Run r = run(dir.file("c.obj") + " -o " + dir.file("lit.ply") + " --scene " + dir.file("scene.json"));
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("16 vertices added so that each corner is lit with its own normal") != std::string::npos);
  const Mesh m = read_mesh(dir.file("lit.ply"));
  REQUIRE(m.num_vertices() == 24);  // 8 corners x 3 faces
  REQUIRE(m.vertex_normals.size() == 72);
  int top = 0;
  for (std::size_t v = 0; v < 24; ++v) {
    const bool up = m.vertex_normals[3 * v + 2] > 0.999;
    top += up;
    CHECK(std::lround(255 * m.vertex_colors[3 * v]) == (up ? kKdSrgbBytes[0] : 0));  // 8-bit: sRGB
    CHECK(std::lround(255 * m.vertex_colors[3 * v + 2]) == (up ? kKdSrgbBytes[2] : 0));
  }
  CHECK(top == 4);
}
