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
//
// Precision: double (edges, cross products and lengths), whatever the kernels accumulate in;
// corner_contributions.h and face_normals.cpp round the finished result once.
// Degenerate input: a repeated index or coincident positions give an exactly zero area vector;
// callers take `checked_length` (0 for zero or non-finite vectors) and test it before dividing.
#pragma once

#include <cmath>
#include <cstdint>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

// The kernels' per-face helpers must be inlined into their loops (GCC otherwise keeps some out of
// line and the result goes through the stack); this only affects code generation.
#if defined(__GNUC__)
#define SHADETOOL_NORMALS_INLINE inline __attribute__((always_inline))
#else
#define SHADETOOL_NORMALS_INLINE inline
#endif

namespace shadetool::normals_detail {

SHADETOOL_NORMALS_INLINE Vec3d load_position(const double* positions, std::uint32_t v) {
  const double* p = positions + 3 * std::size_t(v);
  return {p[0], p[1], p[2]};
}

// Area vector 2 A n of triangle (v0, v1, v2) whose edges e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2
// have squared lengths l0, l1, l2. Any two edges from one vertex give the same cross product in
// exact arithmetic; we take the two shortest, i.e. those from the vertex opposite the longest
// edge (the apex), keeping the cyclic order so the orientation is unchanged:
// e0 longest -> (p0 - p2) x (p1 - p2); e1 longest -> (p1 - p0) x (p2 - p0); e2 longest ->
// (p2 - p1) x (p0 - p1). Rounding error is then smallest for slivers. The apex is chosen among
// vertex indices (integer selects, no branch: which edge is longest is unpredictable on irregular
// meshes, and a mispredicted branch cost more than the product itself).
// Corner opposite the longest edge (the apex): 2 when e0 = p1 - p0 is longest, 0 for e1 = p2 - p1,
// 1 for e2 = p0 - p2 (ties resolved in that order). Its angle is the triangle's largest.
// Arithmetic on the comparison results, not ?: or &&, so that no branch is emitted (which edge is
// longest is unpredictable on irregular meshes; a mispredicted branch per triangle cost more than
// the whole area-weighted kernel).
template <class T>
SHADETOOL_NORMALS_INLINE int apex_corner(T l0, T l1, T l2) {
  const int e0_longest = int(l0 >= l1) & int(l0 >= l2);
  const int e1_longest = int(l1 > l0) & int(l1 >= l2);
  return 1 + e0_longest - e1_longest;  // 2, 0, or 1 when e2 is longest
}

SHADETOOL_NORMALS_INLINE Vec3d triangle_area_vector(const double* positions, std::uint32_t v0, std::uint32_t v1,
                                                    std::uint32_t v2, double l0, double l1, double l2) {
  const std::uint32_t v[5] = {v0, v1, v2, v0, v1};
  const int k = apex_corner(l0, l1, l2);
  const Vec3d p = load_position(positions, v[k]);
  return cross(load_position(positions, v[k + 1]) - p, load_position(positions, v[k + 2]) - p);
}

// Newell's method about p_0: N = sum_i (p_i - p_0) x (p_{i+1} - p_0) = 2 A n for a planar
// polygon; for a non-planar one, the normal of the plane that best fits its projected areas.
inline Vec3d newell_area_vector(const Mesh& mesh, std::size_t f) {
  const std::uint32_t begin = mesh.face_start[f], end = mesh.face_start[f + 1];
  Vec3d n{};
  if (end - begin < 3) return n;
  const Vec3d p0 = load_position(mesh.positions.data(), mesh.corner_vertex[begin]);
  Vec3d prev = load_position(mesh.positions.data(), mesh.corner_vertex[begin + 1]) - p0;
  for (std::uint32_t c = begin + 2; c < end; ++c) {
    const Vec3d cur = load_position(mesh.positions.data(), mesh.corner_vertex[c]) - p0;
    n += cross(prev, cur);
    prev = cur;
  }
  return n;
}

// Length of n, or 0 when n is zero or not finite (the caller then treats the face as degenerate).
// Squares directly when that neither underflows nor overflows, else scales (core/vec3.h length).
template <class T>
SHADETOOL_NORMALS_INLINE T checked_length(const Vec3<T>& n) {
  const T l2 = dot(n, n);
  T l;
  if (l2 > T(1e-30) && l2 < T(1e30)) l = std::sqrt(l2);
  else l = length(n);
  return (l > T(0) && std::isfinite(l)) ? l : T(0);
}

}  // namespace shadetool::normals_detail
