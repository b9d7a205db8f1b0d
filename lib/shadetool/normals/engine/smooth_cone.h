// smooth_cone.h: SmoothCone, the per-vertex test of corner_normals' crease path that no crease can
// split a vertex (internal to lib/normals; corner_normals.cpp's vertex fans and one-thread path,
// and bench/normals' crease experiments, use this one copy).
// Inputs:  crease_angle (radians); per vertex d (corners, >= 1) and the float sum (x, y, z) of its
//          faces' unit normals, each rounded to float (NaN once a face is degenerate)
// Output:  passes(d, x, y, z): true only when every pair of the vertex's faces is smooth by
//          CreaseTest's fast path (corner_normals.cpp); the argument and its margins below.
// Precision: the test in double on float sums; margins cover every rounding (below).
#pragma once

#include <cmath>
#include <cstdint>

#include <shadetool/core/math_constants.h>

namespace shadetool::normals_detail {

// SmoothCone: a sufficient test, per vertex, that no crease can split it, from two numbers
// vertex_fans adds up in face order: d, the vertex's corners, and U = sum of their faces' unit
// normals n_i (face_normals.h, rounded to float; a degenerate face adds NaN, so U is NaN).
// Why it holds: for unit vectors u_i and m = (sum u_i) / |sum u_i|, sum_i (1 - u_i . m) =
// d - |sum u_i|, every term >= 0, so any two faces a, b have (1 - cos beta_a) + (1 - cos beta_b)
// <= d - |sum u_i| (beta: a face's angle to m). When that is below room = 2 (1 - cos alpha) <= 1,
// each beta < pi/2, where 1 - cos is convex, so (Jensen) 2 (1 - cos((beta_a + beta_b) / 2)) <= room
// gives beta_a + beta_b < 2 alpha: every pair of faces lies within 2 alpha of each other (triangle
// inequality for angles on the sphere). (Where 2 (1 - cos alpha) > 1, room = 1 - cos alpha: every
// face within alpha of m.) alpha is chosen so that 2 alpha clears the crease angle by a margin that
// covers every rounding, so CreaseTest calls each such pair smooth by its fast path:
// cos(2 alpha) = cos(crease_angle) + 5e-5, so the true cos between two faces exceeds it, and their
// computed n_a . n_b (within 4e-7 of it, CreaseTest's bound for |n| within 1e-6 of 1) exceeds
// cos(crease_angle) + 5e-5 - 4e-7 > CreaseTest's `above` (= cos(crease_angle) + 1e-5).
// Roundings between the computed U and sum u_i: |n_i - u_i| <= 1e-6 (|n_i| within 1e-6 of 1),
// float(n_i) adds 2^-24 |n_i| per component (<= 1.1e-7 in length), and the float sum of d terms
// errs by at most (d - 1) 2^-24 sum_i |float(n_i)|_1 <= 1.1e-7 d^2 in length; so
// |sum u_i| >= |U| - 1.2e-6 d - 1.1e-7 d^2, and the test asks
// (d (1 + 2e-6 + 2e-7 d) - room)^2 < U . U in double (relative error ~1e-15 in either
// side, far inside the slack of the margins), i.e. d - |U| + 2e-6 d + 2e-7 d^2 < room. The bound
// is tight for two faces (d = 2, beta_a = beta_b: accepted up to a pair angle of 2 alpha).
// Crease_angle >= pi: every edge is smooth, every vertex of valid faces passes (U not NaN).
// Negative or NaN crease_angle (every edge a crease) and angles below ~0.6 degrees
// (cos(crease_angle) + 5e-5 >= 1): no vertex passes, every vertex is grouped by CreaseTest.
// Large fans pass only when the margin (quadratic in d) leaves room: a vertex that fails the test
// is not a crease vertex: it is grouped edge by edge with the same verdicts.
// (Until round 4 of issue 31 the test was face by face against the vertex's last face normal: a
// compare and a select per corner in vertex_fans' fill pass; this one is three adds per corner in
// its counting pass and one test per vertex. bench/normals/results/notes.md.)
struct SmoothCone {
  static constexpr double kAngleMargin = 5e-5;
  bool usable = false, every_valid = false;  // every_valid: crease_angle >= pi
  double room = 0.0;                         // 2 (1 - cos(alpha)), or 1 - cos(alpha) where that is > 1

  explicit SmoothCone(double crease_angle) {
    if (!(crease_angle >= 0.0)) return;
    if (crease_angle >= kPi) {
      usable = every_valid = true;
      return;
    }
    const double cos_2alpha = std::cos(crease_angle) + kAngleMargin;
    if (!(cos_2alpha < 1.0)) return;
    usable = true;
    const double one_face = 1.0 - std::cos(0.5 * std::acos(cos_2alpha));
    room = 2.0 * one_face <= 1.0 ? 2.0 * one_face : one_face;
  }
  // d corners (>= 1) whose unit face normals, rounded to float, sum to (x, y, z) in float (also
  // the one-thread path's U, engine/vertex_slots.h, whose normals lie within ~1e-13 of the true ones).
  bool passes(std::uint32_t d, float x, float y, float z) const {
    const double ux = x, uy = y, uz = z, n = d;
    const double uu = ux * ux + uy * uy + uz * uz;  // NaN when a face is degenerate
    if (!usable || std::isnan(uu)) return false;
    if (every_valid) return true;
    const double lhs = n * (1.0 + 2e-6 + 2e-7 * n) - room;  // > 0: d >= 1 and room < 1
    return lhs * lhs < uu;
  }
};

}  // namespace shadetool::normals_detail
