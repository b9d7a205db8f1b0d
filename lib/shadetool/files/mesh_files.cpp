// mesh_files.cpp: format names and dispatch through the format table (format_table.h), atomic output.
#include <shadetool/files/mesh_files.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include <shadetool/core/error.h>
#include <shadetool/core/unit_normals.h>
#include <shadetool/io/atomic_write.h>
#include <shadetool/io/file_bytes.h>
#include <shadetool/files/format_table.h>

namespace shadetool {

namespace {

std::string format_upper_name(const FormatEntry& format) {
  std::string s = format.name;
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

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

namespace {

// Colours read with a NaN or infinite value (float-typed colours can hold them: OBJ
// `v x y z nan nan nan`, PLY float red green blue): no writer can encode one, and such a colour is
// no colour, so each such row is read as white, what the readers give a vertex without a colour
// (OBJ), and counted in a note (trimesh reads the file too; before, every command that writes
// colours refused it). Colours a command computes are not touched: a NaN there is refused when
// written (check_writable), as it is a computation's failure.
void whiten_nonfinite_colors(Mesh& mesh, ReadInfo& info) {
  if (!mesh.colors_are_float) return;
  const std::size_t k = std::size_t(std::max(mesh.color_channels, 1));
  auto whiten = [k, &info](std::vector<float>& colors) {
    std::size_t rows = 0;
    for (std::size_t r = 0; r + k <= colors.size(); r += k) {
      std::size_t bad = 0;
      for (std::size_t j = 0; j < k; ++j) bad += !std::isfinite(colors[r + j]);
      if (bad == 0) continue;
      info.nonfinite_color_values += bad;
      std::fill_n(colors.begin() + std::ptrdiff_t(r), k, 1.0f);
      ++rows;
    }
    return rows;
  };
  const std::size_t v = whiten(mesh.vertex_colors), f = whiten(mesh.face_colors);
  if (v + f == 0) return;
  auto rows = [](std::size_t n, const char* what) {
    return n == 0 ? std::string() : std::to_string(n) + " " + what + (n == 1 ? " colour" : " colours");
  };
  info.notes.push_back(rows(v, "vertex") + (v && f ? " and " : "") + rows(f, "face") +
                       " with a NaN or infinite value: read as white, the colour of a vertex without one");
}

}  // namespace

Mesh read_mesh_from_memory(std::string_view bytes, Format format, const std::string& name, ReadInfo* info) {
  ReadInfo local;
  ReadInfo& ri = info ? *info : local;
  if (format == Format::Auto) format = format_from_extension(name);
  ri.format = format;
  if (bytes.empty()) fail(name, 0, "file is empty");
  if (format == Format::Auto) fail(name, 0, "no mesh format given");
  const FormatEntry& entry = format_entry(format);
  report_begin(ri.progress.sink(), "reading", entry.reports_progress ? bytes.size() : 0);
  Mesh mesh = entry.read(bytes, name, ri);
  if (entry.reports_progress) ri.progress.at(bytes.size());
  // A file with content that yields no vertex is not an empty mesh but a file we could not read.
  if (mesh.num_vertices() == 0) fail(name, 0, "no vertex in the file: nothing to read as a mesh");
  whiten_nonfinite_colors(mesh, ri);
  return mesh;
}

Mesh read_mesh(const std::string& path, Format format, ReadInfo* info) {
  // The format is settled before the file is opened: a bad extension is reported as such.
  if (format == Format::Auto) format = format_from_extension(path);
  const io::FileBytes bytes = io::read_file_bytes(path);
  return read_mesh_from_memory(bytes.view(), format, path, info);
}

namespace {

bool finite3(const double* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// Counts the rows of a flat N*3 array that are zero or not finite.
std::size_t unusable_normals(const std::vector<double>& a) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < a.size(); i += 3)
    n += !finite3(&a[i]) || (a[i] == 0 && a[i + 1] == 0 && a[i + 2] == 0);
  return n;
}

bool beyond_float(double x) { return std::fabs(x) > double(std::numeric_limits<float>::max()); }

bool has_off_unit_normals(const Mesh& mesh) {
  return any_off_unit_normal(mesh.vertex_normals) || any_off_unit_normal(mesh.corner_normals) ||
         any_off_unit_normal(mesh.face_normals);
}

// What no writer writes (see mesh_files.h). Returns true when a float-typed binary output must widen
// to double to hold the values (binary PLY), after refusing what cannot be written at all.
bool check_writable(const Mesh& mesh, const FormatEntry& format, const WriteOptions& options, const std::string& name) {
  std::size_t bad_positions = 0;
  bool overflow = false;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    bad_positions += !std::isfinite(mesh.positions[i]);
    overflow = overflow || beyond_float(mesh.positions[i]);
  }
  if (bad_positions > 0)
    fail(name, 0, std::to_string(bad_positions) + " coordinates are NaN or infinite: no writer writes them (nothing written)");
  std::size_t bad_normals = 0;
  if (options.refuse_unusable_normals) {
    if (format.holds.vertex_normals != Holds::No) bad_normals += unusable_normals(mesh.vertex_normals);
    if (format.holds.corner_normals != Holds::No) bad_normals += unusable_normals(mesh.corner_normals);
    if (format.holds.face_normals != Holds::No && options.format != Format::Stl) bad_normals += unusable_normals(mesh.face_normals);
  }
  if (bad_normals > 0)
    fail(name, 0, std::to_string(bad_normals) + (bad_normals == 1 ? " normal is" : " normals are") +
                      " zero, NaN or infinite: no writer writes them (nothing written; `shadetool repair` or "
                      "`shadetool normals --recompute` replaces them)");
  if (format.holds.texcoords != Holds::No)
    for (double t : mesh.texcoords) {
      if (!std::isfinite(t)) fail(name, 0, "a texture coordinate is NaN or infinite: no writer writes it (nothing written)");
      overflow = overflow || beyond_float(t);
    }
  if (mesh.colors_are_float)
    for (const auto* a : {&mesh.vertex_colors, &mesh.face_colors})
      for (float c : *a)
        if (!std::isfinite(c)) fail(name, 0, "a colour value is NaN or infinite: no writer writes it (nothing written)");
  if (!overflow || !options.binary || !format.has_binary_form) return false;
  if (options.format == Format::Stl)  // binary STL is float whatever the mesh's precision
    fail(name, 0, "a coordinate is beyond the range of float (|x| > 3.4e38), the only number type of binary STL: "
                  "nothing written (write --ascii, or PLY, which takes double)");
  return mesh.precision == ValuePrecision::Float;  // binary PLY: double properties hold it
}

}  // namespace

io::ProduceBytes prepare_mesh_write(const Mesh& mesh, const WriteOptions& options, WriteInfo* info) {
  const std::string name = options.name.empty() ? std::string("<output>") : options.name;
  if (options.format == Format::Auto) fail(name, 0, "no output format given");
  const FormatEntry& format = format_entry(options.format);
  const bool widen = check_writable(mesh, format, options, name);
  const bool unit = has_off_unit_normals(mesh);
  return [&mesh, &format, options, info, widen, unit](io::ByteSink& out) {
    WriteInfo local;
    WriteInfo& wi = info ? *info : local;
    if (widen || unit) {
      Mesh copy = mesh;
      if (unit) {
        // Normals are directions: a reader (glTF requires it: its validator's
        // ACCESSOR_VECTOR3_NON_UNIT) and a fixed-function renderer take their length as given.
        OffUnitNormals found;
        for (auto* a : {&copy.vertex_normals, &copy.corner_normals, &copy.face_normals}) normalise_off_unit_normals(*a, found);
        wi.notes.push_back(off_unit_normals_note(found));
      }
      // A float-typed binary file cannot hold the values: the wider type (PLY: double properties).
      if (widen) copy.precision = ValuePrecision::Double;
      format.write(copy, options, out, wi);
      if (widen) wi.notes.push_back("values beyond the range of float: written as double");
    } else {
      format.write(mesh, options, out, wi);
    }
    if (mesh.has_groups() && format.holds.groups == Holds::No) {
      std::size_t lines = 0;
      for (const std::string& run : mesh.group_statements) lines += std::size_t(std::count(run.begin(), run.end(), '\n'));
      wi.notes.push_back("materials and groups not written (" + std::to_string(lines) +
                         " mtllib/usemtl/g/o/s lines): " + format_upper_name(format) + " holds none");
    }
    if (format.holds.quality == Holds::No && (mesh.has_vertex_quality() || mesh.has_face_quality()))
      wi.notes.push_back("quality (per-vertex / per-face scalar) not written: only PLY holds it");
    if (format.holds.properties == Holds::No && (!mesh.vertex_properties.empty() || !mesh.face_properties.empty())) {
      std::string names;
      for (const auto* list : {&mesh.vertex_properties, &mesh.face_properties})
        for (const MeshProperty& p : *list) names += (names.empty() ? "" : ", ") + p.name;
      wi.notes.push_back("vertex/face properties not written (" + names + "): only PLY holds them");
    }
    if (format.holds.comments == Holds::No && !mesh.comments.empty())
      wi.notes.push_back(std::to_string(mesh.comments.size()) + " comment line" + (mesh.comments.size() == 1 ? "" : "s") +
                         " not written (first: '" + mesh.comments[0].substr(0, 60) + "'): " + format_upper_name(format) +
                         " holds none");
  };
}

void write_mesh_to_sink(const Mesh& mesh, const WriteOptions& options, io::ByteSink& sink, WriteInfo* info) {
  prepare_mesh_write(mesh, options, info)(sink);
}

std::string write_mesh_to_memory(const Mesh& mesh, const WriteOptions& options, WriteInfo* info) {
  const io::ProduceBytes produce = prepare_mesh_write(mesh, options, info);
  std::string out;
  io::StringSink sink(out);
  produce(sink);
  sink.flush();
  return out;
}

Format output_format(const std::string& path, Format given) {
  if (given != Format::Auto) return given;
  if (path == "-") fail("stdout", 0, "writing stdout needs a format (--format)");
  return format_from_extension(path);
}

void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options, WriteInfo* info) {
  WriteOptions o = options;
  o.format = output_format(path, o.format);
  if (o.name.empty()) o.name = path;
  io::write_file_atomically(path, prepare_mesh_write(mesh, o, info));
}

}  // namespace shadetool
