// format_table.cpp: the table of mesh formats (see format_table.h). One entry per format.
#include <shadetool/files/format_table.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include <shadetool/core/error.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/io/obj_format.h>
#include <shadetool/io/off_format.h>
#include <shadetool/io/ply_format.h>
#include <shadetool/io/stl_format.h>

namespace shadetool {

namespace {

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// The first line that is neither blank nor a comment ('#'), without leading spaces; at most the
// first 4 KiB are looked at.
std::string_view first_content_line(std::string_view bytes) {
  bytes = bytes.substr(0, 4096);
  while (!bytes.empty()) {
    const std::size_t eol = bytes.find_first_of("\r\n");
    std::string_view line = bytes.substr(0, eol);
    bytes = eol == std::string_view::npos ? std::string_view() : bytes.substr(eol + 1);
    const std::size_t b = line.find_first_not_of(" \t");
    if (b == std::string_view::npos || line[b] == '#') continue;
    return line.substr(b);
  }
  return {};
}

bool detect_obj(std::string_view bytes) {
  if (std::memchr(bytes.data(), '\0', std::min<std::size_t>(bytes.size(), 4096))) return false;
  const std::string_view line = first_content_line(bytes);
  const std::string_view keyword = line.substr(0, line.find_first_of(" \t"));
  for (const char* k : {"v", "vn", "vt", "vp", "f", "o", "g", "s", "mtllib", "usemtl", "l", "p"})
    if (keyword == k) return true;
  return false;
}

bool detect_ply(std::string_view bytes) {
  return starts_with(bytes, "ply\n") || starts_with(bytes, "ply\r") || starts_with(bytes, "ply ");
}

bool detect_off(std::string_view bytes) {
  const std::string_view line = first_content_line(bytes);
  const std::string_view keyword = line.substr(0, line.find_first_of(" \t"));
  return keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF" && keyword.size() <= 7;
}

bool detect_stl(std::string_view bytes) {
  if (bytes.size() >= 84) {
    std::uint32_t n = 0;
    for (int k = 3; k >= 0; --k) n = (n << 8) | static_cast<unsigned char>(bytes[80 + std::size_t(k)]);
    if (84 + 50 * std::uint64_t(n) == bytes.size()) return true;
  }
  const std::size_t b = bytes.find_first_not_of(" \t\r\n");
  return b != std::string_view::npos && starts_with(bytes.substr(b), "solid");
}

bool detect_gltf(std::string_view bytes) {
  if (starts_with(bytes, "glTF")) return true;
  const std::size_t b = bytes.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  return b != std::string_view::npos && bytes[b] == '{' && bytes.substr(0, 4096).find("\"asset\"") != std::string_view::npos;
}

// glTF through the table is one Mesh: every triangle primitive placed in world space by the
// scene's nodes (gltf/gltf_scene.h); the CLI keeps the whole document instead (cli/driver.cpp).
Mesh read_gltf_entry(std::string_view bytes, const std::string& name, ReadInfo& info) {
  const GltfDocument doc = read_gltf(bytes, name);
  info.notes.insert(info.notes.end(), doc.notes.begin(), doc.notes.end());  // compressed geometry decoded
  // Points and lines are carried by glTF outputs only (cli/driver.cpp); as one Mesh they are
  // nothing, and "no vertex in the file" (mesh_files.cpp) would be wrong: they have vertices.
  if (doc.primitives.empty() && doc.passed_through_primitives > 0)
    fail(name, 0, "a glTF whose primitives are points or lines only (" + std::to_string(doc.passed_through_primitives) +
                      " POINTS/LINES primitives, " + std::to_string(doc.passed_through_vertices) +
                      " vertices): no triangle to read as a mesh");
  if (doc.primitives.empty())  // no mesh, or triangle primitives without POSITION only (a note names them)
    fail(name, 0, "a glTF with no TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive with positions: nothing to read as a mesh");
  return gltf_world_mesh(doc, info.notes);
}
void write_gltf_entry(const Mesh& mesh, const WriteOptions& options, io::ByteSink& out, WriteInfo& info) {
  GltfWriteResult result;
  GltfDocument doc = gltf_document_from_mesh(mesh);
  doc.unlit_materials = options.gltf_unlit;
  // glTF builds its document in memory (JSON and binary chunk in one string, gltf_write.cpp); the
  // sink takes that string without copying it again (an append longer than its buffer skips it).
  out.append(write_gltf(doc, options.binary && !gltf_name_is_text(options.name), options.name, result));
  info.split_vertices += result.split_vertices;
  for (auto& n : result.notes) info.notes.push_back(n);
}

void write_obj_entry(const Mesh& mesh, const WriteOptions&, io::ByteSink& out, WriteInfo& info) {
  io::write_obj(mesh, out, info);
}
void write_ply_entry(const Mesh& mesh, const WriteOptions& options, io::ByteSink& out, WriteInfo& info) {
  io::write_ply(mesh, options.binary, out, info);
}
void write_off_entry(const Mesh& mesh, const WriteOptions&, io::ByteSink& out, WriteInfo& info) {
  io::write_off(mesh, out, info);
}
void write_stl_entry(const Mesh& mesh, const WriteOptions& options, io::ByteSink& out, WriteInfo& info) {
  io::write_stl(mesh, options.binary, out, info);
}

std::vector<FormatEntry> make_table() {
  std::vector<FormatEntry> t;
  {
    FormatEntry e{Format::Obj, "obj", {"obj"}, detect_obj, io::read_obj, write_obj_entry, false, {}};
    e.holds.vertex_normals = Holds::Converted;  // one vn per vertex, each corner indexes its vertex's
    e.holds.corner_normals = Holds::Yes;   // the vn pool
    e.holds.face_normals = Holds::Converted;    // one vn per face, indexed by the face's corners
    e.holds.texcoords = Holds::Yes;
    e.holds.vertex_colors = Holds::Yes;    // v x y z r g b
    e.holds.face_colors = Holds::Converted;  // vertices split (io/split_face_colors.h)
    e.holds.groups = Holds::Yes;
    e.holds.comments = Holds::Converted;   // `#` lines after the first
    e.reports_progress = true;             // every 65536 lines
    t.push_back(e);
  }
  {
    FormatEntry e{Format::Ply, "ply", {"ply"}, detect_ply, io::read_ply, write_ply_entry, true, {}};
    e.holds.vertex_normals = Holds::Yes;
    e.holds.corner_normals = Holds::Converted;  // vertices split (io/split_corner_normals.h)
    e.holds.face_normals = Holds::Yes;
    e.holds.texcoords = Holds::Yes;             // per-corner list `texcoord`
    e.holds.vertex_colors = Holds::Yes;
    e.holds.face_colors = Holds::Yes;
    e.holds.quality = Holds::Yes;               // float `quality` of vertex and face
    e.holds.properties = Holds::Yes;            // every other scalar, by name and declared type
    e.reports_progress = true;                  // every element
    e.holds.comments = Holds::Yes;              // comment / obj_info header lines
    t.push_back(e);
  }
  {
    FormatEntry e{Format::Off, "off", {"off"}, detect_off, io::read_off, write_off_entry, false, {}};
    e.holds.vertex_normals = Holds::Yes;        // NOFF
    e.holds.corner_normals = Holds::Converted;  // vertices split
    e.holds.vertex_colors = Holds::Yes;         // COFF
    e.holds.face_colors = Holds::Yes;
    t.push_back(e);
  }
  {
    FormatEntry e{Format::Stl, "stl", {"stl"}, detect_stl, io::read_stl, write_stl_entry, true, {}};
    e.holds.face_normals = Holds::Yes;  // facet normals
    t.push_back(e);
  }
  {
    FormatEntry e{Format::Gltf, "gltf", {"glb", "gltf"}, detect_gltf, read_gltf_entry, write_gltf_entry, true, {}};
    e.holds.vertex_normals = Holds::Yes;        // NORMAL
    e.holds.corner_normals = Holds::Converted;  // vertices split
    e.holds.face_normals = Holds::Converted;    // vertices split per face
    e.holds.vertex_colors = Holds::Yes;         // COLOR_0
    e.holds.face_colors = Holds::Converted;     // vertices split per face
    e.holds.texcoords = Holds::Converted;       // TEXCOORD_0, vertices split per texture coordinate, v flipped
    t.push_back(e);
  }
  return t;
}

}  // namespace

const std::vector<FormatEntry>& mesh_formats() {
  static const std::vector<FormatEntry> table = make_table();
  return table;
}

const FormatEntry& format_entry(Format format) {
  for (const FormatEntry& e : mesh_formats())
    if (e.format == format) return e;
  fail("<format>", 0, "no mesh format given");
}

const FormatEntry* find_format(std::string_view name) {
  for (const FormatEntry& e : mesh_formats()) {
    if (equal_ignoring_case(name, e.name)) return &e;
    for (const char* ext : e.extensions)
      if (equal_ignoring_case(name, ext)) return &e;
  }
  return nullptr;
}

std::vector<std::string> format_names() {
  std::vector<std::string> names;
  for (const FormatEntry& e : mesh_formats()) names.emplace_back(e.name);
  return names;
}

std::string format_list(bool with_dots) {
  const auto& t = mesh_formats();
  std::string s;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i > 0) s += i + 1 == t.size() ? " or " : ", ";
    if (!with_dots) {
      s += t[i].name;
      continue;
    }
    for (std::size_t k = 0; k < t[i].extensions.size(); ++k) s += std::string(k ? "/." : ".") + t[i].extensions[k];
  }
  return s;
}

bool holds_any(const FormatAttributes& holds, const std::vector<HeldAttribute>& attributes) {
  for (HeldAttribute a : attributes)
    switch (holds.*a) {
      case Holds::Yes:
      case Holds::Converted:
        return true;
      case Holds::No:
        break;
    }
  return false;
}

std::string formats_holding(const std::vector<HeldAttribute>& attributes) {
  std::vector<const char*> names;
  for (const FormatEntry& e : mesh_formats())
    if (holds_any(e.holds, attributes)) names.push_back(e.name);
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += std::string(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}

Format detect_format(std::string_view bytes) {
  for (const FormatEntry& e : mesh_formats())
    if (e.detect(bytes)) return e.format;
  return Format::Auto;
}

}  // namespace shadetool
