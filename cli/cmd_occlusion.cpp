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
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include "fit_options.h"
#include "usage_error.h"
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/fit_occlusion.h>
#include <shadetool/visibility/occlusion_to_error.h>
#include <shadetool/gltf/gltf_occlusion.h>
#include <shadetool/visibility/visibility_scene.h>

namespace shadetool_cli {
namespace {

struct OcclusionOptions {
  std::uint32_t samples = 64;
  double distance = std::numeric_limits<double>::infinity();
  std::string as = "both";
  std::string per = "vertex";
};

// The open fraction as grey (r = g = b = value, alpha 1) in `colors`, keeping the channel count the
// mesh's other colour array uses.
void store_grey(shadetool::Mesh& mesh, const std::vector<float>& open, std::vector<float>& colors, bool other_has_colors) {
  if (!other_has_colors) mesh.color_channels = 3;
  const std::size_t ch = std::size_t(mesh.color_channels);
  colors.assign(ch * open.size(), 1.0f);
  for (std::size_t i = 0; i < open.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) colors[ch * i + k] = open[i];
}

RegisterCommand reg(60, [](CLI::App& app) -> std::function<int()> {
  static IoOptions io;
  static OcclusionOptions opt;
  static FitCliOptions fit;
  static double target_error = 0;
  auto* sub = app.add_subcommand(
      "occlusion",
      "Ambient occlusion by ray casting (Embree): per vertex or face, the cosine-weighted fraction of the sky "
      "open to distance D, as grey colours and/or a PLY quality property");
  add_io_options(*sub, io, /*writes_mesh=*/true);
  auto* samples_opt = sub->add_option("--samples", opt.samples, "Rays per vertex or face (default 64; error falls as N^-3/4); with --error the most rays per vertex or face (default 4096)")
      ->check(CLI::Range(1u, 1u << 20))
      ->type_name("N");
  sub->add_option("--distance", opt.distance,
                  "Only occluders nearer than D (mesh units) count (default: unlimited)")
      ->check(CLI::PositiveNumber)
      ->type_name("D");
  sub->add_option("--as", opt.as, "Store the open fraction as grey colours, the PLY quality property, or both (default)")
      ->check(CLI::IsMember({"color", "quality", "both"}));
  sub->add_option("--per", opt.per, "One value per vertex (default) or per face")
      ->check(CLI::IsMember({"vertex", "face"}));
  auto* error_opt = sub->add_option("--error", target_error,
                                    "Add rays in batches until the estimated standard error of each open fraction is at "
                                    "most E (a pilot of " + std::to_string(shadetool::kOcclusionReplicates) +
                                        " scrambled Sobol replicates, then one sequence; --samples caps the rays, default 4096)")
                        ->check(CLI::PositiveNumber)
                        ->type_name("E");
  add_fit_options(*sub, fit, "open fraction");
  return [samples_opt, error_opt] {
    const bool to_error = error_opt->count() > 0;
    const bool least_squares = fit_method(fit) == shadetool::VertexFit::LeastSquares;
    shadetool::OcclusionToErrorOptions error_options;
    error_options.target_error = target_error;
    error_options.max_samples = samples_opt->count() > 0 ? opt.samples : 4096u;
    error_options.max_distance = opt.distance;
    if (to_error && error_options.max_samples < shadetool::kOcclusionReplicates * shadetool::kOcclusionFirstBatch)
      throw UsageError("--error needs --samples of at least " +
                       std::to_string(shadetool::kOcclusionReplicates * shadetool::kOcclusionFirstBatch) +
                       " (one batch of every replicate)");
    shadetool::AmbientOcclusionOptions options;
    options.samples = opt.samples;
    options.max_distance = opt.distance;
    const bool per_face = opt.per == "face";
    const bool colors = opt.as != "quality", quality = opt.as != "color";
    return run_mesh_command(
        "occlusion", io,
        [options, per_face, colors, quality, to_error, least_squares, error_options](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
          shadetool::require_faces(mesh, input);
          shadetool::require_finite_positions(mesh, input);
          // Normals pass through to the output: none may carry NaN or Inf into it.
          shadetool::require_finite_normals(mesh, input, "fix them first (`shadetool normals --recompute` or `shadetool repair`)");
          // glTF: every primitive against the whole scene (gltf/gltf_occlusion.h), computed at
          // the first primitive for all of them; the BVH statistics then count once, there.
          shadetool::MeshOcclusion job;
          bool scene_stats = true;
          if ((to_error || least_squares) && r.gltf_document)
            throw UsageError(input + ": --error and --fit least-squares do not yet work on a glTF scene (convert the mesh "
                             "to PLY or OBJ first)");
          shadetool::OcclusionToError adaptive;
          if (r.gltf_document && r.gltf && r.gltf_document_state) {
            std::shared_ptr<void>& state = *r.gltf_document_state;
            const std::size_t index = std::size_t(r.gltf - r.gltf_document->primitives.data());
            if (!state) {
              state = std::make_shared<shadetool::GltfSceneOcclusion>(shadetool::gltf_scene_occlusion(
                  *r.gltf_document, per_face, options, shadetool::gltf_source_name(*r.gltf_document)));
            } else {
              scene_stats = false;
            }
            const auto& scene = *static_cast<const shadetool::GltfSceneOcclusion*>(state.get());
            for (const auto& n : scene.notes) r.notes.push_back(n);  // the same line from every primitive: said once
            job.ao = scene.primitives[index];
            job.normals_computed = scene.normals_computed[index];
            job.scene = scene.scene;
          } else if (to_error) {  // visibility/occlusion_to_error.h
            adaptive = shadetool::mesh_occlusion_to_error(mesh, per_face, error_options, input, job.normals_computed);
            job.ao.open_fraction = adaptive.open_fraction;
            job.ao.rays = adaptive.total_rays;
            job.ao.hits = adaptive.hits;
            job.ao.skipped = adaptive.skipped;
            job.scene = adaptive.scene;
          } else {
            // The normals (when computed) and the BVH are freed inside: the outputs are made after.
            job = shadetool::mesh_occlusion(mesh, per_face, options, input);
          }
          if (least_squares && per_face) {
            r.notes.push_back("--fit least-squares ignored with --per face (a face holds one value)");
          } else if (least_squares) {  // visibility/fit_occlusion.h
            shadetool::VertexFitOptions vfit;
            vfit.method = shadetool::VertexFit::LeastSquares;
            vfit.samples = fit.samples;
            vfit.solve.regularization = fit.regularization;
            shadetool::OcclusionFit lsq = shadetool::fit_occlusion(mesh, job.ao.open_fraction, options,
                                                                   to_error ? &error_options : nullptr, vfit, input);
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
            if (per_face ? mesh.has_face_colors() : mesh.has_vertex_colors())
              r.notes.push_back(fmt::format("the input's {} colours replaced by grey occlusion", what));
            if (per_face) store_grey(mesh, ao.open_fraction, mesh.face_colors, mesh.has_vertex_colors());
            else store_grey(mesh, ao.open_fraction, mesh.vertex_colors, mesh.has_face_colors());
          }
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
        true);
  };
});

}  // namespace
}  // namespace shadetool_cli
