// obj_format.cpp: Wavefront OBJ, one pass over the bytes, line by line.
#include <shadetool/io/obj_format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <shadetool/core/error.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/io/engine/newell_normal.h>
#include <shadetool/io/engine/number_text.h>
#include <shadetool/io/split_face_colors.h>
#include <shadetool/io/engine/text_encoding.h>
#include <shadetool/io/engine/text_parse.h>

namespace shadetool::io {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Resolves a 1-based or negative (relative) OBJ index against `count` elements defined so far.
std::uint32_t resolve_index(std::int64_t idx, std::size_t count, const char* what, const std::string& name,
                            std::size_t line) {
  if (idx > 0 && static_cast<std::uint64_t>(idx) <= count) return static_cast<std::uint32_t>(idx - 1);
  if (idx < 0 && static_cast<std::uint64_t>(-idx) <= count) return static_cast<std::uint32_t>(std::int64_t(count) + idx);
  if (idx == 0) fail(name, line, std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
  const std::string plural = std::string(what) == "vertex" ? "vertices" : std::string(what) + "s";
  fail(name, line,
       std::string(what) + " index " + std::to_string(idx) + " out of range (" + std::to_string(count) + " " +
           (count == 1 ? std::string(what) : plural) + " defined so far)");
}

// What one pass over the lines gathers: the mesh's positions and faces as read, and the pools and
// per-corner indices the build steps turn into the mesh's arrays.
struct ObjLines {
  Mesh mesh;
  bool any_double = false;
  std::vector<double> normals;                 // vn pool, 3 per entry
  std::vector<double> tex;                     // vt pool, 3 per entry (missing components 0)
  int tex_dims = 0;                            // most components any vt had
  std::vector<float> rgba;                     // 4 per vertex once any vertex has a colour
  int color_channels = 0;                      // 3 or 4 once seen
  std::size_t colored_vertices = 0;
  std::vector<std::uint32_t> cn, ct;           // per corner, kNone where absent (allocated lazily)
  bool have_cn = false, have_ct = false;
  std::size_t corners_with_normal = 0, corners_with_tex = 0;
  // Corners naming a vn (vt) index while the file has defined no vn (vt) at all: ignored, as
  // assimp does (OpenSubdiv's shapes write `f v/vt/vn` with no vn line).
  std::size_t dangling_normal = 0, dangling_tex = 0;
  std::size_t skipped_lines = 0;
  std::string skipped_keyword;
  std::size_t skipped_empty_faces = 0, skipped_lines_l = 0, skipped_points = 0;
  std::string pending_statements;              // grouping lines since the last face
  bool any_statement = false;
};

// One line's numbers: the cursor, the line's end and number, for messages.
struct ObjLine {
  const char* q;
  const char* eol;
  std::size_t number;
};

// Parses the next number of the line into x; false at the end of the line (or a comment).
bool next_number(ObjLines& s, ObjLine& l, const std::string& name, double& x) {
  const char* b = skip_spaces(l.q, l.eol);
  if (b == l.eol || *b == '#') return false;
  l.q = b;
  if (!parse_double(l.q, l.eol, x)) fail(name, l.number, "malformed number '" + token_at(b, l.eol) + "'");
  if (!s.any_double && (has_more_digits_than_float(b, l.q) || outside_float_range(x))) s.any_double = true;
  return true;
}

// `v x y z [w]` or `v x y z r g b [a]`.
void read_v(ObjLines& s, ObjLine& l, const std::string& name) {
  double v[8];
  int n = 0;
  while (n < 8 && next_number(s, l, name, v[n])) ++n;
  if (n == 8) fail(name, l.number, "v has more than 7 values (expected x y z [w] or x y z r g b [a])");
  if (n < 3) fail(name, l.number, "v has " + std::to_string(n) + " values (need x y z)");
  if (n == 5) fail(name, l.number, "v has 5 values (expected x y z [w] or x y z r g b [a])");
  Mesh& mesh = s.mesh;
  mesh.positions.insert(mesh.positions.end(), v, v + 3);
  if (n >= 6) {
    if (s.rgba.empty()) s.rgba.assign(4 * (mesh.num_vertices() - 1), 1.0f);
    s.rgba.insert(s.rgba.end(), {float(v[3]), float(v[4]), float(v[5]), n == 7 ? float(v[6]) : 1.0f});
    s.color_channels = std::max(s.color_channels, n == 7 ? 4 : 3);
    ++s.colored_vertices;
  } else if (!s.rgba.empty()) {
    s.rgba.insert(s.rgba.end(), {1.0f, 1.0f, 1.0f, 1.0f});
  }
}

void read_vn(ObjLines& s, ObjLine& l, const std::string& name) {
  double v[3];
  int n = 0;
  while (n < 3 && next_number(s, l, name, v[n])) ++n;
  if (n < 3) fail(name, l.number, "vn has " + std::to_string(n) + " values (need x y z)");
  s.normals.insert(s.normals.end(), v, v + 3);
}

void read_vt(ObjLines& s, ObjLine& l, const std::string& name) {
  double v[3] = {0, 0, 0};
  int n = 0;
  while (n < 3 && next_number(s, l, name, v[n])) ++n;
  if (n < 1) fail(name, l.number, "vt has no values (need u [v [w]])");
  s.tex_dims = std::max(s.tex_dims, n);
  s.tex.insert(s.tex.end(), v, v + 3);
}

// `f` in the forms i, i/j, i//k, i/j/k. Returns false for an `f` with no index (skipped, counted).
bool read_f(ObjLines& s, ObjLine& l, const std::string& name) {
  Mesh& mesh = s.mesh;
  const std::size_t nv = mesh.num_vertices();
  const std::size_t first_corner = mesh.corner_vertex.size();
  const char*& q = l.q;
  const char* const eol = l.eol;
  const std::size_t line = l.number;
  for (;;) {
    q = skip_spaces(q, eol);
    if (q == eol || *q == '#') break;
    std::int64_t idx;
    const char* tok = q;
    if (!parse_int64(q, eol, idx)) fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
    mesh.corner_vertex.push_back(resolve_index(idx, nv, "vertex", name, line));
    std::uint32_t t = kNone, nn = kNone;
    if (q < eol && *q == '/') {
      ++q;
      if (q < eol && *q != '/') {
        if (!parse_int64(q, eol, idx) || (q < eol && *q != '/' && !is_space(*q)))
          fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
        if (s.tex.empty()) ++s.dangling_tex;
        else t = resolve_index(idx, s.tex.size() / 3, "texcoord", name, line);
      }
      if (q < eol && *q == '/') {
        ++q;
        if (!parse_int64(q, eol, idx)) fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
        if (s.normals.empty()) ++s.dangling_normal;
        else nn = resolve_index(idx, s.normals.size() / 3, "normal", name, line);
      }
    }
    if (q < eol && !is_space(*q)) fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
    if (nn != kNone) {
      if (!s.have_cn) s.cn.assign(mesh.corner_vertex.size() - 1, kNone);
      s.have_cn = true;
      ++s.corners_with_normal;
    }
    if (s.have_cn) s.cn.push_back(nn);
    if (t != kNone) {
      if (!s.have_ct) s.ct.assign(mesh.corner_vertex.size() - 1, kNone);
      s.have_ct = true;
      ++s.corners_with_tex;
    }
    if (s.have_ct) s.ct.push_back(t);
  }
  const std::size_t size = mesh.corner_vertex.size() - first_corner;
  if (size == 0) {  // `f` alone: nothing to keep (other readers skip it too)
    ++s.skipped_empty_faces;
    return false;
  }
  if (size < 3)
    fail(name, line, "face has " + std::to_string(size) + (size == 1 ? " vertex" : " vertices") +
                         " (a face needs at least 3)");
  if (mesh.corner_vertex.size() > std::numeric_limits<std::uint32_t>::max() - 1)
    fail(name, line, "too many face corners (more than 2^32)");
  mesh.face_start.push_back(static_cast<std::uint32_t>(mesh.corner_vertex.size()));
  if (s.any_statement) {
    if (!s.pending_statements.empty()) mesh.group_statements.push_back(std::move(s.pending_statements));
    s.pending_statements.clear();
    mesh.face_group_run.push_back(static_cast<std::uint32_t>(mesh.group_statements.size()));
  }
  return true;
}

// Step 1, read: every line, in order, into `s`.
void read_lines(std::string_view bytes, const std::string& name, ObjLines& s, ProgressCursor& progress) {
  Mesh& mesh = s.mesh;
  const char* p = bytes.data();
  const char* const end = p + bytes.size();
  std::size_t line = 0;

  // OBJ is text: a NUL byte means binary data (another format, or garbage), not lines to skip.
  if (const void* nul = std::memchr(p, '\0', bytes.size()))
    fail(name, 1 + std::size_t(std::count(p, static_cast<const char*>(nul), '\n')),
         "binary data (a NUL byte) in an OBJ file: not a text mesh");

  // Capacity guessed from the file size, generously (untouched capacity costs address space,
  // not memory): a `v` line is >= 24 bytes in practice, a triangle line about 12 per corner.
  reserve_bulk(mesh.positions, bytes.size() / 24 * 3);
  reserve_bulk(mesh.corner_vertex, bytes.size() / 8);
  reserve_bulk(mesh.face_start, bytes.size() / 24 + 1);

  while (p < end) {
    if ((++line & 0xffff) == 0) progress.at(std::uint64_t(p - bytes.data()));  // bytes read, every 65536 lines
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
    if (!eol) eol = end;
    const char* q = skip_spaces(p, eol);
    if (q < eol && *q != '#') {
      const char* kw = q;
      while (q < eol && !is_space(*q)) ++q;
      const std::size_t kwlen = std::size_t(q - kw);
      ObjLine l{q, eol, line};
      if (kwlen == 1 && kw[0] == 'v') {
        read_v(s, l, name);
      } else if (kwlen == 2 && kw[0] == 'v' && kw[1] == 'n') {
        read_vn(s, l, name);
      } else if (kwlen == 2 && kw[0] == 'v' && kw[1] == 't') {
        read_vt(s, l, name);
      } else if (kwlen == 1 && kw[0] == 'f') {
        read_f(s, l, name);
      } else if ((kwlen == 1 && (kw[0] == 'o' || kw[0] == 'g' || kw[0] == 's')) ||
                 std::string_view(kw, kwlen) == "usemtl" || std::string_view(kw, kwlen) == "mtllib") {
        // Grouping, smoothing groups and materials: kept verbatim, in place relative to the faces.
        if (!s.any_statement) mesh.face_group_run.assign(mesh.num_faces(), 0);
        s.any_statement = true;
        const char* e = eol;
        while (e > kw && is_space(e[-1])) --e;
        s.pending_statements.append(kw, std::size_t(e - kw));
        s.pending_statements += '\n';
      } else if (kwlen == 1 && kw[0] == 'l') {
        ++s.skipped_lines_l;
      } else if (kwlen == 1 && kw[0] == 'p') {
        ++s.skipped_points;
      } else {
        if (s.skipped_lines++ == 0) s.skipped_keyword.assign(kw, std::min<std::size_t>(kwlen, 40));
      }
    }
    if (eol == end) break;
    p = eol + 1;
  }
  if (!s.pending_statements.empty()) mesh.group_statements.push_back(std::move(s.pending_statements));
}

// Step 2, validate: a file without vertices is not a mesh.
void validate_lines(const ObjLines& s, const std::string& name) {
  if (s.mesh.num_vertices() == 0 && s.skipped_lines > 0)
    fail(name, 0, "not an OBJ file: no vertices, " + std::to_string(s.skipped_lines) + " line" +
                      (s.skipped_lines == 1 ? "" : "s") + " with unknown keywords (first: '" + s.skipped_keyword + "')");
  if (s.mesh.num_vertices() == 0) fail(name, 0, "no vertex (`v` line) in the file: not a mesh");
  if (s.mesh.num_vertices() > std::numeric_limits<std::uint32_t>::max())
    fail(name, 0, "too many vertices (more than 2^32)");
}

// Step 3, build: the vn pool and per-corner indices become the mesh's corner normals.
void build_corner_normals(ObjLines& s, ReadInfo& info) {
  Mesh& mesh = s.mesh;
  const std::size_t corners = mesh.corner_vertex.size();
  if (s.corners_with_normal == 0) return;
  // Faces without vn beside faces with vn: those corners get their face's normal (the mesh
  // holds a normal for every corner or none); the faces that had vn keep theirs exactly.
  std::vector<double>& normals = s.normals;
  std::vector<std::uint32_t>& cn = s.cn;
  std::size_t filled = 0, degenerate = 0;
  std::uint32_t face_entry = kNone;
  for (std::size_t f = 0; f + 1 < mesh.face_start.size(); ++f) {
    face_entry = kNone;
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      if (cn[c] != kNone) continue;
      if (face_entry == kNone) {
        Vec3d n = newell_normal(mesh, f);
        if (n.x == 0 && n.y == 0 && n.z == 0) {
          n = {0, 0, 1};  // a face with no area has no normal of its own: +z, counted
          ++degenerate;
        }
        face_entry = std::uint32_t(normals.size() / 3);
        normals.insert(normals.end(), {n.x, n.y, n.z});
      }
      cn[c] = face_entry;
      ++filled;
    }
  }
  mesh.corner_normals = std::move(normals);
  mesh.corner_normal_index = std::move(cn);
  if (filled > 0)
    info.notes.push_back("normals (vn): " + std::to_string(filled) + " of " + std::to_string(corners) +
                         " face corners have none: given their face's normal" +
                         (degenerate > 0 ? " (" + std::to_string(degenerate) + (degenerate == 1 ? " face" : " faces") + " with no area: +z)"
                                          : std::string()));
}

// Step 3, build: the vt pool and per-corner indices become the mesh's texture coordinates.
void build_texcoords(ObjLines& s) {
  if (s.corners_with_tex == 0) return;
  Mesh& mesh = s.mesh;
  // Corners without vt keep none (kNoTexcoord): OBJ writes them back as they were.
  const int dims = std::max(2, s.tex_dims);
  mesh.texcoord_dims = dims;
  mesh.texcoords.resize(s.tex.size() / 3 * std::size_t(dims));
  for (std::size_t i = 0; i < s.tex.size() / 3; ++i)
    for (int k = 0; k < dims; ++k) mesh.texcoords[i * std::size_t(dims) + std::size_t(k)] = s.tex[3 * i + std::size_t(k)];
  mesh.corner_texcoord_index = std::move(s.ct);
  static_assert(kNone == kNoTexcoord, "a corner without vt is kNoTexcoord in the mesh");
}

// Step 3, build: `v x y z r g b [a]` colours become vertex colours (white where a vertex has none).
void build_vertex_colors(ObjLines& s, ReadInfo& info) {
  if (s.rgba.empty()) return;
  Mesh& mesh = s.mesh;
  mesh.color_channels = s.color_channels;
  mesh.colors_are_float = true;
  mesh.vertex_colors.resize(mesh.num_vertices() * std::size_t(s.color_channels));
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < s.color_channels; ++k)
      mesh.vertex_colors[v * std::size_t(s.color_channels) + std::size_t(k)] = s.rgba[4 * v + std::size_t(k)];
  if (s.colored_vertices < mesh.num_vertices())
    info.notes.push_back(std::to_string(mesh.num_vertices() - s.colored_vertices) + " of " +
                         std::to_string(mesh.num_vertices()) + " vertices have no colour: given white");
}

// What was read and not kept, one note each kind.
void note_skipped(const ObjLines& s, ReadInfo& info) {
  if (s.dangling_normal + s.dangling_tex > 0) {
    std::string what;
    if (s.dangling_normal > 0) what = std::to_string(s.dangling_normal) + " normal (vn)";
    if (s.dangling_tex > 0)
      what += (what.empty() ? "" : " and ") + std::to_string(s.dangling_tex) + " texture (vt)";
    info.notes.push_back("face corners name " + what + " indices but the file defines no " +
                         (s.dangling_normal > 0 && s.dangling_tex > 0 ? "vn or vt" : s.dangling_normal > 0 ? "vn" : "vt") +
                         " line before them: those indices ignored (as assimp does)");
  }
  const std::size_t total = s.skipped_lines + s.skipped_lines_l + s.skipped_points + s.skipped_empty_faces;
  if (total == 0) return;
  std::string what;
  auto add = [&](std::size_t n, const std::string& kind) {
    if (n > 0) what += (what.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  };
  add(s.skipped_lines_l, "`l` (polyline)");
  add(s.skipped_points, "`p` (point)");
  add(s.skipped_empty_faces, "`f` with no indices");
  if (s.skipped_lines > 0)
    add(s.skipped_lines, "with keywords shadetool does not use (first: '" + s.skipped_keyword + "')");
  info.notes.push_back("skipped " + std::to_string(total) + " line" + (total == 1 ? "" : "s") + ": " + what);
}

}  // namespace

Mesh read_obj(std::string_view file_bytes, const std::string& name, ReadInfo& info) {
  refuse_utf16(file_bytes, name);
  const LineEndings lines(skip_utf8_bom(file_bytes));  // CR, LF, CRLF, mixed: all LF
  ObjLines s;
  read_lines(lines.lf(), name, s, info.progress);
  validate_lines(s, name);
  build_corner_normals(s, info);
  build_texcoords(s);
  build_vertex_colors(s, info);
  note_skipped(s, info);
  // Values are kept as parsed (the double nearest to the text), never rounded: precision is only
  // the hint for the value type binary writers use.
  s.mesh.precision = s.any_double ? ValuePrecision::Double : ValuePrecision::Float;
  return std::move(s.mesh);
}

void write_obj(const Mesh& input, ByteSink& out, WriteInfo& info) {
  // Face colours: OBJ holds colours per vertex only, so vertices are split until every corner's
  // vertex carries its face's colour (split_face_colors.h). Faces and corners keep their order, so
  // corner c of `mesh` is corner c of `input`: normals and texcoords stay indexed per corner.
  std::size_t added = 0, unreferenced = 0;
  Mesh split;
  const bool must_split = input.has_face_colors();
  if (must_split) {
    split = split_face_colors(input, added, unreferenced);
    info.notes.push_back("face colours written as vertex colours (v x y z r g b): " + std::to_string(added) +
                         (added == 1 ? " vertex" : " vertices") + " added so that every face's corners carry its colour");
    if (input.has_vertex_colors())
      info.notes.push_back("vertex colours replaced by the face colours: OBJ holds one colour per vertex");
    else if (unreferenced > 0)
      info.notes.push_back(std::to_string(unreferenced) + (unreferenced == 1 ? " vertex" : " vertices") +
                           " used by no face written white");
  }
  info.split_vertices = added;
  const Mesh& mesh = must_split ? split : input;
  out += "# written by shadetool\n";
  for (const std::string& c : mesh.comments)  // another format's comment lines (PLY header comments) as `#` lines
    if (c != "comment written by shadetool" && c.find('\n') == std::string::npos && c.find('\r') == std::string::npos)
      out += "# " + c + "\n";
  const std::size_t nv = mesh.num_vertices();
  const bool colors = mesh.has_vertex_colors() && mesh.vertex_colors.size() == nv * std::size_t(mesh.color_channels);
  // `v x y z r g b`: readers (Blender, MeshLab, assimp) take 7 numbers as x y z w r g b or
  // refuse them, so alpha is not written.
  const int written_channels = std::min(mesh.color_channels, 3);
  if (colors && mesh.color_channels == 4) info.notes.push_back("colour alpha not written: OBJ holds v x y z r g b");
  for (std::size_t v = 0; v < nv; ++v) {
    out += "v ";
    append_shortest(out, mesh.positions[3 * v]);
    out += ' ';
    append_shortest(out, mesh.positions[3 * v + 1]);
    out += ' ';
    append_shortest(out, mesh.positions[3 * v + 2]);
    if (colors) {
      for (int k = 0; k < written_channels; ++k) {
        out += ' ';
        append_shortest_float(out, mesh.vertex_colors[v * std::size_t(mesh.color_channels) + std::size_t(k)]);
      }
    }
    out += '\n';
  }
  const bool tex = mesh.has_texcoords();
  if (tex) {
    const std::size_t dims = std::size_t(mesh.texcoord_dims);
    for (std::size_t i = 0; i + dims <= mesh.texcoords.size(); i += dims) {
      out += "vt";
      for (std::size_t k = 0; k < dims; ++k) {
        out += ' ';
        append_shortest(out, mesh.texcoords[i + k]);
      }
      out += '\n';
    }
  }
  // Which normals, and the vn index of each corner.
  enum class NormalSource { None, Corner, Vertex, Face } source = NormalSource::None;
  const std::vector<double>* pool = nullptr;
  // From `input`: split vertices share their original's vn line (index by the original vertex).
  if (input.has_corner_normals()) {
    source = NormalSource::Corner;
    pool = &input.corner_normals;
  } else if (input.has_vertex_normals()) {
    source = NormalSource::Vertex;
    pool = &input.vertex_normals;
  } else if (input.has_face_normals()) {
    source = NormalSource::Face;
    pool = &input.face_normals;
  }
  if (pool) {
    for (std::size_t i = 0; i + 3 <= pool->size(); i += 3) {
      out += "vn ";
      append_shortest(out, (*pool)[i]);
      out += ' ';
      append_shortest(out, (*pool)[i + 1]);
      out += ' ';
      append_shortest(out, (*pool)[i + 2]);
      out += '\n';
    }
  }
  const std::size_t nf = mesh.num_faces();
  // Grouping statements (mtllib, usemtl, g, o, s) go back where they were relative to the faces.
  const bool groups = mesh.has_groups();
  const bool runs_per_face = mesh.face_group_run.size() == nf;
  std::size_t next_run = 0;
  auto write_runs_until = [&](std::size_t end_run) {
    for (; next_run < end_run && next_run < mesh.group_statements.size(); ++next_run) out += mesh.group_statements[next_run];
  };
  if (groups && !runs_per_face) {
    write_runs_until(mesh.group_statements.size());  // no face positions known: all before the faces
    info.notes.push_back("grouping statements (mtllib, usemtl, g, o, s) written before the first face: their "
                         "positions among the faces were not kept");
  }
  for (std::size_t f = 0; f < nf; ++f) {
    if (groups && runs_per_face) write_runs_until(mesh.face_group_run[f]);
    out += 'f';
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      out += ' ';
      append_uint(out, std::uint64_t(mesh.corner_vertex[c]) + 1);
      const bool corner_tex = tex && mesh.corner_texcoord_index[c] != kNoTexcoord;
      if (corner_tex || source != NormalSource::None) {
        out += '/';
        if (corner_tex) append_uint(out, std::uint64_t(mesh.corner_texcoord_index[c]) + 1);
        if (source != NormalSource::None) {
          out += '/';
          const std::uint64_t n = source == NormalSource::Corner   ? input.corner_normal_index[c]
                                  : source == NormalSource::Vertex ? input.corner_vertex[c]
                                                                   : f;
          append_uint(out, n + 1);
        }
      }
    }
    out += '\n';
  }
  if (groups) write_runs_until(mesh.group_statements.size());  // what followed the last face
}

}  // namespace shadetool::io
