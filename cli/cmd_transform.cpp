// cmd_transform.cpp: `shadetool transform IN -o OUT [--scale S | --scale SX,SY,SZ]
// [--rotate DEG,AX,AY,AZ] [--translate TX,TY,TZ] [--matrix M] [--normals transform|recompute|drop]`.
//
// Parses the transform flags' values into maps, in command-line order (the first flag acts first:
// M = Mn ... M2 M1), composes them once, checks the map before any file is read (a singular map
// with --normals transform is a usage error), then runs transform_mesh (lib/transform) on every
// input. Values on the command line that are malformed are usage errors (exit 2); a malformed
// --matrix @FILE is an input error (exit 1) with FILE:LINE.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_registry.h"
#include <shadetool/normals/replace_invalid_normals.h>
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include <shadetool/gltf/gltf_tangents.h>
#include <shadetool/gltf/gltf_transform.h>
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/classify_affine.h>
#include <shadetool/transform/transform_mesh.h>
#include "usage_error.h"

namespace shadetool_cli {
namespace {

struct TransformCliOptions {
  std::vector<std::string> scale, rotate, translate, matrix;
  std::string normals = shadetool::normals_policy_name(shadetool::NormalsPolicy::Transform);
};

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

// A whole token as a double (optional leading '+'; "1e-3", ".5", "-0.25"). Returns "" or why not.
// std::from_chars: locale-independent and strict about trailing characters.
std::string parse_double(const std::string& token, double& out) {
  const char* b = token.data();
  const char* e = b + token.size();
  if (b != e && *b == '+') ++b;
  if (b == e || *b == '+') return "is not a number";  // "+" alone or "++1"
  const auto res = std::from_chars(b, e, out, std::chars_format::general);
  if (res.ec == std::errc::result_out_of_range && res.ptr == e) return "is out of the range of double";
  if (res.ec != std::errc() || res.ptr != e) return "is not a number";
  if (!std::isfinite(out)) return "is not a finite number";
  return {};
}

// "a,b,c" -> numbers; UsageError naming the flag, the value and the bad item.
std::vector<double> parse_number_list(const std::string& flag, const std::string& value) {
  std::vector<double> out;
  std::size_t start = 0, item = 1;
  while (true) {
    const std::size_t comma = value.find(',', start);
    const std::string token = trim(std::string_view(value).substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (token.empty())
      throw UsageError(flag + " '" + value + "': item " + std::to_string(item) + " is empty (numbers are separated by commas)");
    double x;
    if (const std::string why = parse_double(token, x); !why.empty())
      throw UsageError(flag + " '" + value + "': '" + token + "' " + why);
    out.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
    ++item;
  }
  return out;
}

// --matrix @FILE: 12 or 16 numbers separated by whitespace (or commas); '#' starts a comment.
std::vector<double> read_matrix_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) shadetool::fail(path, 0, std::string("cannot open the matrix file: ") + std::strerror(errno));
  std::vector<double> values;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& ch : line)
      if (ch == ',' || ch == '\t' || ch == '\r') ch = ' ';
    std::istringstream words(line);
    std::string token;
    while (words >> token) {
      double x;
      if (const std::string why = parse_double(token, x); !why.empty()) shadetool::fail(path, line_no, "'" + token + "' " + why);
      values.push_back(x);
    }
  }
  if (in.bad()) shadetool::fail(path, 0, "read error");
  return values;
}

// One flag occurrence -> its map. Library Errors about command-line values become UsageErrors.
shadetool::Affine3d map_for(const std::string& flag, const std::string& value) {
  using namespace shadetool;
  if (flag == "--matrix" && !value.empty() && value[0] == '@') {
    const std::string path = value.substr(1);
    if (path.empty()) throw UsageError("--matrix @FILE: the file name is missing");
    return affine_from_row_major(read_matrix_file(path), path);  // Error: FILE: what (exit 1)
  }
  const std::vector<double> v = parse_number_list(flag, value);
  try {
    if (flag == "--scale") {
      if (v.size() == 1) return scale_map({v[0], v[0], v[0]});
      if (v.size() == 3) return scale_map({v[0], v[1], v[2]});
      throw UsageError("--scale '" + value + "': give S or SX,SY,SZ (1 or 3 numbers), got " + std::to_string(v.size()));
    }
    if (flag == "--rotate") {
      if (v.size() != 4)
        throw UsageError("--rotate '" + value + "': give DEG,AX,AY,AZ (4 numbers), got " + std::to_string(v.size()));
      return rotation_map(v[0], {v[1], v[2], v[3]});
    }
    if (flag == "--translate") {
      if (v.size() != 3)
        throw UsageError("--translate '" + value + "': give TX,TY,TZ (3 numbers), got " + std::to_string(v.size()));
      return translation_map({v[0], v[1], v[2]});
    }
    return affine_from_row_major(v, "--matrix");
  } catch (const shadetool::Error& e) {
    throw UsageError(e.what());
  }
}

RegisterCommand reg("transform", HelpSection::Edit, [](CLI::App& app) -> std::function<int()> {
  auto command_options = std::make_shared<CommandOptions<TransformCliOptions>>();  // bound to the flags, read by the run function
  IoOptions& io = command_options->io;
  TransformCliOptions& opt = command_options->opt;
  auto* sub = app.add_subcommand(
      "transform",
      "Apply an affine map: positions by p' = A p + t, normals by the cofactor of A, mirrors re-wound. "
      "Flags repeat and act in command-line order (the first given acts first).");
  add_io_options(*sub, io, OutputKind::Mesh);
  auto* scale = sub->add_option("--scale", opt.scale, "Scale about the origin: S (uniform) or SX,SY,SZ")->allow_extra_args(false);
  auto* rotate = sub->add_option("--rotate", opt.rotate,
                                 "Rotate DEG degrees about the axis (AX,AY,AZ) through the origin, "
                                 "counter-clockwise seen from the axis tip: DEG,AX,AY,AZ")
                     ->allow_extra_args(false);
  auto* translate = sub->add_option("--translate", opt.translate, "Translate by TX,TY,TZ")->allow_extra_args(false);
  auto* matrix = sub->add_option("--matrix", opt.matrix,
                                 "Affine matrix, row-major: 12 numbers (3x4 [A|t]) or 16 (4x4, last row 0,0,0,1), "
                                 "comma-separated, or @FILE with the numbers separated by whitespace")
                     ->allow_extra_args(false);
  for (auto* o : {scale, rotate, translate, matrix}) o->type_name("LIST");
  sub->add_option("--normals", opt.normals,
                  "Normals: transform (default; by the cofactor of A), recompute (from the transformed faces), "
                  "or drop")
      ->check(CLI::IsMember(shadetool::normals_policy_names()));

  return [command_options, sub, scale, rotate, translate, matrix] {
    const IoOptions& io = command_options->io;
    TransformCliOptions& opt = command_options->opt;
    // The maps in the order the flags were given: parse_order() lists every occurrence.
    const std::map<const CLI::Option*, const std::vector<std::string>*> values = {
        {scale, &opt.scale}, {rotate, &opt.rotate}, {translate, &opt.translate}, {matrix, &opt.matrix}};
    std::map<const CLI::Option*, std::size_t> used;
    std::vector<shadetool::Affine3d> maps;
    for (const CLI::Option* o : sub->parse_order()) {
      auto it = values.find(o);
      if (it == values.end()) continue;
      const std::size_t i = used[o]++;
      if (i >= it->second->size()) continue;  // defensive: one result per occurrence
      maps.push_back(map_for(o->get_name(), (*it->second)[i]));
    }
    const shadetool::Affine3d M = shadetool::compose_in_order(maps);
    shadetool::AffineClass cls;
    try {
      cls = shadetool::classify_affine(M);
    } catch (const shadetool::Error&) {  // finite flags whose product overflowed, e.g. --scale 1e200 twice
      throw UsageError("the composed transform has an entry that overflows double (|entry| > 1.8e308)");
    }
    shadetool::TransformOptions options;
    options.normals = shadetool::parse_normals_policy(opt.normals, "--normals");
    // A singular map is fine for a mesh with no normals (it is flattened, and a note says so); a
    // mesh with normals to transform is refused, file by file (exit 1), with the reason.
    const bool singular = cls.path == shadetool::TransformPath::Singular;
    const bool no_map = maps.empty();

    const bool similarity = shadetool::mapped_tangents_stay_mikktspace(cls.path);
    return run_command("transform", io, [M, options, no_map, singular, similarity](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
      const bool had_normals = mesh.has_vertex_normals() || mesh.has_corner_normals() || mesh.has_face_normals();
      shadetool::TransformOptions file_options = options;
      if (singular && had_normals && options.normals == shadetool::NormalsPolicy::Transform)
        throw UsageError(shadetool::singular_map_message(shadetool::classify_affine(M)) + "; " + input + " has normals");
      if (singular && !had_normals && options.normals == shadetool::NormalsPolicy::Transform) {
        file_options.normals = shadetool::NormalsPolicy::Drop;  // nothing to drop: positions only
        r.notes.push_back("the transform is singular (det A = 0 or nearly): the mesh was flattened; it has no normals to transform");
      }
      // transform_mesh leaves a NaN/Inf normal as read; the command does not write one unasked.
      if (options.normals == shadetool::NormalsPolicy::Transform)  // one without a direction: replaced, counted
        if (const std::string note = shadetool::invalid_normals_note(shadetool::replace_invalid_normals(mesh)); !note.empty())
          r.notes.push_back(note);
      if (r.gltf) {  // glTF: tangents and morph-target deltas, before the base normals move
        const shadetool::GltfTransformReport g =
            shadetool::transform_gltf_extras(*r.gltf, M, file_options.normals == shadetool::NormalsPolicy::Drop);
        if (!r.gltf->tangents.empty()) r.stats["tangents"] = g.tangents;
        if (g.tangents_left > 0) r.notes.push_back(std::to_string(g.tangents_left) + " tangents are zero or not finite: left as read");
        if (g.tangents_dropped) r.notes.push_back("TANGENT removed with NORMAL (--normals drop): readers ignore tangents without normals");
        if (!r.gltf->targets.empty()) r.stats["morph_deltas"] = g.target_deltas;
      }
      const shadetool::TransformReport rep = shadetool::transform_mesh(mesh, M, file_options, input);
      r.stats["path"] = shadetool::path_name(rep.affine.path);
      r.stats["mirror"] = rep.affine.mirror;
      r.stats["normals"] = file_options.normals != options.normals ? std::string("none") : rep.normals;
      if (no_map) r.notes.push_back("no --scale, --rotate, --translate or --matrix given: the output is a copy");
      if (rep.winding_reversed)
        r.notes.push_back("det(A) < 0 (a mirror): face winding reversed so that faces keep their orientation");
      if (rep.normals_left > 0) {
        r.stats["normals_left_as_read"] = rep.normals_left;
        r.notes.push_back(std::to_string(rep.normals_left) +
                          " input normals are zero or NaN and were left as read (shadetool repair fixes them)");
      }
      if (rep.fallback_normals > 0) {
        r.stats["fallback_normals"] = rep.fallback_normals;
        r.notes.push_back(std::to_string(rep.fallback_normals) +
                          " recomputed normals had no valid face and got the documented fallback");
      }
      if (options.normals == shadetool::NormalsPolicy::Recompute && !had_normals)
        r.notes.push_back("the input has no normals: nothing to recompute");
      // PLY tangents (vertex properties tx ty tz tw): mapped or removed by transform_mesh.
      if (std::string_view(rep.tangents) == "mapped") {
        r.stats["tangents"] = rep.tangents_mapped;
        r.notes.push_back(similarity ? "tangents tx ty tz tw mapped by A (w flipped under a mirror)"
                                     : "tangents tx ty tz tw mapped by A (w flipped under a mirror): orthogonal to the new normals, "
                                       "but the map is not a similarity, so they are not the mapped mesh's MikkTSpace frames "
                                       "(`shadetool normals --tangents` recomputes them)");
      } else if (std::string_view(rep.tangents) == "dropped") {
        r.notes.push_back("tangents tx ty tz tw removed: they belonged to the normals as read (`shadetool normals --tangents` makes new ones)");
      }
      // glTF: new normals get TANGENT recomputed by MikkTSpace (gltf_tangents.h): recomputed
      // normals, and normals mapped by a map that is not a similarity (gltf_transform.h,
      // mapped_tangents_stay_mikktspace). A similarity keeps the mapped tangents: they are the
      // MikkTSpace frames of the mapped mesh.
      const bool recomputed = had_normals && file_options.normals == shadetool::NormalsPolicy::Recompute;
      const bool non_similar = had_normals && file_options.normals == shadetool::NormalsPolicy::Transform && !similarity;
      if (r.gltf && r.gltf_document && (recomputed || non_similar)) {
        const std::string note = shadetool::gltf_update_tangents(*r.gltf_document, *r.gltf, false);
        if (!note.empty())
          r.notes.push_back(non_similar ? note + " (the map is not a similarity: mapped tangents would not be MikkTSpace's)" : note);
      }
    }, OutputKind::Mesh);
  };
});

}  // namespace
}  // namespace shadetool_cli
