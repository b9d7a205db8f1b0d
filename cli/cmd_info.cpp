// cmd_info.cpp: `shadetool info MESH... [--json]`: what a mesh holds and what is wrong with it.
// Read-only: the statistics come from lib/shadetool/info/mesh_info.h; this file only formats them.
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "command_registry.h"
#include "driver.h"
#include <shadetool/info/mesh_info.h>
#include <shadetool/files/mesh_files.h>

namespace shadetool_cli {
namespace {

using shadetool::info::MeshInfo;

nlohmann::json info_json(const MeshInfo& m, const std::string& format) {
  nlohmann::json j;
  j["format"] = format;
  j["precision"] = m.double_precision ? "double" : "float";
  j["vertices"] = m.vertices;
  j["faces"] = m.faces;
  j["corners"] = m.corners;
  j["triangles"] = m.triangles;
  j["quads"] = m.quads;
  j["polygons"] = m.polygons;
  nlohmann::json sizes = nlohmann::json::object();
  for (auto& [size, count] : m.faces_by_size) sizes[std::to_string(size)] = count;
  j["faces_by_size"] = sizes;
  if (m.has_bbox) {
    j["bbox"] = {{"min", {m.bbox_min.x, m.bbox_min.y, m.bbox_min.z}}, {"max", {m.bbox_max.x, m.bbox_max.y, m.bbox_max.z}}};
  } else {
    j["bbox"] = nullptr;
  }
  j["attributes"] = {{"vertex_normals", m.vertex_normals}, {"corner_normals", m.corner_normals},
                     {"face_normals", m.face_normals},     {"vertex_colors", m.vertex_colors},
                     {"face_colors", m.face_colors},       {"texcoords", m.texcoords},
                     {"color_channels", m.color_channels},  {"vertex_quality", m.vertex_quality},
                     {"face_quality", m.face_quality},      {"vertex_properties", m.vertex_properties},
                     {"face_properties", m.face_properties}};
  j["edges"] = m.topology.edges;
  j["boundary_edges"] = m.topology.boundary_edges;
  j["non_manifold_edges"] = m.topology.non_manifold_edges;
  j["inconsistent_edges"] = m.topology.inconsistent_edges;
  j["non_manifold_vertices"] = m.topology.non_manifold_vertices;
  j["components"] = m.components;
  j["degenerate_faces"] = m.degenerate.count();
  j["repeated_index_faces"] = m.degenerate.repeated_index;
  j["zero_area_faces"] = m.degenerate.zero_area + m.degenerate.too_few_corners;  // < 3 corners: no area at all
  j["nonfinite_faces"] = m.degenerate.non_finite;
  j["unreferenced_vertices"] = m.unreferenced_vertices;
  j["nonfinite_vertices"] = m.nonfinite_vertices;
  j["nonfinite_values"] = m.nonfinite_values;
  if (m.nonfinite_vertices > 0) j["nonfinite_unreferenced_vertices"] = m.nonfinite_unreferenced_vertices;
  j["closed_manifold"] = m.closed_manifold();
  return j;
}

// A coordinate that is exactly a float (float data: binary PLY and STL, glTF) as the shortest text
// of that float (the widened double would print 17 digits of binary noise), else the shortest
// text that reads back to the double.
bool is_float(double x) { return double(float(x)) == x; }
std::string coordinate_text(double x) { return is_float(x) ? fmt::format("{}", float(x)) : fmt::format("{}", x); }
// A size, hi - lo: between floats to a float's digits, else to 15 significant digits (the
// subtraction's last bits are rounding: 0.072612, not 0.07261200000000001).
std::string size_text(double lo, double hi) {
  return is_float(lo) && is_float(hi) ? fmt::format("{}", float(hi - lo)) : fmt::format("{:.15g}", hi - lo);
}

// texcoord_sets: a glTF primitive's TEXCOORD_n attributes ("TEXCOORD_0"), which its mesh does not
// hold (they pass through); empty otherwise.
std::string info_text(const MeshInfo& m, const std::string& input, const std::string& format,
                      const std::string& texcoord_sets) {
  std::string s = fmt::format("{}: {} ({})\n", input, format, m.double_precision ? "double" : "float");
  s += fmt::format("  vertices               {}\n", m.vertices);
  std::string sizes;
  for (auto& [size, count] : m.faces_by_size) {
    const std::string kind = size == 3 ? "triangle" : size == 4 ? "quad" : fmt::format("{}-gon", size);
    sizes += fmt::format("{}{} {}{}", sizes.empty() ? "" : ", ", count, kind, count == 1 ? "" : "s");
  }
  s += fmt::format("  faces                  {}{}\n", m.faces, sizes.empty() ? "" : " (" + sizes + ")");
  s += fmt::format("  corners                {}\n", m.corners);
  if (m.has_bbox) {
    s += fmt::format("  bounding box           min ({}, {}, {})  max ({}, {}, {})\n", coordinate_text(m.bbox_min.x),
                     coordinate_text(m.bbox_min.y), coordinate_text(m.bbox_min.z), coordinate_text(m.bbox_max.x),
                     coordinate_text(m.bbox_max.y), coordinate_text(m.bbox_max.z));
    s += fmt::format("  size                   {} x {} x {}\n", size_text(m.bbox_min.x, m.bbox_max.x),
                     size_text(m.bbox_min.y, m.bbox_max.y), size_text(m.bbox_min.z, m.bbox_max.z));
  } else {
    s += "  bounding box           none (no finite vertex)\n";
  }
  std::string attrs;
  auto add = [&](bool on, const std::string& what) {
    if (on) attrs += (attrs.empty() ? "" : ", ") + what;
  };
  add(m.vertex_normals, "vertex normals");
  add(m.corner_normals, fmt::format("corner normals ({} distinct)", m.corner_normal_pool));
  add(m.face_normals, "face normals");
  add(m.vertex_colors, fmt::format("vertex colours ({})", m.color_channels == 4 ? "rgba" : "rgb"));
  add(m.face_colors, fmt::format("face colours ({})", m.color_channels == 4 ? "rgba" : "rgb"));
  if (!texcoord_sets.empty()) add(true, "texcoords (" + texcoord_sets + ")");
  else add(m.texcoords, fmt::format("texcoords ({} distinct)", m.texcoord_pool));
  add(m.vertex_quality, "vertex quality");
  add(m.face_quality, "face quality");
  auto names = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& n : v) s += (s.empty() ? "" : " ") + n;
    return s;
  };
  add(!m.vertex_properties.empty(), "vertex properties (" + names(m.vertex_properties) + ")");
  add(!m.face_properties.empty(), "face properties (" + names(m.face_properties) + ")");
  s += fmt::format("  attributes             {}\n", attrs.empty() ? "none" : attrs);
  s += fmt::format("  edges                  {}\n", m.topology.edges);
  s += fmt::format("  boundary edges         {}\n", m.topology.boundary_edges);
  s += fmt::format("  non-manifold edges     {}\n", m.topology.non_manifold_edges);
  s += fmt::format("  non-manifold vertices  {}\n", m.topology.non_manifold_vertices);
  s += fmt::format("  inconsistent winding   {} edges\n", m.topology.inconsistent_edges);
  s += fmt::format("  components             {}\n", m.components);
  // NaN/Inf faces named only when there are some, so the parts always sum to the total.
  const std::string nonfinite_faces =
      m.degenerate.non_finite > 0 ? fmt::format(", {} NaN/Inf", m.degenerate.non_finite) : std::string();
  s += fmt::format("  degenerate faces       {} ({} repeated index, {} zero area{})\n", m.degenerate.count(),
                   m.degenerate.repeated_index, m.degenerate.zero_area + m.degenerate.too_few_corners, nonfinite_faces);
  s += fmt::format("  unreferenced vertices  {}\n", m.unreferenced_vertices);
  s += fmt::format("  NaN/Inf                {} vertices{}, {} attribute values\n", m.nonfinite_vertices,
                   m.nonfinite_unreferenced_vertices > 0
                       ? fmt::format(" ({} used by no face: `shadetool repair --remove-unreferenced` removes them)",
                                     m.nonfinite_unreferenced_vertices)
                       : std::string(),
                   m.nonfinite_values);
  s += fmt::format("  closed manifold        {}\n", m.closed_manifold() ? "yes" : "no");
  return s;
}

RegisterCommand reg("info", HelpSection::Inspect, [](CLI::App& app) -> std::function<int()> {
  auto options = std::make_shared<IoOptions>();  // bound to the flags, read by the run function
  IoOptions& io = *options;
  auto* sub = app.add_subcommand("info", "Print counts, bounding box, attributes and defects of meshes");
  add_io_options(*sub, io, OutputKind::Report);
  return [options] {
    const IoOptions& io = *options;
    return run_command(
        "info", io,
        [&io](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
          std::string format;
          if (r.gltf_document) format = r.gltf_document->was_binary ? "glb" : "gltf";
          else if (!io.input_format.empty()) format = io.input_format;
          else format = shadetool::format_extension(shadetool::format_from_extension(input));
          for (auto& c : format) c = char(std::toupper(static_cast<unsigned char>(c)));
          MeshInfo m = shadetool::info::mesh_info(mesh);
          // Colour values the reader read as NaN/Inf (and whitened, with a note) are the file's.
          if (r.stats.contains("nonfinite_colour_values_read")) m.nonfinite_values += r.stats["nonfinite_colour_values_read"].get<std::size_t>();
          // A glTF primitive's TEXCOORD_n pass through beside its mesh: it has texture coordinates.
          std::string texcoord_sets;
          if (r.gltf)
            for (const auto& a : r.gltf->attributes)
              if (a.rfind("TEXCOORD_", 0) == 0) texcoord_sets += (texcoord_sets.empty() ? "" : " ") + a;
          if (!texcoord_sets.empty()) m.texcoords = true;
          r.stats = info_json(m, format);
          r.text = info_text(m, input, format, texcoord_sets);
          if (r.gltf) {  // what the primitive holds beyond the mesh (passed through by every command)
            std::string attrs;
            for (const auto& a : r.gltf->attributes) attrs += (attrs.empty() ? "" : " ") + a;
            const char* mode = r.gltf->mode == 5 ? "TRIANGLE_STRIP" : r.gltf->mode == 6 ? "TRIANGLE_FAN" : "TRIANGLES";
            r.text += fmt::format("  glTF                   {}; {}; {} morph targets\n", mode, attrs, r.gltf->targets.size());
            r.stats["gltf_attributes"] = r.gltf->attributes;
            r.stats["gltf_mode"] = mode;
            r.stats["gltf_morph_targets"] = r.gltf->targets.size();
          }
        },
        OutputKind::Report);
  };
});

}  // namespace
}  // namespace shadetool_cli
