// corner_contributions.h: what each face corner adds to its vertex's normal under each weighting
// (internal to lib/normals; header-only so that the kernels inline it into their loops).
//
// For face f with area vector N = 2 A n (face_geometry.h) and a corner at vertex v whose edges
// to the next and previous corners are a and b, the contribution is
//   Uniform  n                                  (Gouraud 1971)
//   Area     N = 2 A n                          (area weighting; OpenMesh update_normals,
//                                                libigl PER_VERTEX_NORMALS_WEIGHTING_TYPE_AREA)
//   Angle    theta n, theta = atan2(|a x b|, a.b) (Thuermer & Wuethrich 1998; libigl ANGLE)
//   Max      n sin(theta) / (|a| |b|) = (a x b) / (|a|^2 |b|^2) for a triangle (Max 1999, eq. 6)
// For a triangle, |a x b| = |N| at every corner, so all three corners use the one well-conditioned
// N. For a polygon (4+ corners), n comes from Newell's method and the corner's own angle is used:
// theta = atan2((a x b).n, a.b), taken in [0, 2 pi) so that a reflex corner of a concave polygon
// counts as reflex; Max uses |(a x b).n| / (|a|^2 |b|^2).
//
// Precision: T (double or float) for every operation after the edge vectors, which are formed in
// double and rounded once to T (face_geometry.h, `edge`).
// Degenerate input: a face whose area vector is zero or not finite (repeated index, coincident or
// collinear positions, NaN/Inf) contributes nothing at all (the sink is not called); a Max corner
// whose edge-length product is zero or underflows contributes nothing.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "core/mesh.h"
#include "normals/face_geometry.h"
#include "normals/weighting.h"

namespace shadetool::normals_detail {

constexpr double kTwoPi = 6.283185307179586476925286766559;

// Calls sink(corner, vertex, contribution) for every corner of the triangles in [f_begin, f_end)
// whose area vector is valid. Requires mesh.all_triangles() (corner = 3 f + k).
template <class T, Weighting W, class Sink>
inline void triangle_contributions(const Mesh& mesh, std::size_t f_begin, std::size_t f_end, Sink&& sink) {
  const double* P = mesh.positions.data();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  for (std::size_t f = f_begin; f < f_end; ++f) {
    const std::size_t c = 3 * f;
    const std::uint32_t v0 = cv[c], v1 = cv[c + 1], v2 = cv[c + 2];
    const Vec3d p0 = load_position(P, v0), p1 = load_position(P, v1), p2 = load_position(P, v2);
    const Vec3<T> e0 = edge<T>(p0, p1), e1 = edge<T>(p1, p2), e2 = edge<T>(p2, p0);
    const T l0 = dot(e0, e0), l1 = dot(e1, e1), l2 = dot(e2, e2);
    const Vec3<T> N = triangle_area_vector(e0, e1, e2, l0, l1, l2);
    if constexpr (W == Weighting::Area) {
      if (!std::isfinite(N.x + N.y + N.z) || (N.x == T(0) && N.y == T(0) && N.z == T(0))) continue;
      sink(c, v0, N); sink(c + 1, v1, N); sink(c + 2, v2, N);
    } else if constexpr (W == Weighting::Max) {
      if (!std::isfinite(N.x + N.y + N.z) || (N.x == T(0) && N.y == T(0) && N.z == T(0))) continue;
      // corner 0: edges e0 and -e2; corner 1: e1 and -e0; corner 2: e2 and -e1.
      const T d0 = l0 * l2, d1 = l1 * l0, d2 = l2 * l1;
      if (d0 > T(0)) sink(c, v0, N * (T(1) / d0));
      if (d1 > T(0)) sink(c + 1, v1, N * (T(1) / d1));
      if (d2 > T(0)) sink(c + 2, v2, N * (T(1) / d2));
    } else {
      const T len = checked_length(N);
      if (!(len > T(0))) continue;  // degenerate: contributes nothing
      const Vec3<T> n = N * (T(1) / len);
      if constexpr (W == Weighting::Uniform) {
        sink(c, v0, n); sink(c + 1, v1, n); sink(c + 2, v2, n);
      } else {  // Angle: the corner at v_k lies between e_k and -e_{k-1}
        sink(c, v0, n * interior_angle(len, -dot(e0, e2)));
        sink(c + 1, v1, n * interior_angle(len, -dot(e1, e0)));
        sink(c + 2, v2, n * interior_angle(len, -dot(e2, e1)));
      }
    }
  }
}

// The same for any face sizes (triangles among polygons take the triangle formulas).
template <class T, Weighting W, class Sink>
inline void polygon_contributions(const Mesh& mesh, std::size_t f_begin, std::size_t f_end, Sink&& sink) {
  const double* P = mesh.positions.data();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  for (std::size_t f = f_begin; f < f_end; ++f) {
    const std::uint32_t begin = mesh.face_start[f], end = mesh.face_start[f + 1], n_corners = end - begin;
    if (n_corners < 3) continue;
    Vec3<T> N;
    if (n_corners == 3) {
      const Vec3d p0 = load_position(P, cv[begin]), p1 = load_position(P, cv[begin + 1]), p2 = load_position(P, cv[begin + 2]);
      const Vec3<T> e0 = edge<T>(p0, p1), e1 = edge<T>(p1, p2), e2 = edge<T>(p2, p0);
      N = triangle_area_vector(e0, e1, e2, dot(e0, e0), dot(e1, e1), dot(e2, e2));
    } else {
      N = newell_area_vector<T>(mesh, f);
    }
    const T len = checked_length(N);
    if (!(len > T(0))) continue;  // degenerate: contributes nothing
    const Vec3<T> n = N * (T(1) / len);
    for (std::uint32_t c = begin; c < end; ++c) {
      const std::uint32_t v = cv[c];
      if constexpr (W == Weighting::Uniform) {
        sink(c, v, n);
      } else if constexpr (W == Weighting::Area) {
        sink(c, v, N);
      } else {
        const std::uint32_t next = c + 1 < end ? c + 1 : begin, prev = c > begin ? c - 1 : end - 1;
        const Vec3d p = load_position(P, v);
        const Vec3<T> a = edge<T>(p, load_position(P, cv[next])), b = edge<T>(p, load_position(P, cv[prev]));
        if (n_corners == 3) {
          // Triangle among polygons: |a x b| = |N| exactly as in triangle_contributions.
          if constexpr (W == Weighting::Angle) {
            sink(c, v, n * interior_angle(len, dot(a, b)));
          } else {
            const T d = dot(a, a) * dot(b, b);
            if (d > T(0)) sink(c, v, N * (T(1) / d));
          }
        } else {
          const T s = dot(cross(a, b), n);  // |a||b| sin(theta), signed about the face normal
          if constexpr (W == Weighting::Angle) {
            T theta = std::atan2(s, dot(a, b));
            if (theta < T(0)) theta += T(kTwoPi);  // reflex corner of a concave polygon
            sink(c, v, n * theta);
          } else {
            const T d = dot(a, a) * dot(b, b);
            if (d > T(0)) sink(c, v, n * (std::fabs(s) / d));
          }
        }
      }
    }
  }
}

template <Weighting W>
using WeightingTag = std::integral_constant<Weighting, W>;

// Calls fn(T{}, WeightingTag<W>{}) with the compile-time T and W for the run-time choices; in a
// generic lambda: `using T = decltype(t); constexpr Weighting W = decltype(w)::value;`.
template <class Fn>
inline auto dispatch(Weighting weighting, Precision precision, Fn&& fn) {
  const bool f32 = precision == Precision::Float;
  switch (weighting) {
    case Weighting::Uniform:
      return f32 ? fn(float{}, WeightingTag<Weighting::Uniform>{}) : fn(double{}, WeightingTag<Weighting::Uniform>{});
    case Weighting::Area:
      return f32 ? fn(float{}, WeightingTag<Weighting::Area>{}) : fn(double{}, WeightingTag<Weighting::Area>{});
    case Weighting::Max:
      return f32 ? fn(float{}, WeightingTag<Weighting::Max>{}) : fn(double{}, WeightingTag<Weighting::Max>{});
    case Weighting::Angle:
      break;
  }
  return f32 ? fn(float{}, WeightingTag<Weighting::Angle>{}) : fn(double{}, WeightingTag<Weighting::Angle>{});
}

}  // namespace shadetool::normals_detail
