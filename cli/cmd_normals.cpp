// cmd_normals.cpp: `shadetool normals IN -o OUT [--weight uniform|area|angle|max] [--crease DEG]
// [--recompute] [--faces] [--precision double|float] [--stats]`.
// Parses, calls lib/shadetool/normals/update_mesh_normals.h, prints notes and counts; exit codes in driver.h.
#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "command_registry.h"
#include <shadetool/core/math_constants.h>
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include "number_flags.h"
#include <shadetool/files/mesh_files.h>
#include <shadetool/gltf/gltf_morph_normals.h>
#include <shadetool/gltf/gltf_tangents.h>
#include <shadetool/normals/tangent_vertices.h>
#include <shadetool/normals/tangents.h>
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
  bool tangents = false;
  std::string smoothing_groups = shadetool::smoothing_groups_name(shadetool::SmoothingGroups::Honour);
  bool flat_patches = false;
  int weight_strength = 50;
  double weight_threshold = 0.01;
};

// The format the step's mesh is written in: --format, else -o's extension, else the input's.
shadetool::Format written_format(const IoOptions& io, const std::string& input) {
  if (!io.format.empty()) return shadetool::parse_format_name(io.format, "--format");
  if (!io.output.empty() && io.output != "-") return shadetool::format_from_extension(io.output);
  try {
    return shadetool::format_from_extension(input);
  } catch (const shadetool::Error&) {
    return shadetool::Format::Auto;
  }
}

// --tangents on a mesh written to a non-glTF file: MikkTSpace frames per corner; PLY carries them
// as vertex properties tx ty tz tw (vertices split where corners differ), other formats cannot.
void add_tangents(shadetool::Mesh& mesh, const std::string& input, shadetool::Format format, FileResult& r) {
  if (!mesh.has_texcoords()) {
    r.notes.push_back("--tangents: the mesh has no texture coordinates: no tangents (MikkTSpace needs them)");
    r.stats["tangents"] = 0;
    return;
  }
  const shadetool::TangentFrames frames = shadetool::mikktspace_tangents(mesh);
  r.stats["tangents"] = frames.tangents.size() / 4;
  r.stats["tangent_fallback_corners"] = frames.fallback_corners;
  if (frames.fallback_corners > 0)
    r.notes.push_back(fmt::format("--tangents: {} corners without a texture coordinate: a tangent perpendicular to the normal, w = +1",
                                  frames.fallback_corners));
  r.stats["tangent_zero_corners"] = frames.zero_corners;
  if (frames.zero_corners > 0) r.notes.push_back(shadetool::tangent_zero_corners_note(frames.zero_corners));
  if (format != shadetool::Format::Ply) {
    if (format == shadetool::Format::Gltf)
      r.notes.push_back("--tangents: computed, not written: glTF made from another format gets no TANGENT (write .ply, or start from a glTF)");
    else
      r.notes.push_back(fmt::format("--tangents: {} cannot hold tangents: computed, not written (write .ply, or a glTF from a glTF)",
                                    format == shadetool::Format::Auto ? "the output format" : shadetool::format_extension(format)));
    return;
  }
  const std::size_t added = shadetool::store_tangents_per_vertex(mesh, frames.tangents);
  r.stats["tangent_split_vertices"] = added;
  r.notes.push_back(fmt::format("--tangents: written as vertex properties tx ty tz tw ({} vertices split where corners' frames differ)", added));
  (void)input;
}

// The --weight names: the four weightings, then Blender's Weighted Normal modes (weighting.h).
std::vector<std::string> weight_names() {
  std::vector<std::string> names = shadetool::weighting_names();
  for (const std::string& n : shadetool::ranked_weighting_names()) names.push_back(n);
  return names;
}


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
                                 "angle (Thuermer-Wuethrich, default), max (Max 1999); or Blender's Weighted Normal "
                                 "modes face-area, corner-angle, face-area-angle (large faces dominate)")
                     ->check(CLI::IsMember(weight_names()));
  auto* strength = sub->add_option("--weight-strength", opt.weight_strength,
                                   "Weighted Normal modes: Blender's Weight, 1..100 (default 50: every rank alike; "
                                   "higher: the largest faces dominate)")
                       ->check(CLI::Range(1, 100))
                       ->type_name("W");
  auto* threshold = sub->add_option("--weight-threshold", opt.weight_threshold,
                                    "Weighted Normal modes: values closer than T share a rank (default 0.01)")
                        ->check(finite_number(0.0, 1e300))
                        ->type_name("T");
  auto* crease = sub->add_option("--crease", opt.crease_degrees,
                                 "Per-corner normals: split where the angle between two faces' normals exceeds DEG "
                                 "degrees (0..180); boundary and non-manifold edges always split")
                     ->check(finite_number(0.0, 180.0))
                     ->type_name("DEG");
  sub->add_flag("--recompute", opt.recompute, "Discard normals read from the input and compute new ones");
  auto* faces = sub->add_flag("--faces", opt.faces, "Write one normal per face instead of vertex normals");
  sub->add_option("--precision", opt.precision, "Accumulate in double (default) or float")
      ->check(CLI::IsMember(shadetool::precision_names()));
  sub->add_option("--smoothing-groups", opt.smoothing_groups,
                  "honour (default): an OBJ's smoothing groups (s N / s off) split the normals, s off faces "
                  "are flat; ignore: smooth across them")
      ->check(CLI::IsMember(shadetool::smoothing_groups_names()));
  auto* flat = sub->add_flag("--flat-patches", opt.flat_patches,
                             "A vertex all of whose faces lie in one plane gets exactly that plane's normal");
  auto* tangents = sub->add_flag("--tangents", opt.tangents,
                                  "Also compute MikkTSpace tangent frames (xyz, w = handedness) from the normals and "
                                  "texture coordinates: glTF TANGENT, PLY tx ty tz tw");
  faces->excludes(crease);
  faces->excludes(tangents);
  faces->excludes(flat);
  return [options, weight, faces, strength, threshold] {
    const IoOptions& io = options->io;
    const NormalsOptions& opt = options->opt;
    if (faces->count() > 0 && weight->count() > 0)
      throw UsageError("--weight applies to vertex and corner normals, not to --faces");
    const std::optional<shadetool::RankedWeighting> ranked = shadetool::find_ranked_weighting(opt.weight);
    if (!ranked && (strength->count() > 0 || threshold->count() > 0))
      throw UsageError("--weight-strength and --weight-threshold apply to --weight face-area, corner-angle or face-area-angle");
    shadetool::NormalsRequest request;
    request.kind = opt.faces ? shadetool::NormalKind::Face
                   : opt.crease_degrees >= 0 ? shadetool::NormalKind::Corner
                                             : shadetool::NormalKind::Vertex;
    if (!ranked) request.weighting = shadetool::parse_weighting(opt.weight, "--weight");
    request.crease_angle = opt.crease_degrees >= 0 ? opt.crease_degrees * shadetool::kPi / 180.0 : 0.0;
    request.precision = shadetool::parse_precision(opt.precision, "--precision");
    request.recompute = opt.recompute;
    request.flat_patches = opt.flat_patches;
    if (ranked) {
      request.ranked = true;
      request.ranked_options.mode = *ranked;
      request.ranked_options.strength = opt.weight_strength;
      request.ranked_options.threshold = opt.weight_threshold;
    }
    request.smoothing_groups = shadetool::parse_smoothing_groups(opt.smoothing_groups, "--smoothing-groups");
    return run_command(
        "normals", io,
        [request, &opt, &io](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
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
          if (opt.tangents && !r.gltf) add_tangents(mesh, input, written_format(io, input), r);
          if (r.gltf && r.gltf_document) {
            // New normals: TANGENT recomputed (or removed when it cannot be); kept normals: only
            // --tangents adds missing ones.
            const bool had = std::find(r.gltf->attributes.begin(), r.gltf->attributes.end(), "TANGENT") != r.gltf->attributes.end();
            if (!rep.kept || (opt.tangents && !had)) {
              const std::string note = shadetool::gltf_update_tangents(*r.gltf_document, *r.gltf, opt.tangents);
              if (!note.empty()) r.notes.push_back(note);
              r.stats["tangents"] = r.gltf->corner_tangents.size() / 4;
            }
          }
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
          if (opt.flat_patches) r.stats["flat_patches"] = rep.flat_patches;
          if (rep.honoured_groups) {
            r.stats["normals"] = "corner";
            r.stats["smoothing_groups"] = rep.smoothing_groups;
            r.stats["flat_faces"] = rep.flat_faces;
            r.notes.push_back(fmt::format("corner normals split by the file's smoothing groups ({} group{}, {} flat face{}: s off); "
                                          "--smoothing-groups ignore smooths across them",
                                          rep.smoothing_groups, rep.smoothing_groups == 1 ? "" : "s", rep.flat_faces,
                                          rep.flat_faces == 1 ? "" : "s"));
          }
          if (request.kind != shadetool::NormalKind::Face) r.stats["weight"] = opt.weight;
          if (request.kind == shadetool::NormalKind::Corner) {
            r.stats["crease_degrees"] = opt.crease_degrees;
            r.stats["corner_normals"] = rep.computed;
          }
          r.stats["precision"] = opt.precision;
          r.stats["degenerate_faces"] = rep.degenerate_faces;
          const char* fallback_key = request.kind == shadetool::NormalKind::Face     ? "fallback_faces"
                                     : (request.kind == shadetool::NormalKind::Corner || rep.honoured_groups) ? "fallback_corners"
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
                                                        : (request.kind == shadetool::NormalKind::Corner || rep.honoured_groups) ? "corners"
                                                                                                        : "vertices"));
        },
        OutputKind::Mesh);
  };
});

}  // namespace
}  // namespace shadetool_cli
