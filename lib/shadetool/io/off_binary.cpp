// off_binary.cpp: binary OFF bodies, Geomview's layout and pmp-library's (off_binary.h).
#include <shadetool/io/off_binary.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/io/engine/rgba_channels.h>

namespace shadetool::io {

namespace {

// One reading of the body in one layout: big- or little-endian, faces with or without ncolors.
struct Layout {
  bool big_endian;
  bool face_color_count;  // Geomview's per-face ncolors (pmp-library writes none)
};

// 32-bit words from the body, bounds-checked; the first failure is kept (offset and reason).
class Words {
 public:
  Words(std::string_view body, bool big_endian) : body_(body), big_(big_endian) {}
  bool u32(std::uint32_t& v) {
    if (body_.size() - at_ < 4) return false;
    unsigned char b[4];
    std::memcpy(b, body_.data() + at_, 4);
    at_ += 4;
    v = big_ ? (std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3])
             : (std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 | b[0]);
    return true;
  }
  bool f32(float& x) {
    std::uint32_t v;
    if (!u32(v)) return false;
    std::memcpy(&x, &v, 4);
    return true;
  }
  std::size_t at() const { return at_; }
  std::size_t remaining() const { return body_.size() - at_; }

 private:
  std::string_view body_;
  bool big_;
  std::size_t at_ = 0;
};

struct Attempt {
  Mesh mesh;
  std::vector<float> vrgba, frgba;  // 4 per vertex (C), 4 per kept face (from the first coloured one)
  std::size_t short_faces = 0, colormap_faces = 0;
  bool any_alpha = false;
  std::size_t fail_at = 0;  // byte offset in the body of the failure
  std::string why;
};

bool fail_attempt(Attempt& a, const Words& w, std::string why) {
  a.fail_at = w.at();
  a.why = std::move(why);
  return false;
}

// Reads the whole body in one layout; false (with a.fail_at, a.why) when the bytes do not fit it.
bool read_in_layout(std::string_view body, OffBinaryFlags fl, Layout layout, Attempt& a) {
  Words w(body, layout.big_endian);
  std::uint32_t nv, nf, ne;
  if (!w.u32(nv) || !w.u32(nf) || !w.u32(ne)) {
    fail_attempt(a, w, "the body ends before the counts #V #F #E (12 bytes)");
    a.fail_at = 0;  // where the counts start
    return false;
  }
  const std::size_t per_vertex = 3 + (fl.has_n ? 3 : 0) + (fl.has_c ? 4 : 0) + (fl.has_st ? 2 : 0);
  // Bound the counts by the bytes before allocating: per vertex 4*per_vertex, per face at least 4.
  if (std::uint64_t(nv) * per_vertex * 4 > w.remaining() || std::uint64_t(nf) * 4 > w.remaining() ||
      (std::uint64_t(nv) * per_vertex * 4 + std::uint64_t(nf) * 4) > w.remaining())
    return fail_attempt(a, w, "the counts (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
                                  " faces) need more bytes than the file holds");
  Mesh& m = a.mesh;
  m.positions.resize(3 * std::size_t(nv));
  if (fl.has_n) m.vertex_normals.resize(3 * std::size_t(nv));
  if (fl.has_c) a.vrgba.resize(4 * std::size_t(nv));
  std::vector<double> vtex(fl.has_st ? 2 * std::size_t(nv) : 0);
  for (std::size_t v = 0; v < nv; ++v) {
    float x[12] = {};
    for (std::size_t k = 0; k < per_vertex; ++k) w.f32(x[k]);  // bounded above
    std::size_t k = 0;
    for (int i = 0; i < 3; ++i) m.positions[3 * v + std::size_t(i)] = x[k++];
    if (fl.has_n)
      for (int i = 0; i < 3; ++i) m.vertex_normals[3 * v + std::size_t(i)] = x[k++];
    if (fl.has_c) {
      for (int i = 0; i < 4; ++i) a.vrgba[4 * v + std::size_t(i)] = x[k++];
      a.any_alpha = a.any_alpha || a.vrgba[4 * v + 3] != 1.0f;
    }
    if (fl.has_st)
      for (int i = 0; i < 2; ++i) vtex[2 * v + std::size_t(i)] = x[k++];
  }
  m.face_start.reserve(std::size_t(nf) + 1);
  m.corner_vertex.reserve(std::min<std::size_t>(3 * std::size_t(nf), w.remaining() / 4));
  bool any_face_color = false;
  std::size_t kept = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    std::uint32_t k;
    if (!w.u32(k)) return fail_attempt(a, w, "the body ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    if (k > w.remaining() / 4) return fail_attempt(a, w, "face " + std::to_string(f) + " says " + std::to_string(k) + " indices, more than the bytes left");
    const std::size_t first = m.corner_vertex.size();
    for (std::uint32_t i = 0; i < k; ++i) {
      std::uint32_t idx = 0;
      w.u32(idx);  // bounded above
      if (idx >= nv)
        return fail_attempt(a, w, "face " + std::to_string(f) + " has vertex index " + std::to_string(idx) + " out of range (" +
                                      std::to_string(nv) + " vertices)");
      m.corner_vertex.push_back(idx);
    }
    float c[4] = {1, 1, 1, 1};
    std::uint32_t nc = 0;
    if (layout.face_color_count) {
      if (!w.u32(nc)) return fail_attempt(a, w, "the body ends before face " + std::to_string(f) + "'s colour count");
      if (nc == 2 || nc > 4) return fail_attempt(a, w, "face " + std::to_string(f) + " has " + std::to_string(nc) + " colour values (expected 0, 1, 3 or 4)");
      for (std::uint32_t i = 0; i < nc; ++i)
        if (!w.f32(c[i])) return fail_attempt(a, w, "the body ends inside face " + std::to_string(f) + "'s colour");
    }
    if (k < 3) {  // not a face: dropped with its colour, as the text reader does
      m.corner_vertex.resize(first);
      ++a.short_faces;
      continue;
    }
    if (m.corner_vertex.size() > std::numeric_limits<std::uint32_t>::max() - 1)
      return fail_attempt(a, w, "too many face corners (more than 2^32)");
    m.face_start.push_back(std::uint32_t(m.corner_vertex.size()));
    if (nc == 1) ++a.colormap_faces;  // a colormap index: no colour table to look it up in
    if (nc >= 3) {
      if (!any_face_color) a.frgba.assign(4 * kept, 1.0f);
      any_face_color = true;
      if (nc == 4) a.any_alpha = a.any_alpha || c[3] != 1.0f;
    }
    if (any_face_color) a.frgba.insert(a.frgba.end(), {c[0], c[1], c[2], nc == 4 ? c[3] : 1.0f});
    ++kept;
  }
  if (w.remaining() != 0)
    return fail_attempt(a, w, std::to_string(w.remaining()) + " bytes after the last face: the counts disagree with the body");
  if (fl.has_st) {
    m.texcoords = std::move(vtex);
    m.texcoord_dims = 2;
    m.corner_texcoord_index = m.corner_vertex;
  }
  return true;
}

}  // namespace

Mesh read_off_binary_body(std::string_view body, std::size_t header_bytes, OffBinaryFlags flags, const std::string& name,
                          ReadInfo& info) {
  const Layout layouts[4] = {{true, true}, {true, false}, {false, true}, {false, false}};
  const char* layout_names[4] = {"Geomview's big-endian layout", "big-endian without face colour counts (pmp-library)",
                                 "little-endian with face colour counts", "little-endian without face colour counts (pmp-library before 3.0)"};
  Attempt first_failure;
  for (int i = 0; i < 4; ++i) {
    Attempt a;
    if (!read_in_layout(body, flags, layouts[i], a)) {
      if (i == 0) first_failure = std::move(a);
      continue;
    }
    Mesh& m = a.mesh;
    const int channels = a.any_alpha ? 4 : 3;
    if (flags.has_c) pack_rgba(a.vrgba, channels, m.vertex_colors);
    if (!a.frgba.empty()) pack_rgba(a.frgba, channels, m.face_colors);
    m.color_channels = channels;
    m.colors_are_float = true;
    m.precision = ValuePrecision::Float;
    if (i != 0) info.notes.push_back("binary OFF read in " + std::string(layout_names[i]));
    if (a.short_faces > 0)
      info.notes.push_back("skipped " + std::to_string(a.short_faces) + " faces with fewer than 3 vertices (not a face), with their colours");
    if (a.colormap_faces > 0)
      info.notes.push_back(std::to_string(a.colormap_faces) + " face colours given as a colormap index not read (no colormap)");
    return std::move(m);
  }
  fail(name, 0, "binary OFF: byte " + std::to_string(header_bytes + first_failure.fail_at) + ": " + first_failure.why +
                    " (read in Geomview's big-endian layout; pmp-library's and little-endian layouts do not fit either)");
}

}  // namespace shadetool::io
