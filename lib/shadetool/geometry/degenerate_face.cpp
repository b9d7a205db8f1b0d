// degenerate_face.cpp: see degenerate_face.h.
#include <shadetool/geometry/degenerate_face.h>

#include <algorithm>
#include <cmath>

namespace shadetool {

DegenerateKind triangle_degenerate_kind(const double* P, std::uint32_t v0, std::uint32_t v1, std::uint32_t v2) {
  const TriangleAreaVector t = triangle_area_vector(P, v0, v1, v2);
  bool zero_area = false;
  if (triangle_zero_area_by_squares(dot(t.N, t.N), t.la, t.lb, zero_area))
    return zero_area ? DegenerateKind::ZeroArea : DegenerateKind::None;
  // Out of the squares' range (or NaN): the two shortest edges again, as vectors, and scaled lengths.
  const Vec3d p0 = load_position(P, v0), p1 = load_position(P, v1), p2 = load_position(P, v2);
  if (!is_finite(p0) || !is_finite(p1) || !is_finite(p2)) return DegenerateKind::NonFinite;
  const Vec3d e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
  const int k = apex_corner(dot(e0, e0), dot(e1, e1), dot(e2, e2));
  const Vec3d p[5] = {p0, p1, p2, p0, p1};
  const Vec3d a = p[k + 1] - p[k], b = p[k + 2] - p[k];  // N = a x b (triangle_area_vector)
  const double area = length(t.N), bound = length(a) * length(b);
  if (!std::isfinite(area) || !std::isfinite(bound)) return DegenerateKind::NonFinite;
  return area <= kDegenerateTolerance * bound ? DegenerateKind::ZeroArea : DegenerateKind::None;
}

DegenerateKind face_degenerate_kind(const Mesh& mesh, std::size_t f, std::vector<std::uint32_t>& scratch) {
  const std::uint32_t b = mesh.face_start[f], n = mesh.face_start[f + 1] - b;
  if (n < 3) return DegenerateKind::TooFewCorners;
  if (has_repeated_index(mesh.corner_vertex.data() + b, n, scratch)) return DegenerateKind::RepeatedIndex;
  return face_area_kind(mesh, f);
}

DegenerateKind face_area_kind(const Mesh& mesh, std::size_t f) {
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  return face_area_kind(mesh.positions.data(), mesh.corner_vertex.data() + b, e - b);
}

DegenerateKind face_area_kind(const double* P, const std::uint32_t* cv, std::uint32_t n) {
  if (n < 3) return DegenerateKind::TooFewCorners;
  if (n == 3) return triangle_degenerate_kind(P, cv[0], cv[1], cv[2]);
  // Polygon: Newell's sum about p0 against the bound its rounding scales with.
  const Vec3d p0 = load_position(P, cv[0]);
  bool finite = is_finite(p0);
  double bound = 0.0;
  Vec3d prev = load_position(P, cv[1]) - p0;
  for (std::uint32_t i = 2; i < n; ++i) {
    const Vec3d cur = load_position(P, cv[i]) - p0;
    bound += length(prev) * length(cur);
    finite = finite && is_finite(prev) && is_finite(cur);
    prev = cur;
  }
  const double area = length(newell_area_vector(P, cv, n));
  if (!finite || !std::isfinite(area) || !std::isfinite(bound)) return DegenerateKind::NonFinite;
  return area <= kDegenerateTolerance * bound ? DegenerateKind::ZeroArea : DegenerateKind::None;
}

DegenerateKind face_degenerate_kind(const Mesh& mesh, std::size_t f) {
  std::vector<std::uint32_t> scratch;
  return face_degenerate_kind(mesh, f, scratch);
}

}  // namespace shadetool
