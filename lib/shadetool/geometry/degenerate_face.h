// degenerate_face.h: the one rule for a degenerate face, used by info (counts), repair (removal)
// and normals (which faces contribute nothing).
//
// Inputs:  mesh  positions #V by 3, a face f (any corner count)
// Output:  DegenerateKind of face f, tested in this order (the last three: face_area_kind, the
//          part normals use, see there):
//   TooFewCorners  fewer than 3 corners
//   RepeatedIndex  a vertex index used at two corners ((a, a, b) has no winding of its own)
//   NonFinite      a corner position, the area vector or its bound is NaN or Inf (positions
//                  beyond ~1e150 whose cross products overflow count here)
//   ZeroArea       the area vector N (geometry/face_area_vector.h) vanishes to rounding:
//                  |N| <= kDegenerateTolerance * B, kDegenerateTolerance = 64 eps (~1.4e-14),
//                  B = |a| |b| for a triangle (a, b its two shortest edges, the pair N is made
//                  of: the test reads sin(largest angle) <= 64 eps, i.e. collinear to double
//                  precision, whatever the corner order), B = sum_i |p_i - p_0| |p_{i+1} - p_0|
//                  for a polygon (the bound Newell's sum's rounding scales with)
//   None           otherwise
// The test is scale-free: a face 1e-20 wide with a fine shape is not degenerate. One tolerance
// for every caller; nothing else in the library decides what a degenerate face is.
// Precision: double. A triangle whose two shortest squared edge lengths la, lb both lie in
// (1e-125, 1e125) is tested on squares, N . N <= tol^2 (la lb) (triangle_zero_area_by_squares;
// no square roots, no over- or underflow there: la lb in (1e-250, 1e250)); others use the scaled
// lengths of core/vec3.h. The normals kernels evaluate that same expression on the same values
// (normals/engine/triangle_blocks.cpp), or a sufficient test that provably implies it
// (triangle_surely_valid below: the area kernel of normals/engine/corner_contributions.h and
// repair's volume pass), and call triangle_degenerate_kind (or face_degenerate_kind) for every
// other face, so they skip exactly the faces this rule calls degenerate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/repeated_index.h>  // has_repeated_index: the RepeatedIndex test
#include <shadetool/geometry/face_area_vector.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class DegenerateKind : std::uint8_t { None = 0, TooFewCorners, RepeatedIndex, ZeroArea, NonFinite };

constexpr double kDegenerateTolerance = 64 * 2.220446049250313e-16;  // 64 eps
constexpr double kDegenerateTolerance2 = kDegenerateTolerance * kDegenerateTolerance;
// Squared lengths for which the triangle test runs on squares.
constexpr double kSquaresTestFrom = 1e-125, kSquaresTestTo = 1e125;

// The triangle test on squares: true when la and lb (squared lengths of the two shortest edges)
// are in range; then `zero_area` says whether nn = N . N <= tol^2 (la lb). False: use
// triangle_degenerate_kind (scaled lengths). NaN input returns false.
SHADETOOL_INLINE bool triangle_zero_area_by_squares(double nn, double la, double lb, bool& zero_area) {
  if (!((la > kSquaresTestFrom) & (la < kSquaresTestTo) & (lb > kSquaresTestFrom) & (lb < kSquaresTestTo))) return false;
  zero_area = !(nn > kDegenerateTolerance2 * (la * lb));
  return true;
}

// A sufficient test that a triangle is not degenerate, for a loop that has computed
// N0 = e0 x e2 with e0 = p1 - p0, e2 = p2 - p0 anyway (the area-weighted normals kernel, repair's
// volume pass): true when N0 . N0 > (96 eps)^2 |e0|^2 |e2|^2 with |e0|^2 |e2|^2 in [1e-250, 1e249]
// (then N0 . N0 <= |e0|^2 |e2|^2 is in range too). True implies the rule's verdict None: N0 and the
// rule's N are both within 5 eps |e0| |e2| of the exact area vector (rounded edges, two products
// and a difference per component, no over/underflow in that range) and the rule's |a| |b| <=
// |e0| |e2| (the two shortest edges have the smallest product), so |N| > (96 - 10) eps |e0| |e2| >
// 64 eps |a| |b| with room for the rule's own rounding of its lengths. False: ask the rule
// (face_degenerate_kind or triangle_degenerate_kind; near-degenerate faces, NaN, a repeated index).
// Evaluated as: |e0|^2 |e2|^2 = nn + d^2 with d = e0 . e2 (Lagrange's identity), so the test reads
// nn > K' d^2 with K' = (96 eps)^2 / (1 - (96 eps)^2): one dot product instead of two squared
// lengths and their product; q = nn + d^2 in [1e-250, 1e249] as one unsigned compare of the bit
// patterns (monotonic for q >= 0; NaN lies above). Two dot products and no branch that
// mispredicts, where the rule itself picks the two shortest edges.
constexpr double kSurelyValid2 = (96 * 2.220446049250313e-16) * (96 * 2.220446049250313e-16);
constexpr double kSurelyValidLagrange = kSurelyValid2 / (1 - kSurelyValid2);
// Bit patterns of 1e-250 and 1e249, and the span between them.
constexpr std::uint64_t kSurelyValidQFrom = 0x0c06e93f5da2824cull, kSurelyValidQTo = 0x73a1e0b622c774d0ull;
constexpr std::uint64_t kSurelyValidQSpan = kSurelyValidQTo - kSurelyValidQFrom;

SHADETOOL_INLINE bool triangle_surely_valid(const Vec3d& N0, const Vec3d& e0, const Vec3d& e2) {
  const double nn = dot(N0, N0), d = dot(e0, e2), d2 = d * d, q = nn + d2;
  std::uint64_t q_bits;
  std::memcpy(&q_bits, &q, sizeof q);
  return (nn > kSurelyValidLagrange * d2) & (q_bits - kSurelyValidQFrom < kSurelyValidQSpan);
}

// Kind of triangle (v0, v1, v2) from its positions only: None, ZeroArea or NonFinite (a repeated
// index gives a zero edge and so ZeroArea here; face_degenerate_kind names it RepeatedIndex).
#if defined(__GNUC__)
__attribute__((cold))
#endif
DegenerateKind triangle_degenerate_kind(const double* positions, std::uint32_t v0, std::uint32_t v1, std::uint32_t v2);

// Whether triangle (v0, v1, v2), whose TriangleAreaVector t the caller has computed, is degenerate
// (the squares test on t, else triangle_degenerate_kind).
SHADETOOL_INLINE bool triangle_is_degenerate(const TriangleAreaVector& t, const double* positions, std::uint32_t v0,
                                             std::uint32_t v1, std::uint32_t v2) {
  bool zero_area = false;
  if (triangle_zero_area_by_squares(dot(t.N, t.N), t.la, t.lb, zero_area)) return zero_area;
  return triangle_degenerate_kind(positions, v0, v1, v2) != DegenerateKind::None;
}

// Kind of face f. scratch: reused storage for the repeated-index test of large polygons.
DegenerateKind face_degenerate_kind(const Mesh& mesh, std::size_t f, std::vector<std::uint32_t>& scratch);
DegenerateKind face_degenerate_kind(const Mesh& mesh, std::size_t f);

// The area part of the rule alone (TooFewCorners, NonFinite, ZeroArea or None; no index test):
// whether face f has an area vector, i.e. a normal. Normals use this: a face with a repeated
// index (a quad (a, a, b, c) is the triangle (a, b, c)) has no winding of its own, so info counts
// it and repair removes it, but when it still has area its normal is well defined and it
// contributes to its vertices' normals. A face without area is degenerate for all three.
DegenerateKind face_area_kind(const Mesh& mesh, std::size_t f);
// The same for the face whose corner list is corners[0 .. n) (vertex indices into positions).
DegenerateKind face_area_kind(const double* positions, const std::uint32_t* corners, std::uint32_t n);

}  // namespace shadetool
#pragma GCC visibility pop
