// triangle_blocks.h: the vectorised passes of the triangle kernels (internal to lib/normals): per
// block of up to kTriangleBlock triangles, from corner positions to the corners' contributions,
// in loops the compiler vectorises; and the arctangent they use (interior_angles).
//
// Vectorisation: no table, no branch, every step a lane-wise select, so that GCC vectorises the
// loops at -O3 with the default x86-64 baseline (SSE2, 2 lanes) and, on processors that have them,
// AVX2 (4 lanes) and AVX-512 (8 lanes, 32 registers: fewer spills than AVX2; notes.md in bench/normals/results);
// GCC target_clones, one chosen at load time. Same bits from every clone: lane-wise IEEE
// operations in the same order, and the file is built without FMA contraction (CMakeLists.txt),
// so results depend neither on the processor's vector width nor on the thread count.
//
// interior_angles: theta = atan2(s, c) for s >= 0, in [0, pi]; 0 for (0, 0) (degenerate).
// NaN or Inf input gives NaN or some value in [0, pi] (no table, nothing indexed).
// Method (one division per angle):
//   1. octant: num = min(s, |c|), den = max(s, |c|), t = num / den in [0, 1];
//   2. centre: atan(t) = k pi/8 + atan(x), x = (t - tan(k pi/8)) / (1 + t tan(k pi/8)), with k = 0,
//      1 or 2 the nearest centre (t beyond tan(pi/16), tan(3 pi/16)), computed as
//      (num - centre den) / (den + centre num): one division; |x| <= tan(pi/16) = 0.19891 (the
//      addition formula for arctangent; Muller, "Elementary Functions", 3rd ed., ch. 5);
//   3. atan(x) = x sum_{k=0}^{9} (-1)^k z^k / (2k + 1), z = x^2 <= 0.039566 (Taylor, Estrin);
//   4. theta = pi/2 - . where s > |c|, then pi - . where c < 0.
// Error: the series alternates with decreasing terms, so its truncation error is below the first
// omitted term, |x| z^10 / 21 <= 4.5e-16 |x|; the centre tan(pi/8) is rounded, which shifts x by
// ~1e-16 absolute (an angle error ~1e-16 rad on an angle >= pi/16); rounding in steps 1-4 adds a
// few ulp. Measured against std::atan2: relative error <= 1e-13 asserted
// (tests/normals/triangle_blocks.cpp, also against geometry/interior_angle.h), 7e-16 observed.
// Why even 1e-13 is invisible in a vertex normal: the angle-weighted sum S = sum_i w_i n_i (unit
// n_i); weights perturbed by relative delta change S by at most delta sum_i w_i, so the normal
// turns by at most delta (sum_i w_i) / |S| rad. Unless the terms nearly cancel (|S| < 1e-3
// sum_i w_i, a vertex whose faces fold back over each other), that is < 1e-13 * 1e3 = 1e-10 rad =
// 6e-9 deg, far below the double path's other rounding and the float path's 2^-24 per term.
//
// triangle_block_{angle,max,uniform}: for triangle i of the block, with corners p0, p1, p2, edges
// e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2, squared lengths l0, l1, l2, and area vector N = 2 A n
// from the two shortest edges (the same products as geometry/face_area_vector.h's triangle_area_vector, so
// the same bits), the contributions of its corners 0, 1, 2 (corner_contributions.h):
//   angle    N theta_k / |N|, theta_0 = atan2(|N|, -e0.e2), theta_1 = atan2(|N|, -e1.e0),
//            theta_2 = pi - theta_0 - theta_1
//   max      N l1 / (l0 l1 l2), N l2 / (l0 l1 l2), N l0 / (l0 l1 l2)
//   uniform  N / |N| at every corner
// Inputs:  n             how many triangles, at most kTriangleBlock
//          corner_xyz    9 rows of kTriangleBlock values (first n used): x, y, z of corner 0, then
//                        of corner 1, of corner 2
// Outputs: contribution  9 rows of kTriangleBlock values (first n written): x, y, z of corner 0's
//                        contribution, then corner 1's, corner 2's. NaN for a triangle the vector
//                        pass does not take: degenerate or out of the squares test's range by
//                        geometry/degenerate_face.h (the rule's own test, same values), N . N
//                        outside [1e-250, 1e250] (tiny or huge, non-finite input) or, for max,
//                        l0 l1 l2 outside the normal range; the caller computes that one on its
//                        scalar path (which asks the rule).
//
// triangle_block_unit_normals: N / |N| per triangle (the unit face normal of normals/face_normals.h:
// N.x / |N| per component, |N| = sqrt(N . N), as geometry/scaled_length.h's checked_length inside
// its direct range), into 3 rows (x, y, z) of kTriangleBlock values; NaN under the same conditions
// as the contributions (degenerate, or out of the vector pass's range): the caller's scalar path.
#pragma once

#include <cstddef>

namespace shadetool::normals_detail {

void interior_angles(std::size_t n, const double* sin_part, const double* cos_part, double* theta);

constexpr std::size_t kTriangleBlock = 64;
void triangle_block_angle(std::size_t n, const double* corner_xyz, double* contribution);
void triangle_block_max(std::size_t n, const double* corner_xyz, double* contribution);
void triangle_block_uniform(std::size_t n, const double* corner_xyz, double* contribution);
void triangle_block_unit_normals(std::size_t n, const double* corner_xyz, double* unit);

}  // namespace shadetool::normals_detail
