// cmd_render.cpp: `shadetool render IN -o OUT.png --scene SCENE.json [...]`.
// Parses options, reads the scene once, and per mesh calls render/render_mesh.h; the step hands
// the picture to the driver (OutputKind::Image), which checks and writes the output like every
// other subcommand's: PNG (8-bit sRGB) or, with --hdr or a .pfm output, PFM (linear float).
#include <CLI/CLI.hpp>
#include <array>

#include <filesystem>
#include <string>
#include <vector>

#include "command_registry.h"
#include "driver.h"
#include "usage_error.h"
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include <shadetool/io/image_io.h>
#include <shadetool/io/image_png.h>
#include <shadetool/lighting/default_scene.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/render/output_image.h>
#include <shadetool/render/render_mesh.h>

namespace shadetool_cli {
namespace {

namespace fs = std::filesystem;

struct RenderCliOptions {
  std::string scene;
  std::string shading = shadetool::render_shading_name(shadetool::RenderShading::Phong);
  std::array<int, 2> size{800, 600};  // one value W,H (or W H): an input after it is not taken as a third
  int samples = 1;
  std::array<double, 3> background{0, 0, 0};
  std::string model;
  std::string space = shadetool::shading_space_name(shadetool::ShadingSpace::Auto);
  bool hdr = false;
  int threads = 0;
  bool shadows = false;
  std::uint32_t shadow_samples = 16;
  std::string camera = shadetool::camera_choice_name(shadetool::CameraChoice::Scene);
  int png_compression = shadetool::io::kPngDefaultCompression;
};

// A path's extension without its dot ("" when none).
std::string extension_of(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  if (!ext.empty()) ext.erase(0, 1);  // the dot
  return ext;
}

// The image format the driver will write (io/image_io.h's table, looked up the way the driver
// looks it up: --format, else -o's extension, else the table's default), or null when unknown.
const shadetool::ImageFormatEntry* output_image_format(const IoOptions& io) {
  std::string name = io.format;
  if (name.empty() && !io.output.empty() && io.output != "-") name = extension_of(io.output);
  return shadetool::find_image_format(name.empty() ? shadetool::image_format_names().front() : name);
}

bool is_pfm(const shadetool::ImageFormatEntry* f) { return f != nullptr && std::string(f->name) == "pfm"; }

RegisterCommand reg("render", HelpSection::Shade, [](CLI::App& app) -> std::function<int()> {
  auto options = std::make_shared<CommandOptions<RenderCliOptions>>();  // bound to the flags, read by the run function
  IoOptions& io = options->io;
  RenderCliOptions& opt = options->opt;
  auto* sub = app.add_subcommand(
      "render", "Render a mesh to a PNG (or PFM): flat, Gouraud or Phong shading with bake-lighting's lighting");
  add_io_options(*sub, io, OutputKind::Image);
  sub->add_option("--scene", opt.scene,
                  "Scene file (JSON): material, lights, camera (fov_y, near, far, orthographic); default: a sky and a "
                  "key light over the viewer's shoulder, the mesh framed (lighting/default_scene.h)")
      ->type_name("SCENE.json");
  sub->add_option("--png-compression", opt.png_compression,
                  "PNG compression 0..9: 1 (default) fast, zlib 1 with the Up filter; 2..9 zlib's levels with adaptive "
                  "filters, 9 the smallest file and the slowest (io/image_png.h); 0 stored")
      ->check(CLI::Range(0, 9))
      ->type_name("L");
  sub->add_option("--camera", opt.camera,
                  "scene: the scene's camera (default); frame: a camera that frames the mesh instead of the scene's")
      ->check(CLI::IsMember(shadetool::camera_choice_names()));
  sub->add_option("--shading", opt.shading, "flat (face normal), gouraud (baked vertex colours) or phong (per sample; default)")
      ->check(CLI::IsMember(shadetool::render_shading_names()));
  sub->add_option("--size", opt.size, "Image size W,H in pixels (default 800,600)")->delimiter(',');
  sub->add_option("--samples", opt.samples, "N: N x N samples per pixel, box-filtered (default 1; 1..16)");
  sub->add_option("--background", opt.background, "Background colour R,G,B, linear (default 0,0,0)")->delimiter(',');
  sub->add_option("--model", opt.model, "Shading model, overriding the scene's")
      ->check(CLI::IsMember(shadetool::shading_model_names()));
  sub->add_option("--space", opt.space,
                  "Space bake-lighting evaluates in, for flat and gouraud shading only (phong refuses any but auto: "
                  "it evaluates per sample in world space); same colours (default auto)")
      ->check(CLI::IsMember(shadetool::shading_space_names()));
  sub->add_flag("--hdr", opt.hdr, "Write a float image (PFM, linear, unclamped) instead of an 8-bit sRGB PNG");
  sub->add_option("--threads", opt.threads, "Threads for the tiles of one image (default: all cores)");
  auto* shadows_flag = sub->add_flag(
      "--shadows", opt.shadows,
      "Shadows: multiply each light's diffuse and specular terms by its visibility from the shaded point (one ray "
      "for directional, point and spot lights; --shadow-samples rays for area and sky lights), as bake-lighting "
      "--shadows");
  sub->add_option("--shadow-samples", opt.shadow_samples,
                  "With --shadows: rays per shaded point per area or sky light (default 16; --samples is taken: "
                  "samples per pixel)")
      ->needs(shadows_flag)
      ->type_name("N");

  return [options] {
    IoOptions& io = options->io;
    const RenderCliOptions& opt = options->opt;
    if (opt.hdr) {
      if (!io.format.empty() && !is_pfm(shadetool::find_image_format(io.format)))
        throw UsageError("--hdr writes a float image (PFM), not --format " + io.format);
      if (!io.output.empty() && io.output != "-" && !is_pfm(shadetool::find_image_format(extension_of(io.output))))
        throw UsageError("--hdr writes a float image (PFM): name the output .pfm");
      if (io.format.empty()) io.format = "pfm";
    }

    shadetool::RenderOptions ro;
    ro.shading = shadetool::parse_render_shading(opt.shading, "--shading");
    ro.width = opt.size[0];
    ro.height = opt.size[1];
    ro.samples = opt.samples;
    ro.background = {opt.background[0], opt.background[1], opt.background[2]};
    if (!opt.model.empty()) ro.lighting.model = shadetool::parse_shading_model(opt.model, "--model");
    ro.lighting.space = shadetool::parse_shading_space(opt.space, "--space");
    ro.threads = opt.threads;
    ro.lighting.shadows.enabled = opt.shadows;
    ro.lighting.shadows.samples = opt.shadow_samples;
    // The library's limits (render_mesh.h), relayed as usage errors (exit 2) before any file is read.
    try {
      shadetool::check_render_options(ro, "render");
    } catch (const shadetool::Error& e) {
      throw UsageError(e.what());
    }
    const bool default_scene = opt.scene.empty();
    shadetool::Scene scene = default_scene ? shadetool::default_scene() : shadetool::read_scene(opt.scene);
    if (shadetool::parse_camera_choice(opt.camera, "--camera") == shadetool::CameraChoice::Frame)
      scene.has_camera = false;  // render/camera.h frames the mesh

    const bool pfm = is_pfm(output_image_format(io));  // --hdr has set io.format to pfm
    ro.clamp_vertex_colors = !pfm;  // Gouraud: OpenGL 2.1's clamped vertex colours, unless a float image
    const int png_compression = opt.png_compression;
    return run_command("render", io, [ro, &scene, pfm, default_scene, png_compression](shadetool::Mesh& mesh, const std::string& input,
                                                                        FileResult& r) {
      // A mesh without faces renders as the background alone: not a picture of it (exit 1).
      shadetool::require_faces(mesh, input);
      shadetool::require_finite_positions(mesh, input);
      shadetool::require_finite_normals(mesh, input, "run `shadetool repair` or `shadetool normals --recompute` first");
      shadetool::RenderOptions with_progress = ro;
      with_progress.progress = r.progress;
      const shadetool::RenderResult result = shadetool::render_mesh(mesh, scene, with_progress, input);
      std::size_t nonfinite = 0;
      for (float c : result.image.rgb) nonfinite += !std::isfinite(c);
      if (nonfinite > 0)
        throw shadetool::Error(shadetool::located(input, 0, std::to_string(nonfinite) +
                                                                " colour values came out NaN or infinite; nothing written"));
      r.image = shadetool::render_output_image(result.image, pfm);
      r.image.png_compression = png_compression;

      const shadetool::RenderStats& s = result.stats;
      if (default_scene)
        r.notes.push_back("no --scene: the default scene (a sky and a key light over the viewer's shoulder, grey "
                          "Blinn-Phong), the mesh framed");
      else if (result.camera.framed)
        r.notes.push_back("using a camera that frames the mesh (the scene has none, or --camera frame)");
      if (s.quad_fallbacks > 0)
        r.notes.push_back(std::to_string(s.quad_fallbacks) +
                          " samples of degenerate quads were interpolated over their fan triangles");
      r.stats["shading"] = shadetool::render_shading_name(ro.shading);
      r.stats["size"] = std::to_string(ro.width) + "x" + std::to_string(ro.height);
      r.stats["samples_per_pixel"] = ro.samples * ro.samples;
      r.stats["triangles"] = s.triangles;
      r.stats["culled_faces"] = s.faces_culled;
      r.stats["faces_outside_view"] = s.faces_outside_view;
      r.stats["degenerate_faces"] = s.faces_degenerate;
      r.stats["near_clipped_triangles"] = s.triangles_near_clipped;
      r.stats["covered_samples"] = s.samples_covered;
      if (ro.lighting.shadows.enabled) r.stats["shadows"] = "on";
    }, OutputKind::Image);
  };
});

}  // namespace
}  // namespace shadetool_cli
