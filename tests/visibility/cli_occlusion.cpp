// Tests of `shadetool occlusion` (cli/cmd_occlusion.cpp) end to end: the written grey colours and
// PLY quality are the library's open fractions for the same mesh, the quality round-trips through
// the PLY reader, and bad input leaves no output and exits 1 (2 for usage).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/visibility_scene.h>
#include "support/run_process.h"

using namespace shadetool;
using namespace shadetool_test;

namespace {

std::string temp_path(const std::string& name) {
  return "/tmp/shadetool_test_occlusion_" + std::to_string(::getpid()) + "_" + name;
}

bool exists(const std::string& path) { return std::ifstream(path).good(); }

// IEC 61966-2-1's encoding, written out here independently of lighting/encode_color.h.
double iec_srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

}  // namespace

TEST_CASE("occlusion writes the library's open fraction as PLY quality and grey colours", "[visibility][cli][issue28]") {
  const std::string in = std::string(SHADETOOL_SOURCE_DIR) + "/data/torus_knot.ply";
  const std::string out = temp_path("knot.ply"), linear = temp_path("knot_linear.ply");
  const ProcessResult r = run_shadetool("occlusion '" + in + "' -o '" + out + "' --samples 32");
  REQUIRE(r.code == 0);
  REQUIRE(run_shadetool("occlusion '" + in + "' -o '" + linear + "' --samples 32 --linear").code == 0);
  const Mesh mesh = read_mesh(in);
  const VisibilityScene scene(mesh);
  AmbientOcclusionOptions o;
  o.samples = 32;
  // The CLI computes the angle-weighted normals (block by block, the same bits as all at once).
  const AmbientOcclusion ao = ambient_occlusion_per_vertex(scene, mesh, vertex_normals(mesh).normals, o);
  REQUIRE(ao.hits > 0);
  const Mesh written = read_mesh(out), written_linear = read_mesh(linear);
  REQUIRE(written.vertex_quality == ao.open_fraction);  // float written, float read: bit for bit
  REQUIRE(written_linear.vertex_quality == ao.open_fraction);  // --linear changes the colours only
  REQUIRE(written.vertex_colors.size() == 3 * mesh.num_vertices());
  REQUIRE(written_linear.vertex_colors.size() == 3 * mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    // uchar colours: sRGB-encoded by default (issue 28, man shadetool COLOUR), linear with --linear
    const double open = ao.open_fraction[v];
    REQUIRE(std::lround(255 * written.vertex_colors[3 * v]) == std::lround(255 * iec_srgb(open)));
    REQUIRE(std::lround(255 * written_linear.vertex_colors[3 * v]) == std::lround(255 * open));
    REQUIRE(written.vertex_colors[3 * v + 1] == written.vertex_colors[3 * v]);
    REQUIRE(written.vertex_colors[3 * v + 2] == written.vertex_colors[3 * v]);
  }
  REQUIRE(written.positions == mesh.positions);
  // Written again as ASCII and read back: the quality survives (shortest float text).
  const std::string ascii = temp_path("knot_ascii.ply");
  REQUIRE(run_shadetool("occlusion '" + out + "' -o '" + ascii + "' --samples 32 --ascii --as quality --per face").code == 0);
  const Mesh a = read_mesh(ascii);
  REQUIRE(a.vertex_quality == ao.open_fraction);  // the input's vertex quality passes through
  REQUIRE(a.face_quality.size() == mesh.num_faces());
  const AmbientOcclusion af = ambient_occlusion_per_face(scene, mesh, o);
  REQUIRE(a.face_quality == af.open_fraction);
  std::remove(out.c_str());
  std::remove(linear.c_str());
  std::remove(ascii.c_str());
}

TEST_CASE("occlusion names what it replaces and what a format cannot hold", "[visibility][cli]") {
  const std::string in = std::string(SHADETOOL_SOURCE_DIR) + "/data/torus_knot.ply";
  const std::string first = temp_path("first.ply"), obj = temp_path("knot.obj");
  REQUIRE(run_shadetool("occlusion '" + in + "' -o '" + first + "' --samples 4").code == 0);
  const ProcessResult r = run_shadetool("occlusion '" + first + "' -o '" + obj + "' --samples 4");
  REQUIRE(r.code == 0);
  REQUIRE(r.err.find("colours replaced") != std::string::npos);
  REQUIRE(r.err.find("quality replaced") != std::string::npos);
  REQUIRE(r.err.find("only PLY holds it") != std::string::npos);
  std::remove(first.c_str());
  std::remove(obj.c_str());
}

TEST_CASE("occlusion refuses bad input without touching the output", "[visibility][cli]") {
  const std::string bad = temp_path("nan.obj"), out = temp_path("out.ply");
  {
    std::ofstream f(bad);
    f << "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n";
  }
  {
    std::ofstream f(out);
    f << "keep me";
  }
  const ProcessResult r = run_shadetool("occlusion '" + bad + "' -o '" + out + "'");
  REQUIRE(r.code == 1);
  REQUIRE(r.err.find(bad) != std::string::npos);
  REQUIRE(read_file(out) == "keep me");
  REQUIRE(run_shadetool("occlusion '" + bad + "' -o '" + out + "' --samples 0").code == 2);
  REQUIRE(run_shadetool("occlusion '" + bad + "' -o '" + out + "' --distance -1").code == 2);
  REQUIRE(run_shadetool("occlusion '" + bad + "' -o '" + out + "' --as grey").code == 2);
  REQUIRE(read_file(out) == "keep me");
  {
    std::ofstream f(bad);
    f << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // no faces
  }
  const std::string none = temp_path("none.ply");
  REQUIRE(run_shadetool("occlusion '" + bad + "' -o '" + none + "'").code == 1);
  REQUIRE(!exists(none));
  std::remove(bad.c_str());
  std::remove(out.c_str());
}

TEST_CASE("occlusion keeps the input's colour alpha (transparency is not occlusion)", "[visibility][cli][issue27]") {
  // issue 27, item 10: VCG's cycloidal.ply has rgba colours; the alpha became 1.
  const std::string in = temp_path("rgba.ply"), out = temp_path("rgba_ao.ply");
  {
    std::ofstream f(in);
    f << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0 10 20 30 51\n1 0 0 10 20 30 102\n0 1 0 10 20 30 255\n3 0 1 2\n";
  }
  const ProcessResult r = run_shadetool("occlusion '" + in + "' -o '" + out + "' --samples 4 --ascii");
  REQUIRE(r.code == 0);
  const Mesh m = read_mesh(out);
  REQUIRE(m.color_channels == 4);
  REQUIRE(m.vertex_colors.size() == 12);
  CHECK(std::lround(255 * m.vertex_colors[3]) == 51);
  CHECK(std::lround(255 * m.vertex_colors[7]) == 102);
  CHECK(std::lround(255 * m.vertex_colors[11]) == 255);
  CHECK(m.vertex_colors[0] == 1.0f);  // a lone triangle: nothing occludes it
  std::remove(in.c_str());
  std::remove(out.c_str());
}
