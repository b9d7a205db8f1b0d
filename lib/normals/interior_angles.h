// interior_angles.h: many angles between edge vectors at once, from |a x b| and a . b, in a loop
// the compiler vectorises (internal to lib/normals; the triangle kernels' arctangent pass).
//
// Inputs:  n          how many angles
//          sin_part   n values |a x b| = |a||b| sin(theta), >= 0
//          cos_part   n values a . b   = |a||b| cos(theta)
// Output:  theta      n values atan2(sin_part, cos_part) in [0, pi]; 0 for (0, 0) (degenerate).
//          NaN or Inf input gives NaN or some value in [0, pi] (no table, nothing indexed).
//
// Method (no table, no branch, one division; every step a lane-wise select, so that GCC
// vectorises the loop at -O3 with the default x86-64 baseline (SSE2, 2 lanes) and, on processors
// that have it, AVX2 (4 lanes; GCC target_clones, chosen once at load time)):
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
// (tests/normals/interior_angle.cpp), a few 1e-16 observed.
// Why even 1e-13 is invisible in a vertex normal: the angle-weighted sum S = sum_i w_i n_i (unit n_i);
// weights perturbed by relative delta change S by at most delta sum_i w_i, so the normal turns by
// at most delta (sum_i w_i) / |S| rad. Unless the terms nearly cancel (|S| < 1e-3 sum_i w_i, a
// vertex whose faces fold back over each other), that is < 1e-13 * 1e3 = 1e-10 rad = 6e-9 deg,
// far below the double path's other rounding and the float path's 2^-24 per term.
// Same bits with either instruction set: lane-wise IEEE operations in the same order, and the
// clones are built without FMA contraction (AVX2 alone implies no FMA), so results do not depend
// on the processor's vector width (nor on the thread count).
#pragma once

#include <cstddef>

namespace shadetool::normals_detail {

void interior_angles(std::size_t n, const double* sin_part, const double* cos_part, double* theta);

// The angle weights of n triangles at once (the angle-weighted kernel's vector pass). For a
// triangle with area vector N (|N| = 2 A = |a x b| at every corner) and cos parts a . b at its
// corners 0 and 1:
// Inputs:  length      n values |N| (callers keep N . N within [1e-250, 1e250] by an exact
//                      power-of-two rescaling of N, so |N| is its correctly rounded square root;
//                      0 or NaN marks a degenerate face)
//          cos0, cos1  n values a . b at corners 0 and 1
// Output:  w0, w1, w2  n values theta_k / |N|, theta_2 = pi - theta_0 - theta_1, so that
//                      N w_k = theta_k n is the corner's contribution; 0 for |N| = 0 or Inf
//                      (NaN possible for NaN input: callers skip degenerate faces).
void triangle_angle_weights(std::size_t n, const double* length, const double* cos0, const double* cos1,
                            double* w0, double* w1, double* w2);

// The angle-weighted kernel's whole per-face computation for n triangles, vectorised: from corner
// positions in structure-of-arrays form to the three corners' contributions theta_k n.
// Inputs:  n             how many triangles, at most kAngleBlock
//          corner_xyz    9 rows of kAngleBlock values (first n used): x, y, z of corner 0, then of
//                        corner 1, of corner 2
// Outputs: contribution  9 rows of kAngleBlock values (first n written): x, y, z of theta_0 n,
//                        then theta_1 n, theta_2 n,
//                        computed as N (theta_k / |N|) with N = 2 A n from the two shortest edges
//                        (the same products as face_geometry.h's triangle_area_vector, so the same
//                        bits) and theta_2 = pi - theta_0 - theta_1. NaN when N . N lies outside
//                        [1e-250, 1e250] (zero-area, huge or tiny faces, non-finite input): the
//                        caller handles that face on its scalar path.
constexpr std::size_t kAngleBlock = 64;
void triangle_angle_block(std::size_t n, const double* corner_xyz, double* contribution);

}  // namespace shadetool::normals_detail
