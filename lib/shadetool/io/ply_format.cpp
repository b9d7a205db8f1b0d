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
#include <shadetool/io/split_corner_normals.h>

namespace shadetool::io {

Mesh read_ply(std::string_view bytes, const std::string& name, ReadInfo& info) {
  ply::PlyHeader header = ply::parse_ply_header(bytes, name, info);             // elements, types
  const ply::PlyLayout layout = ply::map_ply_properties(header.elements, name);  // which array each goes to
  Mesh mesh = ply::read_ply_body(bytes, header, layout, name, info);            // the values
  mesh.comments = std::move(header.comments);
  return mesh;
}

// ---- writer

namespace {

template <class T>
void put(std::string& out, T v) {
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
void put_extra(std::string& out, double v, ply::Type t, bool binary) {
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

}  // namespace

void write_ply(const Mesh& input, bool binary, std::string& out, WriteInfo& info) {
  Mesh split;
  const Mesh& mesh = with_corner_normals_split(input, split, info.split_vertices);

  const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  const bool dbl = mesh.precision == ValuePrecision::Double;
  const char* real = dbl ? "double" : "float";
  const bool vnormals = mesh.has_vertex_normals();
  const int ch = mesh.color_channels;
  const bool vcolors = mesh.has_vertex_colors();
  const bool fcolors = mesh.has_face_colors();
  const bool fnormals = mesh.has_face_normals();
  const bool cfloat = mesh.colors_are_float;
  const bool wedge = mesh.has_texcoords();
  // Quality (one float per vertex / face) is written when it has one value per element; a step
  // that changed the element count without carrying it leaves it out, with a note.
  const bool vquality = mesh.has_vertex_quality() && mesh.vertex_quality.size() == nv;
  const bool fquality = mesh.has_face_quality() && mesh.face_quality.size() == nf;
  if (mesh.has_vertex_quality() && !vquality)
    info.notes.push_back("vertex quality not written: " + std::to_string(mesh.vertex_quality.size()) + " values for " +
                         std::to_string(nv) + " vertices");
  if (mesh.has_face_quality() && !fquality)
    info.notes.push_back("face quality not written: " + std::to_string(mesh.face_quality.size()) + " values for " +
                         std::to_string(nf) + " faces");
  // Extra properties (scanners' confidence, intensity, flags ...) after the known ones, as declared.
  std::vector<std::string> vtaken = {"x", "y", "z"}, ftaken = {"vertex_indices"};
  if (vnormals) vtaken.insert(vtaken.end(), {"nx", "ny", "nz"});
  static const char* cnames[] = {"red", "green", "blue", "alpha"};  // the colour properties written below
  if (vcolors) vtaken.insert(vtaken.end(), cnames, cnames + ch);
  if (vquality) vtaken.push_back("quality");
  if (wedge) ftaken.push_back("texcoord");
  if (fnormals) ftaken.insert(ftaken.end(), {"nx", "ny", "nz"});
  if (fcolors) ftaken.insert(ftaken.end(), cnames, cnames + ch);
  if (fquality) ftaken.push_back("quality");
  const std::vector<ExtraOut> vextras = extras_to_write(mesh.vertex_properties, nv, "vertex", vtaken, info);
  const std::vector<ExtraOut> fextras = extras_to_write(mesh.face_properties, nf, "face", ftaken, info);
  std::size_t vextra_bytes = 0, fextra_bytes = 0;
  for (const ExtraOut& e : vextras) vextra_bytes += ply::type_size(e.type);
  for (const ExtraOut& e : fextras) fextra_bytes += ply::type_size(e.type);
  std::uint32_t max_size = 0;
  for (std::size_t f = 0; f < nf; ++f) max_size = std::max<std::uint32_t>(max_size, std::uint32_t(mesh.face_size(f)));
  const bool uchar_count = max_size <= 255;
  const bool int_index = nv <= std::size_t(std::numeric_limits<std::int32_t>::max());
  if (wedge && mesh.texcoord_dims != 2) info.notes.push_back("texture coordinates: only u v written to PLY");
  std::size_t corners_without_tex = 0;
  if (wedge)
    for (std::uint32_t t : mesh.corner_texcoord_index) corners_without_tex += t == kNoTexcoord;
  if (corners_without_tex > 0)
    info.notes.push_back("texture coordinates: " + std::to_string(corners_without_tex) +
                         " face corners had none and are written as (0, 0): PLY's texcoord list holds one per corner");

  // Every byte counted, so the string never doubles and copies (a doubling held old and new
  // blocks at once: the peak of `occlusion` on 1M triangles, bench/visibility/results.md).
  const std::size_t real_bytes = dbl ? 8 : 4, color_bytes = std::size_t(ch) * (cfloat ? 4 : 1);
  out.reserve(out.size() + 300 + 40 * (vextras.size() + fextras.size()) +
              nv * (real_bytes * (vnormals ? 6 : 3) + (vcolors ? color_bytes : 0) + (vquality ? 4 : 0) + vextra_bytes) +
              mesh.num_corners() * 4 +
              nf * (1 + (fnormals ? 3 * real_bytes : 0) + (fcolors ? color_bytes : 0) + (fquality ? 4 : 0) + fextra_bytes));
  out += "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by shadetool\n";
  for (const std::string& c : mesh.comments)  // the input's comment and obj_info lines (MeshLab's TextureFile ...)
    if (c != "comment written by shadetool" && c.find('\n') == std::string::npos && c.find('\r') == std::string::npos) out += c + "\n";
  out += "element vertex ";
  append_uint(out, nv);
  out += '\n';
  for (const char* n : {"x", "y", "z"}) out += std::string("property ") + real + " " + n + "\n";
  if (vnormals)
    for (const char* n : {"nx", "ny", "nz"}) out += std::string("property ") + real + " " + n + "\n";
  const char* ctype = cfloat ? "float" : "uchar";
  if (vcolors)
    for (int k = 0; k < ch; ++k) out += std::string("property ") + ctype + " " + cnames[k] + "\n";
  if (vquality) out += "property float quality\n";
  for (const ExtraOut& e : vextras) out += std::string("property ") + ply::type_name(e.type) + " " + mesh.vertex_properties[e.index].name + "\n";
  out += "element face ";
  append_uint(out, nf);
  out += "\nproperty list ";
  out += uchar_count ? "uchar " : "int ";
  out += int_index ? "int" : "uint";
  out += " vertex_indices\n";
  if (wedge) out += std::string("property list ") + (uchar_count ? "uchar " : "int ") + real + " texcoord\n";
  if (fnormals)
    for (const char* n : {"nx", "ny", "nz"}) out += std::string("property ") + real + " " + n + "\n";
  if (fcolors)
    for (int k = 0; k < ch; ++k) out += std::string("property ") + ctype + " " + cnames[k] + "\n";
  if (fquality) out += "property float quality\n";
  for (const ExtraOut& e : fextras) out += std::string("property ") + ply::type_name(e.type) + " " + mesh.face_properties[e.index].name + "\n";
  out += "end_header\n";

  auto real_value = [&](double v, bool first) {
    if (binary) {
      if (dbl) put<double>(out, v);
      else put<float>(out, float(v));
    } else {
      if (!first) out += ' ';
      append_shortest(out, v);
    }
  };
  auto color_value = [&](float c) {
    if (binary) {
      if (cfloat) put<float>(out, c);
      else out += char(color_to_uchar(c));
    } else {
      out += ' ';
      if (cfloat) append_shortest_float(out, c);
      else append_uint(out, color_to_uchar(c));
    }
  };
  auto quality_value = [&](float q) {
    if (binary) {
      put<float>(out, q);
    } else {
      out += ' ';
      append_shortest_float(out, q);
    }
  };
  auto count_value = [&](std::uint32_t k) {
    if (binary) {
      if (uchar_count) out += char(std::uint8_t(k));
      else put<std::int32_t>(out, std::int32_t(k));
    } else {
      append_uint(out, k);
    }
  };

  for (std::size_t v = 0; v < nv; ++v) {
    real_value(mesh.positions[3 * v], true);
    real_value(mesh.positions[3 * v + 1], false);
    real_value(mesh.positions[3 * v + 2], false);
    if (vnormals)
      for (int k = 0; k < 3; ++k) real_value(mesh.vertex_normals[3 * v + std::size_t(k)], false);
    if (vcolors)
      for (int k = 0; k < ch; ++k) color_value(mesh.vertex_colors[std::size_t(ch) * v + std::size_t(k)]);
    if (vquality) quality_value(mesh.vertex_quality[v]);
    for (const ExtraOut& e : vextras) put_extra(out, mesh.vertex_properties[e.index].values[v], e.type, binary);
    if (!binary) out += '\n';
  }
  const std::size_t td = std::size_t(mesh.texcoord_dims);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    count_value(e - b);
    for (std::uint32_t c = b; c < e; ++c) {
      if (binary) {
        if (int_index) put<std::int32_t>(out, std::int32_t(mesh.corner_vertex[c]));
        else put<std::uint32_t>(out, mesh.corner_vertex[c]);
      } else {
        out += ' ';
        append_uint(out, mesh.corner_vertex[c]);
      }
    }
    if (wedge) {
      if (!binary) out += ' ';
      count_value(2 * (e - b));
      for (std::uint32_t c = b; c < e; ++c) {
        if (mesh.corner_texcoord_index[c] == kNoTexcoord) {
          real_value(0.0, false);
          real_value(0.0, false);
          continue;
        }
        const std::size_t t = std::size_t(mesh.corner_texcoord_index[c]) * td;
        real_value(mesh.texcoords[t], false);
        real_value(td > 1 ? mesh.texcoords[t + 1] : 0.0, false);
      }
    }
    if (fnormals)
      for (int k = 0; k < 3; ++k) real_value(mesh.face_normals[3 * f + std::size_t(k)], false);
    if (fcolors)
      for (int k = 0; k < ch; ++k) color_value(mesh.face_colors[std::size_t(ch) * f + std::size_t(k)]);
    if (fquality) quality_value(mesh.face_quality[f]);
    for (const ExtraOut& e : fextras) put_extra(out, mesh.face_properties[e.index].values[f], e.type, binary);
    if (!binary) out += '\n';
  }
}

}  // namespace shadetool::io
