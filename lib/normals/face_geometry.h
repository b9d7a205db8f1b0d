// face_geometry.h: the per-face and per-corner quantities every normals kernel is built from
// (internal to lib/normals; header-only so the kernels inline it into their loops).
//
//   triangle_area_vector  2 * area * unit normal of a triangle, from the cross product of its two
//                         shortest edges (the pair that leaves out the longest edge): of the three
//                         equivalent cross products it has the smallest rounding error for slivers.
//   newell_area_vector    2 * area * unit normal of a polygon (planar or not) by Newell's method
//                         (Sutherland, Sproull & Schumacker 1974; Tampieri, "Newell's method for
//                         computing the plane equation of a polygon", Graphics Gems III, 1992),
//                         evaluated about the polygon's first vertex to keep coordinates small.
//   interior_angle        angle between two edge vectors, atan2(|a x b|, a . b): accurate for
//                         angles near 0 and pi, where acos of the normalised dot product is not.
//
// Precision: T is the type the caller computes in (double or float). Positions stay double; edge
// vectors are formed in double and rounded once to T (see `edge`), everything after is in T.
// Degenerate input: a repeated index or coincident positions give an exactly zero area vector;
// callers take `checked_length` (0 for zero or non-finite vectors) and test it before dividing.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/mesh.h"
#include "core/vec3.h"

namespace shadetool::normals_detail {

inline Vec3d load_position(const double* positions, std::uint32_t v) {
  const double* p = positions + 3 * std::size_t(v);
  return {p[0], p[1], p[2]};
}

// Edge vector b - a: the subtraction is done in double (the stored precision), then rounded once
// to T. For T = float this keeps the error relative to the edge's length, not to the coordinates'
// magnitude (a 1e-3 edge at distance 1 from the origin keeps 7 digits, not 4).
template <class T>
inline Vec3<T> edge(const Vec3d& a, const Vec3d& b) {
  return {T(b.x - a.x), T(b.y - a.y), T(b.z - a.z)};
}

// Edge vectors of triangle (p0, p1, p2): e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2.
// Any two consecutive edges give the same cross product in exact arithmetic
// (e0 x e1 = e1 x e2 = e2 x e0 = 2 A n); we use the pair that excludes the longest edge.
template <class T>
inline Vec3<T> triangle_area_vector(const Vec3<T>& e0, const Vec3<T>& e1, const Vec3<T>& e2,
                                    T l0, T l1, T l2) {
  if (l0 >= l1 && l0 >= l2) return cross(e1, e2);  // longest is e0
  if (l1 >= l2) return cross(e2, e0);               // longest is e1
  return cross(e0, e1);                             // longest is e2
}

// Newell's method about p_0: N = sum_i (p_i - p_0) x (p_{i+1} - p_0) = 2 A n for a planar
// polygon; for a non-planar one, the normal of the plane that best fits its projected areas.
template <class T>
inline Vec3<T> newell_area_vector(const Mesh& mesh, std::size_t f) {
  const std::uint32_t begin = mesh.face_start[f], end = mesh.face_start[f + 1];
  Vec3<T> n{};
  if (end - begin < 3) return n;
  const Vec3d p0 = load_position(mesh.positions.data(), mesh.corner_vertex[begin]);
  Vec3<T> prev = edge<T>(p0, load_position(mesh.positions.data(), mesh.corner_vertex[begin + 1]));
  for (std::uint32_t c = begin + 2; c < end; ++c) {
    const Vec3<T> cur = edge<T>(p0, load_position(mesh.positions.data(), mesh.corner_vertex[c]));
    n += cross(prev, cur);
    prev = cur;
  }
  return n;
}

// Length of n, or 0 when n is zero or not finite (the caller then treats the face as degenerate).
// Squares directly when that neither underflows nor overflows, else scales (core/vec3.h length).
template <class T>
inline T checked_length(const Vec3<T>& n) {
  const T l2 = dot(n, n);
  T l;
  if (l2 > T(1e-30) && l2 < T(1e30)) l = std::sqrt(l2);
  else l = length(n);
  return (l > T(0) && std::isfinite(l)) ? l : T(0);
}

// Interior angle between edge vectors a and b given |a x b| (>= 0) and a . b: in [0, pi].
template <class T>
inline T interior_angle(T cross_length, T dot_ab) {
  return std::atan2(cross_length, dot_ab);
}

}  // namespace shadetool::normals_detail
