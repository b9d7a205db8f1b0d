// cmd_render.cpp: `shadetool render IN -o OUT.png --scene SCENE.json [...]`.
// Parses options, reads the scene once, and per mesh calls render/render_mesh.h; the image is
// encoded by io/image_png.h or io/image_pfm.h and written by write_image (below), the one place
// to move onto the driver's image output once it has one.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "command_registry.h"
#include "driver.h"
#include "usage_error.h"
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include <shadetool/io/atomic_write.h>
#include <shadetool/io/image_pfm.h>
#include <shadetool/io/image_png.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/render/render_mesh.h>

namespace shadetool_cli {
namespace {

namespace fs = std::filesystem;

struct RenderCliOptions {
  std::string output, output_dir;
  std::string scene;
  std::string shading = "phong";
  std::vector<int> size{800, 600};
  int samples = 1;
  std::vector<double> background{0, 0, 0};
  std::string model;
  std::string space = "auto";
  bool hdr = false;
  int threads = 0;
};

// The image's bytes to `path` in one step (temporary file, then rename: no partial file on
// failure, an existing file untouched), or to stdout for "-".
void write_image(const std::string& path, const std::string& bytes) { shadetool::io::write_file_atomically(path, bytes); }

std::string encode_image(const shadetool::ImageRGB& image, bool hdr, const std::string& name) {
  if (hdr) return shadetool::io::encode_pfm(image.width, image.height, image.rgb.data(), image.rgb.size(), name);
  std::vector<std::uint8_t> srgb8(image.rgb.size());
  for (std::size_t i = 0; i < image.rgb.size(); ++i) srgb8[i] = shadetool::encode_srgb_8bit(image.rgb[i]);
  return shadetool::io::encode_png_srgb8(image.width, image.height, srgb8, name);
}

shadetool::RenderShading parse_shading(const std::string& s) {
  if (s == "flat") return shadetool::RenderShading::Flat;
  if (s == "gouraud") return shadetool::RenderShading::Gouraud;
  return shadetool::RenderShading::Phong;
}

RegisterCommand reg(60, [](CLI::App& app) -> std::function<int()> {
  static IoOptions io;
  static RenderCliOptions opt;
  auto* sub = app.add_subcommand(
      "render", "Render a mesh to a PNG (or PFM): flat, Gouraud or Phong shading with bake-lighting's lighting");
  add_io_options(*sub, io, /*writes_mesh=*/false);
  sub->add_option("-o,--output", opt.output, "Output image (.png, or .pfm with --hdr); - writes stdout");
  sub->add_option("--output-dir", opt.output_dir, "Write one image per input into DIR, named after the input");
  sub->add_option("--scene", opt.scene, "Scene file (JSON): material, lights, camera (fov_y, near, far, orthographic)")
      ->required()
      ->type_name("SCENE.json");
  sub->add_option("--shading", opt.shading, "flat (face normal), gouraud (baked vertex colours) or phong (per sample; default)")
      ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
  sub->add_option("--size", opt.size, "Image size W,H in pixels (default 800,600)")->delimiter(',')->expected(2);
  sub->add_option("--samples", opt.samples, "N: N x N samples per pixel, box-filtered (default 1; 1..16)");
  sub->add_option("--background", opt.background, "Background colour R,G,B, linear (default 0,0,0)")
      ->delimiter(',')
      ->expected(3);
  sub->add_option("--model", opt.model, "Shading model, overriding the scene's")
      ->check(CLI::IsMember({"lambert", "phong", "blinn-phong"}));
  sub->add_option("--space", opt.space, "Space bake-lighting evaluates in (flat, gouraud); same colours (default auto)")
      ->check(CLI::IsMember({"world", "camera", "object", "auto"}));
  sub->add_flag("--hdr", opt.hdr, "Write a float image (PFM, linear, unclamped) instead of an 8-bit sRGB PNG");
  sub->add_option("--threads", opt.threads, "Threads for the tiles of one image (default: all cores)")
      ->check(CLI::Range(0, 1024));

  return [] {
    if (opt.output.empty() && opt.output_dir.empty()) throw UsageError("no output given: use -o FILE or --output-dir DIR");
    if (!opt.output.empty() && !opt.output_dir.empty()) throw UsageError("give -o or --output-dir, not both");
    if (!opt.output.empty() && io.inputs.size() > 1) throw UsageError("-o takes one input; use --output-dir DIR for several");
    if (opt.output == "-" && io.json) throw UsageError("--json and -o - both write stdout; choose one");
    if (opt.samples < 1 || opt.samples > shadetool::kMaxSamples)
      throw UsageError("--samples must be 1.." + std::to_string(shadetool::kMaxSamples));
    for (double c : opt.background)
      if (!(c >= 0) || !std::isfinite(c)) throw UsageError("--background channels must be finite and >= 0");
    if (!opt.output_dir.empty() && !fs::is_directory(opt.output_dir))
      throw shadetool::Error(shadetool::located(opt.output_dir, 0, "output directory does not exist"));

    // A zero size is bad input (exit 1), found before any file is read.
    const shadetool::Scene scene = shadetool::read_scene(opt.scene);
    shadetool::RenderOptions ro;
    ro.shading = parse_shading(opt.shading);
    ro.width = opt.size[0];
    ro.height = opt.size[1];
    ro.samples = opt.samples;
    ro.background = {opt.background[0], opt.background[1], opt.background[2]};
    if (!opt.model.empty())
      ro.lighting.model = opt.model == "lambert" ? shadetool::ShadingModel::Lambert
                          : opt.model == "phong" ? shadetool::ShadingModel::Phong
                                                 : shadetool::ShadingModel::BlinnPhong;
    ro.lighting.space = opt.space == "world"    ? shadetool::ShadingSpace::World
                        : opt.space == "camera" ? shadetool::ShadingSpace::Camera
                        : opt.space == "object" ? shadetool::ShadingSpace::Object
                                                : shadetool::ShadingSpace::Auto;
    ro.threads = opt.threads;
    if (ro.width < 1 || ro.height < 1 || ro.width > shadetool::kMaxImageSide || ro.height > shadetool::kMaxImageSide)
      throw shadetool::Error("--size " + std::to_string(ro.width) + "," + std::to_string(ro.height) +
                             ": each side must be 1.." + std::to_string(shadetool::kMaxImageSide) + " pixels");

    return run_mesh_command("render", io, [ro, &scene](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
      std::string output = opt.output;
      if (output.empty()) {
        const fs::path in = input == "-" ? fs::path("stdin") : fs::path(input);
        output = (fs::path(opt.output_dir) / in.stem()).string() + (opt.hdr ? ".pfm" : ".png");
      }
      std::error_code same_ec;
      if (input != "-" && output != "-" && fs::equivalent(input, output, same_ec))
        throw shadetool::Error(shadetool::located(input, 0, "the output " + output + " is the input file: refusing to overwrite the input"));
      shadetool::require_finite_positions(mesh, input);
      shadetool::require_finite_normals(mesh, input, "run `shadetool repair` or `shadetool normals --recompute` first");
      const shadetool::RenderResult result = shadetool::render_mesh(mesh, scene, ro, input);
      std::size_t nonfinite = 0;
      for (float c : result.image.rgb) nonfinite += !std::isfinite(c);
      if (nonfinite > 0)
        throw shadetool::Error(shadetool::located(input, 0, std::to_string(nonfinite) +
                                                                " colour values came out NaN or infinite; nothing written"));
      write_image(output, encode_image(result.image, opt.hdr, output));

      const shadetool::RenderStats& s = result.stats;
      if (result.camera.framed) r.notes.push_back("the scene has no camera: using one that frames the mesh");
      if (s.quad_fallbacks > 0)
        r.notes.push_back(std::to_string(s.quad_fallbacks) +
                          " samples of degenerate quads were interpolated over their fan triangles");
      r.stats["output"] = output;
      r.stats["shading"] = shadetool::render_shading_name(ro.shading);
      r.stats["size"] = std::to_string(ro.width) + "x" + std::to_string(ro.height);
      r.stats["samples_per_pixel"] = ro.samples * ro.samples;
      r.stats["triangles"] = s.triangles;
      r.stats["culled_faces"] = s.faces_culled;
      r.stats["faces_outside_view"] = s.faces_outside_view;
      r.stats["degenerate_faces"] = s.faces_degenerate;
      r.stats["near_clipped_triangles"] = s.triangles_near_clipped;
      r.stats["covered_samples"] = s.samples_covered;
    }, /*writes_mesh=*/false);
  };
});

}  // namespace
}  // namespace shadetool_cli
