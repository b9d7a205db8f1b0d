// obj_format.cpp: Wavefront OBJ, one pass over the bytes, line by line.
#include <shadetool/io/obj_format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>

#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <shadetool/core/error.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/shading_normals.h>
#include <shadetool/core/engine/usable_threads.h>
#include <shadetool/io/file_bytes.h>
#include <shadetool/io/engine/newell_normal.h>
#include <shadetool/io/engine/obj_statement_counts.h>
#include <shadetool/io/engine/rgba_channels.h>
#include <shadetool/io/engine/number_text.h>
#include <shadetool/io/split_face_colors.h>
#include <shadetool/io/engine/text_encoding.h>
#include <shadetool/io/engine/text_parse.h>

namespace shadetool::io {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Files smaller than this are read in one pass; larger ones in chunks of at least kChunkMinBytes,
// large first and small last (chunk_starts_guided).
constexpr std::size_t kParallelMinBytes = std::size_t(4) << 20;
constexpr std::size_t kChunkMinBytes = std::size_t(1) << 20;

[[noreturn]] __attribute__((noinline, cold)) void fail_index(std::int64_t idx, std::size_t count, const char* what,
                                                            const std::string& name, std::size_t line);

// Resolves a 1-based or negative (relative) OBJ index against `count` elements defined so far.
inline std::uint32_t resolve_index(std::int64_t idx, std::size_t count, const char* what, const std::string& name,
                                   std::size_t line) {
  if (idx > 0 && static_cast<std::uint64_t>(idx) <= count) return static_cast<std::uint32_t>(idx - 1);
  if (idx < 0 && static_cast<std::uint64_t>(-idx) <= count) return static_cast<std::uint32_t>(std::int64_t(count) + idx);
  fail_index(idx, count, what, name, line);
}

void fail_index(std::int64_t idx, std::size_t count, const char* what, const std::string& name, std::size_t line) {
  if (idx == 0) fail(name, line, std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
  const std::string plural = std::string(what) == "vertex" ? "vertices" : std::string(what) + "s";
  fail(name, line,
       std::string(what) + " index " + std::to_string(idx) + " out of range (" + std::to_string(count) + " " +
           (count == 1 ? std::string(what) : plural) + " defined so far)");
}

// Where one chunk of lines puts what it reads. Serial reading (one chunk) appends to the mesh's
// vectors; parallel reading writes each chunk's share at the offsets the counting pass
// (io/engine/obj_statement_counts.h) gave it (`at` = the chunk's first element of each kind,
// counted over all chunks before it).
// What one chunk of lines gathers besides the arrays it writes in place: the lazily allocated
// per-vertex colours and per-corner vn/vt indices (chunk-local: merged after all chunks), the
// grouping statements with the number of the chunk's faces before each, and what was skipped.
struct ObjChunk {
  ObjCounts at;                                // the chunk's first v, vt, vn, face, corner, line
  ObjCounts read;                              // what the chunk read so far (chunk-local counts)
  ObjCounts room;                              // parallel reading: what the counting pass found
  bool any_double = false;
  int tex_dims = 0;                            // most components any vt had
  std::vector<float> rgba;                     // 4 per chunk vertex once any has a colour
  int color_channels = 0;                      // 3 or 4 once seen
  std::size_t colored_vertices = 0;
  std::size_t weighted_vertices = 0;           // `v x y z w` with w != 1 (w not read)
  std::vector<std::uint32_t> cn, ct;           // per chunk corner, kNone where absent (lazily)
  bool have_cn = false, have_ct = false;
  std::size_t corners_with_normal = 0, corners_with_tex = 0;
  // Corners naming a vn (vt) index while the file has defined no vn (vt) at all: ignored, as
  // assimp does (OpenSubdiv's shapes write `f v/vt/vn` with no vn line).
  std::size_t dangling_normal = 0, dangling_tex = 0;
  std::size_t skipped_lines = 0;
  std::string skipped_keyword;
  std::size_t skipped_empty_faces = 0, skipped_lines_l = 0, skipped_points = 0;
  std::size_t skipped_short_faces = 0;         // `f` with 1 or 2 vertices: not a face
  // What read_f takes back when a face has 1 or 2 vertices: the counters as before the face.
  // Saved here, in memory, not in locals: as six locals live across the corner loop they made the
  // 2-thread read's CPU time 5% higher (bench/io/results.md, io7; register pressure, presumably).
  struct FaceUndo {
    bool have_cn, have_ct;
    std::size_t corners_with_normal, corners_with_tex, dangling_normal, dangling_tex;
  } undo{};
  struct Statement {
    std::size_t faces_before;                  // chunk faces read before the line
    std::size_t begin, end;                    // the line in `statement_text`
  };
  std::vector<Statement> statements;           // grouping lines (o, g, s, usemtl, mtllib) in order
  // One pass only: the bytes read so far go to `progress` every 65536 lines (core/progress.h),
  // measured from `base`, the text's first byte.
  ProgressCursor* progress = nullptr;
  const char* base = nullptr;
  std::string statement_text;
};

// The arrays a chunk writes: in serial reading the mesh's vectors (appended to), in parallel
// reading the same vectors, sized by the counting pass, written at the chunk's offsets.
struct ObjArrays {
  Mesh& mesh;
  std::vector<double>& normals;                // vn pool, 3 per entry
  std::vector<double>& tex;                    // vt pool, 3 per entry (missing components 0)
};

// One line's numbers: the cursor, the end of the chunk (the line ends at the first '\n' or there:
// the parsers stop at the line feed, so a line is scanned once, not searched for its end first)
// and the line's number, for messages.
struct ObjLine {
  const char* q;
  const char* end;
  std::size_t number;
};

inline bool at_line_end(const char* q, const char* end) { return q == end || *q == '\n'; }

// Line continuation (the OBJ spec: a `\` ending a line continues its statement on the next line).
// Looked for only where a reader expected a token and could not parse one (its error path), so
// ordinary lines pay nothing. `\` at q followed by spaces only up to the line feed: the first byte
// of the next line, or `end` when the text ends there (then no line follows: a final line feed
// starts none, as read_lines counts lines); nullptr when q does not continue the line. Every
// function of the error path takes the line number by value and none takes the reader's ObjLine
// by reference, so the hot loops keep theirs in registers.
inline const char* continuation_at(const char* q, const char* end) {
  if (q == end || *q != '\\') return nullptr;
  const char* r = skip_spaces(q + 1, end);
  if (r == end) return end;
  if (*r != '\n') return nullptr;
  return r + 1;
}

// The error path of a reader that wanted a token at b: where the statement continues (the caller
// counts a line when that is not `end`), or the error `what 'TOKEN'` naming the line.
__attribute__((noinline, cold)) const char* continued_or_fail(const char* b, const char* end, std::size_t number,
                                                              const std::string& name, const char* what) {
  const char* next = continuation_at(b, end);
  if (!next) fail(name, number, std::string(what) + " '" + token_at(b, end) + "'");
  return next;
}

// Whether the line [from, eol) ends in a `\` (spaces after it allowed): read_lines' test for text a
// statement reader left unread (a comment, a grouping statement's words, values it does not read).
inline bool ends_in_backslash(const char* from, const char* eol) {
  while (eol > from && is_space(eol[-1])) --eol;
  return eol > from && eol[-1] == '\\';
}

// Parses the next number of the line into x; false at the end of the line (or a comment).
// (A `\` ending the line continues the statement: the number is looked for on the next line.)
inline bool next_number(ObjChunk& s, ObjLine& l, const std::string& name, double& x) {
  for (;;) {
    const char* b = skip_spaces(l.q, l.end);
    if (at_line_end(b, l.end) || *b == '#') return false;
    l.q = b;
    bool more_digits = false;
    if (parse_double_counting_digits(l.q, l.end, x, more_digits)) {
      if (!s.any_double && (more_digits || outside_float_range(x))) s.any_double = true;
      return true;
    }
    l.q = continued_or_fail(b, l.end, l.number, name, "malformed number");
    if (l.q != l.end) ++l.number;
  }
}

// Raised in parallel reading when a chunk holds more (or fewer) elements than the counting pass
// gave it room for: the two passes split some text differently, and the file is read in one pass.
struct Miscounted {};

// Appends (serial) or stores at element `i` (parallel) n values of one kind.
template <bool kPlaced, class T>
inline void put(std::vector<T>& v, std::size_t i, const T* values, std::size_t n) {
  if constexpr (kPlaced) {
    std::copy(values, values + n, v.data() + i * n);
  } else {
    for (std::size_t k = 0; k < n; ++k) v.push_back(values[k]);
  }
}

// `v x y z [w]` or `v x y z r g b [a]`.
template <bool kPlaced>
void read_v(ObjChunk& s, ObjArrays& a, ObjLine& l, const std::string& name) {
  double v[8];
  int n = 0;
  while (n < 8 && next_number(s, l, name, v[n])) ++n;
  if (n == 8) fail(name, l.number, "v has more than 7 values (expected x y z [w] or x y z r g b [a])");
  if (n < 3) fail(name, l.number, "v has " + std::to_string(n) + " values (need x y z)");
  if (n == 5) fail(name, l.number, "v has 5 values (expected x y z [w] or x y z r g b [a])");
  if (kPlaced && s.read.v >= s.room.v) throw Miscounted{};
  put<kPlaced>(a.mesh.positions, s.at.v + s.read.v, v, 3);
  ++s.read.v;
  if (n == 4 && v[3] != 1.0) ++s.weighted_vertices;  // w: not read (note_skipped)
  if (n >= 6) {
    if (s.rgba.empty()) s.rgba.assign(4 * (s.read.v - 1), 1.0f);
    s.rgba.insert(s.rgba.end(), {float(v[3]), float(v[4]), float(v[5]), n == 7 ? float(v[6]) : 1.0f});
    s.color_channels = std::max(s.color_channels, n == 7 ? 4 : 3);
    ++s.colored_vertices;
  } else if (!s.rgba.empty()) {
    s.rgba.insert(s.rgba.end(), {1.0f, 1.0f, 1.0f, 1.0f});
  }
}

template <bool kPlaced>
void read_vn(ObjChunk& s, ObjArrays& a, ObjLine& l, const std::string& name) {
  double v[3];
  int n = 0;
  while (n < 3 && next_number(s, l, name, v[n])) ++n;
  if (n < 3) fail(name, l.number, "vn has " + std::to_string(n) + " values (need x y z)");
  if (kPlaced && s.read.vn >= s.room.vn) throw Miscounted{};
  put<kPlaced>(a.normals, s.at.vn + s.read.vn, v, 3);
  ++s.read.vn;
}

template <bool kPlaced>
void read_vt(ObjChunk& s, ObjArrays& a, ObjLine& l, const std::string& name) {
  double v[3] = {0, 0, 0};
  int n = 0;
  while (n < 3 && next_number(s, l, name, v[n])) ++n;
  if (n < 1) fail(name, l.number, "vt has no values (need u [v [w]])");
  s.tex_dims = std::max(s.tex_dims, n);
  if (kPlaced && s.read.vt >= s.room.vt) throw Miscounted{};
  put<kPlaced>(a.tex, s.at.vt + s.read.vt, v, 3);
  ++s.read.vt;
}

// read_f's cold path for a face of 1 or 2 vertices: the chunk's corners, per-corner vn/vt indices
// and counters as before the face (ObjChunk::undo), the face counted as skipped.
__attribute__((noinline, cold)) void drop_short_face(ObjChunk& s, std::size_t first_corner) {
  const ObjChunk::FaceUndo& u = s.undo;
  s.read.corners = first_corner;
  if (u.have_cn) s.cn.resize(first_corner);
  else std::vector<std::uint32_t>().swap(s.cn);
  if (u.have_ct) s.ct.resize(first_corner);
  else std::vector<std::uint32_t>().swap(s.ct);
  s.have_cn = u.have_cn;
  s.have_ct = u.have_ct;
  s.corners_with_normal = u.corners_with_normal;
  s.corners_with_tex = u.corners_with_tex;
  s.dangling_normal = u.dangling_normal;
  s.dangling_tex = u.dangling_tex;
  ++s.skipped_short_faces;
}

// `f` in the forms i, i/j, i//k, i/j/k; an empty vt or vn field (`1/`, `1//`, `1/1/`) is absent,
// as tinyobjloader, assimp and trimesh read it. An `f` with no index is skipped (counted), and so
// is one with 1 or 2 vertices (not a face: what it added is taken back, counted).
template <bool kPlaced>
void read_f(ObjChunk& s, ObjArrays& a, ObjLine& l, const std::string& name) {
  Mesh& mesh = a.mesh;
  // Elements defined before this line, in the whole file: what relative indices count back from.
  const std::size_t nv = s.at.v + s.read.v, nt = s.at.vt + s.read.vt, nn = s.at.vn + s.read.vn;
  const std::size_t first_corner = s.read.corners;  // chunk-local
  s.undo = {s.have_cn, s.have_ct, s.corners_with_normal, s.corners_with_tex, s.dangling_normal, s.dangling_tex};
  std::uint32_t* placed = kPlaced ? mesh.corner_vertex.data() + s.at.corners : nullptr;
  const char*& q = l.q;
  const char* const eol = l.end;  // the chunk's end: the line ends at '\n' before it
  const std::size_t& line = l.number;  // advanced by a continued line
  // The field after a '/' is empty when a space, the line's end or another '/' follows it.
  auto field_empty = [eol](const char* at) { return at_line_end(at, eol) || *at == '/' || is_space(*at); };
  for (;;) {
    q = skip_spaces(q, eol);
    if (at_line_end(q, eol) || *q == '#') break;
    std::int64_t idx;
    const char* tok = q;
    if (!parse_int64(q, eol, idx)) {  // a `\` ending the line continues the face, else an error
      q = continued_or_fail(tok, eol, l.number, name, "malformed face index");
      if (q != eol) ++l.number;
      continue;
    }
    const std::uint32_t vertex = resolve_index(idx, nv, "vertex", name, line);
    if constexpr (kPlaced) {
      // Beyond what the counting pass found: the passes split this text differently.
      if (s.read.corners >= s.room.corners) throw Miscounted{};
      placed[s.read.corners] = vertex;
    } else {
      mesh.corner_vertex.push_back(vertex);
    }
    ++s.read.corners;
    std::uint32_t t = kNone, n = kNone;
    if (!at_line_end(q, eol) && *q == '/') {
      ++q;
      if (!field_empty(q)) {
        if (!parse_int64(q, eol, idx) || (!at_line_end(q, eol) && *q != '/' && !is_space(*q)))
          fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
        if (nt == 0) ++s.dangling_tex;
        else t = resolve_index(idx, nt, "texcoord", name, line);
      }
      if (!at_line_end(q, eol) && *q == '/') {
        ++q;
        if (!at_line_end(q, eol) && !is_space(*q)) {
          if (!parse_int64(q, eol, idx)) fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
          if (nn == 0) ++s.dangling_normal;
          else n = resolve_index(idx, nn, "normal", name, line);
        }
      }
    }
    if (!at_line_end(q, eol) && !is_space(*q)) fail(name, line, "malformed face index '" + token_at(tok, eol) + "'");
    if (n != kNone) {
      if (!s.have_cn) s.cn.assign(s.read.corners - 1, kNone);
      s.have_cn = true;
      ++s.corners_with_normal;
    }
    if (s.have_cn) s.cn.push_back(n);
    if (t != kNone) {
      if (!s.have_ct) s.ct.assign(s.read.corners - 1, kNone);
      s.have_ct = true;
      ++s.corners_with_tex;
    }
    if (s.have_ct) s.ct.push_back(t);
  }
  const std::size_t size = s.read.corners - first_corner;
  if (size == 0) {  // `f` alone: nothing to keep (other readers skip it too)
    ++s.skipped_empty_faces;
    return;
  }
  if (size < 3) {  // `f 1 2`: not a face (trimesh, assimp skip it); what it added taken back
    if constexpr (!kPlaced) mesh.corner_vertex.resize(mesh.corner_vertex.size() - size);
    drop_short_face(s, first_corner);
    return;
  }
  const std::size_t corners = s.at.corners + s.read.corners;
  if (corners > std::numeric_limits<std::uint32_t>::max() - 1)
    fail(name, line, "too many face corners (more than 2^32)");
  if constexpr (kPlaced) {
    if (s.read.faces >= s.room.faces) throw Miscounted{};
    mesh.face_start[s.at.faces + s.read.faces + 1] = static_cast<std::uint32_t>(corners);
  } else {
    mesh.face_start.push_back(static_cast<std::uint32_t>(corners));
  }
  ++s.read.faces;
}

// The end of a line [from, eol) whose statement continues while it ends in `\`: the line feed of
// the last line it continues on (or `end`), and how many lines it continued on.
struct ContinuedEnd {
  const char* eol;
  std::size_t lines;
};
__attribute__((noinline)) ContinuedEnd continued_line_end(const char* from, const char* eol, const char* end) {
  std::size_t lines = 0;
  while (eol != end && ends_in_backslash(from, eol)) {
    from = eol + 1;
    if (from == end) return {end, lines};
    ++lines;
    const void* lf = std::memchr(from, '\n', std::size_t(end - from));
    eol = lf ? static_cast<const char*>(lf) : end;
  }
  return {eol, lines};
}

// Step 1, read: every line of [p, end), in order, into `s` and the arrays.
template <bool kPlaced>
void read_lines(const char* p, const char* const end, const std::string& name, ObjChunk& s, ObjArrays& a) {
  std::size_t line = s.at.lines;
  // The line feed (or the end) at or after q.
  auto line_feed = [end](const char* q) {
    if (q >= end) return end;  // (q > end never happens; said so that the length below is seen positive)
    if (*q == '\n') return q;
    const void* lf = std::memchr(q, '\n', std::size_t(end - q));
    return lf ? static_cast<const char*>(lf) : end;
  };
  while (p < end) {
    if ((++line & 0xffff) == 0 && s.progress) s.progress->at(std::uint64_t(p - s.base));
    const char* q = skip_spaces(p, end);
    const char* eol;
    if (at_line_end(q, end) || *q == '#') {
      eol = line_feed(q);
      // A comment line ending in `\` continues too (the text rule Blender and trimesh apply).
      if (eol != q) {
        const ContinuedEnd c = continued_line_end(q, eol, end);
        eol = c.eol;
        line += c.lines;
      }
    } else {
      const char* kw = q;
      while (q < end && !is_space_or_newline(*q)) ++q;
      const std::size_t kwlen = std::size_t(q - kw);
      ObjLine l{q, end, line};
      const ObjKeyword keyword = obj_keyword(kw, kwlen);
      switch (keyword) {
        case ObjKeyword::V: read_v<kPlaced>(s, a, l, name); break;
        case ObjKeyword::Vn: read_vn<kPlaced>(s, a, l, name); break;
        case ObjKeyword::Vt: read_vt<kPlaced>(s, a, l, name); break;
        case ObjKeyword::F: read_f<kPlaced>(s, a, l, name); break;
        case ObjKeyword::Grouping:
        case ObjKeyword::L:
        case ObjKeyword::P:
        case ObjKeyword::Other: break;
      }
      // What the line's reader left (spaces, a comment, values it does not read) up to its end;
      // when it left text, a `\` ending the line continues the statement (not read as one of its own).
      const char* rest = skip_spaces(l.q, end);
      eol = line_feed(rest);
      line = l.number;
      if (eol != rest) {
        const ContinuedEnd c = continued_line_end(rest, eol, end);
        eol = c.eol;
        line += c.lines;
      }
      switch (keyword) {
        case ObjKeyword::V:
        case ObjKeyword::Vn:
        case ObjKeyword::Vt:
        case ObjKeyword::F: break;
        case ObjKeyword::Grouping: {
          // Grouping, smoothing groups and materials: kept verbatim, in place relative to the faces.
          const char* e = eol;
          while (e > kw && is_space(e[-1])) --e;
          const std::size_t begin = s.statement_text.size();
          // A continued statement is kept as one line: each `\` and its line feed become a space.
          for (const char* from = kw; from < e;) {
            const char* lf = static_cast<const char*>(std::memchr(from, '\n', std::size_t(e - from)));
            const char* piece_end = lf ? lf : e;
            const char* b = piece_end;
            if (lf) {
              while (b > from && is_space(b[-1])) --b;
              if (b > from && b[-1] == '\\') --b;  // (always: only a continued line holds a line feed)
              while (b > from && is_space(b[-1])) --b;
              s.statement_text.append(from, std::size_t(b - from));
              s.statement_text += ' ';
              from = skip_spaces(lf + 1, e);
            } else {
              s.statement_text.append(from, std::size_t(piece_end - from));
              from = e;
            }
          }
          s.statements.push_back({s.read.faces, begin, s.statement_text.size()});
          break;
        }
        case ObjKeyword::L: ++s.skipped_lines_l; break;
        case ObjKeyword::P: ++s.skipped_points; break;
        case ObjKeyword::Other:
          if (s.skipped_lines++ == 0) s.skipped_keyword.assign(kw, std::min<std::size_t>(kwlen, 40));
          break;
      }
    }
    if (eol == end) break;
    p = eol + 1;
  }
  s.read.lines = line - s.at.lines;
}

// What the chunks gathered, merged in file order into one ObjLines for the build steps.
struct ObjLines {
  Mesh mesh;
  bool any_double = false;
  std::vector<double> normals;                 // vn pool, 3 per entry
  std::vector<double> tex;                     // vt pool, 3 per entry (missing components 0)
  int tex_dims = 0;
  std::vector<float> rgba;                     // 4 per vertex once any vertex has a colour
  int color_channels = 0;
  std::size_t colored_vertices = 0;
  std::size_t weighted_vertices = 0;           // `v x y z w` with w != 1 (w not read)
  std::vector<std::uint32_t> cn, ct;           // per corner, kNone where absent
  std::size_t corners_with_normal = 0, corners_with_tex = 0;
  std::size_t dangling_normal = 0, dangling_tex = 0;
  std::size_t skipped_lines = 0;
  std::string skipped_keyword;
  std::size_t skipped_empty_faces = 0, skipped_lines_l = 0, skipped_points = 0;
  std::size_t skipped_short_faces = 0;
};

// Grouping statements become runs between faces: a run is the statement lines read since the
// last face; face f's face_group_run is the number of runs before it. Replayed in file order over
// the chunks, so the result does not depend on where the chunks were cut.
void merge_statements(std::vector<ObjChunk>& chunks, Mesh& mesh) {
  bool any_statement = false;
  std::string pending;
  std::size_t faces_done = 0;
  for (ObjChunk& c : chunks) {
    std::size_t f = 0;  // chunk faces placed in face_group_run so far
    auto faces_until = [&](std::size_t end_face) {
      if (any_statement) {
        for (; f < end_face; ++f) {
          if (!pending.empty()) {
            mesh.group_statements.push_back(std::move(pending));
            pending.clear();
          }
          mesh.face_group_run.push_back(static_cast<std::uint32_t>(mesh.group_statements.size()));
        }
      }
      f = end_face;
    };
    for (const ObjChunk::Statement& st : c.statements) {
      faces_until(st.faces_before);
      if (!any_statement) mesh.face_group_run.assign(faces_done + st.faces_before, 0);
      any_statement = true;
      pending.append(c.statement_text, st.begin, st.end - st.begin);
      pending += '\n';
    }
    faces_until(c.read.faces);
    faces_done += c.read.faces;
  }
  if (!pending.empty()) mesh.group_statements.push_back(std::move(pending));
}

// Per-chunk lazily allocated arrays (colours per vertex, vn/vt indices per corner) merged into one:
// allocated for the whole file when any chunk has them, `fill` where a chunk has none.
template <class T>
void merge_lazy(std::vector<ObjChunk>& chunks, std::vector<T> ObjChunk::*member, std::size_t ObjCounts::*count,
                std::size_t width, T fill, std::vector<T>& out) {
  bool any = false;
  for (const ObjChunk& c : chunks) any = any || !(c.*member).empty();
  if (!any) return;
  if (chunks.size() == 1) {
    out = std::move(chunks[0].*member);
    return;
  }
  std::size_t total = 0;
  for (const ObjChunk& c : chunks) total += c.read.*count;
  out.reserve(total * width);
  for (ObjChunk& c : chunks) {
    std::vector<T>& v = c.*member;
    if (v.empty()) out.insert(out.end(), c.read.*count * width, fill);
    else out.insert(out.end(), v.begin(), v.end());
    std::vector<T>().swap(v);
  }
}

void merge_chunks(std::vector<ObjChunk>& chunks, ObjLines& s) {
  for (const ObjChunk& c : chunks) {
    s.any_double = s.any_double || c.any_double;
    s.tex_dims = std::max(s.tex_dims, c.tex_dims);
    s.color_channels = std::max(s.color_channels, c.color_channels);
    s.colored_vertices += c.colored_vertices;
    s.weighted_vertices += c.weighted_vertices;
    s.corners_with_normal += c.corners_with_normal;
    s.corners_with_tex += c.corners_with_tex;
    s.dangling_normal += c.dangling_normal;
    s.dangling_tex += c.dangling_tex;
    if (s.skipped_lines == 0 && c.skipped_lines > 0) s.skipped_keyword = c.skipped_keyword;
    s.skipped_lines += c.skipped_lines;
    s.skipped_empty_faces += c.skipped_empty_faces;
    s.skipped_lines_l += c.skipped_lines_l;
    s.skipped_points += c.skipped_points;
    s.skipped_short_faces += c.skipped_short_faces;
  }
  merge_lazy(chunks, &ObjChunk::rgba, &ObjCounts::v, 4, 1.0f, s.rgba);
  merge_lazy(chunks, &ObjChunk::cn, &ObjCounts::corners, 1, kNone, s.cn);
  merge_lazy(chunks, &ObjChunk::ct, &ObjCounts::corners, 1, kNone, s.ct);
  merge_statements(chunks, s.mesh);
}

// The chunks of [0, size), every cut just after a line feed of a line not ending in `\` (a continued
// statement stays in one chunk), so every line is whole in one chunk:
// each chunk at least want(left) >= 1 bytes, left the bytes not yet cut; none once want(left) >= left.
template <class Want>
std::vector<std::size_t> chunk_starts_by(std::string_view bytes, const Want& want) {
  std::vector<std::size_t> starts{0};
  for (std::size_t at = 0;;) {
    const std::size_t left = bytes.size() - at, w = want(left);
    if (w >= left) break;
    const char* const text_end = bytes.data() + bytes.size();
    const char* lf = static_cast<const char*>(std::memchr(bytes.data() + at + w - 1, '\n', left - w + 1));
    // Never after a line ending in `\`: its statement continues on the next line, in this chunk.
    while (lf && ends_in_backslash(bytes.data() + at, lf))
      lf = static_cast<const char*>(std::memchr(lf + 1, '\n', std::size_t(text_end - lf - 1)));
    if (!lf) break;
    const std::size_t next = std::size_t(lf - bytes.data()) + 1;
    if (next >= bytes.size()) break;
    starts.push_back(next);
    at = next;
  }
  starts.push_back(bytes.size());
  return starts;
}

// Chunks of about `target` >= 1 bytes each.
std::vector<std::size_t> chunk_starts(std::string_view bytes, std::size_t target) {
  return chunk_starts_by(bytes, [target](std::size_t) { return target; });
}

// The chunks for `threads` threads taking them in file order (run_in_order): each a
// 1 / (2 * threads) share of the bytes not yet cut, at least kChunkMinBytes (guided
// self-scheduling, Polychronopoulos and Kuck 1987): the threads start on large chunks and end on
// small ones, so one that was slowed down (another process on its core) leaves the others at most
// a small chunk to wait for.
std::vector<std::size_t> chunk_starts_guided(std::string_view bytes, std::size_t threads) {
  const std::size_t share = 2 * std::max<std::size_t>(threads, 1);
  return chunk_starts_by(bytes, [share](std::size_t left) { return std::max(kChunkMinBytes, left / share); });
}

// fn(0), ..., fn(n - 1) on the arena's threads, each thread taking the next index not yet taken.
template <class F>
void run_in_order(std::size_t n, std::size_t threads, const F& fn) {
  std::atomic<std::size_t> next{0};
  tbb::parallel_for(
      std::size_t(0), std::max<std::size_t>(1, std::min(threads, n)),
      [&](std::size_t) {
        for (std::size_t i = next.fetch_add(1, std::memory_order_relaxed); i < n; i = next.fetch_add(1, std::memory_order_relaxed)) fn(i);
      },
      tbb::simple_partitioner());
}

// Step 1, read, in one pass: every line in order, appended to the mesh's vectors.
void read_one_pass(std::string_view bytes, const std::string& name, ObjLines& s, ProgressCursor& progress) {
  Mesh& mesh = s.mesh;
  ObjArrays arrays{mesh, s.normals, s.tex};
  // Capacity guessed from the file size, generously (untouched capacity costs address space,
  // not memory): a `v` line is >= 24 bytes in practice, a triangle line about 12 per corner.
  reserve_bulk(mesh.positions, bytes.size() / 24 * 3);
  reserve_bulk(mesh.corner_vertex, bytes.size() / 8);
  reserve_bulk(mesh.face_start, bytes.size() / 24 + 1);
  std::vector<ObjChunk> chunks(1);
  chunks[0].progress = &progress;
  chunks[0].base = bytes.data();
  read_lines<false>(bytes.data(), bytes.data() + bytes.size(), name, chunks[0], arrays);
  merge_chunks(chunks, s);
}

// Step 1, read, in one pass (one chunk, appended to the mesh's vectors) or in chunks: a counting
// pass over the chunks in parallel gives each chunk its offsets (the v, vt, vn, faces, corners and
// lines before it), then every chunk is read in parallel into its place, resolving relative
// indices and checking ranges against the elements defined before it in the whole file; what the
// chunks gathered besides the arrays is merged in file order. The first error in file order is
// the one raised, with its line number, as in one pass.
void read_all_lines(std::string_view text, const std::string& name, const ObjReadOptions& options, ObjLines& s,
                    ProgressCursor& progress) {
  Mesh& mesh = s.mesh;
  ObjArrays arrays{mesh, s.normals, s.tex};
  const std::size_t threads = usable_threads();
  // Chunks: of options.chunk_bytes when given, else guided (large first) on more than one thread
  // and 4 MiB, else none (the whole text in one pass).
  const bool guided = options.chunk_bytes == 0 && threads > 1 && text.size() >= kParallelMinBytes;
  const std::size_t target = std::max<std::size_t>(options.chunk_bytes == 0 ? text.size() : options.chunk_bytes, 1);
  // CR, LF, CRLF, mixed: all LF before any line is read. Text without a CR is read as it is (the
  // counting pass looks for CRs in every chunk at once); text with one is converted (a copy) and
  // counted again.
  std::optional<LineEndings> lf_text;
  std::string_view bytes = text;
  auto to_lf = [&] {
    if (lf_text) return;
    lf_text.emplace(text);
    bytes = lf_text->lf();
  };
  // OBJ is text: a NUL byte means binary data (another format, or garbage), not lines to skip.
  // Looked for before any line is read (by the counting pass when there are several chunks).
  auto refuse_nul = [&] {
    const char* at = static_cast<const char*>(std::memchr(bytes.data(), '\0', bytes.size()));
    if (at) fail(name, 1 + std::size_t(std::count(bytes.data(), at, '\n')), "binary data (a NUL byte) in an OBJ file: not a text mesh");
  };
  std::vector<std::size_t> starts;
  std::vector<ObjCounts> counts;
  bool in_chunks = guided || target < text.size();
  while (in_chunks) {
    starts = guided ? chunk_starts_guided(bytes, threads) : chunk_starts(bytes, target);
    counts.assign(starts.size() - 1, ObjCounts{});
    if (counts.size() < 2) {
      in_chunks = false;
      break;
    }
    run_in_order(counts.size(), threads, [&](std::size_t i) {
      counts[i] = count_obj_statements(bytes.data() + starts[i], bytes.data() + starts[i + 1]);
    });
    if (lf_text || std::none_of(counts.begin(), counts.end(), [](const ObjCounts& c) { return c.cr; })) break;
    to_lf();  // counted again: the converted text has no CR
  }
  if (in_chunks) {
    if (std::any_of(counts.begin(), counts.end(), [](const ObjCounts& c) { return c.nul; })) refuse_nul();
    std::size_t v = 0, corners = 0;
    for (const ObjCounts& c : counts) {
      v += c.v;
      corners += c.corners;
    }
    // Beyond 32-bit indices: the one pass stops at the line where the count overflows.
    if (v > std::numeric_limits<std::uint32_t>::max() || corners > std::numeric_limits<std::uint32_t>::max() - 1) in_chunks = false;
  }
  if (!in_chunks) {
    if (lf_text || obj_text_has_cr_or_nul(bytes.data(), bytes.data() + bytes.size())) {  // else both find nothing
      to_lf();
      refuse_nul();
    }
    read_one_pass(bytes, name, s, progress);
    return;
  }
  const std::size_t n = counts.size();
  std::vector<ObjChunk> chunks(n);
  ObjCounts total;
  for (std::size_t i = 0; i < n; ++i) {
    chunks[i].at = total;
    chunks[i].room = counts[i];
    total.v += counts[i].v;
    total.vt += counts[i].vt;
    total.vn += counts[i].vn;
    total.faces += counts[i].faces;
    total.corners += counts[i].corners;
    total.lines += counts[i].lines;
  }
  // The arrays, sized by the counts, zero-filled by resize(): their first write, which faults in
  // their fresh pages (the kernel zeroes each; reserve_bulk asks for huge pages) with the fill
  // right behind it while the page is in cache. One array per task, largest first, on the threads
  // at once (run_in_order: longest first balances the threads to within the smallest array, vn
  // and vt pools included). Faulting them in first (MADV_POPULATE_WRITE in 2 MiB blocks) and
  // filling after took the same time in quiet runs (bench/io/results.md, objread6) with more code.
  reserve_bulk(mesh.positions, 3 * total.v);
  reserve_bulk(mesh.corner_vertex, total.corners);
  reserve_bulk(mesh.face_start, total.faces + 1);
  reserve_bulk(s.normals, 3 * total.vn);
  reserve_bulk(s.tex, 3 * total.vt);
  struct Sized {
    std::size_t bytes;
    std::function<void()> resize;
  };
  std::array<Sized, 5> arrays_by_size{{
      {3 * total.v * sizeof(double), [&] { mesh.positions.resize(3 * total.v); }},
      {total.corners * sizeof(std::uint32_t), [&] { mesh.corner_vertex.resize(total.corners); }},
      {(total.faces + 1) * sizeof(std::uint32_t), [&] { mesh.face_start.resize(total.faces + 1); }},
      {3 * total.vn * sizeof(double), [&] { s.normals.resize(3 * total.vn); }},
      {3 * total.vt * sizeof(double), [&] { s.tex.resize(3 * total.vt); }},
  }};
  std::stable_sort(arrays_by_size.begin(), arrays_by_size.end(), [](const Sized& a, const Sized& b) { return a.bytes > b.bytes; });
  run_in_order(arrays_by_size.size(), threads, [&](std::size_t i) { arrays_by_size[i].resize(); });
  std::vector<std::exception_ptr> errors(n);
  std::vector<char> miscounted(n, 0);
  std::mutex progress_mutex;  // the cursor is serial: chunks report their bytes as they finish
  std::uint64_t chunk_bytes_done = 0;
  run_in_order(n, threads, [&](std::size_t i) {
    try {
      read_lines<true>(bytes.data() + starts[i], bytes.data() + starts[i + 1], name, chunks[i], arrays);
      {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        chunk_bytes_done += starts[i + 1] - starts[i];
        progress.at(chunk_bytes_done);
      }
      const ObjCounts& r = chunks[i].read;
      const ObjCounts& c = counts[i];
      if (r.v != c.v || r.vt != c.vt || r.vn != c.vn || r.faces != c.faces || r.corners != c.corners) throw Miscounted{};
      // Done with the chunk's bytes: its pages of the file's mapping are dropped here, on this
      // thread, not in the serial munmap at the end (io/file_bytes.h; a no-op on a copy).
      release_mapped_pages(bytes.data() + starts[i], bytes.data() + starts[i + 1]);
    } catch (const Miscounted&) {
      miscounted[i] = 1;
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  if (std::find(miscounted.begin(), miscounted.end(), 1) != miscounted.end()) {
    // Text the two passes count differently (a face continued on the next line: the counting
    // pass takes its `\` for a corner and not the next line's; an `f` of 1 or 2 vertices, which
    // the reader skips): the one pass reads it.
    s = ObjLines{};
    read_one_pass(bytes, name, s, progress);
    return;
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  merge_chunks(chunks, s);
}
// Step 2, validate: a file without vertices is not a mesh.
void validate_lines(const ObjLines& s, const std::string& name) {
  // BIC/MNI surface files share the .obj extension: their first line is `P` and 6 numbers
  // (ambient diffuse specular shininess transparency npoints), then the points, no keywords.
  if (s.mesh.num_vertices() == 0 && s.skipped_lines > 0 && s.skipped_keyword == "P")
    fail(name, 0, "not a Wavefront OBJ file: it starts as an MNI surface .obj does (`P` and numbers, no `v` line): "
                  "MNI's format (BIC), which shadetool does not read");
  if (s.mesh.num_vertices() == 0 && s.skipped_lines > 0)
    fail(name, 0, "not an OBJ file: no vertices, " + std::to_string(s.skipped_lines) + " line" +
                      (s.skipped_lines == 1 ? "" : "s") + " with unknown keywords (first: '" + s.skipped_keyword + "')");
  if (s.mesh.num_vertices() == 0) fail(name, 0, "no vertex (`v` line) in the file: not a mesh");
  if (s.mesh.num_vertices() > std::numeric_limits<std::uint32_t>::max())
    fail(name, 0, "too many vertices (more than 2^32)");
}

// vn lines that no face corner names are no part of the mesh: not read (a note), as when no corner
// names any (note_skipped). Kept in the pool they were written back by every OBJ output, and a zero
// one (MeshLab writes `vn 0 0 0` for the vertices no face uses: draco's testdata/test_nm.obj) made
// every writer refuse the mesh, `repair` included, since no writer writes a zero normal. The pool
// keeps its order; cn is renumbered. file_normals: the entries read from the file (those after it
// are the face normals given to corners without vn, all named by a corner).
void drop_unreferenced_normals(std::vector<double>& normals, std::vector<std::uint32_t>& cn, std::size_t file_normals,
                               ReadInfo& info) {
  const std::size_t pool = normals.size() / 3;
  std::vector<std::uint32_t> renumber(pool, kNone);
  for (std::uint32_t e : cn)
    if (e != kNone) renumber[e] = 0;  // named by a corner
  std::size_t dropped = 0;
  for (std::size_t e = 0; e < file_normals; ++e) dropped += renumber[e] == kNone;
  if (dropped == 0) return;
  std::size_t kept = 0;
  for (std::size_t e = 0; e < pool; ++e) {
    if (renumber[e] == kNone) continue;
    renumber[e] = std::uint32_t(kept);
    for (std::size_t k = 0; k < 3; ++k) normals[3 * kept + k] = normals[3 * e + k];
    ++kept;
  }
  normals.resize(3 * kept);
  for (std::uint32_t& e : cn)
    if (e != kNone) e = renumber[e];
  info.notes.push_back(std::to_string(dropped) + " of " + std::to_string(file_normals) +
                       " normals (vn) no face references: not read");
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
  const std::size_t file_normals = normals.size() / 3;
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
  drop_unreferenced_normals(normals, cn, file_normals, info);
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
  pack_rgba(s.rgba, s.color_channels, mesh.vertex_colors);
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
  // `v x y z w`: the rational weight of a curve's control point (OBJ spec); a mesh's position is
  // x y z as written, as Blender 3.4 and PDAL read it (assimp divides x y z by w).
  if (s.weighted_vertices > 0)
    info.notes.push_back(std::to_string(s.weighted_vertices) + " of " + std::to_string(s.mesh.num_vertices()) +
                         " vertices have a weight w other than 1 (v x y z w): not read, positions are x y z as "
                         "written (as Blender reads them; assimp divides by w)");
  // vt / vn lines no face corner names (faces written `f 1 2 3`): not read, said.
  auto unreferenced = [&](std::size_t n, std::size_t referenced, const char* what) {
    if (n > 0 && referenced == 0)
      info.notes.push_back(std::to_string(n) + " " + what + " no face references: not read");
  };
  unreferenced(s.tex.size() / 3, s.corners_with_tex, s.tex.size() == 3 ? "texture coordinate (vt)" : "texture coordinates (vt)");
  unreferenced(s.normals.size() / 3, s.corners_with_normal, s.normals.size() == 3 ? "normal (vn)" : "normals (vn)");
  const std::size_t total =
      s.skipped_lines + s.skipped_lines_l + s.skipped_points + s.skipped_empty_faces + s.skipped_short_faces;
  if (total == 0) return;
  std::string what;
  auto add = [&](std::size_t n, const std::string& kind) {
    if (n > 0) what += (what.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  };
  add(s.skipped_lines_l, "`l` (polyline)");
  add(s.skipped_points, "`p` (point)");
  add(s.skipped_empty_faces, "`f` with no indices (no face)");
  add(s.skipped_short_faces, "`f` with fewer than 3 vertices (not a face)");
  if (s.skipped_lines > 0)
    add(s.skipped_lines, "with keywords shadetool does not use (first: '" + s.skipped_keyword + "')");
  info.notes.push_back("skipped " + std::to_string(total) + " line" + (total == 1 ? "" : "s") + ": " + what);
}

}  // namespace

Mesh read_obj(std::string_view file_bytes, const std::string& name, ReadInfo& info) {
  return read_obj(file_bytes, name, info, ObjReadOptions{});
}

Mesh read_obj(std::string_view file_bytes, const std::string& name, ReadInfo& info, const ObjReadOptions& options) {
  refuse_utf16(file_bytes, name);
  ObjLines s;
  read_all_lines(skip_utf8_bom(file_bytes), name, options, s, info.progress);
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
  // Which normals (core/shading_normals.h: the ones that shade), and the vn index of each corner.
  // From `input`: split vertices share their original's vn line (index by the original vertex).
  const ShadingNormals source = shading_normals(input);
  const std::vector<double>* pool = nullptr;
  switch (source) {
    case ShadingNormals::Corner: pool = &input.corner_normals; break;
    case ShadingNormals::Vertex: pool = &input.vertex_normals; break;
    case ShadingNormals::Face: pool = &input.face_normals; break;
    case ShadingNormals::None: break;
  }
  if (const std::string note = face_normals_not_written_note(input, "OBJ"); !note.empty()) info.notes.push_back(note);
  // Points (a mesh without faces, a PLY point cloud): OBJ ties a normal to a face corner only, so
  // vn lines no face names are written but no reader (shadetool's included, note_skipped) reads them
  // back: said, since what is written is as good as dropped.
  if (pool && mesh.num_faces() == 0 && !pool->empty())
    info.notes.push_back(std::to_string(pool->size() / 3) + " normals written as vn lines no face names: OBJ ties a "
                         "normal to a face corner, so readers do not read them back for points");
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
      if (corner_tex || source != ShadingNormals::None) {
        out += '/';
        if (corner_tex) append_uint(out, std::uint64_t(mesh.corner_texcoord_index[c]) + 1);
        if (source != ShadingNormals::None) {
          out += '/';
          const std::uint64_t n = source == ShadingNormals::Corner   ? input.corner_normal_index[c]
                                  : source == ShadingNormals::Vertex ? input.corner_vertex[c]
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
