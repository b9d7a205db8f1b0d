// corner_contributions.h: the loops that call each face corner's contribution (the formulas:
// normals/weighting.h) for a range of faces, on the fastest path that gives them (internal to
// lib/normals; header-only so that the kernels inline it into their loops).
//
// For a triangle, |a x b| = |N| at every corner, so all three corners use the one well-conditioned
// N (geometry/face_area_vector.h). For a polygon (4+ corners), n comes from Newell's method and
// the corner's own angle is used (geometry/interior_angle.h, polygon_corner_angle).
//
// Precision: every contribution is computed in double (edges, cross products, lengths, angles,
// weights) and rounded once to T (the accumulation type) on its way to the sink, so T = float adds
// one rounding (relative 2^-24 per component) per term and nothing else: slivers keep the
// double-precision digits of their cross product (formerly the edges were rounded to float first,
// which left 1.3e-3 deg differences from double at sliver vertices). Unit contributions (Uniform,
// Angle) are scale-free. The callers pass meshes whose largest coordinate lies in [2^-32, 2^32)
// (engine/mesh_scale.h scales the others exactly), so no double product over- or underflows. Area
// (~ length^2) and Max (~ length^-2) contributions can still leave float's range (1.2e-38 ..
// 3.4e38) for a mesh with a wide range of face sizes, so for T = float they are multiplied by one
// power of two per mesh, `scale` (exact; the same for every face, so relative weights and the
// unit vertex normal are unchanged; contribution_scale below chooses it by the same rule,
// power_of_two_scale).
// Degenerate input: a face without area by geometry/degenerate_face.h (face_area_kind: fewer than
// 3 corners, NaN/Inf, zero area to 64 eps; a triangle with a repeated index has zero area)
// contributes nothing at all (the sink is not called), and is counted; a Max corner whose edge-length product is zero or underflows
// contributes nothing. Which path applies the rule how: see "Degenerate faces" below.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/interior_angle.h>
#include <shadetool/geometry/scaled_length.h>
#include <shadetool/normals/engine/mesh_scale.h>
#include <shadetool/normals/engine/triangle_blocks.h>
#include <shadetool/normals/weighting.h>

namespace shadetool::normals_detail {


// Calls sink(corner, vertex, contribution) for every corner of the triangles in [f_begin, f_end)
// whose area vector is valid. Requires mesh.all_triangles() (corner = 3 f + k).
// Returns the number of degenerate faces skipped. rows (optional): where the caller's per-vertex
// sums are, prefetched ahead of the sink's additions (kPrefetchFaces).
//
// Which cross product, per weighting (e_a x e_b has rounding error ~ eps |e_a| |e_b|, i.e.
// relative error ~ eps / sin(angle between them)):
//   Area     (p1 - p0) x (p2 - p0): the contribution is the unnormalised N itself, so its error
//            eps |e0| |e2| is at most eps (longest edge)^2, tiny against the vertex's sum of
//            areas whatever the triangle's shape: no need to pay for choosing edges.
//   Uniform, Angle  normalise N per face, and Max divides it by |a|^2 |b|^2: a sliver's error
//            would be amplified by its aspect ratio, so these take the two shortest edges
//            (geometry/face_area_vector.h, triangle_area_vector), whose relative error is ~ 2 eps.
// Degenerate faces (geometry/degenerate_face.h, the one rule), per path:
//   vector pass (triangle_blocks.cpp)  takes a face only when la, lb (squared lengths of the two
//            shortest edges) lie in (1e-125, 1e125) and N . N > tol^2 (la lb): the rule's own
//            squares test, the same expression on the same computed values (same bits); every
//            other face goes to triangle_scalar.
//   triangle_scalar, polygon_contributions  call the rule (triangle_degenerate_kind,
//            face_area_kind) for the face.
//   Area triangles  compute N0 = (p1 - p0) x (p2 - p0) (see below) and take a face as valid when
//            the rule's sufficient test triangle_surely_valid passes (N0 . N0 > (96 eps)^2
//            |e0|^2 |e2|^2, in range; it implies the rule's verdict None, proof there), else ask
//            the rule. It costs two dot products per triangle and no branch that mispredicts (the
//            rule itself runs only for near-degenerate faces).

// Software prefetch, kPrefetchFaces faces ahead, of the positions a triangle loop will read and
// (when the caller passes its per-vertex sums, `rows`, 3 values per vertex) of the sums it will
// add to: the hardware prefetchers do not follow the corner indices (figures:
// bench/normals/results/notes.md, "Timing notes moved from the source"). Only a hint: no effect
// on results.
constexpr std::size_t kPrefetchFaces = 64;

// The caller's per-vertex sums for prefetching: base address and bytes per vertex (none: null).
struct RowHint {
  const char* base = nullptr;
  std::size_t bytes = 0;
};

SHADETOOL_INLINE void prefetch_face(const double* P, const std::uint32_t* corners, RowHint rows) {
#if defined(__GNUC__)
  for (int k = 0; k < 3; ++k) {
    __builtin_prefetch(P + 3 * std::size_t(corners[k]));
    if (rows.base) __builtin_prefetch(rows.base + rows.bytes * std::size_t(corners[k]), 1);
  }
#else
  (void)P; (void)corners; (void)rows;
#endif
}

// A double contribution rounded to the accumulation type (no-op for double).
template <class T>
SHADETOOL_INLINE Vec3<T> to(const Vec3d& v) {
  if constexpr (std::is_same_v<T, double>) return v;
  else return {T(v.x), T(v.y), T(v.z)};
}

// Whether contributions of weighting W accumulated in T are multiplied by a per-mesh power of two.
template <class T, Weighting W>
constexpr bool kScaledContributions = !std::is_same_v<T, double> && (W == Weighting::Area || W == Weighting::Max);

// A double contribution times `scale` (only where kScaledContributions; else scale is 1 and unused)
// rounded to T.
template <class T, Weighting W>
SHADETOOL_INLINE Vec3<T> scaled(const Vec3d& v, double scale) {
  if constexpr (kScaledContributions<T, W>) return to<T>(v * scale);
  else { (void)scale; return to<T>(v); }
}

// One triangle's contributions on the scalar path: the faces the vector pass does not take
// (triangle_blocks.h: N . N outside [1e-250, 1e250], or for max l0 l1 l2 outside the normal
// range). The same formulas, with every length taken without over- or underflow. Returns false
// for a degenerate face (zero or non-finite area vector), which contributes nothing.
template <class T, Weighting W, class Sink>
inline bool triangle_scalar(const double* P, const std::uint32_t* cv, std::size_t c, Sink&& sink, double scale) {
  const std::uint32_t v0 = cv[c], v1 = cv[c + 1], v2 = cv[c + 2];
  const Vec3d p0 = load_position(P, v0), p1 = load_position(P, v1), p2 = load_position(P, v2);
  const Vec3d e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
  const double l0 = dot(e0, e0), l1 = dot(e1, e1), l2 = dot(e2, e2);
  if (triangle_degenerate_kind(P, v0, v1, v2) != DegenerateKind::None) return false;
  const Vec3d N = triangle_area_vector(P, v0, v1, v2, l0, l1, l2);
  if constexpr (W == Weighting::Max) {
    const double q = l0 * l1 * l2;
    if (q > std::numeric_limits<double>::min() && q < std::numeric_limits<double>::max()) {  // divisor checked
      const double inv = 1.0 / q;
      sink(c, v0, scaled<T, W>(N * (l1 * inv), scale));
      sink(c + 1, v1, scaled<T, W>(N * (l2 * inv), scale));
      sink(c + 2, v2, scaled<T, W>(N * (l0 * inv), scale));
    } else {  // the product under- or overflows: per corner, each divisor checked
      const double d[3] = {l0 * l2, l1 * l0, l2 * l1};
      const std::uint32_t v[3] = {v0, v1, v2};
      for (int k = 0; k < 3; ++k) {
        if (!(d[k] > 0.0)) continue;
        const Vec3d w = N * (1.0 / d[k]);
        if (is_finite(w)) sink(c + k, v[k], scaled<T, W>(w, scale));
      }
    }
    return true;
  } else {
    (void)scale;
    const double len = checked_length(N);  // scales instead of squaring where N . N under/overflows
    if (!(len > 0.0)) return false;        // not reached for a face the rule calls valid
    const Vec3d n = unit_normal(N, len);   // divisor checked
    if constexpr (W == Weighting::Uniform) {
      const Vec3<T> u = to<T>(uniform_contribution(n));
      sink(c, v0, u); sink(c + 1, v1, u); sink(c + 2, v2, u);
    } else {
      const double t0 = interior_angle(len, -dot(e0, e2)), t1 = interior_angle(len, -dot(e1, e0));
      sink(c, v0, to<T>(angle_contribution(n, t0)));
      sink(c + 1, v1, to<T>(angle_contribution(n, t1)));
      sink(c + 2, v2, to<T>(angle_contribution(n, kPi - t0 - t1)));
    }
    return true;
  }
}

// Steps (1) and (2) of triangle_block_contributions (below) for the block of faces [b, b + count)
// (positions prefetched kPrefetchFaces ahead, never past f_end): the corner positions into xyz
// (structure of arrays: row 3k + j is coordinate j of corner k) and the weighting's contributions
// into w (triangle_blocks.h's layout; NaN in w[0][i] where the vector pass does not take face
// b + i). Shared with the crease path's slot pass (vertex_slots.h).
template <Weighting W>
inline void gather_block_contributions(const double* P, const std::uint32_t* cv, std::size_t b, std::size_t count,
                                       std::size_t f_end, double (&xyz)[9][kTriangleBlock],
                                       double (&w)[9][kTriangleBlock]) {
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t c = 3 * (b + i);
    if (b + i + kPrefetchFaces < f_end) prefetch_face(P, cv + c + 3 * kPrefetchFaces, RowHint{});
    for (int k = 0; k < 3; ++k) {
      const double* p = P + 3 * std::size_t(cv[c + k]);
      xyz[3 * k][i] = p[0]; xyz[3 * k + 1][i] = p[1]; xyz[3 * k + 2][i] = p[2];
    }
  }
  if constexpr (W == Weighting::Angle) triangle_block_angle(count, &xyz[0][0], &w[0][0]);
  else if constexpr (W == Weighting::Max) triangle_block_max(count, &xyz[0][0], &w[0][0]);
  else triangle_block_uniform(count, &xyz[0][0], &w[0][0]);
}

// Uniform, Angle and Max for triangles, in blocks of kTriangleBlock faces and three passes over
// each block: (1) gather the corner positions (structure of arrays; positions prefetched
// kPrefetchFaces ahead), (2) the contributions of the whole block by the vectorised
// triangle_block_* (triangle_blocks.h: edges, shortest pair, cross product, and the weighting's
// lengths, square root, division, arctangents; 2, 4 or 8 faces per instruction), (3) the sums
// (the caller's sums prefetched ahead). Faces the vector pass cannot take go through
// triangle_scalar.
template <class T, Weighting W, class Sink>
inline std::size_t triangle_block_contributions(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, Sink&& sink,
                                                double scale, RowHint rows) {
  std::size_t degenerate = 0;
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  alignas(64) double xyz[9][kTriangleBlock];
  alignas(64) double w[9][kTriangleBlock];
  for (std::size_t b = f_begin; b < f_end; b += kTriangleBlock) {
    const std::size_t count = std::min(kTriangleBlock, f_end - b);
    gather_block_contributions<W>(P, cv, b, count, f_end, xyz, w);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t c = 3 * (b + i);
      if (rows.base && b + i + kPrefetchFaces < f_end) prefetch_face(P, cv + c + 3 * kPrefetchFaces, rows);
      if (std::isnan(w[0][i])) {  // out of the vector pass's range: scalar path
        degenerate += !triangle_scalar<T, W>(P, cv, c, sink, scale);
        continue;
      }
      sink(c, cv[c], scaled<T, W>(Vec3d{w[0][i], w[1][i], w[2][i]}, scale));
      sink(c + 1, cv[c + 1], scaled<T, W>(Vec3d{w[3][i], w[4][i], w[5][i]}, scale));
      sink(c + 2, cv[c + 2], scaled<T, W>(Vec3d{w[6][i], w[7][i], w[8][i]}, scale));
    }
  }
  return degenerate;
}

template <class T, Weighting W, class Sink>
inline std::size_t triangle_contributions(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, Sink&& sink,
                                          double scale = 1.0, RowHint rows = {}) {
  if constexpr (W != Weighting::Area) {
    return triangle_block_contributions<T, W>(mesh, f_begin, f_end, sink, scale, rows);
  } else {
    // Area: (p1 - p0) x (p2 - p0) and three additions per face; already memory-bound, no blocks.
    std::size_t degenerate = 0;
    const double* P = mesh.positions;
    const std::uint32_t* cv = mesh.corner_vertex;
    for (std::size_t f = f_begin; f < f_end; ++f) {
      const std::size_t c = 3 * f;
      if (f + kPrefetchFaces < f_end) prefetch_face(P, cv + c + 3 * kPrefetchFaces, rows);
      const std::uint32_t v0 = cv[c], v1 = cv[c + 1], v2 = cv[c + 2];
      const Vec3d p0 = load_position(P, v0), p1 = load_position(P, v1), p2 = load_position(P, v2);
      const Vec3d e0 = p1 - p0, e2 = p2 - p0;
      const Vec3d N = cross(e0, e2);
      // Valid by the sufficient test (geometry/degenerate_face.h), else ask the rule (rare).
      const bool fast = triangle_surely_valid(N, e0, e2);
      if (__builtin_expect(!fast, 0) && triangle_degenerate_kind(P, v0, v1, v2) != DegenerateKind::None) {
        ++degenerate;
        continue;
      }
      const Vec3<T> w = scaled<T, W>(area_contribution(N), scale);
      sink(c, v0, w); sink(c + 1, v1, w); sink(c + 2, v2, w);
    }
    return degenerate;
  }
}

// The same for any face sizes (triangles among polygons take the triangle formulas).
template <class T, Weighting W, class Sink>
inline std::size_t polygon_contributions(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, Sink&& sink,
                                         double scale = 1.0) {
  std::size_t degenerate = 0;
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  for (std::size_t f = f_begin; f < f_end; ++f) {
    const std::uint32_t begin = mesh.face_begin(f), end = mesh.face_end(f), n_corners = end - begin;
    if (face_area_kind(P, cv + begin, n_corners) != DegenerateKind::None) { ++degenerate; continue; }
    Vec3d N;
    if (n_corners == 3) {
      const Vec3d p0 = load_position(P, cv[begin]), p1 = load_position(P, cv[begin + 1]), p2 = load_position(P, cv[begin + 2]);
      const Vec3d e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
      N = triangle_area_vector(P, cv[begin], cv[begin + 1], cv[begin + 2], dot(e0, e0), dot(e1, e1), dot(e2, e2));
    } else {
      N = newell_area_vector(P, cv + begin, n_corners);
    }
    const double len = checked_length(N);
    if (!(len > 0.0)) { ++degenerate; continue; }  // not reached for a face the rule calls valid
    const Vec3d n = unit_normal(N, len);            // divisor checked
    for (std::uint32_t c = begin; c < end; ++c) {
      const std::uint32_t v = cv[c];
      if constexpr (W == Weighting::Uniform) {
        sink(c, v, to<T>(uniform_contribution(n)));
      } else if constexpr (W == Weighting::Area) {
        sink(c, v, scaled<T, W>(area_contribution(N), scale));
      } else {
        const std::uint32_t next = c + 1 < end ? c + 1 : begin, prev = c > begin ? c - 1 : end - 1;
        const Vec3d p = load_position(P, v);
        const Vec3d a = load_position(P, cv[next]) - p, b = load_position(P, cv[prev]) - p;
        if (n_corners == 3) {
          // Triangle among polygons: |a x b| = |N| exactly as in triangle_contributions.
          if constexpr (W == Weighting::Angle) {
            sink(c, v, to<T>(angle_contribution(n, interior_angle(len, dot(a, b)))));
          } else {
            Vec3d w;
            if (max_contribution(N, 1.0, dot(a, a) * dot(b, b), w)) sink(c, v, scaled<T, W>(w, scale));
          }
        } else {
          const double s = dot(cross(a, b), n);  // |a||b| sin(theta), signed about the face normal
          if constexpr (W == Weighting::Angle) {
            sink(c, v, to<T>(angle_contribution(n, polygon_corner_angle(s, dot(a, b)))));
          } else {
            Vec3d w;
            if (max_contribution(n, std::fabs(s), dot(a, a) * dot(b, b), w)) sink(c, v, scaled<T, W>(w, scale));
          }
        }
      }
    }
  }
  return degenerate;
}

// The power of two by which kScaledContributions<T, W> multiplies contributions before rounding
// them to T: 2^-e, e = ilogb of the largest contribution magnitude (max |component|, double) among
// up to kScaleSample faces spread evenly over the mesh (deterministic; a few microseconds), so the
// sampled contributions land in [1, 2) and the whole mesh in float's range unless its faces
// differ in size by a factor beyond ~2^100 from the sample's largest (a float sum that then
// overflows makes its vertex take the callers' documented fallback; never NaN). sample = false
// scans every face. Returns 1 where nothing is scaled or no face is valid. The exponent is
// clamped to [-1000, 1000] (2^1000 is finite).
constexpr std::size_t kScaleSample = 1024;

template <class T, Weighting W>
inline double contribution_scale(const MeshView& mesh, bool sample = true) {
  if constexpr (!kScaledContributions<T, W>) {
    (void)mesh; (void)sample;
    return 1.0;
  } else {
    const std::size_t F = mesh.num_faces();
    double peak = 0.0;
    auto track = [&peak](std::size_t, std::uint32_t, const Vec3d& w) {
      const double m = std::fmax(std::fabs(w.x), std::fmax(std::fabs(w.y), std::fabs(w.z)));
      if (std::isfinite(m)) peak = std::fmax(peak, m);
    };
    const bool triangles = mesh.all_triangles();
    auto one = [&](std::size_t f) {
      if (triangles) triangle_contributions<double, W>(mesh, f, f + 1, track);
      else polygon_contributions<double, W>(mesh, f, f + 1, track);
    };
    if (sample && F > kScaleSample) {
      for (std::size_t i = 0; i < kScaleSample; ++i) one(i * F / kScaleSample);
    } else if (triangles) {
      triangle_contributions<double, W>(mesh, 0, F, track);
    } else {
      polygon_contributions<double, W>(mesh, 0, F, track);
    }
    return power_of_two_scale(peak);  // the one rule (engine/mesh_scale.h); 1 when no face is valid
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
