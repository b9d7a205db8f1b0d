// face_area_vector.h: the one area vector of a face, N = 2 A n (twice its area times its unit
// normal), from which every normal, every area weight and the degenerate-face rule are computed.
//
//   triangle_area_vector  cross product of the triangle's two shortest edges (the pair that leaves
//                         out the longest edge): of the three cross products that are equal in
//                         exact arithmetic it has the smallest rounding error for slivers.
//   newell_area_vector    a polygon (planar or not) by Newell's method (Sutherland, Sproull &
//                         Schumacker 1974; Tampieri, "Newell's method for computing the plane
//                         equation of a polygon", Graphics Gems III, 1992), about the polygon's
//                         first corner to keep coordinates small.
//   face_area_vector      either, by the face's corner count (3: triangle; 4+: Newell; fewer: 0).
//
// Inputs:  positions #V by 3 (double), a face's corner vertex indices (or mesh and face index)
// Output:  Vec3d N. Precision: double (edges, cross products).
// Degenerate input: a repeated index or coincident positions give an exactly zero N; collinear
// corners give N zero to rounding; NaN/Inf positions a non-finite N. Whether a face counts as
// degenerate is decided by geometry/degenerate_face.h, nowhere else.
#pragma once

#include <cstddef>
#include <cstdint>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

// Per-face helpers that the normals kernels must inline into their loops (GCC otherwise keeps
// some out of line and the result goes through the stack); this only affects code generation.
#if defined(__GNUC__)
#define SHADETOOL_INLINE inline __attribute__((always_inline))
#else
#define SHADETOOL_INLINE inline
#endif

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

SHADETOOL_INLINE Vec3d load_position(const double* positions, std::uint32_t v) {
  const double* p = positions + 3 * std::size_t(v);
  return {p[0], p[1], p[2]};
}

// Corner opposite the longest edge (the apex) of a triangle whose edges e0 = p1 - p0,
// e1 = p2 - p1, e2 = p0 - p2 have squared lengths l0, l1, l2: 2 when e0 is longest, 0 for e1,
// 1 for e2 (ties resolved in that order). Its angle is the triangle's largest.
// Arithmetic on the comparison results, not ?: or &&, so that no branch is emitted (which edge is
// longest is unpredictable on irregular meshes; a mispredicted branch per triangle cost more than
// the whole area-weighted kernel).
template <class T>
SHADETOOL_INLINE int apex_corner(T l0, T l1, T l2) {
  const int e0_longest = int(l0 >= l1) & int(l0 >= l2);
  const int e1_longest = int(l1 > l0) & int(l1 >= l2);
  return 1 + e0_longest - e1_longest;  // 2, 0, or 1 when e2 is longest
}

// N of triangle (v0, v1, v2) from its two shortest edges, those from the apex, keeping the cyclic
// order so the orientation is unchanged: e0 longest -> (p0 - p2) x (p1 - p2); e1 longest ->
// (p1 - p0) x (p2 - p0); e2 longest -> (p2 - p1) x (p0 - p1). The apex is chosen among vertex
// indices (integer selects, no branch). l0, l1, l2 as for apex_corner.
SHADETOOL_INLINE Vec3d triangle_area_vector(const double* positions, std::uint32_t v0, std::uint32_t v1,
                                            std::uint32_t v2, double l0, double l1, double l2) {
  const std::uint32_t v[5] = {v0, v1, v2, v0, v1};
  const int k = apex_corner(l0, l1, l2);
  const Vec3d p = load_position(positions, v[k]);
  return cross(load_position(positions, v[k + 1]) - p, load_position(positions, v[k + 2]) - p);
}

// The same with the squared lengths of the two edges whose cross product N is (for the
// degenerate-face rule: |N| against |a| |b| of the same two edges).
struct TriangleAreaVector {
  Vec3d N;
  double la, lb;  // squared lengths of the two shortest edges
};

SHADETOOL_INLINE TriangleAreaVector triangle_area_vector(const double* positions, std::uint32_t v0, std::uint32_t v1,
                                                         std::uint32_t v2) {
  const Vec3d p0 = load_position(positions, v0), p1 = load_position(positions, v1), p2 = load_position(positions, v2);
  const Vec3d e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
  const double l0 = dot(e0, e0), l1 = dot(e1, e1), l2 = dot(e2, e2);
  const int k = apex_corner(l0, l1, l2);
  // the two shortest: all but the longest (k = 2: e0 longest -> l1, l2; k = 0: l2, l0; k = 1: l0, l1)
  const double la = k == 2 ? l1 : (k == 0 ? l2 : l0), lb = k == 2 ? l2 : (k == 0 ? l0 : l1);
  return {triangle_area_vector(positions, v0, v1, v2, l0, l1, l2), la, lb};
}

// Newell's method about p_0: N = sum_i (p_i - p_0) x (p_{i+1} - p_0) = 2 A n for a planar
// polygon; for a non-planar one, the normal of the plane that best fits its projected areas.
// The face is the corner list corners[0 .. n) (vertex indices into positions, #V by 3).
inline Vec3d newell_area_vector(const double* positions, const std::uint32_t* corners, std::uint32_t n) {
  Vec3d sum{};
  if (n < 3) return sum;
  const Vec3d p0 = load_position(positions, corners[0]);
  Vec3d prev = load_position(positions, corners[1]) - p0;
  for (std::uint32_t i = 2; i < n; ++i) {
    const Vec3d cur = load_position(positions, corners[i]) - p0;
    sum += cross(prev, cur);
    prev = cur;
  }
  return sum;
}

inline Vec3d newell_area_vector(const Mesh& mesh, std::size_t f) {
  const std::uint32_t begin = mesh.face_start[f], end = mesh.face_start[f + 1];
  return newell_area_vector(mesh.positions.data(), mesh.corner_vertex.data() + begin, end - begin);
}

inline Vec3d face_area_vector(const Mesh& mesh, std::size_t f) {
  const std::uint32_t begin = mesh.face_start[f], n = mesh.face_start[f + 1] - begin;
  if (n != 3) return newell_area_vector(mesh, f);  // fewer than 3 corners: zero
  const std::uint32_t* cv = mesh.corner_vertex.data() + begin;
  return triangle_area_vector(mesh.positions.data(), cv[0], cv[1], cv[2]).N;
}

}  // namespace shadetool
#pragma GCC visibility pop
