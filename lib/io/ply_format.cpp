// ply_format.cpp: PLY header parsed line by line, body read element by element by declared type.
#include <shadetool/io/ply_format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/engine/bulk_reserve.h>
#include <shadetool/io/number_text.h>
#include <shadetool/io/split_corner_normals.h>
#include <shadetool/io/text_parse.h>

namespace shadetool::io {

namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t type_size(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

bool parse_type(std::string_view s, Type& t) {
  struct Name { const char* name; Type type; };
  static const Name names[] = {{"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},
                               {"uint8", Type::UInt8},   {"short", Type::Int16},     {"int16", Type::Int16},
                               {"ushort", Type::UInt16}, {"uint16", Type::UInt16},   {"int", Type::Int32},
                               {"int32", Type::Int32},   {"uint", Type::UInt32},     {"uint32", Type::UInt32},
                               {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64},
                               {"float64", Type::Float64}};
  for (const auto& n : names)
    if (s == n.name) {
      t = n.type;
      return true;
    }
  return false;
}

bool is_float_type(Type t) { return t == Type::Float32 || t == Type::Float64; }

// What an integer colour channel of this type is divided by to land in [0,1] (uchar: 255).
double color_divisor(Type t) {
  switch (t) {
    case Type::UInt16: case Type::Int16: return 65535.0;
    case Type::UInt32: case Type::Int32: return 4294967295.0;
    case Type::Float32: case Type::Float64: return 1.0;
    default: return 255.0;
  }
}

enum class Target { Skip, X, Y, Z, NX, NY, NZ, R, G, B, A, U, V, Quality, Indices, TexcoordList };

struct Property {
  std::string name;
  bool is_list = false;
  Type type = Type::Float32;        // item type for lists
  Type count_type = Type::UInt8;    // lists only
  Target target = Target::Skip;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t line = 0;  // header line that declared it
};

enum class Encoding { Ascii, BinaryLE, BinaryBE };

// ---- binary values

template <class T>
T load(const char* p, bool swap) {
  T v;
  if (!swap) {
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  char b[sizeof(T)];
  for (std::size_t i = 0; i < sizeof(T); ++i) b[i] = p[sizeof(T) - 1 - i];
  std::memcpy(&v, b, sizeof v);
  return v;
}

double load_as_double(const char* p, Type t, bool swap) {
  switch (t) {
    case Type::Int8: return double(load<std::int8_t>(p, swap));
    case Type::UInt8: return double(load<std::uint8_t>(p, swap));
    case Type::Int16: return double(load<std::int16_t>(p, swap));
    case Type::UInt16: return double(load<std::uint16_t>(p, swap));
    case Type::Int32: return double(load<std::int32_t>(p, swap));
    case Type::UInt32: return double(load<std::uint32_t>(p, swap));
    case Type::Float32: return double(load<float>(p, swap));
    case Type::Float64: return load<double>(p, swap);
  }
  return 0;
}

// Integer value of a list count or index; float-typed lists are refused at header time.
std::int64_t load_as_int(const char* p, Type t, bool swap) {
  switch (t) {
    case Type::Int8: return load<std::int8_t>(p, swap);
    case Type::UInt8: return load<std::uint8_t>(p, swap);
    case Type::Int16: return load<std::int16_t>(p, swap);
    case Type::UInt16: return load<std::uint16_t>(p, swap);
    case Type::Int32: return load<std::int32_t>(p, swap);
    case Type::UInt32: return load<std::uint32_t>(p, swap);
    default: return 0;
  }
}

// ---- the body reader: one interface over ascii tokens and binary values

class BodyReader {
 public:
  BodyReader(const char* p, const char* end, Encoding enc, const std::string& name, std::size_t line)
      : p_(p), end_(end), enc_(enc), swap_(host_is_little() != (enc == Encoding::BinaryLE)), name_(name), line_(line) {}

  static bool host_is_little() {
    const std::uint16_t one = 1;
    char b;
    std::memcpy(&b, &one, 1);
    return b == 1;
  }

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
      skip_ascii_space();
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
      skip_ascii_space();
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

 private:
  const char* p_;
  const char* end_;
  Encoding enc_;
  bool swap_;
  const std::string& name_;
  std::size_t line_;
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

}  // namespace

Mesh read_ply(std::string_view bytes, const std::string& name, ReadInfo& info) {
  const char* p = bytes.data();
  const char* const end = p + bytes.size();
  std::size_t line = 0;

  // ---- header
  auto next_line = [&](std::string_view& out) -> bool {
    if (p >= end) return false;
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
    const char* stop = eol ? eol : end;
    const char* e = stop;
    while (e > p && is_space(e[-1])) --e;
    out = std::string_view(p, std::size_t(e - p));
    p = eol ? eol + 1 : end;
    ++line;
    return true;
  };
  auto split = [](std::string_view s) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && is_space(s[i])) ++i;
      const std::size_t b = i;
      while (i < s.size() && !is_space(s[i])) ++i;
      if (i > b) words.push_back(s.substr(b, i - b));
    }
    return words;
  };

  std::string_view l;
  if (!next_line(l) || l != "ply") fail(name, 1, "not a PLY file (first line is not 'ply')");
  Encoding enc = Encoding::Ascii;
  bool have_format = false, have_end = false;
  std::vector<Element> elements;
  while (next_line(l)) {
    const auto w = split(l);
    if (w.empty()) continue;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() < 3) fail(name, line, "malformed format line");
      if (w[1] == "ascii") enc = Encoding::Ascii;
      else if (w[1] == "binary_little_endian") enc = Encoding::BinaryLE;
      else if (w[1] == "binary_big_endian") enc = Encoding::BinaryBE;
      else fail(name, line, "unknown PLY format '" + std::string(w[1]) + "'");
      have_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) fail(name, line, "malformed element line (expected: element NAME COUNT)");
      Element e;
      e.name = std::string(w[1]);
      e.line = line;
      const char* b = w[2].data();
      std::int64_t count;
      if (!parse_int64(b, w[2].data() + w[2].size(), count) || b != w[2].data() + w[2].size() || count < 0)
        fail(name, line, "malformed element count '" + std::string(w[2]) + "'");
      e.count = std::uint64_t(count);
      elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (elements.empty()) fail(name, line, "property before any element");
      Property prop;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() != 5) fail(name, line, "malformed list property (expected: property list COUNT_TYPE ITEM_TYPE NAME)");
        prop.is_list = true;
        if (!parse_type(w[2], prop.count_type) || is_float_type(prop.count_type))
          fail(name, line, "bad list count type '" + std::string(w[2]) + "'");
        if (!parse_type(w[3], prop.type)) fail(name, line, "unknown property type '" + std::string(w[3]) + "'");
        prop.name = std::string(w[4]);
      } else {
        if (w.size() != 3) fail(name, line, "malformed property line (expected: property TYPE NAME)");
        if (!parse_type(w[1], prop.type)) fail(name, line, "unknown property type '" + std::string(w[1]) + "'");
        prop.name = std::string(w[2]);
      }
      elements.back().props.push_back(std::move(prop));
    } else if (w[0] == "end_header") {
      have_end = true;
      break;
    } else {
      fail(name, line, "unexpected header line '" + std::string(l.substr(0, 40)) + "'");
    }
  }
  if (!have_end) fail(name, line, "PLY header has no end_header");
  if (!have_format) fail(name, 2, "PLY header has no format line");

  // ---- what we keep
  Element* vertex = nullptr;
  Element* face = nullptr;
  for (auto& e : elements) {
    if (e.name == "vertex" && !vertex) vertex = &e;
    if (e.name == "face" && !face) face = &e;
  }
  Mesh mesh;
  bool any_double = false;
  bool vnormal[3] = {false, false, false}, fnormal[3] = {false, false, false};
  bool vcolor[4] = {false, false, false, false}, fcolor[4] = {false, false, false, false};
  bool vtex[2] = {false, false};
  bool colors_float = false;
  bool face_texcoords = false;
  bool vquality = false, fquality = false;  // `quality` (MeshLab's per-vertex / per-face scalar)
  if (vertex) {
    for (auto& prop : vertex->props) {
      if (prop.is_list) continue;
      const std::string& n = prop.name;
      Target t = Target::Skip;
      if (n == "x") t = Target::X;
      else if (n == "y") t = Target::Y;
      else if (n == "z") t = Target::Z;
      else if (n == "nx") t = Target::NX;
      else if (n == "ny") t = Target::NY;
      else if (n == "nz") t = Target::NZ;
      else if (n == "red" || n == "diffuse_red" || n == "r") t = Target::R;
      else if (n == "green" || n == "diffuse_green" || n == "g") t = Target::G;
      else if (n == "blue" || n == "diffuse_blue" || n == "b") t = Target::B;
      else if (n == "alpha" || n == "diffuse_alpha" || n == "a") t = Target::A;
      else if (n == "s" || n == "u" || n == "texture_u" || n == "texture_s") t = Target::U;
      else if (n == "t" || n == "v" || n == "texture_v" || n == "texture_t") t = Target::V;
      else if (n == "quality" && !vquality) t = Target::Quality, vquality = true;
      prop.target = t;
      if (t >= Target::X && t <= Target::NZ) {
        if (t >= Target::NX) vnormal[int(t) - int(Target::NX)] = true;
        if (prop.type == Type::Float64 || prop.type == Type::Int32 || prop.type == Type::UInt32) any_double = true;
      }
      if (t >= Target::R && t <= Target::A) {
        vcolor[int(t) - int(Target::R)] = true;
        if (is_float_type(prop.type)) colors_float = true;
      }
      if (t == Target::U || t == Target::V) {
        vtex[t == Target::V] = true;
        if (prop.type == Type::Float64) any_double = true;
      }
    }
    bool xyz[3] = {false, false, false};
    for (auto& prop : vertex->props)
      if (prop.target >= Target::X && prop.target <= Target::Z) xyz[int(prop.target) - int(Target::X)] = true;
    if (!(xyz[0] && xyz[1] && xyz[2])) fail(name, vertex->line, "vertex element has no x, y and z properties");
  }
  if (face) {
    for (auto& prop : face->props) {
      const std::string& n = prop.name;
      if (prop.is_list) {
        if ((n == "vertex_indices" || n == "vertex_index") && !is_float_type(prop.type)) {
          bool taken = false;
          for (auto& q : face->props) taken = taken || q.target == Target::Indices;
          if (!taken) prop.target = Target::Indices;
        } else if (n == "texcoord" && is_float_type(prop.type)) {
          prop.target = Target::TexcoordList;
          face_texcoords = true;
          if (prop.type == Type::Float64) any_double = true;
        }
        continue;
      }
      Target t = Target::Skip;
      if (n == "nx") t = Target::NX;
      else if (n == "ny") t = Target::NY;
      else if (n == "nz") t = Target::NZ;
      else if (n == "red" || n == "diffuse_red") t = Target::R;
      else if (n == "green" || n == "diffuse_green") t = Target::G;
      else if (n == "blue" || n == "diffuse_blue") t = Target::B;
      else if (n == "alpha" || n == "diffuse_alpha") t = Target::A;
      else if (n == "quality" && !fquality) t = Target::Quality, fquality = true;
      prop.target = t;
      if (t >= Target::NX && t <= Target::NZ) {
        fnormal[int(t) - int(Target::NX)] = true;
        if (prop.type == Type::Float64) any_double = true;
      }
      if (t >= Target::R && t <= Target::A) {
        fcolor[int(t) - int(Target::R)] = true;
        if (is_float_type(prop.type)) colors_float = true;
      }
    }
    bool indices = false;
    for (auto& prop : face->props) indices = indices || prop.target == Target::Indices;
    if (!indices) fail(name, face->line, "face element has no vertex_indices list");
    if (!vertex && face->count > 0) fail(name, face->line, "faces but no vertex element");
  }
  const bool has_vnormals = vnormal[0] && vnormal[1] && vnormal[2];
  const bool has_fnormals = fnormal[0] && fnormal[1] && fnormal[2];
  const bool has_vcolors = vcolor[0] && vcolor[1] && vcolor[2];
  const bool has_fcolors = fcolor[0] && fcolor[1] && fcolor[2];
  const bool has_vtex = vtex[0] && vtex[1];
  const int channels = ((has_vcolors && vcolor[3]) || (has_fcolors && fcolor[3])) ? 4 : 3;
  const std::uint64_t nv = vertex ? vertex->count : 0;

  // ---- body
  BodyReader in(p, end, enc, name, line + 1);
  std::vector<double> vtexcoords;
  for (auto& e : elements) {
    // Bound the claimed count by the bytes left before allocating anything for it.
    const std::size_t min_bytes = min_item_bytes(e, enc);
    if (min_bytes > 0 && e.count > in.remaining() / min_bytes + (enc == Encoding::Ascii ? 1 : 0))
      fail(name, e.line, "header claims " + std::to_string(e.count) + " " + e.name + " elements but only " +
                             std::to_string(in.remaining()) + " bytes of data follow");
    if (&e == vertex) {
      if (nv > std::numeric_limits<std::uint32_t>::max()) fail(name, e.line, "too many vertices (more than 2^32)");
      const std::size_t n = std::size_t(e.count);
      std::size_t i = in.ascii() ? 0 : read_binary_vertices_fast(e, in, mesh);
      if (i == 0) {
        reserve_bulk(mesh.positions, 3 * n);
        mesh.positions.assign(3 * n, 0.0);
      }
      if (has_vnormals) mesh.vertex_normals.assign(3 * n, 0.0);
      if (has_vcolors) mesh.vertex_colors.assign(std::size_t(channels) * n, 1.0f);
      if (has_vtex) vtexcoords.assign(2 * n, 0.0);
      if (vquality) mesh.vertex_quality.assign(n, 0.0f);
      for (; i < n; ++i) {
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
              if (has_vnormals) mesh.vertex_normals[3 * i + std::size_t(int(prop.target) - int(Target::NX))] = v;
              break;
            case Target::R: case Target::G: case Target::B: case Target::A:
              if (has_vcolors)
                mesh.vertex_colors[std::size_t(channels) * i + std::size_t(int(prop.target) - int(Target::R))] =
                    float(v / color_divisor(prop.type));
              break;
            case Target::U: if (has_vtex) vtexcoords[2 * i] = v; break;
            case Target::V: if (has_vtex) vtexcoords[2 * i + 1] = v; break;
            case Target::Quality: mesh.vertex_quality[i] = float(v); break;
            default: break;
          }
        }
      }
    } else if (&e == face) {
      const std::size_t n = std::size_t(e.count);
      reserve_bulk(mesh.face_start, n + 1);
      reserve_bulk(mesh.corner_vertex, std::min<std::size_t>(3 * n, in.remaining()));
      if (has_fnormals) mesh.face_normals.assign(3 * n, 0.0);
      if (has_fcolors) mesh.face_colors.assign(std::size_t(channels) * n, 1.0f);
      if (fquality) mesh.face_quality.assign(n, 0.0f);
      std::vector<double> wedge;  // texcoord list of the current face
      std::vector<double> corner_tex;
      std::size_t i = 0;
      if (!in.ascii()) i = read_binary_triangles_fast(e, in, nv, mesh);
      for (; i < n; ++i) {
        if (in.ascii()) in.skip_ascii_space();
        const std::size_t item_line = in.line();
        bool have_wedge = false;
        wedge.clear();
        for (const auto& prop : e.props) {
          if (prop.is_list) {
            const std::int64_t k = in.integer(prop.count_type, "a face list count");
            if (k < 0) in.error("negative list count in " + element_item(e, i));
            if (!in.ascii() && std::uint64_t(k) > in.remaining() / type_size(prop.type))
              in.error("file is truncated: it ends in " + element_item(e, i));
            if (prop.target == Target::Indices) {
              if (k < 3)
                fail(name, item_line, element_item(e, i) + " has " + std::to_string(k) +
                                          (k == 1 ? " vertex" : " vertices") + " (a face needs at least 3)");
              for (std::int64_t j = 0; j < k; ++j) {
                const std::int64_t idx = in.integer(prop.type, "a face's vertex indices");
                if (idx < 0 || std::uint64_t(idx) >= nv)
                  fail(name, in.line(), element_item(e, i) + ": vertex index " + std::to_string(idx) +
                                            " out of range (" + std::to_string(nv) + " vertices)");
                mesh.corner_vertex.push_back(std::uint32_t(idx));
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
          const double v = in.scalar(prop.type, "face data");
          switch (prop.target) {
            case Target::NX: case Target::NY: case Target::NZ:
              if (has_fnormals) mesh.face_normals[3 * i + std::size_t(int(prop.target) - int(Target::NX))] = v;
              break;
            case Target::R: case Target::G: case Target::B: case Target::A:
              if (has_fcolors)
                mesh.face_colors[std::size_t(channels) * i + std::size_t(int(prop.target) - int(Target::R))] =
                    float(v / color_divisor(prop.type));
              break;
            case Target::Quality: mesh.face_quality[i] = float(v); break;
            default: break;
          }
        }
        if (face_texcoords) {
          const std::size_t size = mesh.face_size(i);
          if (!have_wedge || wedge.size() != 2 * size)
            fail(name, item_line, element_item(e, i) + ": texcoord list has " + std::to_string(wedge.size()) +
                                      " values, expected " + std::to_string(2 * size) + " (u v per corner)");
          corner_tex.insert(corner_tex.end(), wedge.begin(), wedge.end());
        }
      }
      if (face_texcoords) {
        mesh.texcoords = std::move(corner_tex);
        mesh.texcoord_dims = 2;
        mesh.corner_texcoord_index.resize(mesh.corner_vertex.size());
        for (std::size_t c = 0; c < mesh.corner_texcoord_index.size(); ++c) mesh.corner_texcoord_index[c] = std::uint32_t(c);
      }
    } else {
      // An element we do not keep: skipped by its declared types. One without properties takes no
      // bytes in either encoding (looping over its claimed count would hang on a count like 2^60).
      bool fixed = enc != Encoding::Ascii || e.props.empty();
      std::size_t size = 0;
      for (const auto& prop : e.props) {
        fixed = fixed && !prop.is_list;
        size += type_size(prop.type);
      }
      if (fixed) {
        if (e.count * size > in.remaining()) in.error("file is truncated: it ends in the " + e.name + " elements");
        in.advance(std::size_t(e.count) * size);
        continue;
      }
      for (std::uint64_t i = 0; i < e.count; ++i)
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
      info.notes.push_back("skipped " + std::to_string(e.count) + " '" + e.name + "' elements");
    }
  }
  // Whatever follows the last element means the header counts disagree with the body.
  if (enc == Encoding::Ascii) {
    in.skip_ascii_space();
    if (in.remaining() > 0)
      in.error("more data than the header declares ('" + token_at(in.pos(), in.end()) + "' after the last element)");
  } else {
    const char* q = in.pos();
    while (q < in.end() && is_space_or_newline(*q)) ++q;
    if (q < in.end())
      fail(name, 0, std::to_string(in.remaining()) + " bytes after the last element: the header counts disagree with the body");
  }

  if (has_vtex && !face_texcoords) {
    mesh.texcoords = std::move(vtexcoords);
    mesh.texcoord_dims = 2;
    mesh.corner_texcoord_index = mesh.corner_vertex;
  }
  mesh.color_channels = channels;
  mesh.colors_are_float = colors_float;
  mesh.precision = any_double ? ValuePrecision::Double : ValuePrecision::Float;
  return mesh;
}

// ---- writer

namespace {

template <class T>
void put(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof v);
  if (!BodyReader::host_is_little()) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
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
  std::uint32_t max_size = 0;
  for (std::size_t f = 0; f < nf; ++f) max_size = std::max<std::uint32_t>(max_size, std::uint32_t(mesh.face_size(f)));
  const bool uchar_count = max_size <= 255;
  const bool int_index = nv <= std::size_t(std::numeric_limits<std::int32_t>::max());
  if (wedge && mesh.texcoord_dims != 2) info.notes.push_back("texture coordinates: only u v written to PLY");

  out.reserve(out.size() + 300 + nv * (dbl ? 24 : 12) * (vnormals ? 2 : 1) + mesh.num_corners() * 4 + nf);
  out += "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by shadetool\nelement vertex ";
  append_uint(out, nv);
  out += '\n';
  for (const char* n : {"x", "y", "z"}) out += std::string("property ") + real + " " + n + "\n";
  if (vnormals)
    for (const char* n : {"nx", "ny", "nz"}) out += std::string("property ") + real + " " + n + "\n";
  const char* ctype = cfloat ? "float" : "uchar";
  static const char* cnames[] = {"red", "green", "blue", "alpha"};
  if (vcolors)
    for (int k = 0; k < ch; ++k) out += std::string("property ") + ctype + " " + cnames[k] + "\n";
  if (vquality) out += "property float quality\n";
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
    if (!binary) out += '\n';
  }
}

}  // namespace shadetool::io
