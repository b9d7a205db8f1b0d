// cmd_normals.cpp: `shadetool normals IN -o OUT [--weight uniform|area|angle|max] [--crease DEG]
// [--recompute] [--faces] [--precision double|float] [--stats]`.
// Parses, calls lib/shadetool/normals/update_mesh_normals.h, prints notes and counts; exit codes in driver.h.
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "command_registry.h"
#include <shadetool/core/math_constants.h>
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include "number_flags.h"
#include <shadetool/gltf/gltf_morph_normals.h>
#include <shadetool/normals/update_mesh_normals.h>
#include "usage_error.h"

namespace shadetool_cli {
namespace {


struct NormalsOptions {
  std::string weight = shadetool::weighting_name(shadetool::Weighting::Angle);
  double crease_degrees = -1;  // < 0: not given (vertex normals)
  bool recompute = false;
  bool faces = false;
  std::string precision = shadetool::precision_name(shadetool::Precision::Double);
};

// True when update_mesh_normals would keep the mesh's normals (no computation, positions unused).
bool has_normals_for(const shadetool::Mesh& mesh, shadetool::NormalKind kind) {
  return kind == shadetool::NormalKind::Face ? mesh.has_face_normals()
                                             : mesh.has_vertex_normals() || mesh.has_corner_normals();
}

RegisterCommand reg("normals", HelpSection::Edit, [](CLI::App& app) -> std::function<int()> {
  auto options = std::make_shared<CommandOptions<NormalsOptions>>();  // bound to the flags, read by the run function
  IoOptions& io = options->io;
  NormalsOptions& opt = options->opt;
  auto* sub = app.add_subcommand("normals", "Compute vertex normals (default), corner normals split at creases, or face normals");
  add_io_options(*sub, io, OutputKind::Mesh);
  auto* weight = sub->add_option("--weight", opt.weight,
                                 "How face normals are weighted into vertex normals: uniform (Gouraud), area, "
                                 "angle (Thuermer-Wuethrich, default), max (Max 1999)")
                     ->check(CLI::IsMember(shadetool::weighting_names()));
  auto* crease = sub->add_option("--crease", opt.crease_degrees,
                                 "Per-corner normals: split where the angle between two faces' normals exceeds DEG "
                                 "degrees (0..180); boundary and non-manifold edges always split")
                     ->check(finite_number(0.0, 180.0))
                     ->type_name("DEG");
  sub->add_flag("--recompute", opt.recompute, "Discard normals read from the input and compute new ones");
  auto* faces = sub->add_flag("--faces", opt.faces, "Write one normal per face instead of vertex normals");
  sub->add_option("--precision", opt.precision, "Accumulate in double (default) or float")
      ->check(CLI::IsMember(shadetool::precision_names()));
  faces->excludes(crease);
  return [options, weight, faces] {
    const IoOptions& io = options->io;
    const NormalsOptions& opt = options->opt;
    if (faces->count() > 0 && weight->count() > 0)
      throw UsageError("--weight applies to vertex and corner normals, not to --faces");
    shadetool::NormalsRequest request;
    request.kind = opt.faces ? shadetool::NormalKind::Face
                   : opt.crease_degrees >= 0 ? shadetool::NormalKind::Corner
                                             : shadetool::NormalKind::Vertex;
    request.weighting = shadetool::parse_weighting(opt.weight, "--weight");
    request.crease_angle = opt.crease_degrees >= 0 ? opt.crease_degrees * shadetool::kPi / 180.0 : 0.0;
    request.precision = shadetool::parse_precision(opt.precision, "--precision");
    request.recompute = opt.recompute;
    return run_command(
        "normals", io,
        [request, &opt](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
          shadetool::require_faces(mesh, input);
          if (request.recompute || !has_normals_for(mesh, request.kind)) shadetool::require_finite_positions(mesh, input);
          const shadetool::NormalsReport rep = shadetool::update_mesh_normals(mesh, request);
          if (rep.kept && rep.invalid_existing > 0)
            throw shadetool::Error(shadetool::located(
                input, 0,
                fmt::format("{} of {} {} are invalid (NaN, Inf or zero length); use --recompute to replace them "
                            "(or `shadetool repair`)",
                            rep.invalid_existing, rep.existing, rep.kept_what)));
          // Normals of the other kind pass through unchanged (e.g. an STL's facet normals when vertex
          // normals are computed): none of them may carry NaN/Inf into the output.
          shadetool::require_finite_normals(mesh, input, "use --recompute to replace the input's normals (or `shadetool repair`)");
          if (rep.kept) {
            r.notes.push_back(fmt::format("input has {}: kept unchanged, nothing computed (use --recompute to replace them)",
                                          rep.kept_what));
            r.stats["normals"] = "kept";
            r.stats["kept_normals"] = rep.existing;
            return;
          }
          if (r.gltf && !r.gltf->targets.empty()) {  // glTF morph targets: their NORMAL deltas follow
            shadetool::NormalsRequest displaced = request;
            displaced.recompute = true;
            const std::size_t redone = shadetool::recompute_morph_normal_deltas(
                *r.gltf, [displaced](shadetool::Mesh& m) { shadetool::update_mesh_normals(m, displaced); });
            if (redone > 0)
              r.notes.push_back(fmt::format("morph targets: NORMAL deltas of {} targets recomputed from their displaced positions", redone));
            else if (request.kind != shadetool::NormalKind::Vertex)
              r.notes.push_back("morph targets: NORMAL deltas kept as read (recomputed only with vertex normals)");
            r.stats["morph_targets_recomputed"] = redone;
          }
          const char* kind = request.kind == shadetool::NormalKind::Face     ? "face"
                             : request.kind == shadetool::NormalKind::Corner ? "corner"
                                                                             : "vertex";
          r.stats["normals"] = kind;
          if (request.kind != shadetool::NormalKind::Face) r.stats["weight"] = opt.weight;
          if (request.kind == shadetool::NormalKind::Corner) {
            r.stats["crease_degrees"] = opt.crease_degrees;
            r.stats["corner_normals"] = rep.computed;
          }
          r.stats["precision"] = opt.precision;
          r.stats["degenerate_faces"] = rep.degenerate_faces;
          const char* fallback_key = request.kind == shadetool::NormalKind::Face     ? "fallback_faces"
                                     : request.kind == shadetool::NormalKind::Corner ? "fallback_corners"
                                                                                     : "fallback_vertices";
          r.stats[fallback_key] = rep.fallback;
          if (rep.two_sided_faces > 0) {
            r.stats["two_sided_faces"] = rep.two_sided_faces;
            r.notes.push_back(fmt::format(
                "{} faces are the back of an earlier face on the same vertices (a two-sided surface): normals from the "
                "front faces only{}",
                rep.two_sided_faces, request.kind == shadetool::NormalKind::Corner ? ", reversed on the back faces' corners" : ""));
          }
          if (rep.discarded > 0) r.notes.push_back(fmt::format("--recompute: {} normals from the input discarded", rep.discarded));
          if (rep.dropped > 0)
            r.notes.push_back(fmt::format("{} vertex/corner normals from the input dropped: --faces writes face normals", rep.dropped));
          if (rep.fallback > 0)
            r.notes.push_back(fmt::format("{} {} had no valid face (isolated or only degenerate faces) or a cancelling sum: "
                                          "given a fallback normal (see man shadetool-normals)",
                                          rep.fallback, request.kind == shadetool::NormalKind::Face     ? "degenerate faces"
                                                        : request.kind == shadetool::NormalKind::Corner ? "corners"
                                                                                                        : "vertices"));
        },
        OutputKind::Mesh);
  };
});

}  // namespace
}  // namespace shadetool_cli
