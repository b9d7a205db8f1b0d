// degenerate_faces.cpp: degenerate face detection and face removal (see the header).
#include <shadetool/repair/degenerate_faces.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <shadetool/core/error.h>

namespace shadetool {

namespace {

bool has_repeated_index(const std::uint32_t* v, std::uint32_t n, std::vector<std::uint32_t>& scratch) {
  if (n <= 16) {
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j)
        if (v[i] == v[j]) return true;
    return false;
  }
  scratch.assign(v, v + n);
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

DegenerateKind classify(const Mesh& mesh, std::size_t f, std::vector<std::uint32_t>& scratch) {
  constexpr double kTolerance = 64 * std::numeric_limits<double>::epsilon();
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1], n = e - b;
  const std::uint32_t* cv = mesh.corner_vertex.data();
  if (n < 3) return DegenerateKind::TooFewCorners;
  if (n == 3 ? (cv[b] == cv[b + 1] || cv[b + 1] == cv[b + 2] || cv[b] == cv[b + 2]) : has_repeated_index(cv + b, n, scratch))
    return DegenerateKind::RepeatedIndex;
  const Vec3d p0 = mesh.position(cv[b]);
  if (n == 3) {
    // Triangle: |e1 x e2|^2 <= tol^2 |e1|^2 |e2|^2, no square roots, while the squares can neither
    // overflow nor underflow; otherwise the general path below.
    const Vec3d e1 = mesh.position(cv[b + 1]) - p0, e2 = mesh.position(cv[b + 2]) - p0;
    DegenerateKind kind;
    if (triangle_kind_by_squares(squared_length(e1), squared_length(e2), squared_length(cross(e1, e2)), kind)) return kind;
  }
  Vec3d twice_area{};
  double bound = 0;
  bool finite = is_finite(p0);
  Vec3d pi = mesh.position(cv[b + 1]) - p0;
  for (std::uint32_t i = b + 2; i < e; ++i) {
    const Vec3d pj = mesh.position(cv[i]) - p0;
    twice_area += cross(pi, pj);
    bound += length(pi) * length(pj);
    finite = finite && is_finite(pi) && is_finite(pj);
    pi = pj;
  }
  const double area = length(twice_area);
  if (!finite || !std::isfinite(area) || !std::isfinite(bound)) return DegenerateKind::NonFinite;
  return area <= kTolerance * bound ? DegenerateKind::ZeroArea : DegenerateKind::None;
}

}  // namespace

DegenerateFaces degenerate_faces(const Mesh& mesh) {
  const std::size_t F = mesh.num_faces();
  DegenerateFaces d;
  d.kind.assign(F, DegenerateKind::None);
  // Faces are independent: split over threads (results do not depend on their number).
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, F, 1 << 14), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<std::uint32_t> scratch;
    for (std::size_t f = r.begin(); f < r.end(); ++f) d.kind[f] = classify(mesh, f, scratch);
  });
  count_degenerate_kinds(d);
  return d;
}

DegenerateKind degenerate_kind(const Mesh& mesh, std::size_t f) {
  std::vector<std::uint32_t> scratch;
  return classify(mesh, f, scratch);
}

void count_degenerate_kinds(DegenerateFaces& d) {
  d.too_few_corners = d.repeated_index = d.zero_area = d.non_finite = 0;
  for (DegenerateKind k : d.kind) {
    switch (k) {
      case DegenerateKind::None: break;
      case DegenerateKind::TooFewCorners: ++d.too_few_corners; break;
      case DegenerateKind::RepeatedIndex: ++d.repeated_index; break;
      case DegenerateKind::ZeroArea: ++d.zero_area; break;
      case DegenerateKind::NonFinite: ++d.non_finite; break;
    }
  }
}

std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove) {
  const std::size_t F = mesh.num_faces();
  if (remove.size() != F) fail("remove_faces", 0, "flag array size differs from the face count");
  const bool fn = mesh.has_face_normals(), fc = mesh.has_face_colors();
  const bool cn = mesh.has_corner_normals(), ct = mesh.has_texcoords();
  const std::size_t ch = std::size_t(mesh.color_channels);
  const bool fg = mesh.face_group_run.size() == F;  // OBJ statements stay with the faces that remain
  std::size_t kept = 0, corner_out = 0;
  for (std::size_t f = 0; f < F; ++f) {
    if (remove[f]) continue;
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    for (std::uint32_t c = b; c < e; ++c, ++corner_out) {
      mesh.corner_vertex[corner_out] = mesh.corner_vertex[c];
      if (cn) mesh.corner_normal_index[corner_out] = mesh.corner_normal_index[c];
      if (ct) mesh.corner_texcoord_index[corner_out] = mesh.corner_texcoord_index[c];
    }
    if (fn) for (int i = 0; i < 3; ++i) mesh.face_normals[3 * kept + i] = mesh.face_normals[3 * f + i];
    if (fc) for (std::size_t i = 0; i < ch; ++i) mesh.face_colors[ch * kept + i] = mesh.face_colors[ch * f + i];
    if (fg) mesh.face_group_run[kept] = mesh.face_group_run[f];
    mesh.face_start[kept + 1] = std::uint32_t(corner_out);
    ++kept;
  }
  mesh.face_start.resize(kept + 1);
  mesh.corner_vertex.resize(corner_out);
  if (cn) mesh.corner_normal_index.resize(corner_out);
  if (ct) mesh.corner_texcoord_index.resize(corner_out);
  if (fn) mesh.face_normals.resize(3 * kept);
  if (fc) mesh.face_colors.resize(ch * kept);
  if (fg) mesh.face_group_run.resize(kept);
  return F - kept;
}

}  // namespace shadetool
