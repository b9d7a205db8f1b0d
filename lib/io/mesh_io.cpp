// mesh_io.cpp: format names and dispatch through the format table (format_table.h), atomic output.
#include <shadetool/io/mesh_io.h>

#include <shadetool/core/error.h>
#include <shadetool/io/atomic_write.h>
#include <shadetool/io/file_bytes.h>
#include <shadetool/io/format_table.h>

namespace shadetool {

Format parse_format_name(const std::string& name, const std::string& what) {
  const FormatEntry* e = find_format(name);
  if (!e) fail(what, 0, "unknown mesh format '" + name + "' (expected " + format_list(false) + ")");
  return e->format;
}

Format format_from_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    fail(path, 0, "no file extension to tell the mesh format (expected " + format_list(true) + ")");
  const std::string ext = path.substr(dot + 1);
  const FormatEntry* e = find_format(ext);
  if (!e) fail(path, 0, "unknown mesh format '" + ext + "' (expected " + format_list(true) + ")");
  return e->format;
}

const char* format_extension(Format format) {
  for (const FormatEntry& e : mesh_formats())
    if (e.format == format) return e.extensions.front();
  return "";
}

Mesh read_mesh_from_memory(std::string_view bytes, Format format, const std::string& name, ReadInfo* info) {
  ReadInfo local;
  ReadInfo& ri = info ? *info : local;
  if (format == Format::Auto) format = format_from_extension(name);
  ri.format = format;
  if (bytes.empty()) fail(name, 0, "file is empty");
  if (format == Format::Auto) fail(name, 0, "no mesh format given");
  return format_entry(format).read(bytes, name, ri);
}

Mesh read_mesh(const std::string& path, Format format, ReadInfo* info) {
  // The format is settled before the file is opened: a bad extension is reported as such.
  if (format == Format::Auto) format = format_from_extension(path);
  const io::FileBytes bytes = io::read_file_bytes(path);
  return read_mesh_from_memory(bytes.view(), format, path, info);
}

std::string write_mesh_to_memory(const Mesh& mesh, const WriteOptions& options, WriteInfo* info) {
  WriteInfo local;
  WriteInfo& wi = info ? *info : local;
  if (options.format == Format::Auto) fail("<output>", 0, "no output format given");
  std::string out;
  const FormatEntry& entry = format_entry(options.format);
  entry.write(mesh, options, out, wi);
  if (entry.holds.quality == Holds::No && (mesh.has_vertex_quality() || mesh.has_face_quality()))
    wi.notes.push_back("quality (per-vertex / per-face scalar) not written: only PLY holds it");
  return out;
}

void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options, WriteInfo* info) {
  WriteOptions o = options;
  if (o.format == Format::Auto) {
    if (path == "-") fail("stdout", 0, "writing stdout needs a format (--format)");
    o.format = format_from_extension(path);
  }
  const std::string bytes = write_mesh_to_memory(mesh, o, info);
  io::write_file_atomically(path, bytes);
}

}  // namespace shadetool
