// interior_angles.cpp: see interior_angles.h (method, error bound, why the clones agree bitwise).
#include "normals/interior_angles.h"

#include <cmath>
#include <limits>

namespace shadetool::normals_detail {

// GCC: one clone for AVX2 and one for the baseline, picked at load time (ifunc). This file is built
// with -fno-math-errno -fno-trapping-math (CMakeLists.txt): a std::sqrt that may set errno, or a
// possibly-signalling comparison feeding a select, counts as control flow and stops GCC from
// vectorising; we never read errno or floating-point exception flags, and the values are the same.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SHADETOOL_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SHADETOOL_VECTOR_CLONES
#endif

namespace {

constexpr double kPi = 3.141592653589793, kHalfPi = 1.5707963267948966, kQuarterPi = 0.7853981633974483;
constexpr double kTanPi8 = 0.41421356237309503;  // tan(pi/8) = sqrt(2) - 1

// atan2(s, c) for s >= 0, steps 1-4 of interior_angles.h. Every value is computed
// unconditionally and then selected, so that a loop calling it has no control flow and vectorises
// (a conditional floating-point operation would count as control flow).
inline __attribute__((always_inline)) double angle_of(double s, double c) {
  // (-1)^k / (2k + 1), k = 0 .. 15
  constexpr double c0 = 1.0, c1 = -1.0 / 3, c2 = 1.0 / 5, c3 = -1.0 / 7, c4 = 1.0 / 9, c5 = -1.0 / 11,
                   c6 = 1.0 / 13, c7 = -1.0 / 15, c8 = 1.0 / 17, c9 = -1.0 / 19, c10 = 1.0 / 21, c11 = -1.0 / 23,
                   c12 = 1.0 / 25, c13 = -1.0 / 27, c14 = 1.0 / 29, c15 = -1.0 / 31;
  const double a = std::fabs(c);
  const double num = s < a ? s : a, den = s < a ? a : s;
  const double diff = num - den, total = num + den, den_or_one = den > 0.0 ? den : 1.0;
  const bool big = num > kTanPi8 * den;
  // den == 0 only when num == 0 too: x = 0 / 1 (divisor checked)
  const double x = (big ? diff : num) / (big ? total : den_or_one), z = x * x;
  // Estrin's scheme: four levels of independent products instead of Horner's 15 dependent
  // steps (the loop is otherwise latency-bound).
  const double z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double q0 = c0 + c1 * z, q1 = c2 + c3 * z, q2 = c4 + c5 * z, q3 = c6 + c7 * z;
  const double q4 = c8 + c9 * z, q5 = c10 + c11 * z, q6 = c12 + c13 * z, q7 = c14 + c15 * z;
  const double r0 = q0 + q1 * z2, r1 = q2 + q3 * z2, r2 = q4 + q5 * z2, r3 = q6 + q7 * z2;
  const double p = (r0 + r1 * z4) + (r2 + r3 * z4) * z8;
  const double t0 = (big ? kQuarterPi : 0.0) + x * p;
  const double t1 = s > a ? kHalfPi - t0 : t0;
  return c < 0.0 ? kPi - t1 : t1;
}

}  // namespace

SHADETOOL_VECTOR_CLONES
void interior_angles(std::size_t n, const double* __restrict sin_part, const double* __restrict cos_part,
                     double* __restrict theta) {
  for (std::size_t i = 0; i < n; ++i) theta[i] = angle_of(sin_part[i], cos_part[i]);
}

SHADETOOL_VECTOR_CLONES
void triangle_angle_weights(std::size_t n, const double* __restrict length, const double* __restrict cos0,
                            const double* __restrict cos1, double* __restrict w0, double* __restrict w1,
                            double* __restrict w2) {
  for (std::size_t i = 0; i < n; ++i) {
    // A degenerate face (length 0 or NaN) runs with s = 1, c = 0 and gets weights 0; an infinite
    // length gives inv = 0 and weights 0 too (callers skip such faces anyway).
    const double len = length[i], a0 = cos0[i], a1 = cos1[i];
    const double ok = len > 0.0 ? 1.0 : 0.0;
    const double s = len > 0.0 ? len : 1.0;
    const double inv = ok / s;  // s > 0 (divisor checked)
    const double t0 = angle_of(s, a0 * ok), t1 = angle_of(s, a1 * ok);
    w0[i] = t0 * inv;
    w1[i] = t1 * inv;
    w2[i] = (kPi - t0 - t1) * inv;
  }
}

SHADETOOL_VECTOR_CLONES
void triangle_angle_block(std::size_t n, const double* const* corner_xyz, double* __restrict Nx,
                          double* __restrict Ny, double* __restrict Nz, double* __restrict w0, double* __restrict w1,
                          double* __restrict w2) {
  const double *__restrict x0 = corner_xyz[0], *__restrict y0 = corner_xyz[1], *__restrict z0 = corner_xyz[2];
  const double *__restrict x1 = corner_xyz[3], *__restrict y1 = corner_xyz[4], *__restrict z1 = corner_xyz[5];
  const double *__restrict x2 = corner_xyz[6], *__restrict y2 = corner_xyz[7], *__restrict z2 = corner_xyz[8];
  for (std::size_t i = 0; i < n; ++i) {
    // edges e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2 and their squared lengths
    const double e0x = x1[i] - x0[i], e0y = y1[i] - y0[i], e0z = z1[i] - z0[i];
    const double e1x = x2[i] - x1[i], e1y = y2[i] - y1[i], e1z = z2[i] - z1[i];
    const double e2x = x0[i] - x2[i], e2y = y0[i] - y2[i], e2z = z0[i] - z2[i];
    const double l0 = e0x * e0x + e0y * e0y + e0z * e0z;
    const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
    // the two shortest edges, as face_geometry.h's apex_corner / triangle_area_vector (same ties,
    // same products, so the same bits): e0 longest -> e1 x e2; e1 longest -> e2 x e0; else e0 x e1
    const bool k2 = (l0 >= l1) & (l0 >= l2), k0 = (l1 > l0) & (l1 >= l2);
    const double ax = k2 ? e1x : (k0 ? e2x : e0x), ay = k2 ? e1y : (k0 ? e2y : e0y), az = k2 ? e1z : (k0 ? e2z : e0z);
    const double bx = k2 ? e2x : (k0 ? e0x : e1x), by = k2 ? e2y : (k0 ? e0y : e1y), bz = k2 ? e2z : (k0 ? e0z : e1z);
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    const double nn = nx * nx + ny * ny + nz * nz;
    // In range: |N| is the correctly rounded root and the weights follow. Out of range (or zero,
    // Inf, NaN): weights NaN, the caller takes its scalar path for that face.
    const double in = (nn >= 1e-250) & (nn <= 1e250) ? 1.0 : 0.0;
    const double len = std::sqrt(in > 0.0 ? nn : 1.0);
    const double inv = 1.0 / len;
    const double cos0 = -(e0x * e2x + e0y * e2y + e0z * e2z), cos1 = -(e1x * e0x + e1y * e0y + e1z * e0z);
    const double t0 = angle_of(len, cos0 * in), t1 = angle_of(len, cos1 * in);
    const double flag = in > 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    Nx[i] = nx; Ny[i] = ny; Nz[i] = nz;
    w0[i] = t0 * inv + flag;
    w1[i] = t1 * inv + flag;
    w2[i] = (kPi - t0 - t1) * inv + flag;
  }
}

}  // namespace shadetool::normals_detail
