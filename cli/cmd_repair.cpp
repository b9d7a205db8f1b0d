// cmd_repair.cpp: `shadetool repair IN -o OUT [--report FILE.json] [--weight W]
// [--remove-degenerate] [--remove-unreferenced] [--weld EPS]`. Parses, prints one line per step that changed something,
// writes the JSON report; the repair itself is lib/shadetool/repair/repair_mesh.h.
#include <filesystem>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "command_registry.h"
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include <shadetool/gltf/gltf_tangents.h>
#include "number_flags.h"
#include <shadetool/repair/remove_unreferenced.h>
#include <shadetool/repair/repair_mesh.h>
#include <shadetool/repair/repair_report_json.h>
#include "usage_error.h"

namespace shadetool_cli {
namespace {

using shadetool::RepairReport;

struct RepairCliOptions {
  std::string report;
  std::string weight = shadetool::weighting_name(shadetool::Weighting::Angle);
  bool remove_degenerate = false;
  bool remove_unreferenced = false;
  double weld = -1;  // < 0: not given
};

// "1 face", "2 faces".
std::string count(std::size_t n, const char* one, const char* many) { return fmt::format("{} {}", n, n == 1 ? one : many); }

// One line per step that changed something (the driver prefixes `shadetool: INPUT: `).
void add_notes(const RepairReport& r, const RepairCliOptions& opt, FileResult& out) {
  if (r.vertices_welded > 0)
    out.notes.push_back(fmt::format("weld: merged {} within {}", count(r.vertices_welded, "vertex", "vertices"), opt.weld));
  if (r.seam_vertices_joined > 0)
    out.notes.push_back(fmt::format("seams: oriented across {} at the exact position of another (joined for the decision only; "
                                    "the output keeps them)", count(r.seam_vertices_joined, "boundary vertex", "boundary vertices")));
  if (r.oriented_by_normals > 0)
    out.notes.push_back(fmt::format("orientation: {} followed the input's normals (inconsistent winding, or no geometric evidence)",
                                    count(r.oriented_by_normals, "component", "components")));
  if (r.orientation_by.geometry_overruled > 0)
    out.notes.push_back(fmt::format("orientation: kept {} as authored: winding and normals agree, though volume, nesting or "
                                    "the open-surface vote would have reversed {}",
                                    count(r.orientation_by.geometry_overruled, "component", "components"),
                                    r.orientation_by.geometry_overruled == 1 ? "it" : "them"));
  if (r.faces_flipped_for_consistency > 0) {
    std::string s = fmt::format("winding: reversed {} to make the winding consistent in {}",
                                count(r.faces_flipped_for_consistency, "face", "faces"),
                                count(r.components, "component", "components"));
    if (r.non_manifold_edges > 0) s += fmt::format("; {} not crossed", count(r.non_manifold_edges, "non-manifold edge", "non-manifold edges"));
    if (r.non_orientable_components > 0)
      s += fmt::format("; {}, {} left inconsistent", count(r.non_orientable_components, "non-orientable component", "non-orientable components"),
                       count(r.inconsistent_edges, "edge", "edges"));
    out.notes.push_back(s);
  }
  if (r.components_inverted > 0) {
    std::string s = fmt::format("orientation: reversed {} of {} as a whole", r.components_inverted,
                                count(r.components, "component", "components"));
    if (r.nested_shells > 0) s += fmt::format(" ({} facing a cavity)", count(r.nested_shells, "nested shell", "nested shells"));
    out.notes.push_back(s);
  }
  if (r.normals.missing > 0)
    out.notes.push_back(fmt::format("normals: computed {} ({} weighting; the mesh had none)",
                                    count(r.normals.missing, "vertex normal", "vertex normals"), opt.weight));
  const std::size_t fixed = r.normals.total() - r.normals.missing;
  if (fixed > 0)
    out.notes.push_back(fmt::format("normals: recomputed {} ({} NaN, {} Inf, {} zero, {} against their faces)",
                                    count(fixed, "stored normal", "stored normals"), r.normals.nan, r.normals.inf,
                                    r.normals.zero, r.normals.flipped));
  if (r.degenerate_faces_removed > 0)
    out.notes.push_back(fmt::format("degenerate: removed {} ({} zero area, {} repeated index, {} fewer than 3 corners, {} NaN/Inf)",
                                    count(r.degenerate_faces_removed, "face", "faces"), r.degenerate_zero_area, r.degenerate_repeated_index,
                                    r.degenerate_too_few_corners, r.degenerate_non_finite));
}

void add_stats(const RepairReport& r, FileResult& out) {
  auto& s = out.stats;
  s["components"] = r.components;
  s["closed_components"] = r.closed_components;
  s["open_components"] = r.open_components;
  s["faces_flipped"] = r.faces_flipped;
  s["components_inverted"] = r.components_inverted;
  s["nested_shells"] = r.nested_shells;
  s["non_manifold_edges"] = r.non_manifold_edges;
  s["duplicate_faces"] = r.duplicate_faces;
  s["non_orientable_components"] = r.non_orientable_components;
  s["boundary_loops"] = r.boundary_loops;
  s["degenerate_faces"] = r.degenerate_faces;
  s["degenerate_faces_removed"] = r.degenerate_faces_removed;
  s["vertices_welded"] = r.vertices_welded;
  s["seam_vertices_joined"] = r.seam_vertices_joined;
  s["oriented_by_normals"] = r.oriented_by_normals;
  s["normals_recomputed"] = r.normals.total();
}

RegisterCommand reg("repair", HelpSection::Edit, [](CLI::App& app) -> std::function<int()> {
  auto options = std::make_shared<CommandOptions<RepairCliOptions>>();  // bound to the flags, read by the run function
  IoOptions& io = options->io;
  RepairCliOptions& opt = options->opt;
  auto* sub = app.add_subcommand("repair", "Make winding consistent, orient outward, fix broken normals, report");
  add_io_options(*sub, io, OutputKind::Mesh);
  sub->add_option("--report", opt.report, "Write what was found and changed as a JSON object to FILE (one input only)");
  sub->add_option("--weight", opt.weight, "Weighting of recomputed normals: uniform, area, angle (default) or max")
      ->check(CLI::IsMember(shadetool::weighting_names()));
  sub->add_flag("--remove-degenerate", opt.remove_degenerate,
                "Remove degenerate faces (zero area, repeated index, < 3 corners); default: report only");
  sub->add_flag("--remove-unreferenced", opt.remove_unreferenced,
                "Remove vertices no face uses (also when their coordinates are NaN or Inf); default: keep them");
  sub->add_option("--weld", opt.weld, "Merge vertices within distance EPS (>= 0) of each other before orienting")
      ->check(finite_number(0.0, std::numeric_limits<double>::infinity()));
  return [options] {
    IoOptions& io = options->io;
    const RepairCliOptions& opt = options->opt;
    if (!opt.report.empty() && io.inputs.size() != 1) throw UsageError("--report takes one input");
    if (opt.report == "-" && (io.output == "-" || io.json)) throw UsageError("--report - and -o - or --json all write stdout; choose one");
    if (!opt.report.empty() && opt.report != "-") {
      // Fail before any work (and any output) if the report cannot be written there.
      const std::filesystem::path dir = std::filesystem::path(opt.report).parent_path();
      if (!dir.empty() && !std::filesystem::is_directory(dir))
        throw shadetool::Error(shadetool::located(opt.report, 0, "cannot write the report: no such directory"));
    }
    if (!opt.report.empty()) io.other_outputs = {{"--report", opt.report}};
    // The report is committed together with the mesh (driver.h: both or neither).
    return run_command(
        "repair", io,
        [&io, &opt](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
          // Before the check of the positions: unused vertices' NaN (Open3D's) goes with them.
          std::size_t unreferenced = opt.remove_unreferenced ? shadetool::remove_unreferenced_vertices(mesh) : 0;
          shadetool::require_finite_positions(mesh, input);
          shadetool::require_faces(mesh, input);
          shadetool::RepairOptions o;
          o.weighting = shadetool::parse_weighting(opt.weight, "--weight");
          o.remove_degenerate = opt.remove_degenerate;
          o.weld_eps = opt.weld;
          o.progress = r.progress;
          const RepairReport rep = shadetool::repair_mesh(mesh, o);
          // Faces removed as degenerate may leave vertices unused: removed too.
          if (opt.remove_unreferenced) unreferenced += shadetool::remove_unreferenced_vertices(mesh);
          add_notes(rep, opt, r);
          add_stats(rep, r);
          if (opt.remove_unreferenced) {
            r.stats["unreferenced_vertices_removed"] = unreferenced;
            if (unreferenced > 0) r.notes.push_back(fmt::format("unreferenced: removed {} no face used", count(unreferenced, "vertex", "vertices")));
          }
          if (r.gltf && r.gltf_document && rep.normals.total() > 0) {  // new normals: TANGENT follows (gltf_tangents.h)
            const std::string note = shadetool::gltf_update_tangents(*r.gltf_document, *r.gltf, false);
            if (!note.empty()) r.notes.push_back(note);
          }
          if (!opt.report.empty()) {
            nlohmann::json j{{"input", input}};
            if (!io.output.empty()) j["output"] = io.output;
            j.update(nlohmann::json::parse(shadetool::repair_report_json(rep, opt.weld, opt.weight)));
            if (opt.remove_unreferenced) j["unreferenced_vertices_removed"] = unreferenced;
            r.other_files.emplace_back(opt.report, j.dump(2) + "\n");
          }
        },
        OutputKind::Mesh);
  };
});

}  // namespace
}  // namespace shadetool_cli
