// format_table.h: every mesh format shadetool reads and writes, one entry each.
//
// An entry says everything the rest of the program needs to know about a format: its name and
// file extensions, how to recognise its bytes, its reader and writer, whether it has a binary
// and a text form, and which attributes of a Mesh it can hold. Format names in messages, the CLI's
// option checks (--format, --input-format), --output-dir's extension and the notes about what an
// output format leaves out are all derived from this table, so adding a format is one entry here
// (plus its enumerator in io/mesh_io.h's Format).
//
// Inputs/outputs of the functions below:
//   mesh_formats()            the table, in the order formats are listed to users
//   format_entry(Format)      the entry of one format (Format::Auto has none: throws Error)
//   find_format(name)         the entry whose name or one of whose extensions equals `name`,
//                             any case, without a leading dot; nullptr if none
//   format_names()            {"obj", "ply", ...}: what CLI option checks accept
//   format_list(dot)          "obj, ply, off, stl or gltf" (dot: every extension, ".obj, ... or
//                             .glb/.gltf"): for messages
//   holds_any, formats_holding  whether a format can hold a command's result (see below)
//   detect_format(bytes)      the format whose detect() recognises the bytes, else Format::Auto.
//                             Detection is a hint for messages and for callers without a file
//                             name; reading always uses the extension or the format given.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/io/byte_sink.h>
#include <shadetool/io/mesh_io.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// How an output format holds one attribute of a Mesh.
enum class Holds {
  No,         // left out (a note names it)
  Yes,        // written as it is
  Converted,  // written in another form (corner normals as split vertices, face colours as split
              // vertex colours, a per-vertex attribute as per-corner ...); a note may say so
};

// What a format holds, attribute by attribute (as written; readers may accept more forms).
struct FormatAttributes {
  Holds vertex_normals = Holds::No;
  Holds corner_normals = Holds::No;
  Holds face_normals = Holds::No;
  Holds texcoords = Holds::No;
  Holds vertex_colors = Holds::No;
  Holds face_colors = Holds::No;
  Holds groups = Holds::No;  // materials and groups (OBJ mtllib, usemtl, g, o, s)
  Holds quality = Holds::No;  // vertex_quality / face_quality (PLY `quality`)
  Holds properties = Holds::No;  // vertex_properties / face_properties (PLY's other scalars)
  Holds comments = Holds::No;    // Mesh::comments (PLY header lines; OBJ writes them as `#` lines)
};

struct FormatEntry {
  Format format;
  const char* name;                     // lower case, as on the command line: "obj"
  std::vector<const char*> extensions;  // lower case, no dot; the first is what writers name files
  bool (*detect)(std::string_view bytes);
  Mesh (*read)(std::string_view bytes, const std::string& name, ReadInfo& info);
  void (*write)(const Mesh& mesh, const WriteOptions& options, io::ByteSink& out, WriteInfo& info);
  bool has_binary_form;                 // --ascii / --binary choose between two forms
  FormatAttributes holds;
  // The reader tells ReadInfo::progress the bytes it has read as it goes (OBJ, PLY): reading is
  // a stage with a fraction. Otherwise reading shows its name alone (core/progress.h, total 0).
  bool reports_progress = false;
};

// One attribute of FormatAttributes, to name what a command's result is written as (bake-lighting:
// &FormatAttributes::vertex_colors).
using HeldAttribute = Holds FormatAttributes::*;

// True when `holds` holds (as it is, or converted) at least one of `attributes`: a command whose
// result is in `attributes` can write that format. Commands refuse (usage error, before any
// work) an output format for which this is false.
bool holds_any(const FormatAttributes& holds, const std::vector<HeldAttribute>& attributes);
// "obj, ply or off": the formats of the table that hold at least one of `attributes`, for messages.
std::string formats_holding(const std::vector<HeldAttribute>& attributes);

const std::vector<FormatEntry>& mesh_formats();
const FormatEntry& format_entry(Format format);
const FormatEntry* find_format(std::string_view name_or_extension);
std::vector<std::string> format_names();
std::string format_list(bool with_dots);
Format detect_format(std::string_view bytes);

}  // namespace shadetool
#pragma GCC visibility pop
