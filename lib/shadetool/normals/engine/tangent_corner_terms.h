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

}  // namespace shadetool::normals_detail
