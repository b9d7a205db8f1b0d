// mesh_io.cpp: format names, dispatch to the per-format readers and writers, atomic output.
#include <shadetool/io/mesh_io.h>

#include <algorithm>
#include <cctype>

#include <shadetool/core/error.h>
#include <shadetool/io/atomic_write.h>
#include <shadetool/io/file_bytes.h>
#include <shadetool/io/obj_format.h>
#include <shadetool/io/off_format.h>
#include <shadetool/io/ply_format.h>
#include <shadetool/io/stl_format.h>

namespace shadetool {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool name_to_format(const std::string& name, Format& f) {
  const std::string n = lower(name);
  if (n == "obj") f = Format::Obj;
  else if (n == "ply") f = Format::Ply;
  else if (n == "off") f = Format::Off;
  else if (n == "stl") f = Format::Stl;
  else return false;
  return true;
}

}  // namespace

Format parse_format_name(const std::string& name, const std::string& what) {
  Format f;
  if (!name_to_format(name, f)) fail(what, 0, "unknown mesh format '" + name + "' (expected obj, ply, off or stl)");
  return f;
}

Format format_from_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    fail(path, 0, "no file extension to tell the mesh format (expected .obj, .ply, .off or .stl)");
  const std::string ext = path.substr(dot + 1);
  Format f;
  if (!name_to_format(ext, f)) fail(path, 0, "unknown mesh format '" + ext + "' (expected .obj, .ply, .off or .stl)");
  return f;
}

const char* format_extension(Format format) {
  switch (format) {
    case Format::Obj: return "obj";
    case Format::Ply: return "ply";
    case Format::Off: return "off";
    case Format::Stl: return "stl";
    case Format::Auto: break;
  }
  return "";
}

Mesh read_mesh_from_memory(std::string_view bytes, Format format, const std::string& name, ReadInfo* info) {
  ReadInfo local;
  ReadInfo& ri = info ? *info : local;
  if (format == Format::Auto) format = format_from_extension(name);
  ri.format = format;
  if (bytes.empty()) fail(name, 0, "file is empty");
  switch (format) {
    case Format::Obj: return io::read_obj(bytes, name, ri);
    case Format::Ply: return io::read_ply(bytes, name, ri);
    case Format::Off: return io::read_off(bytes, name, ri);
    case Format::Stl: return io::read_stl(bytes, name, ri);
    case Format::Auto: break;
  }
  fail(name, 0, "no mesh format given");
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
  std::string out;
  switch (options.format) {
    case Format::Obj: io::write_obj(mesh, out, wi); break;
    case Format::Ply: io::write_ply(mesh, options.binary, out, wi); break;
    case Format::Off: io::write_off(mesh, out, wi); break;
    case Format::Stl: io::write_stl(mesh, options.binary, out, wi); break;
    case Format::Auto: fail("<output>", 0, "no output format given");
  }
  if (options.format != Format::Ply && (mesh.has_vertex_quality() || mesh.has_face_quality()))
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
