// ply_body.cpp: the PLY body (see ply_body.h).
#include <shadetool/io/engine/ply_body.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/io/engine/text_parse.h>

namespace shadetool::io::ply {

namespace {

// ---- the body reader: one interface over ascii tokens and binary values

// How an ascii body is cut into items. Tokens: an item is its properties' next values, wherever the
// lines break (what the PLY format says). Lines: every item is one line (ply.c, Turk's reference
// reader, reads an ascii item per line and ignores extra words): its values may not run past the
// line's end, and values after its properties on the line are skipped, counted per element.
enum class AsciiItems { Tokens, Lines };

// Items of one element whose line held values beyond the header's properties (line mode).
struct ExtraValues {
  std::string element;
  std::size_t items = 0, first_line = 0;
};

class BodyReader {
 public:
  BodyReader(const char* p, const char* end, Encoding enc, const std::string& name, std::size_t line,
             AsciiItems items = AsciiItems::Tokens)
      : p_(p), end_(end), enc_(enc), swap_(host_is_little() != (enc == Encoding::BinaryLE)), name_(name), line_(line),
        lines_(enc == Encoding::Ascii && items == AsciiItems::Lines) {}

  bool ascii() const { return enc_ == Encoding::Ascii; }
  std::size_t remaining() const { return std::size_t(end_ - p_); }
  std::size_t line() const { return ascii() ? line_ : 0; }
  const char* pos() const { return p_; }
  const char* end() const { return end_; }
  bool swap() const { return swap_; }
  void advance(std::size_t n) { p_ += n; }

  // Where we are, for messages: ascii gives the line; binary names the element and item.
  [[noreturn]] void error(const std::string& what) const { fail(name_, line(), what); }

  double scalar(Type t, const char* what) {
    if (ascii()) {
      skip_value_space(what);
      if (p_ == end_) error(std::string("file ends early, in ") + what);
      double v;
      const char* b = p_;
      if (!parse_double(p_, end_, v)) error(std::string("malformed number '") + token_at(b, end_) + "' in " + what);
      return v;
    }
    const std::size_t s = type_size(t);
    if (remaining() < s) error(std::string("file is truncated: it ends in ") + what);
    const double v = load_as_double(p_, t, swap_);
    p_ += s;
    return v;
  }

  std::int64_t integer(Type t, const char* what) {
    if (ascii()) {
      skip_value_space(what);
      if (p_ == end_) error(std::string("file ends early, in ") + what);
      std::int64_t v;
      const char* b = p_;
      if (!parse_int64(p_, end_, v) || (p_ < end_ && !is_space_or_newline(*p_)))
        error(std::string("malformed integer '") + token_at(b, end_) + "' in " + what);
      return v;
    }
    const std::size_t s = type_size(t);
    if (remaining() < s) error(std::string("file is truncated: it ends in ") + what);
    const std::int64_t v = load_as_int(p_, t, swap_);
    p_ += s;
    return v;
  }

  void skip_ascii_space() {
    while (p_ < end_ && is_space_or_newline(*p_)) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
  }

  // An item starts: in line mode at the next line with a value (blank lines skipped).
  void begin_item() {
    if (lines_) skip_ascii_space();
  }
  // An item ends: in line mode, values left on its line are skipped (counted for `e`).
  void end_item(const Element& e) {
    if (!lines_) return;
    while (p_ < end_ && is_space(*p_)) ++p_;
    if (p_ == end_ || *p_ == '\n') return;
    if (extra_.empty() || extra_.back().element != e.name) extra_.push_back({e.name, 0, line_});
    ++extra_.back().items;
    const void* lf = std::memchr(p_, '\n', std::size_t(end_ - p_));
    p_ = lf ? static_cast<const char*>(lf) : end_;
  }
  const std::vector<ExtraValues>& extra_values() const { return extra_; }

 private:
  // Before a value: spaces and (token mode) line feeds; in line mode a line feed ends the item early.
  void skip_value_space(const char* what) {
    if (!lines_) return skip_ascii_space();
    while (p_ < end_ && is_space(*p_)) ++p_;
    if (p_ < end_ && *p_ == '\n') error(std::string("line ends early, in ") + what);
  }

  const char* p_;
  const char* end_;
  Encoding enc_;
  bool swap_;
  const std::string& name_;
  std::size_t line_;
  bool lines_;                     // ascii, AsciiItems::Lines
  std::vector<ExtraValues> extra_;
};

std::string element_item(const Element& e, std::uint64_t i) {
  return e.name + " " + std::to_string(i) + " of " + std::to_string(e.count);
}

// Smallest number of body bytes one item of `e` can take: bounds header counts by the file size.
std::size_t min_item_bytes(const Element& e, Encoding enc) {
  std::size_t s = 0;
  for (const auto& p : e.props) s += enc == Encoding::Ascii ? 2 : type_size(p.is_list ? p.count_type : p.type);
  return s;
}

// Fast path for binary vertex records of scalars only: the positions of every vertex, at fixed
// offsets, by declared type (float x y z in native order, the common case, without a switch).
// Other kept properties are left to the general loop, which then starts at 0; returns how many
// vertices were read here (all of them, or 0).
std::size_t read_binary_vertices_fast(const Element& e, BodyReader& in, Mesh& mesh) {
  std::size_t record = 0, ox = 0, oy = 0, oz = 0;
  bool only_xyz_float = true;
  for (const auto& p : e.props) {
    if (p.is_list) return 0;
    if (p.target == Target::X) ox = record;
    else if (p.target == Target::Y) oy = record;
    else if (p.target == Target::Z) oz = record;
    else if (p.target != Target::Skip) return 0;
    if (p.target != Target::Skip && p.type != Type::Float32) only_xyz_float = false;
    record += type_size(p.type);
  }
  const std::size_t n = std::size_t(e.count);
  if (n == 0 || n * record > in.remaining()) return 0;  // the general loop reports the truncation
  const char* base = in.pos();
  reserve_bulk(mesh.positions, 3 * n);
  mesh.positions.resize(3 * n);
  double* out = mesh.positions.data();
  if (only_xyz_float && !in.swap()) {
    for (std::size_t i = 0; i < n; ++i, base += record) {
      float x, y, z;
      std::memcpy(&x, base + ox, 4);
      std::memcpy(&y, base + oy, 4);
      std::memcpy(&z, base + oz, 4);
      out[3 * i] = x;
      out[3 * i + 1] = y;
      out[3 * i + 2] = z;
    }
  } else {
    Type tx = Type::Float32, ty = Type::Float32, tz = Type::Float32;
    for (const auto& p : e.props) {
      if (p.target == Target::X) tx = p.type;
      if (p.target == Target::Y) ty = p.type;
      if (p.target == Target::Z) tz = p.type;
    }
    for (std::size_t i = 0; i < n; ++i, base += record) {
      out[3 * i] = load_as_double(base + ox, tx, in.swap());
      out[3 * i + 1] = load_as_double(base + oy, ty, in.swap());
      out[3 * i + 2] = load_as_double(base + oz, tz, in.swap());
    }
  }
  in.advance(n * record);
  return n;
}

// Fast path for binary faces that are only `list uchar int|uint vertex_indices` holding
// triangles: reads until the first face that is not a valid triangle (returns how many it read;
// the general loop goes on from there and reports any error).
std::size_t read_binary_triangles_fast(const Element& e, BodyReader& in, std::uint64_t nv, Mesh& mesh) {
  if (e.props.size() != 1 || e.props[0].target != Target::Indices || e.props[0].count_type != Type::UInt8 ||
      (e.props[0].type != Type::Int32 && e.props[0].type != Type::UInt32))
    return 0;
  const std::size_t n = std::size_t(e.count);
  const bool swap = in.swap();
  const char* p = in.pos();
  const char* const end = in.end();
  const std::size_t fit = std::min<std::size_t>(n, in.remaining() / 13);
  if (mesh.corner_vertex.size() + 3 * fit >= std::numeric_limits<std::uint32_t>::max()) return 0;
  const std::size_t first_corner = mesh.corner_vertex.size(), first_face = mesh.face_start.size();
  reserve_bulk(mesh.corner_vertex, first_corner + 3 * fit);
  reserve_bulk(mesh.face_start, first_face + fit);
  mesh.corner_vertex.resize(first_corner + 3 * fit);
  mesh.face_start.resize(first_face + fit);
  std::uint32_t* cv = mesh.corner_vertex.data() + first_corner;
  std::uint32_t* fs = mesh.face_start.data() + first_face;
  std::size_t f = 0;
  for (; f < fit && end - p >= 13 && p[0] == 3; ++f, p += 13) {
    const std::uint32_t a = load<std::uint32_t>(p + 1, swap), b = load<std::uint32_t>(p + 5, swap),
                        c = load<std::uint32_t>(p + 9, swap);
    if (a >= nv || b >= nv || c >= nv) break;  // (negative int32 indices are huge as uint32)
    cv[3 * f] = a;
    cv[3 * f + 1] = b;
    cv[3 * f + 2] = c;
    fs[f] = std::uint32_t(first_corner + 3 * (f + 1));
  }
  mesh.corner_vertex.resize(first_corner + 3 * f);
  mesh.face_start.resize(first_face + f);
  in.advance(std::size_t(p - in.pos()));
  return f;
}


// The vertex element: positions (fast path for binary scalar records), normals, colours, and
// per-vertex texcoords into `vtexcoords` (u v per vertex; they become per-corner at the end).
// Mesh properties for the element's extra scalars (PlyLayout: Target::Extra), n values each; and
// one note per list property no array takes (skipped).
void start_extras(const Element& e, std::vector<MeshProperty>& out, std::size_t count, std::size_t n, ReadInfo& info) {
  out.resize(count);
  for (const auto& prop : e.props) {
    if (prop.target == Target::Extra) {
      MeshProperty& p = out[std::size_t(prop.extra)];
      p.name = prop.name;
      p.type = type_name(prop.type);
      p.values.assign(n, 0.0);
    } else if (prop.is_list && prop.target == Target::Skip) {
      info.notes.push_back(e.name + " list property '" + prop.name + "' not kept (only scalar properties are)");
    }
  }
}

void read_vertex_element(const Element& e, const PlyLayout& layout, BodyReader& in, Mesh& mesh,
                         std::vector<double>& vtexcoords, const std::string& name, ReadInfo& info) {
  if (layout.num_vertices() > std::numeric_limits<std::uint32_t>::max()) fail(name, e.line, "too many vertices (more than 2^32)");
  const std::size_t n = std::size_t(e.count);
  std::size_t i = in.ascii() ? 0 : read_binary_vertices_fast(e, in, mesh);
  if (i == 0) {
    reserve_bulk(mesh.positions, 3 * n);
    mesh.positions.assign(3 * n, 0.0);
  }
  if (layout.has_vnormals()) mesh.vertex_normals.assign(3 * n, 0.0);
  if (layout.has_vcolors()) mesh.vertex_colors.assign(std::size_t(layout.channels()) * n, 1.0f);
  if (layout.has_vtex()) vtexcoords.assign(2 * n, 0.0);
  if (layout.vquality) mesh.vertex_quality.assign(n, 0.0f);
  start_extras(e, mesh.vertex_properties, layout.vertex_extras, n, info);
  for (; i < n; ++i) {
    in.begin_item();
    for (const auto& prop : e.props) {
      if (prop.is_list) {
        const std::int64_t k = in.integer(prop.count_type, "a vertex list count");
        if (k < 0) in.error("negative list count in " + element_item(e, i));
        for (std::int64_t j = 0; j < k; ++j) in.scalar(prop.type, "a vertex list");
        continue;
      }
      const double v = in.scalar(prop.type, "vertex data");
      switch (prop.target) {
        case Target::X: mesh.positions[3 * i] = v; break;
        case Target::Y: mesh.positions[3 * i + 1] = v; break;
        case Target::Z: mesh.positions[3 * i + 2] = v; break;
        case Target::NX: case Target::NY: case Target::NZ:
          if (layout.has_vnormals()) mesh.vertex_normals[3 * i + std::size_t(int(prop.target) - int(Target::NX))] = v;
          break;
        case Target::R: case Target::G: case Target::B: case Target::A:
          if (layout.has_vcolors())
            mesh.vertex_colors[std::size_t(layout.channels()) * i + std::size_t(int(prop.target) - int(Target::R))] =
                float(v / color_divisor(prop.type));
          break;
        case Target::U: if (layout.has_vtex()) vtexcoords[2 * i] = v; break;
        case Target::V: if (layout.has_vtex()) vtexcoords[2 * i + 1] = v; break;
        case Target::Quality: mesh.vertex_quality[i] = float(v); break;
        case Target::Extra: mesh.vertex_properties[std::size_t(prop.extra)].values[i] = v; break;
        case Target::Skip: case Target::Indices: case Target::TexcoordList: break;  // not a vertex's scalar
      }
    }
    in.end_item(e);
  }
}

// The face element: index lists (fast path for binary triangles), face normals and colours, and
// MeshLab's per-corner `texcoord` lists. An item whose index list has fewer than 3 entries is not a
// face (Blender drops it, assimp makes it a line or point): its indices are still checked, then it
// is dropped with every value of its other properties, so that the kept faces' properties stay
// aligned with them (face f of the mesh is the f-th kept item); one note counts them.
void read_face_element(const Element& e, const PlyLayout& layout, BodyReader& in, Mesh& mesh, const std::string& name,
                       ReadInfo& info) {
  const std::size_t n = std::size_t(e.count);
  reserve_bulk(mesh.face_start, n + 1);
  reserve_bulk(mesh.corner_vertex, std::min<std::size_t>(3 * n, in.remaining()));
  if (layout.has_fnormals()) mesh.face_normals.assign(3 * n, 0.0);
  if (layout.has_fcolors()) mesh.face_colors.assign(std::size_t(layout.channels()) * n, 1.0f);
  if (layout.fquality) mesh.face_quality.assign(n, 0.0f);
  start_extras(e, mesh.face_properties, layout.face_extras, n, info);
  std::vector<double> wedge;  // texcoord list of the current face
  std::vector<double> corner_tex;
  std::size_t i = 0;
  if (!in.ascii()) i = read_binary_triangles_fast(e, in, layout.num_vertices(), mesh);
  std::size_t f = i;  // the mesh face the current item becomes (items before it that were not faces skipped)
  std::size_t short_items = 0;
  for (; i < n; ++i) {
    if (in.ascii()) in.skip_ascii_space();  // (begin_item's line mode skips the same)
    const std::size_t item_line = in.line();
    bool have_wedge = false, is_face = true;
    wedge.clear();
    for (const auto& prop : e.props) {
      if (prop.is_list) {
        const std::int64_t k = in.integer(prop.count_type, "a face list count");
        if (k < 0) in.error("negative list count in " + element_item(e, i));
        if (!in.ascii() && std::uint64_t(k) > in.remaining() / type_size(prop.type))
          in.error("file is truncated: it ends in " + element_item(e, i));
        if (prop.target == Target::Indices) {
          is_face = k >= 3;
          const std::size_t first_corner = mesh.corner_vertex.size();
          for (std::int64_t j = 0; j < k; ++j) {
            const std::int64_t idx = in.integer(prop.type, "a face's vertex indices");
            if (idx < 0 || std::uint64_t(idx) >= layout.num_vertices())
              fail(name, in.line(), element_item(e, i) + ": vertex index " + std::to_string(idx) +
                                        " out of range (" + std::to_string(layout.num_vertices()) + " vertices)");
            mesh.corner_vertex.push_back(std::uint32_t(idx));
          }
          if (!is_face) {  // checked, not kept
            mesh.corner_vertex.resize(first_corner);
            continue;
          }
          if (mesh.corner_vertex.size() > std::numeric_limits<std::uint32_t>::max() - 1)
            in.error("too many face corners (more than 2^32)");
          mesh.face_start.push_back(std::uint32_t(mesh.corner_vertex.size()));
        } else if (prop.target == Target::TexcoordList) {
          have_wedge = true;
          for (std::int64_t j = 0; j < k; ++j) wedge.push_back(in.scalar(prop.type, "a face's texcoord list"));
        } else {
          for (std::int64_t j = 0; j < k; ++j) in.scalar(prop.type, "a face list");
        }
        continue;
      }
      // Scalars go to slot f; an item that turns out not to be a face leaves them there, and the
      // next face overwrites them (the arrays are cut to the faces kept at the end).
      const double v = in.scalar(prop.type, "face data");
      switch (prop.target) {
        case Target::NX: case Target::NY: case Target::NZ:
          if (layout.has_fnormals()) mesh.face_normals[3 * f + std::size_t(int(prop.target) - int(Target::NX))] = v;
          break;
        case Target::R: case Target::G: case Target::B: case Target::A:
          if (layout.has_fcolors())
            mesh.face_colors[std::size_t(layout.channels()) * f + std::size_t(int(prop.target) - int(Target::R))] =
                float(v / color_divisor(prop.type));
          break;
        case Target::Quality: mesh.face_quality[f] = float(v); break;
        case Target::Extra: mesh.face_properties[std::size_t(prop.extra)].values[f] = v; break;
        case Target::Skip: case Target::X: case Target::Y: case Target::Z: case Target::U: case Target::V:
        case Target::Indices: case Target::TexcoordList: break;  // not a face's scalar
      }
    }
    in.end_item(e);
    if (!is_face) {
      ++short_items;
      // The slot is the next face's: back to the values an unwritten slot holds.
      if (layout.has_fnormals()) std::fill_n(mesh.face_normals.begin() + std::ptrdiff_t(3 * f), 3, 0.0);
      if (layout.has_fcolors())
        std::fill_n(mesh.face_colors.begin() + std::ptrdiff_t(std::size_t(layout.channels()) * f), layout.channels(), 1.0f);
      if (layout.fquality) mesh.face_quality[f] = 0.0f;
      for (MeshProperty& p : mesh.face_properties) p.values[f] = 0.0;
      continue;
    }
    if (layout.face_texcoords) {
      const std::size_t size = mesh.face_size(f);
      if (!have_wedge || wedge.size() != 2 * size)
        fail(name, item_line, element_item(e, i) + ": texcoord list has " + std::to_string(wedge.size()) +
                                  " values, expected " + std::to_string(2 * size) + " (u v per corner)");
      corner_tex.insert(corner_tex.end(), wedge.begin(), wedge.end());
    }
    ++f;
  }
  if (short_items > 0) {  // the per-face arrays cut to the faces kept
    if (layout.has_fnormals()) mesh.face_normals.resize(3 * f);
    if (layout.has_fcolors()) mesh.face_colors.resize(std::size_t(layout.channels()) * f);
    if (layout.fquality) mesh.face_quality.resize(f);
    for (MeshProperty& p : mesh.face_properties) p.values.resize(f);
    info.notes.push_back("skipped " + std::to_string(short_items) + " of " + std::to_string(n) + " '" + e.name +
                         "' elements with fewer than 3 vertex indices (not a face), with their properties");
  }
  if (layout.face_texcoords) {
    mesh.texcoords = std::move(corner_tex);
    mesh.texcoord_dims = 2;
    mesh.corner_texcoord_index.resize(mesh.corner_vertex.size());
    for (std::size_t c = 0; c < mesh.corner_texcoord_index.size(); ++c) mesh.corner_texcoord_index[c] = std::uint32_t(c);
  }
}

// Triangles of one strip run s[0..m): triangle j is (s[j], s[j+1], s[j+2]) for even j and
// (s[j+1], s[j], s[j+2]) for odd j, so that every triangle winds like the first (the strip's own
// alternation undone, as VCG's importer, MeshLab's, reads them). A triangle with a repeated index
// joins two strips and has no area: not kept, counted.
void add_strip_run(const std::vector<std::uint32_t>& s, Mesh& mesh, std::size_t& joins) {
  for (std::size_t j = 0; j + 2 < s.size(); ++j) {
    const std::uint32_t a = j % 2 ? s[j + 1] : s[j], b = j % 2 ? s[j] : s[j + 1], c = s[j + 2];
    if (a == b || b == c || a == c) {
      ++joins;
      continue;
    }
    mesh.corner_vertex.insert(mesh.corner_vertex.end(), {a, b, c});
    mesh.face_start.push_back(std::uint32_t(mesh.corner_vertex.size()));
  }
}

// The `tristrips` element (PlyLayout::strips): each item a list of vertex indices where -1 ends a
// strip and starts the next; read as triangles (add_strip_run), with one note.
void read_strips_element(const Element& e, const PlyLayout& layout, BodyReader& in, Mesh& mesh, const std::string& name,
                         ReadInfo& info) {
  std::vector<std::uint32_t> run;
  std::size_t joins = 0, strips = 0;
  for (std::uint64_t i = 0; i < e.count; ++i) {
    in.begin_item();
    for (const auto& prop : e.props) {
      if (!prop.is_list) {
        in.scalar(prop.type, e.name.c_str());
        continue;
      }
      const std::int64_t k = in.integer(prop.count_type, "a list count");
      if (k < 0) in.error("negative list count in " + element_item(e, i));
      if (!in.ascii() && std::uint64_t(k) > in.remaining() / type_size(prop.type))
        in.error("file is truncated: it ends in " + element_item(e, i));
      if (prop.target != Target::Indices) {
        for (std::int64_t j = 0; j < k; ++j) in.scalar(prop.type, e.name.c_str());
        continue;
      }
      run.clear();
      for (std::int64_t j = 0; j < k; ++j) {
        const std::int64_t idx = in.integer(prop.type, "a strip's vertex indices");
        if (idx == -1) {  // the end of one strip, the start of the next
          strips += run.size() >= 3;
          add_strip_run(run, mesh, joins);
          run.clear();
          continue;
        }
        if (idx < 0 || std::uint64_t(idx) >= layout.num_vertices())
          fail(name, in.line(), element_item(e, i) + ": vertex index " + std::to_string(idx) + " out of range (" +
                                    std::to_string(layout.num_vertices()) + " vertices; -1 restarts a strip)");
        run.push_back(std::uint32_t(idx));
      }
      strips += run.size() >= 3;
      add_strip_run(run, mesh, joins);
      if (mesh.corner_vertex.size() > std::numeric_limits<std::uint32_t>::max() - 3)
        in.error("too many face corners (more than 2^32)");
    }
    in.end_item(e);
  }
  info.notes.push_back("triangle strips ('" + e.name + "'): " + std::to_string(strips) + " strips read as " +
                       std::to_string(mesh.num_faces()) + " triangles, winding as the first of each strip (as MeshLab reads them)" +
                       (joins > 0 ? "; " + std::to_string(joins) + " triangles with a repeated index (strip joins, no area) not kept"
                                  : std::string()));
}

// An element we do not keep: skipped by its declared types, counted in a note.
void skip_element(const Element& e, BodyReader& in, ReadInfo& info) {
  // An element we do not keep: skipped by its declared types. One without properties takes no
  // bytes in either encoding (looping over its claimed count would hang on a count like 2^60).
  bool fixed = !in.ascii() || e.props.empty();
  std::size_t size = 0;
  for (const auto& prop : e.props) {
    fixed = fixed && !prop.is_list;
    size += type_size(prop.type);
  }
  if (fixed) {
    if (e.count * size > in.remaining()) in.error("file is truncated: it ends in the " + e.name + " elements");
    in.advance(std::size_t(e.count) * size);
    info.notes.push_back("skipped " + std::to_string(e.count) + " '" + e.name + "' elements");
    return;
  }
  for (std::uint64_t i = 0; i < e.count; ++i) {
    in.begin_item();
    for (const auto& prop : e.props) {
      if (prop.is_list) {
        const std::int64_t k = in.integer(prop.count_type, "a list count");
        if (k < 0) in.error("negative list count in " + element_item(e, i));
        if (!in.ascii() && std::uint64_t(k) > in.remaining() / type_size(prop.type))
          in.error("file is truncated: it ends in " + element_item(e, i));
        for (std::int64_t j = 0; j < k; ++j) in.scalar(prop.type, e.name.c_str());
      } else {
        in.scalar(prop.type, e.name.c_str());
      }
    }
    in.end_item(e);
  }
  info.notes.push_back("skipped " + std::to_string(e.count) + " '" + e.name + "' elements");
}

// Whatever follows the last element means the header counts disagree with the body.
void refuse_trailing_data(BodyReader& in, const std::string& name) {
  if (in.ascii()) {
    in.skip_ascii_space();
    if (in.remaining() > 0)
      in.error("more data than the header declares ('" + token_at(in.pos(), in.end()) + "' after the last element)");
  } else {
    const char* q = in.pos();
    while (q < in.end() && is_space_or_newline(*q)) ++q;
    if (q < in.end())
      fail(name, 0, std::to_string(in.remaining()) + " bytes after the last element: the header counts disagree with the body");
  }

}

}  // namespace

namespace {

Mesh read_body(std::string_view bytes, const PlyHeader& header, const PlyLayout& layout, const std::string& name,
               ReadInfo& info, AsciiItems items) {
  const Encoding enc = header.encoding;
  BodyReader in(bytes.data() + header.body_offset, bytes.data() + bytes.size(), enc, name, header.lines + 1, items);
  Mesh mesh;
  std::vector<double> vtexcoords;
  for (const Element& e : header.elements) {
    // Bound the claimed count by the bytes left before allocating anything for it.
    const std::size_t min_bytes = min_item_bytes(e, enc);
    if (min_bytes > 0 && e.count > in.remaining() / min_bytes + (enc == Encoding::Ascii ? 1 : 0))
      fail(name, e.line, "header claims " + std::to_string(e.count) + " " + e.name + " elements but only " +
                             std::to_string(in.remaining()) + " bytes of data follow");
    if (&e == layout.vertex) read_vertex_element(e, layout, in, mesh, vtexcoords, name, info);
    else if (&e == layout.face) read_face_element(e, layout, in, mesh, name, info);
    else if (&e == layout.strips) read_strips_element(e, layout, in, mesh, name, info);
    else skip_element(e, in, info);
    info.progress.at(bytes.size() - in.remaining());  // bytes read, per element
  }
  refuse_trailing_data(in, name);
  // Faces in an element this reader does not take (a second face element, strips beside faces,
  // another name with a vertex_indices list): a faceless result would be a point cloud the file is
  // not; refused instead of letting a command make nothing of it with exit 0.
  if (mesh.num_faces() == 0)
    for (const Element& e : header.elements) {
      if (&e == layout.face || &e == layout.strips || e.count == 0) continue;
      for (const auto& prop : e.props)
        if (prop.is_list && (prop.name == "vertex_indices" || prop.name == "vertex_index"))
          fail(name, e.line, "element '" + e.name + "' holds " + std::to_string(e.count) + " faces (list " + prop.name +
                                 ") that shadetool does not read (it reads 'face', and 'tristrips' when there is no face "
                                 "element): nothing usable");
    }

  if (layout.has_vtex() && !layout.face_texcoords) {
    mesh.texcoords = std::move(vtexcoords);
    mesh.texcoord_dims = 2;
    mesh.corner_texcoord_index = mesh.corner_vertex;
    // The names they were read under, for a writer that gives them back per vertex (the last
    // property of each kind is the one whose value was kept).
    mesh.texcoord_names.assign(2, std::string());
    for (const auto& prop : layout.vertex->props)
      if (prop.target == Target::U || prop.target == Target::V) mesh.texcoord_names[prop.target == Target::V] = prop.name;
  }
  mesh.color_channels = layout.channels();
  mesh.colors_are_float = layout.colors_float;
  mesh.precision = layout.any_double ? ValuePrecision::Double : ValuePrecision::Float;
  for (const ExtraValues& x : in.extra_values())
    info.notes.push_back(std::to_string(x.items) + " " + x.element + (x.items == 1 ? " line holds" : " lines hold") +
                         " values beyond the header's properties (first: line " + std::to_string(x.first_line) +
                         "): ignored, as the PLY reference reader (ply.c) reads them");
  return mesh;
}

}  // namespace

Mesh read_ply_body(std::string_view bytes, const PlyHeader& header, const PlyLayout& layout, const std::string& name,
                   ReadInfo& info) {
  if (header.encoding != Encoding::Ascii) return read_body(bytes, header, layout, name, info, AsciiItems::Tokens);
  // Ascii: by tokens (the format's rule); when that fails, by lines (ply.c's), and that result
  // is kept if it reads; else the token mode's error. The failed attempt's notes are dropped.
  const std::size_t notes_before = info.notes.size();
  try {
    return read_body(bytes, header, layout, name, info, AsciiItems::Tokens);
  } catch (const Error&) {
    const std::exception_ptr token_error = std::current_exception();
    info.notes.resize(notes_before);
    try {
      return read_body(bytes, header, layout, name, info, AsciiItems::Lines);
    } catch (const Error&) {
      info.notes.resize(notes_before);
    }
    std::rethrow_exception(token_error);
  }
}

}  // namespace shadetool::io::ply
