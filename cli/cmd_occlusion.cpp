// cmd_occlusion.cpp: `shadetool occlusion IN -o OUT [--samples N] [--distance D]
// [--as color|quality|both] [--per vertex|face] [--stats]`.
// Parses, builds lib/visibility's BVH, calls visibility/ambient_occlusion.h, stores the open
// fraction as grey colours and/or quality, prints notes and counts; exit codes in driver.h.
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "command_registry.h"
#include <shadetool/normals/replace_invalid_normals.h>
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include "fit_options.h"
#include "usage_error.h"
#include <shadetool/lighting/bake_lighting.h>  // ShadingFrequency's vocabulary (--per)
#include <shadetool/lighting/encode_color.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/fit_occlusion.h>
#include <shadetool/visibility/occlusion_to_error.h>
#include <shadetool/gltf/gltf_baked.h>
#include <shadetool/gltf/gltf_occlusion.h>
#include <shadetool/visibility/visibility_scene.h>
#include <shadetool/io/split_corner_normals.h>
#include <shadetool/normals/invalid_normals.h>

namespace shadetool_cli {
namespace {

struct OcclusionOptions {
  std::uint32_t samples = 64;
  double distance = std::numeric_limits<double>::infinity();
  std::string as = "both";
  std::string per = "vertex";
  bool unlit = false;
  bool linear = false;  // 8-bit outputs: linear bytes (lighting/encode_color.h's rule)
  bool srgb = false;    // the default now: a no-op with a note
  double target_error = 0;  // --error E; 0: a fixed --samples
  FitCliOptions fit;
};

// The open fraction as grey (r = g = b = value, `encoding` applied: lighting/encode_color.h) in `colors`, keeping the channel count the mesh's
// other colour array uses, or 4 when `colors` itself had alpha: an alpha the input had is kept
// (transparency is not occlusion), else alpha is 1.
void store_grey(shadetool::Mesh& mesh, const std::vector<float>& open, std::vector<float>& colors, bool other_has_colors,
                const shadetool::ColorEncoding& encoding) {
  const bool own_alpha = mesh.color_channels == 4 && colors.size() == 4 * open.size();
  std::vector<float> alpha;
  if (own_alpha)
    for (std::size_t i = 0; i < open.size(); ++i) alpha.push_back(colors[4 * i + 3]);
  if (!other_has_colors && !own_alpha) mesh.color_channels = 3;
  const std::size_t ch = std::size_t(mesh.color_channels);
  const std::vector<float> grey = shadetool::encode_colors(std::vector<double>(open.begin(), open.end()), encoding);
  colors.assign(ch * open.size(), 1.0f);
  for (std::size_t i = 0; i < open.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) colors[ch * i + k] = grey[i];
    if (own_alpha) colors[ch * i + 3] = alpha[i];
  }
}

// The mesh's corner normals as vertex normals, one vertex per (vertex, normal) pair, in `split`;
// false when any of them (or an unused vertex's, which has none) cannot be a hemisphere's axis:
// the normals are then computed, as for a mesh without any.
bool usable_split(const shadetool::Mesh& mesh, shadetool::Mesh& split, std::size_t& added) {
  split = shadetool::io::split_corner_normals(mesh, added);
  return shadetool::count_invalid_normals(split.vertex_normals) == 0;
}

RegisterCommand reg("occlusion", HelpSection::Shade, [](CLI::App& app) -> std::function<int()> {
  auto options = std::make_shared<CommandOptions<OcclusionOptions>>();  // bound to the flags, read by the run function
  IoOptions& io = options->io;
  OcclusionOptions& opt = options->opt;
  auto* sub = app.add_subcommand(
      "occlusion",
      "Ambient occlusion by ray casting (Embree): per vertex or face, the cosine-weighted fraction of the sky "
      "open to distance D, as grey colours and/or a PLY quality property");
  add_io_options(*sub, io, OutputKind::Mesh);
  auto* samples_opt = sub->add_option("--samples", opt.samples, "Rays per vertex or face (default 64, at most 1048576; error falls as N^-3/4); with --error the most rays per vertex or face (default 4096)")
      ->type_name("N");
  sub->add_option("--distance", opt.distance,
                  "Only occluders nearer than D > 0 (mesh units) count (default: unlimited)")
      ->type_name("D");
  sub->add_option("--as", opt.as, "Store the open fraction as grey colours, the PLY quality property, or both (default)")
      ->check(CLI::IsMember({"color", "quality", "both"}));
  sub->add_option("--per", opt.per, "One value per vertex (default) or per face")
      ->check(CLI::IsMember(shadetool::shading_frequency_names()));
  sub->add_flag("--unlit", opt.unlit,
                "glTF input to glTF output: give the primitives' materials KHR_materials_unlit (a non-glTF input "
                "written as glTF always gets an unlit material)");
  auto* error_opt = sub->add_option("--error", opt.target_error,
                                    "Add rays in batches until the estimated standard error of each open fraction is at "
                                    "most E (a pilot of " + std::to_string(shadetool::kOcclusionReplicates) +
                                        " scrambled Sobol replicates, then one sequence; --samples caps the rays, default 4096)")
                        ->check(CLI::PositiveNumber)
                        ->type_name("E");
  sub->add_flag("--linear", opt.linear,
                "Write the grey as linear 8-bit colours, the OpenGL 2.1 look (default: sRGB-encoded bytes, as viewers "
                "read them; float and glTF colours are always linear; see man shadetool, COLOUR)");
  sub->add_flag("--srgb", opt.srgb, "sRGB-encoded 8-bit grey: the default (kept as a no-op)");
  add_fit_options(*sub, opt.fit, "open fraction");
  return [command_options = options, samples_opt, error_opt] {
    IoOptions& io = command_options->io;
    const OcclusionOptions& opt = command_options->opt;
    const FitCliOptions& fit = opt.fit;
    const bool to_error = error_opt->count() > 0;
    const bool least_squares = fit_method(fit) == shadetool::VertexFit::LeastSquares;
    shadetool::OcclusionToErrorOptions error_options;
    error_options.target_error = opt.target_error;
    error_options.max_samples = samples_opt->count() > 0 ? opt.samples : 4096u;
    error_options.max_distance = opt.distance;
    if (to_error && error_options.max_samples < shadetool::kOcclusionReplicates * shadetool::kOcclusionFirstBatch)
      throw UsageError("--error needs --samples of at least " +
                       std::to_string(shadetool::kOcclusionReplicates * shadetool::kOcclusionFirstBatch) +
                       " (one batch of every replicate)");
    shadetool::AmbientOcclusionOptions options;
    options.samples = opt.samples;
    options.max_distance = opt.distance;
    try {  // the library's limits (visibility/ambient_occlusion.h), relayed as usage errors
      shadetool::check_occlusion_options(options, "occlusion");
    } catch (const shadetool::Error& e) {
      throw UsageError(e.what());
    }
    const bool per_face =
        shadetool::parse_shading_frequency(opt.per, "--per") == shadetool::ShadingFrequency::PerFace;
    const bool colors = opt.as != "quality", quality = opt.as != "color";
    if (opt.linear && opt.srgb) throw UsageError("--linear and --srgb contradict each other");
    // The result is grey colours and/or quality: an output format with neither is refused before any work.
    io.result_attributes.clear();
    if (colors) io.result_attributes.push_back(per_face ? &shadetool::FormatAttributes::face_colors : &shadetool::FormatAttributes::vertex_colors);
    if (quality) io.result_attributes.push_back(&shadetool::FormatAttributes::quality);
    io.result_name = std::string(colors && quality ? "grey colours and quality" : colors ? "grey colours" : "quality") + " per " + opt.per;
    const shadetool::VertexFitOptions fit_options = vertex_fit_options(fit, io);
    return run_command(
        "occlusion", io,
        [base_options = options, per_face, colors, quality, unlit = opt.unlit, linear = opt.linear, srgb = opt.srgb, fit, fit_options, to_error, least_squares, error_options](
            shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
          shadetool::AmbientOcclusionOptions options = base_options;
          options.progress = r.progress;
          shadetool::require_faces(mesh, input);
          shadetool::require_finite_positions(mesh, input);
          // Normals pass through to the output: one without a direction is replaced, with a counted note.
          if (const std::string note = shadetool::invalid_normals_note(shadetool::replace_invalid_normals(mesh)); !note.empty())
            r.notes.push_back(note);
          // glTF: every primitive against the whole scene (gltf/gltf_occlusion.h), computed at
          // the first primitive for all of them; the BVH statistics then count once, there.
          shadetool::MeshOcclusion job;
          shadetool::Mesh split;
          bool scene_stats = true;
          shadetool::OcclusionToError adaptive;
          const shadetool::OcclusionFit* scene_fit = nullptr;  // a glTF primitive's fit, made with the scene's
          if (r.gltf_document && r.gltf && r.gltf_document_state) {
            const std::size_t index = std::size_t(r.gltf - r.gltf_document->primitives.data());
            shadetool::GltfOcclusionMethod method;  // --error, --fit least-squares: per primitive, in world space
            if (to_error) method.to_error = error_options;
            if (least_squares) method.fit = fit_options;
            const auto& scene = r.gltf_document_state->get_or_make<shadetool::GltfSceneOcclusion>(
                [&](shadetool::GltfSceneOcclusion& made) {
                  made = shadetool::gltf_scene_occlusion(*r.gltf_document, per_face, options,
                                                         shadetool::gltf_source_name(*r.gltf_document), method);
                },
                &scene_stats);
            for (const auto& n : scene.notes) r.notes.push_back(n);  // the same line from every primitive: said once
            job.ao = scene.primitives[index];
            job.normals_computed = scene.normals_computed[index];
            job.scene = scene.scene;
            if (to_error) {
              adaptive.rays = scene.to_error[index].rays;
              adaptive.capped = scene.to_error[index].capped;
            }
            if (!scene.fits.empty()) scene_fit = &scene.fits[index];
          } else {
            // Corner normals (OBJ vn) are the file's normals: the rays leave about them, one vertex
            // per distinct (vertex, normal) pair (io/split_corner_normals.h). When that adds no
            // vertex the output keeps its corner normals; else it is the split mesh.
            std::size_t added = 0;
            const bool corners = !per_face && mesh.has_corner_normals() && !mesh.has_vertex_normals() &&
                                 usable_split(mesh, split, added);
            const shadetool::Mesh& source = corners ? split : mesh;
            if (to_error) {  // visibility/occlusion_to_error.h
              adaptive = shadetool::mesh_occlusion_to_error(source, per_face, error_options, input, job.normals_computed);
              job.ao.open_fraction = adaptive.open_fraction;
              job.ao.rays = adaptive.total_rays;
              job.ao.hits = adaptive.hits;
              job.ao.skipped = adaptive.skipped;
              job.scene = adaptive.scene;
            } else {
              // The normals (when computed) and the BVH are freed inside: the outputs are made after.
              job = shadetool::mesh_occlusion(source, per_face, options, input);
            }
            if (corners && added > 0) {
              mesh = std::move(split);
              r.notes.push_back(fmt::format("{} vertices added so that each corner's rays leave about its own normal (corner "
                                            "normals differ there); the output's vertex normals are those corner normals",
                                            added));
            }
          }
          if (least_squares && per_face) {
            r.notes.push_back("--fit least-squares ignored with --per face (a face holds one value)");
          } else if (least_squares) {  // visibility/fit_occlusion.h
            shadetool::OcclusionFit lsq = scene_fit ? *scene_fit
                                                    : shadetool::fit_occlusion(mesh, job.ao.open_fraction, options,
                                                                               to_error ? &error_options : nullptr,
                                                                               fit_options, input);
            job.ao.open_fraction = std::move(lsq.open_fraction);
            report_fit(r, lsq.solve, lsq.error_fit, lsq.error_point, lsq.quadrature_points, fit);
            r.stats["fit_rays"] = lsq.rays;
          }
          if (to_error) {
            r.setting("target_error", error_options.target_error);
            r.stats["capped"] = adaptive.capped;
            nlohmann::json histogram = nlohmann::json::object();
            for (const auto& [rays, count] : shadetool::ray_histogram(adaptive.rays)) histogram[std::to_string(rays)] = count;
            r.stats["rays_histogram"] = histogram;
          }
          const shadetool::AmbientOcclusion& ao = job.ao;
          const shadetool::VisibilitySceneStats& s = job.scene;
          if (job.normals_computed) r.stats["normals"] = "computed (angle-weighted)";
          const char* what = per_face ? "face" : "vertex";
          if (colors) {
            // lighting/encode_color.h's rule: the writer stores these colours as bytes unless the
            // mesh's colours are float (as read); glTF COLOR_0 is linear.
            const shadetool::ColorEncoding encoding =
                shadetool::output_color_encoding(!mesh.colors_are_float, r.output_gltf, linear);
            if (srgb) r.notes.push_back("--srgb is the default now (8-bit colours are sRGB-encoded; float and glTF colours linear)");
            if (per_face ? mesh.has_face_colors() : mesh.has_vertex_colors())
              r.notes.push_back(fmt::format("the input's {} colours replaced by grey occlusion", what));
            if (per_face) store_grey(mesh, ao.open_fraction, mesh.face_colors, mesh.has_vertex_colors(), encoding);
            else store_grey(mesh, ao.open_fraction, mesh.vertex_colors, mesh.has_face_colors(), encoding);
          }
          if (unlit && !r.output_gltf) r.notes.push_back("--unlit ignored: only a glTF output has materials");
          if (colors && r.output_gltf && !r.gltf) {  // a baked glTF from another format: the normals used, an unlit material
            const std::string added = shadetool::add_baked_normals(mesh, per_face);
            if (!added.empty()) r.notes.push_back(added);
            r.unlit = true;
          }
          if (colors && r.output_gltf && r.gltf && unlit) r.unlit = true;
          if (quality) {
            if (per_face ? mesh.has_face_quality() : mesh.has_vertex_quality())
              r.notes.push_back(fmt::format("the input's {} quality replaced by occlusion", what));
            (per_face ? mesh.face_quality : mesh.vertex_quality) = ao.open_fraction;
          }
          if (s.degenerate_faces > 0 && scene_stats)
            r.notes.push_back(fmt::format("{} degenerate faces (repeated index or zero area) cast no shadow", s.degenerate_faces));
          if (ao.skipped > 0)
            r.notes.push_back(fmt::format("{} {} without a usable normal (isolated vertices, degenerate faces) given "
                                          "open fraction 1, no ray cast",
                                          ao.skipped, per_face ? "faces" : "vertices"));
          double mean = 0;
          for (float v : ao.open_fraction) mean += v;
          r.stats["per"] = what;
          r.setting(to_error ? "max_samples" : "samples", to_error ? error_options.max_samples : options.samples);
          if (std::isfinite(options.max_distance)) r.stats["distance"] = options.max_distance;
          r.stats["rays"] = ao.rays;
          r.stats["hits"] = ao.hits;
          r.stats["skipped"] = ao.skipped;
          r.stats["mean_open_fraction"] = ao.open_fraction.empty() ? 1.0 : mean / double(ao.open_fraction.size());
          if (!scene_stats) return;  // a glTF scene's BVH: counted at its first primitive
          r.stats["bvh_triangles"] = s.triangles;
          r.stats["bvh_bytes"] = s.bvh_bytes;
          r.stats["bvh_buffer_bytes"] = s.buffer_bytes;
          r.stats["bvh_indices"] = s.shared_indices ? "shared" : "copied";
          r.stats["bvh_build_ms"] = s.build_ms;
          r.stats["degenerate_faces"] = s.degenerate_faces;
        },
        OutputKind::Mesh);
  };
});

}  // namespace
}  // namespace shadetool_cli
