// stl_format.cpp
#include <shadetool/io/stl_format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/io/engine/newell_normal.h>
#include <shadetool/geometry/polygon_triangles.h>
#include <shadetool/io/engine/number_text.h>
#include <shadetool/io/engine/text_encoding.h>
#include <shadetool/io/engine/text_parse.h>

namespace shadetool::io {

namespace {

// Positions -> shared vertices. Keys are the vertex ids already in `positions`.
class PositionMerger {
 public:
  PositionMerger(Mesh& mesh, std::size_t expected_corners) : mesh_(mesh) {
    std::size_t cap = 16;
    while (cap < 2 * expected_corners) cap *= 2;
    slots_.assign(cap, kEmpty);
  }

  std::uint32_t add(double x, double y, double z) {
    if (std::isnan(x) || std::isnan(y) || std::isnan(z)) return append(x, y, z);  // NaN equals nothing
    std::size_t h = hash(x, y, z) & (slots_.size() - 1);
    for (;;) {
      const std::uint32_t v = slots_[h];
      if (v == kEmpty) break;
      const double* p = &mesh_.positions[3 * std::size_t(v)];
      if (p[0] == x && p[1] == y && p[2] == z) {
        ++merged_;
        return v;
      }
      h = (h + 1) & (slots_.size() - 1);
    }
    const std::uint32_t v = append(x, y, z);
    slots_[h] = v;
    if (2 * mesh_.num_vertices() > slots_.size()) grow();
    return v;
  }
  std::size_t merged() const { return merged_; }

 private:
  static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();

  static std::uint64_t bits(double d) {
    std::uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    return u;
  }
  // -0 and +0 are the same position (compared as values): they hash alike.
  static std::size_t hash(double x, double y, double z) {
    x += 0.0;  // -0 + 0 = +0; every other value is unchanged
    y += 0.0;
    z += 0.0;
    std::uint64_t h = bits(x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(y) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    h ^= bits(z) + 0x85EBCA77C2B2AE63ull + (h << 6) + (h >> 2);
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return std::size_t(h);
  }
  std::uint32_t append(double x, double y, double z) {
    if (mesh_.num_vertices() >= kEmpty) fail("", 0, "too many vertices (more than 2^32)");
    return mesh_.add_vertex({x, y, z});
  }
  void grow() {
    std::vector<std::uint32_t> old(slots_.size() * 2, kEmpty);
    old.swap(slots_);
    for (std::uint32_t v : old) {
      if (v == kEmpty) continue;
      const double* p = &mesh_.positions[3 * std::size_t(v)];
      std::size_t h = hash(p[0], p[1], p[2]) & (slots_.size() - 1);
      while (slots_[h] != kEmpty) h = (h + 1) & (slots_.size() - 1);
      slots_[h] = v;
    }
  }

  Mesh& mesh_;
  std::vector<std::uint32_t> slots_;
  std::size_t merged_ = 0;
};

float load_le_float(const char* p) {
  std::uint32_t u = std::uint32_t(std::uint8_t(p[0])) | std::uint32_t(std::uint8_t(p[1])) << 8 |
                    std::uint32_t(std::uint8_t(p[2])) << 16 | std::uint32_t(std::uint8_t(p[3])) << 24;
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

std::uint32_t load_le_u32(const char* p) {
  return std::uint32_t(std::uint8_t(p[0])) | std::uint32_t(std::uint8_t(p[1])) << 8 |
         std::uint32_t(std::uint8_t(p[2])) << 16 | std::uint32_t(std::uint8_t(p[3])) << 24;
}

// Unit normal of the triangle (v0, v1, v2) (right-handed winding), or (0,0,0) when it is
// degenerate by the library's one rule (geometry/degenerate_face.h: a repeated index, a
// non-finite corner, or an area vector below 64 eps of its bound: a direction made of rounding
// noise is no normal). The cross product is scaled by its largest component before the length is
// taken, so its square neither overflows nor underflows (divisors checked).
Vec3d triangle_normal(const Mesh& mesh, std::uint32_t v0, std::uint32_t v1, std::uint32_t v2) {
  if (triangle_degenerate_kind(mesh.positions.data(), v0, v1, v2) != DegenerateKind::None) return {0, 0, 0};
  const Vec3d a = mesh.position(v0), b = mesh.position(v1), c = mesh.position(v2);
  Vec3d n = cross(b - a, c - a);
  const double m = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
  if (!(m > 0) || !std::isfinite(m)) return {0, 0, 0};
  n = n * (1.0 / m);
  return n * (1.0 / length(n));  // length in [1, sqrt(3)]
}

// Facet normals as read, checked against the winding: exporters often write (0,0,0) or the
// opposite normal. A zero normal, or one pointing away from the triangle's own (dot < 0), is
// replaced by the triangle's unit normal; a zero normal of a triangle with no area becomes +z.
// A triangle with no area has no winding to be against: its non-zero facet normal is kept as read
// (the writer gives such triangles +z; reading that back changes nothing).
// A NaN/Inf facet normal (OpenSCAD writes `facet normal nan nan nan` for a sliver) is replaced the
// same way as a zero one: the triangle's own, +z with no area; a facet normal repeats the winding,
// and every command refused the whole file for it. Counted in the note. All zero: none kept.
// Whole file: when the median facet normal (of triangles with area and a finite non-zero normal)
// is more than 45 degrees from its triangle's own, the normals are not the triangles' (Meshmixer
// writes them in its Y-up frame beside Z-up positions: 60-90 degrees off on most facets, and the
// per-facet rule above would keep every one that is less than 90 off): every facet with area gets
// its triangle's own, and a note gives the median (only where the per-facet rule would keep one
// more than 45 degrees off: a file whose usable normals are all against the winding keeps its note). Clean files have medians below a degree;
// exporters' rounding never reaches 45.
void finish(Mesh& mesh, std::vector<double>& normals, const PositionMerger& merger, ReadInfo& info) {
  bool any = false;
  for (double n : normals) any = any || n != 0;
  if (any) {
    std::size_t zero = 0, against = 0, no_area = 0, nonfinite = 0;
    std::vector<float> cosines;  // per facet with area and a usable normal: cos(facet normal, triangle's own)
    cosines.reserve(mesh.num_faces());
    std::size_t kept_far = 0;
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
      const std::uint32_t c = mesh.face_start[f];
      const Vec3d g = triangle_normal(mesh, mesh.corner_vertex[c], mesh.corner_vertex[c + 1], mesh.corner_vertex[c + 2]);
      const Vec3d n = get3(normals, f);
      const bool finite = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
      const bool is_zero = n.x == 0 && n.y == 0 && n.z == 0;
      const bool arealess = g.x == 0 && g.y == 0 && g.z == 0;
      if (finite && !is_zero && !arealess) {
        const double len = length(n);
        cosines.push_back(len > 0 && std::isfinite(len) ? float(dot(n, g) / len) : 0.0f);  // divisor checked
        kept_far += cosines.back() > 0 && cosines.back() < 0.70710678f;  // kept below, yet over 45 degrees off
      }
      if (!finite) {
        set3(normals, f, arealess ? Vec3d{0, 0, 1} : g);
        ++nonfinite;
      } else if (is_zero && arealess) {
        set3(normals, f, {0, 0, 1});
        ++no_area;
      } else if (is_zero) {
        set3(normals, f, g);
        ++zero;
      } else if (!arealess && !(dot(n, g) > 0)) {
        // against the winding, or perpendicular to the face
        set3(normals, f, g);
        ++against;
      }
    }
    float median = 1;
    if (!cosines.empty()) {
      auto mid = cosines.begin() + std::ptrdiff_t(cosines.size() / 2);
      std::nth_element(cosines.begin(), mid, cosines.end());
      median = *mid;
    }
    const bool other_frame = median < 0.70710678f && kept_far > 0;  // cos 45 degrees
    if (other_frame) {  // every facet with area gets its triangle's own
      std::size_t replaced = 0;
      for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        const std::uint32_t c = mesh.face_start[f];
        const Vec3d g = triangle_normal(mesh, mesh.corner_vertex[c], mesh.corner_vertex[c + 1], mesh.corner_vertex[c + 2]);
        if (g.x == 0 && g.y == 0 && g.z == 0) continue;  // no area: as decided above
        set3(normals, f, g);
        ++replaced;
      }
      const double degrees = std::acos(double(std::max(-1.0f, median))) * 180.0 / kPi;
      info.notes.push_back("facet normals replaced by the triangles' own on all " + std::to_string(replaced) +
                           " facets with area: the median is " + std::to_string(int(std::lround(degrees))) +
                           " degrees from its triangle's own (normals in another frame, as Meshmixer writes them)");
    }
    mesh.face_normals = std::move(normals);
    if (!other_frame && zero + against + no_area + nonfinite > 0)
      info.notes.push_back("facet normals replaced by the triangles' own: " + std::to_string(zero) + " zero, " +
                           std::to_string(against) + " against the winding" +
                           (no_area > 0 ? ", " + std::to_string(no_area) + " zero on a triangle with no area (+z)" : std::string()) +
                           (nonfinite > 0 ? ", " + std::to_string(nonfinite) + " NaN or Inf (+z where no area)" : std::string()));
  } else if (mesh.num_faces() > 0) {
    info.notes.push_back("facet normals all (0,0,0): not kept (normals are computed from the triangles where needed)");
  }
  info.merged_vertices = merger.merged();
  if (merger.merged() > 0)
    info.notes.push_back("merged " + std::to_string(merger.merged()) + " corners with identical positions into " +
                         std::to_string(mesh.num_vertices()) + " shared vertices");
}

// The 2 attribute bytes of each binary facet as colours, by the one convention a file marks as its
// own: Materialise Magics writes "COLOR=" and four bytes R G B A (the default colour) into the
// 80-byte header; a facet whose attribute has bit 15 clear has its own colour, R in bits 0-4,
// G in 5-9, B in 10-14 (5 bits each, 31 = full: value / 31); bit 15 set means the default colour
// (bytes / 255). Colours are stored as read (uchar-like values in [0,1], 3 channels; a default
// alpha other than 255 is named in a note). A COLOR= header with every attribute 0 is read as no
// colours (every facet black by the rule: a tool that copied the header, not a colour), with a note.
// Without a COLOR= header the bytes have no marked meaning (VisCAM/SolidView put B,G,R with bit 15
// set "valid"; others write 0xFFFF or counts), so non-zero bytes are not read, and a note says so.
void read_attribute_colors(std::string_view header, const std::vector<std::uint16_t>& attributes, Mesh& mesh,
                           ReadInfo& info) {
  std::size_t nonzero = 0;
  for (std::uint16_t a : attributes) nonzero += a != 0;
  const std::size_t key = header.find("COLOR=");
  const bool materialise = key != std::string_view::npos && key + 6 + 4 <= header.size();
  if (!materialise) {
    if (nonzero > 0)
      info.notes.push_back("attribute bytes non-zero on " + std::to_string(nonzero) + " of " +
                           std::to_string(attributes.size()) +
                           " facets, no COLOR= in the header: not read as colours (no marked convention)");
    return;
  }
  if (nonzero == 0) {
    info.notes.push_back("header has COLOR= but every facet's attribute bytes are 0: no colours read");
    return;
  }
  const unsigned char* d = reinterpret_cast<const unsigned char*>(header.data() + key + 6);
  const float fallback[3] = {d[0] / 255.0f, d[1] / 255.0f, d[2] / 255.0f};
  mesh.color_channels = 3;
  mesh.colors_are_float = false;
  mesh.face_colors.resize(3 * attributes.size());
  std::size_t own = 0;
  for (std::size_t f = 0; f < attributes.size(); ++f) {
    const std::uint16_t a = attributes[f];
    float* c = &mesh.face_colors[3 * f];
    if (a & 0x8000u) {
      std::copy(fallback, fallback + 3, c);
    } else {
      c[0] = float(a & 31u) / 31.0f;
      c[1] = float((a >> 5) & 31u) / 31.0f;
      c[2] = float((a >> 10) & 31u) / 31.0f;
      ++own;
    }
  }
  info.notes.push_back("face colours read from the attribute bytes (Materialise COLOR= header): " + std::to_string(own) +
                       " facets with their own colour, " + std::to_string(attributes.size() - own) +
                       " with the header's default" +
                       (d[3] != 255 && own < attributes.size() ? ", whose alpha " + std::to_string(int(d[3])) + " is not kept" : std::string()));
}

Mesh read_binary(std::string_view bytes, std::uint32_t n, ReadInfo& info) {
  Mesh mesh;
  mesh.precision = ValuePrecision::Float;
  PositionMerger merger(mesh, std::size_t(n) * 3 / 5);  // closed meshes: V ~ F/2 = 3n/6
  reserve_bulk(mesh.positions, std::size_t(n) * 3 / 2 + 3);
  reserve_bulk(mesh.corner_vertex, 3 * std::size_t(n));
  reserve_bulk(mesh.face_start, std::size_t(n) + 1);
  std::vector<double> normals(3 * std::size_t(n));
  std::vector<std::uint16_t> attributes(n);
  const char* p = bytes.data() + 84;
  for (std::uint32_t t = 0; t < n; ++t, p += 50) {
    for (int k = 0; k < 3; ++k) normals[3 * std::size_t(t) + std::size_t(k)] = load_le_float(p + 4 * k);
    for (int c = 0; c < 3; ++c) {
      const char* q = p + 12 + 12 * c;
      mesh.corner_vertex.push_back(merger.add(load_le_float(q), load_le_float(q + 4), load_le_float(q + 8)));
    }
    mesh.face_start.push_back(std::uint32_t(mesh.corner_vertex.size()));
    attributes[t] = std::uint16_t(std::uint8_t(p[48]) | std::uint16_t(std::uint8_t(p[49])) << 8);
  }
  finish(mesh, normals, merger, info);
  read_attribute_colors(bytes.substr(0, 80), attributes, mesh, info);
  return mesh;
}

Mesh read_ascii(std::string_view bytes, const std::string& name, ReadInfo& info) {
  Mesh mesh;
  const char* p = bytes.data();
  const char* const end = p + bytes.size();
  std::size_t line = 1;
  PositionMerger merger(mesh, bytes.size() / 200);  // a facet takes ~250 bytes of text
  std::vector<double> normals;
  bool any_double = false;

  auto skip_ws = [&] {
    while (p < end && is_space_or_newline(*p)) {
      if (*p == '\n') ++line;
      ++p;
    }
  };
  auto word = [&]() -> std::string_view {
    skip_ws();
    const char* b = p;
    while (p < end && !is_space_or_newline(*p)) ++p;
    return std::string_view(b, std::size_t(p - b));
  };
  auto expect = [&](std::string_view w) {
    const std::size_t at = (skip_ws(), line);
    const std::string_view got = word();
    if (got != w)
      fail(name, at, "expected '" + std::string(w) + "', found '" + (got.empty() ? std::string("end of file") : std::string(got.substr(0, 40))) + "'");
  };
  auto number = [&]() -> double {
    skip_ws();
    const char* b = p;
    double x;
    if (p == end) fail(name, line, "file ends inside a facet");
    if (!parse_double(p, end, x)) fail(name, line, "malformed number '" + token_at(b, end) + "'");
    if (!any_double && (has_more_digits_than_float(b, p) || outside_float_range(x))) any_double = true;
    return x;
  };
  auto rest_of_line = [&] {
    while (p < end && *p != '\n') ++p;
  };

  std::size_t solids = 0;
  for (;;) {
    skip_ws();
    if (p == end) break;
    expect("solid");
    rest_of_line();  // the solid's name
    ++solids;
    for (;;) {
      const std::size_t at = (skip_ws(), line);
      const std::string_view w = word();
      if (w == "endsolid") {
        rest_of_line();
        break;
      }
      if (w != "facet")
        fail(name, at, w.empty() ? std::string("file ends inside a solid (no endsolid)")
                                 : "expected 'facet' or 'endsolid', found '" + std::string(w.substr(0, 40)) + "'");
      expect("normal");
      for (int k = 0; k < 3; ++k) normals.push_back(number());
      expect("outer");
      expect("loop");
      const std::size_t first = mesh.corner_vertex.size();
      for (;;) {
        const std::size_t vat = (skip_ws(), line);
        const std::string_view v = word();
        if (v == "endloop") break;
        if (v != "vertex")
          fail(name, vat, v.empty() ? std::string("file ends inside a facet")
                                    : "expected 'vertex' or 'endloop', found '" + std::string(v.substr(0, 40)) + "'");
        const double x = number(), y = number(), z = number();
        mesh.corner_vertex.push_back(merger.add(x, y, z));
      }
      const std::size_t size = mesh.corner_vertex.size() - first;
      if (size < 3)
        fail(name, line, "facet has " + std::to_string(size) + (size == 1 ? " vertex" : " vertices") +
                             " (a face needs at least 3)");
      mesh.face_start.push_back(std::uint32_t(mesh.corner_vertex.size()));
      expect("endfacet");
    }
  }
  if (solids == 0) fail(name, 1, "file is empty");
  mesh.precision = any_double ? ValuePrecision::Double : ValuePrecision::Float;
  finish(mesh, normals, merger, info);
  return mesh;
}

}  // namespace

Mesh read_stl(std::string_view file_bytes, const std::string& name, ReadInfo& info) {
  if (file_bytes.size() >= 84) {
    const std::uint32_t n = load_le_u32(file_bytes.data() + 80);
    if (84 + 50 * std::uint64_t(n) == file_bytes.size()) return read_binary(file_bytes, n, info);
  }
  // Not binary by its size: text, after the checks every text reader makes.
  refuse_utf16(file_bytes, name);
  const LineEndings text(skip_utf8_bom(file_bytes));  // CR, LF, CRLF, mixed: all LF
  const std::string_view bytes = text.lf();
  // Ascii: starts with "solid" and reads as text. Many binary files also start with "solid" in
  // their 80-byte header, but their counts and floats soon hold control bytes (0x00-0x08...).
  const char* p = bytes.data();
  const char* end = p + bytes.size();
  while (p < end && is_space_or_newline(*p)) ++p;
  if (end - p >= 5 && std::memcmp(p, "solid", 5) == 0 && (end - p == 5 || is_space_or_newline(p[5]))) {
    const char* control = nullptr;  // the first byte no text holds, in the first 1024
    for (const char* q = bytes.data(); q < end && q < bytes.data() + 1024 && !control; ++q) {
      const unsigned char c = static_cast<unsigned char>(*q);
      if (!(c >= 0x20 || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v')) control = q;
    }
    if (!control || bytes.size() < 84) return read_ascii(bytes, name, info);
    // Starts as ascii STL with a facet on lines of text before a control byte, and its size is no
    // binary STL's: an ascii file cut or overwritten. Name the byte's line and both readings.
    // (A binary header is one line of 80 bytes: no newline and 'facet' before its control bytes.)
    const std::string_view before(bytes.data(), std::size_t(control - bytes.data()));
    if (before.find('\n') != std::string_view::npos && before.find("facet") != std::string_view::npos) {
      const std::size_t line = 1 + std::size_t(std::count(bytes.data(), control, '\n'));
      const std::uint32_t n = load_le_u32(bytes.data() + 80);
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", unsigned(static_cast<unsigned char>(*control)));
      fail(name, line, "starts with 'solid' (ascii STL) but holds the control byte " + std::string(hex) +
                           " here, and is no binary STL either: its header says " + std::to_string(n) + " triangles (" +
                           std::to_string(84 + 50 * std::uint64_t(n)) + " bytes), the file has " +
                           std::to_string(bytes.size()) + " bytes");
    }
  }
  if (bytes.size() >= 84) {
    const std::uint32_t n = load_le_u32(bytes.data() + 80);
    fail(name, 0, "binary STL header says " + std::to_string(n) + " triangles (" + std::to_string(84 + 50 * std::uint64_t(n)) +
                      " bytes) but the file has " + std::to_string(bytes.size()) + " bytes: truncated or not STL");
  }
  fail(name, 0, "not an STL file (too short for binary STL and no 'solid' keyword)");
}

namespace {

void put_float(ByteSink& out, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  const char b[4] = {char(u & 0xff), char((u >> 8) & 0xff), char((u >> 16) & 0xff), char((u >> 24) & 0xff)};
  out.append(b, 4);
}

}  // namespace

void write_stl(const Mesh& mesh, bool binary, ByteSink& out, WriteInfo& info) {
  info.split_vertices = 0;
  std::size_t triangles = 0, polygons = 0;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    triangles += mesh.face_size(f) - 2;
    polygons += mesh.face_size(f) > 3;
  }
  if (triangles > std::numeric_limits<std::uint32_t>::max()) fail("<output>", 0, "too many triangles for STL (more than 2^32)");
  if (polygons > 0) info.notes.push_back("split " + std::to_string(polygons) + " polygons into triangles for STL (ear clipping: inside each outline, in its winding)");
  if (mesh.has_vertex_normals() || mesh.has_corner_normals())
    info.notes.push_back("vertex and corner normals not written: STL has only facet normals");
  if (mesh.has_vertex_colors() || mesh.has_face_colors()) info.notes.push_back("colours not written: STL has none");
  if (mesh.has_texcoords()) info.notes.push_back("texture coordinates not written to STL");

  const bool face_normals = mesh.has_face_normals();
  std::size_t no_area = 0, replaced = 0;
  if (binary) {
    std::string header = "binary STL written by shadetool";
    header.resize(80, ' ');
    out += header;
    const std::uint32_t n = std::uint32_t(triangles);
    const char b[4] = {char(n & 0xff), char((n >> 8) & 0xff), char((n >> 16) & 0xff), char((n >> 24) & 0xff)};
    out.append(b, 4);
  } else {
    out += "solid shadetool\n";
  }
  std::vector<std::uint32_t> tri;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const std::uint32_t s = mesh.face_start[f], e = mesh.face_start[f + 1];
    tri.clear();  // a polygon's triangles inside its outline, in its winding (convex: the fan from corner 0)
    if (e - s >= 3) polygon_triangles(mesh.positions.data(), mesh.corner_vertex.data() + s, e - s, tri);
    for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
      const std::uint32_t v0 = mesh.corner_vertex[s + tri[t]], v1 = mesh.corner_vertex[s + tri[t + 1]],
                          v2 = mesh.corner_vertex[s + tri[t + 2]];
      const Vec3d p0 = mesh.position(v0), p1 = mesh.position(v1), p2 = mesh.position(v2);
      Vec3d n = face_normals ? get3(mesh.face_normals, f) : triangle_normal(mesh, v0, v1, v2);
      const bool usable = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) && !(n.x == 0 && n.y == 0 && n.z == 0);
      if (face_normals && !usable) {  // a zero or NaN face normal: the triangle's own instead
        n = triangle_normal(mesh, v0, v1, v2);
        ++replaced;
      }
      if (n.x == 0 && n.y == 0 && n.z == 0) n = newell_normal(mesh, f);  // a triangle of no area: its polygon's
      if (n.x == 0 && n.y == 0 && n.z == 0) {  // no area at all: no normal of its own
        n = {0, 0, 1};
        ++no_area;
      }
      if (binary) {
        for (const Vec3d* v : {static_cast<const Vec3d*>(&n), &p0, &p1, &p2}) {
          put_float(out, float(v->x));
          put_float(out, float(v->y));
          put_float(out, float(v->z));
        }
        out.append(2, '\0');
      } else {
        auto vec = [&](const Vec3d& v) {
          append_shortest(out, v.x);
          out += ' ';
          append_shortest(out, v.y);
          out += ' ';
          append_shortest(out, v.z);
          out += '\n';
        };
        out += "facet normal ";
        vec(n);
        out += "outer loop\n";
        for (const Vec3d* v : {&p0, &p1, &p2}) {
          out += "vertex ";
          vec(*v);
        }
        out += "endloop\nendfacet\n";
      }
    }
  }
  if (!binary) out += "endsolid shadetool\n";
  if (replaced > 0)
    info.notes.push_back(std::to_string(replaced) + " zero or non-finite face normals written as the triangles' own "
                                                    "facet normals");
  if (no_area > 0)
    info.notes.push_back(std::to_string(no_area) + " triangles with no area written with facet normal +z (STL "
                                                   "has no 'none'; a zero normal is never written)");
}

}  // namespace shadetool::io
