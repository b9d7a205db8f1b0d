// tangent_corner_terms.h: the vectorised pass of MikkTSpace (normals/tangents.cpp, step 7; internal
// to lib/normals): per corner of a healthy triangle, the terms its group's frame sums, for a block
// of up to kTangentCornerBlock corners at once, in loops the compiler vectorises.
//
// Inputs:  n    how many corners, at most kTangentCornerBlock
//          in   15 rows of kTangentCornerBlock floats (first n used): the corner's unit normal N
//               (x, y, z), its triangle's unit derivatives os (x, y, z) and ot (x, y, z), and the
//               edges e1 = p_prev - p, e2 = p_next - p from the corner to the previous and to the
//               next corner of the triangle (x, y, z each)
// Outputs: out  7 rows of kTangentCornerBlock floats (first n written): ps = project_unit(os, N)
//               (x, y, z), pt = project_unit(ot, N) (x, y, z), and the corner's angle in N's plane,
//               float(arc_cosine(double(c))), c = clamp(project_unit(e1, N) . project_unit(e2, N),
//               -1, 1) (NaN -> -1): the reference's float(acos(double(c))).
// project_unit(v, N): p = v - (N . v) N, then p / |p| where some |component| > FLT_MIN and
//               |p| > 0, else p: the reference's (mikktspace.c) arithmetic, in float, operation for
//               operation in its order.
// arc_cosine(x), x in [-1, 1]: fdlibm's e_acos.c (Sun Microsystems 1993; the algorithm of FreeBSD's
//               and musl's acos): |x| < 0.5: pi/2 - (x + x r(x^2)); else with z = (1 - |x|) / 2,
//               2 asin(sqrt z) (x > 0) or pi - 2 asin(sqrt z) (x < 0), asin(s) = s + s r(s^2),
//               r a rational minimax fit (error < 2^-58.75), in double: < 1 ulp of double. Rounded
//               to float it equals float(std::acos(double(c))) (glibc) for every float c in [-1, 1]:
//               checked exhaustively (all 2130706434 of them) when written, sampled in the test.
// Same bits as the scalar formula (tangents.cpp's project_unit) from every clone: lane-wise IEEE
// float operations (sqrt, division by the length, products) in the same order, selects instead
// of branches, and the file is built without FMA contraction (CMakeLists.txt), as
// triangle_blocks.h explains; checked bitwise against the scalar formula in
// tests/normals/tangent_corner_terms.cpp.
#pragma once

#include <cstddef>

namespace shadetool::normals_detail {

constexpr std::size_t kTangentCornerBlock = 64;
void tangent_corner_terms(std::size_t n, const float* in, float* out);

// tangent_lane_frames: the frames of up to kTangentLanes groups at once, one per lane: each the
// angle-weighted sum of its members' terms in member order, as mikktspace.c's EvalTspace sums them
// (os += angle ps, ot += angle pt, mag_s += angle mag_s, mag_t += angle mag_t, angle_sum += angle,
// each a float product then a float sum), then os and ot made unit where some |component| >
// FLT_MIN and the length > 0 (else left as summed), mag_s and mag_t divided by angle_sum where it
// is > 0. With it, whether the group is surely whole (tangents.cpp, whole_group's first test):
// every member's ps and pt within 60 degrees of the first member's (dot > 0.5).
// Inputs:  rows   members of the longest group, at most kTangentCornerBlock / kTangentLanes
//          count  kTangentLanes members per lane (0: an unused lane; its outputs are meaningless)
//          terms  7 rows of kTangentCornerBlock floats as tangent_corner_terms writes them (ps,
//                 pt, angle), member j of lane g in column j * kTangentLanes + g
//          mags   2 rows of kTangentCornerBlock floats: the member's triangle's mag_s, mag_t, same
//                 columns
// Outputs: out    9 rows of kTangentLanes floats: os (x, y, z), ot (x, y, z), mag_s, mag_t, and
//                 1 where the group is surely whole, else 0
// Same bits as the scalar sums from every clone (lane-wise float operations in the same order,
// selects for the members past a lane's count); checked in tests/normals/tangent_corner_terms.cpp.
constexpr std::size_t kTangentLanes = 8;
void tangent_lane_frames(std::size_t rows, const int* count, const float* terms, const float* mags, float* out);

// tangent_triangle_derivatives: MikkTSpace's step 4 (tangents.cpp, triangle_derivatives) for up to
// kTangentCornerBlock triangles at once, lane-wise: the divisions and square roots that dominate
// the step, in loops the compiler vectorises.
// Inputs:  n    how many triangles, at most kTangentCornerBlock
//          in   7 rows of kTangentCornerBlock floats (first n used): the derivatives os (x, y, z)
//               and ot (x, y, z) before normalisation (eq. 18, 19) and twice the signed texture
//               area a
// Outputs: out  8 rows of kTangentCornerBlock floats (first n written): sign / |os| times os
//               (x, y, z), sign / |ot| times ot (x, y, z), where |os| (|ot|) > FLT_MIN, else 0;
//               mag_s = |os| / |a|, mag_t = |ot| / |a|; all 8 zero where |a| <= FLT_MIN (or NaN).
//               sign = 1 where a > 0, else -1. |v| = sqrt(x x + y y + z z), in that order.
// Same bits as the scalar formula (checked in tests/normals/tangent_corner_terms.cpp): IEEE float
// operations in the same order, selects instead of branches, no FMA contraction.
void tangent_triangle_derivatives(std::size_t n, const float* in, float* out);

}  // namespace shadetool::normals_detail
