// ply_format.cpp: read_ply in three named steps (engine/ply_header, engine/ply_properties,
// engine/ply_body), and the writer.
#include <shadetool/io/ply_format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/io/engine/ply_body.h>
#include <shadetool/io/engine/ply_header.h>
#include <shadetool/io/engine/ply_properties.h>
#include <shadetool/io/engine/ply_types.h>
#include <shadetool/io/engine/number_text.h>
#include <shadetool/io/engine/text_encoding.h>
#include <shadetool/io/split_corner_normals.h>

namespace shadetool::io {

Mesh read_ply(std::string_view file_bytes, const std::string& name, ReadInfo& info) {
  ply::PlyHeader header = ply::parse_ply_header(file_bytes, name, info);        // elements, types
  // An ascii file whose lines end in a lone CR is read with its line ends as LF, so that its body's
  // lines (and the line numbers in messages) are the lines an editor shows. Binary bodies are
  // bytes: never rewritten.
  std::string_view bytes = file_bytes;
  const LineEndings as_lf(header.cr_lines && header.encoding == ply::Encoding::Ascii ? file_bytes : std::string_view());
  if (header.cr_lines && header.encoding == ply::Encoding::Ascii) {
    bytes = as_lf.lf();
    ReadInfo again;  // the notes of the header were given by the first reading
    header = ply::parse_ply_header(bytes, name, again);
  }
  const ply::PlyLayout layout = ply::map_ply_properties(header.elements, name);  // which array each goes to
  Mesh mesh = ply::read_ply_body(bytes, header, layout, name, info);            // the values
  mesh.comments = std::move(header.comments);
  return mesh;
}

// ---- writer

namespace {

template <class T>
void put(ByteSink& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof v);
  if (!ply::host_is_little()) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// An extra property (Mesh::vertex_properties / face_properties) the writer gives back: its index,
// and its declared type (parsed; an unknown name is written as double).
struct ExtraOut {
  std::size_t index;
  ply::Type type;
};

// Which extra properties are written: one value per element, and a name that none of the
// properties the writer already declares uses (else a note names it).
std::vector<ExtraOut> extras_to_write(const std::vector<MeshProperty>& props, std::size_t count, const char* element,
                                      const std::vector<std::string>& taken, WriteInfo& info) {
  std::vector<ExtraOut> out;
  for (std::size_t k = 0; k < props.size(); ++k) {
    const MeshProperty& p = props[k];
    if (p.values.size() != count) {
      info.notes.push_back(std::string(element) + " property '" + p.name + "' not written: " + std::to_string(p.values.size()) +
                           " values for " + std::to_string(count) + " " + element + (count == 1 ? "" : "s"));
      continue;
    }
    bool clash = std::find(taken.begin(), taken.end(), p.name) != taken.end();
    for (const ExtraOut& e : out) clash = clash || props[e.index].name == p.name;
    if (clash) {
      info.notes.push_back(std::string(element) + " property '" + p.name + "' not written: the output already has a property of that name");
      continue;
    }
    ply::Type t = ply::Type::Float64;
    ply::parse_type(p.type, t);
    out.push_back({k, t});
  }
  return out;
}

// One value of an extra property in its declared type: integers as integers (the values were read
// from that type, so they are in range; anything else is rounded and clamped to it).
void put_extra(ByteSink& out, double v, ply::Type t, bool binary) {
  auto integer = [&](double lo, double hi) { return std::isfinite(v) ? std::fmin(hi, std::fmax(lo, std::nearbyint(v))) : 0.0; };
  if (!binary) out += ' ';
  switch (t) {
    case ply::Type::Int8: { const auto x = std::int8_t(integer(-128, 127)); if (binary) put(out, x); else append_int(out, x); return; }
    case ply::Type::UInt8: { const auto x = std::uint8_t(integer(0, 255)); if (binary) put(out, x); else append_uint(out, x); return; }
    case ply::Type::Int16: { const auto x = std::int16_t(integer(-32768, 32767)); if (binary) put(out, x); else append_int(out, x); return; }
    case ply::Type::UInt16: { const auto x = std::uint16_t(integer(0, 65535)); if (binary) put(out, x); else append_uint(out, x); return; }
    case ply::Type::Int32: { const auto x = std::int32_t(integer(-2147483648.0, 2147483647.0)); if (binary) put(out, x); else append_int(out, x); return; }
    case ply::Type::UInt32: { const auto x = std::uint32_t(integer(0, 4294967295.0)); if (binary) put(out, x); else append_uint(out, x); return; }
    case ply::Type::Float32: { const float x = float(v); if (binary) put(out, x); else append_shortest_float(out, x); return; }
    case ply::Type::Float64: if (binary) put(out, v); else append_shortest(out, v); return;
  }
}

// Per-vertex u v (2 per vertex) when every corner of each vertex has the same coordinates, so
// that they can be written per vertex without splitting one; false when a vertex's corners
// disagree or a corner has none. Vertices no face uses keep the value of the pool entry with
// their index when the pool is one entry per vertex (as the PLY reader builds it), else (0, 0).
bool per_vertex_texcoords(const Mesh& mesh, std::vector<double>& uv) {
  const std::size_t nv = mesh.num_vertices(), td = std::size_t(mesh.texcoord_dims);
  if (td == 0) return false;
  uv.assign(2 * nv, 0.0);
  if (mesh.texcoords.size() == nv * td)
    for (std::size_t v = 0; v < nv; ++v) {
      uv[2 * v] = mesh.texcoords[v * td];
      uv[2 * v + 1] = td > 1 ? mesh.texcoords[v * td + 1] : 0.0;
    }
  std::vector<char> seen(nv, 0);
  for (std::size_t c = 0; c < mesh.corner_texcoord_index.size(); ++c) {
    const std::uint32_t t = mesh.corner_texcoord_index[c], v = mesh.corner_vertex[c];
    if (t == kNoTexcoord || v >= nv) return false;
    const double u = mesh.texcoords[std::size_t(t) * td], w = td > 1 ? mesh.texcoords[std::size_t(t) * td + 1] : 0.0;
    if (!seen[v]) {
      seen[v] = 1;
      uv[2 * v] = u;
      uv[2 * v + 1] = w;
    } else if (!(uv[2 * v] == u && uv[2 * v + 1] == w) &&
               !(std::isnan(uv[2 * v]) && std::isnan(u)) && !(std::isnan(uv[2 * v + 1]) && std::isnan(w))) {
      return false;
    }
  }
  return true;
}

// What the writer writes: decided once, before any byte (step 1 of write_ply).
struct PlyPlan {
  std::size_t nv = 0, nf = 0;
  bool binary = true, dbl = false;
  const char* real = "float";
  bool vnormals = false, vcolors = false, fcolors = false, fnormals = false, cfloat = false;
  int ch = 3;
  bool wedge = false;       // per-corner `texcoord` list
  bool vtex = false;        // per-vertex u v under the input's names (vertex_uv)
  std::vector<double> vertex_uv;
  bool vquality = false, fquality = false;
  std::vector<ExtraOut> vextras, fextras;
  bool uchar_count = true, int_index = true;
};

const char* const kColorNames[] = {"red", "green", "blue", "alpha"};  // the colour properties written

// Step 1, plan and validate: which properties, types and counts; a note for each thing left out.
PlyPlan plan_ply(const Mesh& mesh, bool binary, WriteInfo& info) {
  PlyPlan p;
  p.nv = mesh.num_vertices();
  p.nf = mesh.num_faces();
  p.binary = binary;
  p.dbl = mesh.precision == ValuePrecision::Double;
  p.real = p.dbl ? "double" : "float";
  p.vnormals = mesh.has_vertex_normals();
  p.ch = mesh.color_channels;
  p.vcolors = mesh.has_vertex_colors();
  p.fcolors = mesh.has_face_colors();
  p.fnormals = mesh.has_face_normals();
  p.cfloat = mesh.colors_are_float;
  p.wedge = mesh.has_texcoords();
  // Per-vertex coordinates read per vertex stay per vertex, under their names, when no vertex
  // would need splitting (Blender and MeshLab read them only in that form).
  if (p.wedge && mesh.texcoord_names.size() == 2 && per_vertex_texcoords(mesh, p.vertex_uv)) {
    p.vtex = true;
    p.wedge = false;
  }
  // Quality (one float per vertex / face) is written when it has one value per element; a step
  // that changed the element count without carrying it leaves it out, with a note.
  p.vquality = mesh.has_vertex_quality() && mesh.vertex_quality.size() == p.nv;
  p.fquality = mesh.has_face_quality() && mesh.face_quality.size() == p.nf;
  if (mesh.has_vertex_quality() && !p.vquality)
    info.notes.push_back("vertex quality not written: " + std::to_string(mesh.vertex_quality.size()) + " values for " +
                         std::to_string(p.nv) + " vertices");
  if (mesh.has_face_quality() && !p.fquality)
    info.notes.push_back("face quality not written: " + std::to_string(mesh.face_quality.size()) + " values for " +
                         std::to_string(p.nf) + " faces");
  // Extra properties (scanners' confidence, intensity, flags ...) after the known ones, as declared.
  std::vector<std::string> vtaken = {"x", "y", "z"}, ftaken = {"vertex_indices"};
  if (p.vnormals) vtaken.insert(vtaken.end(), {"nx", "ny", "nz"});
  if (p.vtex) vtaken.insert(vtaken.end(), mesh.texcoord_names.begin(), mesh.texcoord_names.end());
  if (p.vcolors) vtaken.insert(vtaken.end(), kColorNames, kColorNames + p.ch);
  if (p.vquality) vtaken.push_back("quality");
  if (p.wedge) ftaken.push_back("texcoord");
  if (p.fnormals) ftaken.insert(ftaken.end(), {"nx", "ny", "nz"});
  if (p.fcolors) ftaken.insert(ftaken.end(), kColorNames, kColorNames + p.ch);
  if (p.fquality) ftaken.push_back("quality");
  p.vextras = extras_to_write(mesh.vertex_properties, p.nv, "vertex", vtaken, info);
  p.fextras = extras_to_write(mesh.face_properties, p.nf, "face", ftaken, info);
  std::uint32_t max_size = 0;
  for (std::size_t f = 0; f < p.nf; ++f) max_size = std::max<std::uint32_t>(max_size, std::uint32_t(mesh.face_size(f)));
  p.uchar_count = max_size <= 255;
  p.int_index = p.nv <= std::size_t(std::numeric_limits<std::int32_t>::max());
  if ((p.wedge || p.vtex) && mesh.texcoord_dims != 2) info.notes.push_back("texture coordinates: only u v written to PLY");
  std::size_t corners_without_tex = 0;
  if (p.wedge)
    for (std::uint32_t t : mesh.corner_texcoord_index) corners_without_tex += t == kNoTexcoord;
  if (corners_without_tex > 0)
    info.notes.push_back("texture coordinates: " + std::to_string(corners_without_tex) +
                         " face corners had none and are written as (0, 0): PLY's texcoord list holds one per corner");
  return p;
}

// Step 2: the header.
void write_ply_header(const Mesh& mesh, const PlyPlan& p, ByteSink& out) {
  const std::string real = p.real;
  out += "ply\nformat ";
  out += p.binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by shadetool\n";
  for (const std::string& c : mesh.comments)  // the input's comment and obj_info lines (MeshLab's TextureFile ...)
    if (c != "comment written by shadetool" && c.find('\n') == std::string::npos && c.find('\r') == std::string::npos) out += c + "\n";
  out += "element vertex ";
  append_uint(out, p.nv);
  out += '\n';
  for (const char* n : {"x", "y", "z"}) out += "property " + real + " " + n + "\n";
  if (p.vnormals)
    for (const char* n : {"nx", "ny", "nz"}) out += "property " + real + " " + n + "\n";
  if (p.vtex)
    for (const std::string& n : mesh.texcoord_names) out += "property " + real + " " + n + "\n";
  const std::string ctype = p.cfloat ? "float" : "uchar";
  if (p.vcolors)
    for (int k = 0; k < p.ch; ++k) out += "property " + ctype + " " + kColorNames[k] + "\n";
  if (p.vquality) out += "property float quality\n";
  for (const ExtraOut& e : p.vextras) out += std::string("property ") + ply::type_name(e.type) + " " + mesh.vertex_properties[e.index].name + "\n";
  out += "element face ";
  append_uint(out, p.nf);
  out += "\nproperty list ";
  out += p.uchar_count ? "uchar " : "int ";
  out += p.int_index ? "int" : "uint";
  out += " vertex_indices\n";
  if (p.wedge) out += std::string("property list ") + (p.uchar_count ? "uchar " : "int ") + real + " texcoord\n";
  if (p.fnormals)
    for (const char* n : {"nx", "ny", "nz"}) out += "property " + real + " " + n + "\n";
  if (p.fcolors)
    for (int k = 0; k < p.ch; ++k) out += "property " + ctype + " " + kColorNames[k] + "\n";
  if (p.fquality) out += "property float quality\n";
  for (const ExtraOut& e : p.fextras) out += std::string("property ") + ply::type_name(e.type) + " " + mesh.face_properties[e.index].name + "\n";
  out += "end_header\n";
}

// One value at a time, in the plan's encoding and types.
struct PlyValues {
  const PlyPlan& p;
  ByteSink& out;

  void real(double v, bool first) {
    if (p.binary) {
      if (p.dbl) put<double>(out, v);
      else put<float>(out, float(v));
    } else {
      if (!first) out += ' ';
      append_shortest(out, v);
    }
  }
  void color(float c) {
    if (p.binary) {
      if (p.cfloat) put<float>(out, c);
      else out += char(color_to_uchar(c));
    } else {
      out += ' ';
      if (p.cfloat) append_shortest_float(out, c);
      else append_uint(out, color_to_uchar(c));
    }
  }
  void quality(float q) {
    if (p.binary) {
      put<float>(out, q);
    } else {
      out += ' ';
      append_shortest_float(out, q);
    }
  }
  void count(std::uint32_t k) {
    if (p.binary) {
      if (p.uchar_count) out += char(std::uint8_t(k));
      else put<std::int32_t>(out, std::int32_t(k));
    } else {
      append_uint(out, k);
    }
  }
  void index(std::uint32_t v) {
    if (p.binary) {
      if (p.int_index) put<std::int32_t>(out, std::int32_t(v));
      else put<std::uint32_t>(out, v);
    } else {
      out += ' ';
      append_uint(out, v);
    }
  }
};

// Step 3: the vertex records.
void write_ply_vertices(const Mesh& mesh, const PlyPlan& p, PlyValues& w) {
  const std::size_t ch = std::size_t(p.ch);
  for (std::size_t v = 0; v < p.nv; ++v) {
    w.real(mesh.positions[3 * v], true);
    w.real(mesh.positions[3 * v + 1], false);
    w.real(mesh.positions[3 * v + 2], false);
    if (p.vnormals)
      for (std::size_t k = 0; k < 3; ++k) w.real(mesh.vertex_normals[3 * v + k], false);
    if (p.vtex) {
      w.real(p.vertex_uv[2 * v], false);
      w.real(p.vertex_uv[2 * v + 1], false);
    }
    if (p.vcolors)
      for (std::size_t k = 0; k < ch; ++k) w.color(mesh.vertex_colors[ch * v + k]);
    if (p.vquality) w.quality(mesh.vertex_quality[v]);
    for (const ExtraOut& e : p.vextras) put_extra(w.out, mesh.vertex_properties[e.index].values[v], e.type, p.binary);
    if (!p.binary) w.out += '\n';
  }
}

// Step 4: the face records.
void write_ply_faces(const Mesh& mesh, const PlyPlan& p, PlyValues& w) {
  const std::size_t ch = std::size_t(p.ch);
  const std::size_t td = std::size_t(mesh.texcoord_dims);
  for (std::size_t f = 0; f < p.nf; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    w.count(e - b);
    for (std::uint32_t c = b; c < e; ++c) w.index(mesh.corner_vertex[c]);
    if (p.wedge) {
      if (!p.binary) w.out += ' ';
      w.count(2 * (e - b));
      for (std::uint32_t c = b; c < e; ++c) {
        if (mesh.corner_texcoord_index[c] == kNoTexcoord) {
          w.real(0.0, false);
          w.real(0.0, false);
          continue;
        }
        const std::size_t t = std::size_t(mesh.corner_texcoord_index[c]) * td;
        w.real(mesh.texcoords[t], false);
        w.real(td > 1 ? mesh.texcoords[t + 1] : 0.0, false);
      }
    }
    if (p.fnormals)
      for (std::size_t k = 0; k < 3; ++k) w.real(mesh.face_normals[3 * f + k], false);
    if (p.fcolors)
      for (std::size_t k = 0; k < ch; ++k) w.color(mesh.face_colors[ch * f + k]);
    if (p.fquality) w.quality(mesh.face_quality[f]);
    for (const ExtraOut& x : p.fextras) put_extra(w.out, mesh.face_properties[x.index].values[f], x.type, p.binary);
    if (!p.binary) w.out += '\n';
  }
}

}  // namespace

void write_ply(const Mesh& input, bool binary, ByteSink& out, WriteInfo& info) {
  Mesh split;
  const Mesh& mesh = with_corner_normals_split(input, split, info.split_vertices);
  const PlyPlan plan = plan_ply(mesh, binary, info);
  write_ply_header(mesh, plan, out);
  PlyValues values{plan, out};
  write_ply_vertices(mesh, plan, values);
  write_ply_faces(mesh, plan, values);
}

}  // namespace shadetool::io
