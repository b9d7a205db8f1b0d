// degenerate_faces.cpp: degenerate face detection and face removal (see the header).
#include "repair/degenerate_faces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

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

}  // namespace

DegenerateFaces degenerate_faces(const Mesh& mesh) {
  const std::size_t F = mesh.num_faces();
  constexpr double kTolerance = 64 * std::numeric_limits<double>::epsilon();
  DegenerateFaces d;
  d.kind.assign(F, DegenerateKind::None);
  std::vector<std::uint32_t> scratch;
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1], n = e - b;
    DegenerateKind& k = d.kind[f];
    if (n < 3) { k = DegenerateKind::TooFewCorners; ++d.too_few_corners; continue; }
    if (has_repeated_index(&mesh.corner_vertex[b], n, scratch)) { k = DegenerateKind::RepeatedIndex; ++d.repeated_index; continue; }
    const Vec3d p0 = mesh.position(mesh.corner_vertex[b]);
    Vec3d twice_area{};
    double bound = 0;
    bool finite = is_finite(p0);
    Vec3d pi = mesh.position(mesh.corner_vertex[b + 1]) - p0;
    for (std::uint32_t i = b + 2; i < e; ++i) {
      const Vec3d pj = mesh.position(mesh.corner_vertex[i]) - p0;
      twice_area += cross(pi, pj);
      bound += length(pi) * length(pj);
      finite = finite && is_finite(pi) && is_finite(pj);
      pi = pj;
    }
    const double area = length(twice_area);
    if (!finite || !std::isfinite(area) || !std::isfinite(bound)) { k = DegenerateKind::NonFinite; ++d.non_finite; continue; }
    if (area <= kTolerance * bound) { k = DegenerateKind::ZeroArea; ++d.zero_area; }
  }
  return d;
}

std::size_t remove_faces(Mesh& mesh, const std::vector<std::uint8_t>& remove) {
  const std::size_t F = mesh.num_faces();
  if (remove.size() != F) fail("remove_faces", 0, "flag array size differs from the face count");
  const bool fn = mesh.has_face_normals(), fc = mesh.has_face_colors();
  const bool cn = mesh.has_corner_normals(), ct = mesh.has_texcoords();
  const std::size_t ch = std::size_t(mesh.color_channels);
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
    mesh.face_start[kept + 1] = std::uint32_t(corner_out);
    ++kept;
  }
  mesh.face_start.resize(kept + 1);
  mesh.corner_vertex.resize(corner_out);
  if (cn) mesh.corner_normal_index.resize(corner_out);
  if (ct) mesh.corner_texcoord_index.resize(corner_out);
  if (fn) mesh.face_normals.resize(3 * kept);
  if (fc) mesh.face_colors.resize(ch * kept);
  return F - kept;
}

}  // namespace shadetool
