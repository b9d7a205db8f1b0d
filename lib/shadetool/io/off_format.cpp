// off_format.cpp: OFF, line by line.
#include <shadetool/io/off_format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/io/engine/number_text.h>
#include <shadetool/io/split_corner_normals.h>
#include <shadetool/io/engine/rgba_channels.h>
#include <shadetool/io/engine/text_encoding.h>
#include <shadetool/io/engine/text_parse.h>
#include <shadetool/io/off_binary.h>

namespace shadetool::io {

namespace {

// Walks the file line by line, skipping blank lines and comments, counting lines.
class Lines {
 public:
  Lines(std::string_view bytes) : p_(bytes.data()), end_(bytes.data() + bytes.size()) {}
  // Next line with content: [b, e) without the comment; false at the end of the file.
  bool next(const char*& b, const char*& e) {
    while (p_ < end_) {
      ++line_;
      const char* eol = static_cast<const char*>(std::memchr(p_, '\n', std::size_t(end_ - p_)));
      if (!eol) eol = end_;
      b = skip_spaces(p_, eol);
      e = std::find(b, eol, '#');
      while (e > b && is_space(e[-1])) --e;
      p_ = eol < end_ ? eol + 1 : end_;
      if (e > b) return true;
    }
    return false;
  }
  std::size_t line() const { return line_; }
  std::size_t remaining() const { return std::size_t(end_ - p_); }

 private:
  const char* p_;
  const char* end_;
  std::size_t line_ = 0;
};

// The header: [ST][C][N]OFF (optional) and the counts line.
struct OffHeader {
  bool has_st = false, has_c = false, has_n = false;
  std::uint64_t nv = 0, nf = 0;
};

// What the vertex and face lines share: the file's lines, its name for messages, and what the
// values said about the data (digits beyond float, colours written as floats).
struct OffBody {
  Lines& lines;
  const std::string& name;
  bool any_double = false;
  bool colors_float = false;

  // The next number of [p, end) into x; false at the end.
  bool number(const char*& p, const char* end, double& x) {
    const char* t = skip_spaces(p, end);
    if (t == end) return false;
    p = t;
    if (!parse_double(p, end, x)) fail(name, lines.line(), "malformed number '" + token_at(t, end) + "'");
    if (!any_double && (has_more_digits_than_float(t, p) || outside_float_range(x))) any_double = true;
    return true;
  }
  // Up to 5 colour values: a token written as an integer is 0..255; with a point or exponent it is
  // a float in [0,1].
  int color_values(const char*& p, const char* end, float* rgba) {
    int k = 0;
    bool integer = true;
    const char* t = skip_spaces(p, end);
    for (const char* c = t; c < end; ++c) integer = integer && !(*c == '.' || *c == 'e' || *c == 'E');
    double x;
    while (k < 5 && number(p, end, x)) rgba[k++] = float(x);
    if (!integer) colors_float = true;
    if (integer)
      for (int i = 0; i < k; ++i) rgba[i] /= 255.0f;
    return k;
  }
};

// The flags of a keyword [ST][C][N]OFF: sets them and returns where "OFF" should start.
std::size_t keyword_flags(std::string_view k, bool& has_st, bool& has_c, bool& has_n) {
  std::size_t i = 0;
  if (k.compare(i, 2, "ST") == 0) has_st = true, i += 2;
  if (i < k.size() && k[i] == 'C') has_c = true, ++i;
  if (i < k.size() && k[i] == 'N') has_n = true, ++i;
  return i;
}

// A binary OFF's header line, `[ST][C][N]OFF BINARY` (the first line, spaces around the words,
// CRLF allowed): its flags and the length of the line with its '\n'; false for a text OFF.
bool binary_off_header(std::string_view t, OffBinaryFlags& fl, std::size_t& header_bytes) {
  const std::size_t nl = t.find('\n');
  if (nl == std::string_view::npos) return false;
  const char* b = skip_spaces(t.data(), t.data() + nl);
  const char* e = t.data() + nl;
  while (e > b && is_space(e[-1])) --e;  // CR and spaces
  const char* q = b;
  while (q < e && !is_space(*q)) ++q;
  const std::string_view k(b, std::size_t(q - b));
  const std::size_t i = keyword_flags(k, fl.has_st, fl.has_c, fl.has_n);
  if (k.substr(i) != "OFF") return false;
  q = skip_spaces(q, e);
  if (std::string_view(q, std::size_t(e - q)) != "BINARY") return false;
  header_bytes = nl + 1;
  return true;
}

// Step 1, read the header: the keyword's flags, then the counts, bounded by the bytes that follow.
OffHeader read_off_header(Lines& lines, const std::string& name) {
  OffHeader h;
  const char *b, *e;
  if (!lines.next(b, e)) fail(name, lines.line(), "no OFF header (file has only comments or blank lines)");
  const char* q = b;
  const char* first_end = b;
  while (first_end < e && *first_end >= '0' && *first_end <= '9') ++first_end;
  const bool starts_with_counts = first_end > b && (first_end == e || is_space(*first_end));
  if (!starts_with_counts) {  // the keyword is optional: a file may start with the counts
    const char* kw = b;
    while (q < e && !is_space(*q)) ++q;
    std::string k(kw, q);
    const std::size_t i = keyword_flags(k, h.has_st, h.has_c, h.has_n);
    // A digit right after the keyword starts the counts (`OFF8 6 12`, trimesh's whitespace.off):
    // no [ST][C][N]OFF variant ends in a digit, so the keyword cannot be read otherwise.
    if (k.compare(i, 3, "OFF") == 0 && i + 3 < k.size() && k[i + 3] >= '0' && k[i + 3] <= '9') {
      q = kw + i + 3;
      k.resize(i + 3);
    }
    if (k.compare(i, std::string::npos, "OFF") != 0) {
      if (k.find("OFF") != std::string::npos)
        fail(name, lines.line(), "unsupported OFF variant '" + k + "' (supported: [ST][C][N]OFF)");
      fail(name, lines.line(), "not an OFF file (header is '" + k + "')");
    }
    q = skip_spaces(q, e);
    if (q < e && std::string_view(q, std::size_t(e - q)).substr(0, 6) == "BINARY")  // not on the first line
      fail(name, lines.line(), "binary OFF's header must be the file's first line, `[ST][C][N]OFF BINARY`");
    if (q == e) {  // the counts are on the next line
      if (!lines.next(b, e)) fail(name, lines.line(), "OFF file ends before the counts line");
      q = b;
    }
  }
  const std::size_t counts_line = lines.line();
  std::int64_t counts[3] = {0, 0, 0};
  int ncounts = 0;
  while (ncounts < 3 && skip_spaces(q, e) < e) {
    const char* t = q;
    if (!parse_int64(q, e, counts[ncounts]) || (q < e && !is_space(*q)) || counts[ncounts] < 0)
      fail(name, counts_line, "malformed count '" + token_at(t, e) + "' (expected: #vertices #faces #edges)");
    ++ncounts;
  }
  if (ncounts < 2) fail(name, counts_line, "counts line needs #vertices #faces [#edges]");
  if (skip_spaces(q, e) < e) fail(name, counts_line, "unexpected '" + token_at(q, e) + "' after the counts");
  h.nv = std::uint64_t(counts[0]);
  h.nf = std::uint64_t(counts[1]);
  // Every vertex line takes at least 6 bytes ("0 0 0\n"), every face line 8 ("3 0 1 2\n").
  if (h.nv > lines.remaining() / 6 + 1 || h.nf > lines.remaining() / 8 + 1 || h.nv > std::numeric_limits<std::uint32_t>::max())
    fail(name, counts_line, "header claims " + std::to_string(h.nv) + " vertices and " + std::to_string(h.nf) +
                                " faces but only " + std::to_string(lines.remaining()) + " bytes follow");
  return h;
}

// Step 2, the vertex lines: positions, normals (NOFF) into the mesh; colours (COFF, 4 per vertex)
// into vrgba and s t (STOFF, 2 per vertex) into vtex. channels becomes 4 when a colour has alpha.
void read_off_vertices(const OffHeader& h, OffBody& body, Mesh& mesh, std::vector<float>& vrgba,
                       std::vector<double>& vtex, int& channels) {
  const std::string& name = body.name;
  Lines& lines = body.lines;
  const std::size_t per_vertex = 3 + (h.has_n ? 3 : 0);
  reserve_bulk(mesh.positions, 3 * h.nv);
  mesh.positions.resize(3 * h.nv);
  if (h.has_n) mesh.vertex_normals.resize(3 * h.nv);
  if (h.has_c) vrgba.assign(4 * h.nv, 1.0f);
  if (h.has_st) vtex.assign(2 * h.nv, 0.0);
  const char *b, *e;
  for (std::uint64_t v = 0; v < h.nv; ++v) {
    if (!lines.next(b, e))
      fail(name, lines.line(), "file ends after " + std::to_string(v) + " of " + std::to_string(h.nv) + " vertices");
    double x[6];
    std::size_t n = 0;
    const char* p = b;
    while (n < per_vertex && body.number(p, e, x[n])) ++n;
    if (n < per_vertex)
      fail(name, lines.line(), "vertex line has " + std::to_string(n) + " values, expected " + std::to_string(per_vertex) +
                                   (h.has_n ? " (x y z nx ny nz)" : " (x y z)"));
    for (int k = 0; k < 3; ++k) mesh.positions[3 * v + std::size_t(k)] = x[k];
    if (h.has_n)
      for (int k = 0; k < 3; ++k) mesh.vertex_normals[3 * v + std::size_t(k)] = x[3 + k];
    if (h.has_c) {
      float c[5];
      int k = body.color_values(p, e, c);
      if (h.has_st) {  // the last two values are s t
        if (k < 2) fail(name, lines.line(), "vertex line is missing s t");
        k -= 2;
        vtex[2 * v] = c[k];
        vtex[2 * v + 1] = c[k + 1];
      }
      if (k != 3 && k != 4) fail(name, lines.line(), "vertex colour has " + std::to_string(k) + " values, expected r g b [a]");
      if (k == 4) channels = 4;
      for (int i = 0; i < k; ++i) vrgba[4 * v + std::size_t(i)] = c[i];
    } else if (h.has_st) {
      double s, t;
      if (!body.number(p, e, s) || !body.number(p, e, t)) fail(name, lines.line(), "vertex line is missing s t");
      vtex[2 * v] = s;
      vtex[2 * v + 1] = t;
    }
    if (skip_spaces(p, e) < e)
      fail(name, lines.line(), "vertex line has more values than the header '" + std::string(h.has_st ? "ST" : "") +
                                   (h.has_c ? "C" : "") + (h.has_n ? "N" : "") + "OFF' declares");
  }
}

// Step 3, the face lines: sizes and indices (validated against the vertex count) into the mesh,
// optional colours into frgba (4 per face, from the first face that has one; white before it).
// A line of fewer than 3 indices is not a face (assimp makes it a point or line, Blender and
// trimesh drop it): its indices and colour are checked, then it is dropped with its colour, as if
// the line were absent; the number dropped is returned (a note in read_off).
std::size_t read_off_faces(const OffHeader& h, OffBody& body, Mesh& mesh, std::vector<float>& frgba, int& channels) {
  const std::string& name = body.name;
  Lines& lines = body.lines;
  reserve_bulk(mesh.face_start, h.nf + 1);
  reserve_bulk(mesh.corner_vertex, std::min<std::uint64_t>(3 * h.nf, lines.remaining()));
  bool any_face_color = false;
  std::size_t kept = 0, short_faces = 0;
  const char *b, *e;
  for (std::uint64_t f = 0; f < h.nf; ++f) {
    if (!lines.next(b, e))
      fail(name, lines.line(), "file ends after " + std::to_string(f) + " of " + std::to_string(h.nf) + " faces");
    const char* p = b;
    const std::size_t face_line = lines.line();
    std::int64_t k;
    if (!parse_int64(p, e, k) || (p < e && !is_space(*p)) || k < 0)
      fail(name, lines.line(), "malformed face size '" + token_at(b, e) + "'");
    if (std::uint64_t(k) > std::uint64_t(e - p) + lines.remaining())
      fail(name, lines.line(), "face line has fewer indices than its size " + std::to_string(k));
    const std::size_t first_corner = mesh.corner_vertex.size();
    for (std::int64_t i = 0; i < k; ++i) {
      const char* t = skip_spaces(p, e);
      std::int64_t idx;
      // Indices may go on over the next lines (Geomview's OFF is free-format; libigl's readOFF
      // reads them with fscanf, and libigl-tutorial-data's inspired_mesh_quads_*.off write one
      // index a line). The colour, if any, follows the last index on its line.
      const char *nb, *ne;
      if (t == e && lines.next(nb, ne)) t = p = b = nb, e = ne;
      if (t == e) fail(name, face_line, "face line has " + std::to_string(i) + " indices, its size says " + std::to_string(k));
      if (!parse_int64(p, e, idx) || (p < e && !is_space(*p)))
        fail(name, lines.line(), "malformed vertex index '" + token_at(t, e) + "'");
      if (idx < 0 || std::uint64_t(idx) >= h.nv)
        fail(name, lines.line(), "vertex index " + std::to_string(idx) + " out of range (" + std::to_string(h.nv) + " vertices)");
      mesh.corner_vertex.push_back(std::uint32_t(idx));
    }
    if (mesh.corner_vertex.size() > std::numeric_limits<std::uint32_t>::max() - 1)
      fail(name, lines.line(), "too many face corners (more than 2^32)");
    float c[5] = {1, 1, 1, 1, 1};
    const bool colors_float_before = body.colors_float, any_double_before = body.any_double;
    const int kc = body.color_values(p, e, c);
    if (kc != 0 && kc != 3 && kc != 4)
      fail(name, lines.line(), "face has " + std::to_string(kc) + " values after its indices, expected none or r g b [a]");
    if (k < 3) {  // not a face: dropped with its colour (which then says nothing about the others)
      mesh.corner_vertex.resize(first_corner);
      body.colors_float = colors_float_before;
      body.any_double = any_double_before;
      ++short_faces;
      continue;
    }
    mesh.face_start.push_back(std::uint32_t(mesh.corner_vertex.size()));
    if (kc > 0) {
      if (!any_face_color) frgba.assign(4 * kept, 1.0f);
      any_face_color = true;
      if (kc == 4) channels = 4;
    }
    if (any_face_color) frgba.insert(frgba.end(), {c[0], c[1], c[2], kc == 4 ? c[3] : 1.0f});
    ++kept;
  }
  if (lines.next(b, e))
    fail(name, lines.line(), "more data than the header declares ('" + token_at(b, e) + "' after the last face)");
  return short_faces;
}

// Step 4, build: colours packed to 3 or 4 channels (four whose alpha is 1 everywhere, what the
// writer gives rgb colours, read as rgb), s t as texture coordinates per corner.
void build_off_attributes(const OffHeader& h, const OffBody& body, const std::vector<float>& vrgba,
                          const std::vector<float>& frgba, std::vector<double>& vtex, int channels, Mesh& mesh) {
  if (channels == 4) {
    bool opaque = true;
    for (std::size_t i = 3; i < vrgba.size() && opaque; i += 4) opaque = vrgba[i] == 1.0f;
    for (std::size_t i = 3; i < frgba.size() && opaque; i += 4) opaque = frgba[i] == 1.0f;
    if (opaque) channels = 3;
  }
  if (h.has_c) pack_rgba(vrgba, channels, mesh.vertex_colors);
  if (!frgba.empty()) pack_rgba(frgba, channels, mesh.face_colors);
  mesh.color_channels = channels;
  mesh.colors_are_float = body.colors_float;
  if (h.has_st) {
    mesh.texcoords = std::move(vtex);
    mesh.texcoord_dims = 2;
    mesh.corner_texcoord_index = mesh.corner_vertex;
  }
  // Values kept as parsed, never rounded; precision is the binary writers' value-type hint.
  mesh.precision = body.any_double ? ValuePrecision::Double : ValuePrecision::Float;
}

}  // namespace

Mesh read_off(std::string_view file_bytes, const std::string& name, ReadInfo& info) {
  refuse_utf16(file_bytes, name);
  OffBinaryFlags binary_flags;
  std::size_t header_bytes = 0;
  const std::string_view unmarked = skip_utf8_bom(file_bytes);
  if (binary_off_header(unmarked, binary_flags, header_bytes))
    return read_off_binary_body(unmarked.substr(header_bytes), header_bytes + (file_bytes.size() - unmarked.size()),
                                binary_flags, name, info);
  const LineEndings text(unmarked);  // CR, LF, CRLF, mixed: all LF
  Lines lines(text.lf());
  const OffHeader header = read_off_header(lines, name);
  OffBody body{lines, name};
  Mesh mesh;
  std::vector<float> vrgba, frgba;
  std::vector<double> vtex;
  int channels = 3;
  read_off_vertices(header, body, mesh, vrgba, vtex, channels);
  const std::size_t short_faces = read_off_faces(header, body, mesh, frgba, channels);
  build_off_attributes(header, body, vrgba, frgba, vtex, channels, mesh);
  if (short_faces > 0)
    info.notes.push_back("skipped " + std::to_string(short_faces) + " of " + std::to_string(header.nf) +
                         " face lines with fewer than 3 vertices (not a face), with their colours");
  return mesh;
}

void write_off(const Mesh& input, ByteSink& out, WriteInfo& info) {
  Mesh split;
  const Mesh& mesh = with_corner_normals_split(input, split, info.split_vertices);

  const bool normals = mesh.has_vertex_normals();
  const bool vcolors = mesh.has_vertex_colors();
  const bool fcolors = mesh.has_face_colors();
  const int ch = mesh.color_channels;
  if (mesh.has_face_normals()) info.notes.push_back("face normals not written: OFF has no face normals");
  if (mesh.has_texcoords()) info.notes.push_back("texture coordinates not written to OFF");

  // Float colours always carry a decimal point or exponent ("1.0", not "1"): the reader takes a
  // line of integer colour tokens as 0..255, so float 1 0 0 would come back as 1/255 0 0.
  auto color = [&](float c) {
    out += ' ';
    if (mesh.colors_are_float) {
      std::string text;
      append_shortest_float(text, c);
      out += text;
      if (text.find_first_of(".eEn") == std::string::npos) out += ".0";  // n: nan, inf
    } else {
      append_uint(out, color_to_uchar(c));
    }
  };
  out += vcolors ? "C" : "";
  out += normals ? "N" : "";
  out += "OFF\n";
  append_uint(out, mesh.num_vertices());
  out += ' ';
  append_uint(out, mesh.num_faces());
  out += " 0\n";
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) {
      if (k) out += ' ';
      append_shortest(out, mesh.positions[3 * v + std::size_t(k)]);
    }
    if (normals)
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        append_shortest(out, mesh.vertex_normals[3 * v + std::size_t(k)]);
      }
    if (vcolors) {
      for (int k = 0; k < ch; ++k) color(mesh.vertex_colors[std::size_t(ch) * v + std::size_t(k)]);
      if (ch == 3) color(1.0f);  // r g b a: readers (assimp, MeshLab) expect four components
    }
    out += '\n';
  }
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    append_uint(out, mesh.face_size(f));
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      out += ' ';
      append_uint(out, mesh.corner_vertex[c]);
    }
    if (fcolors) {
      for (int k = 0; k < ch; ++k) color(mesh.face_colors[std::size_t(ch) * f + std::size_t(k)]);
      if (ch == 3) color(1.0f);
    }
    out += '\n';
  }
}

}  // namespace shadetool::io
