// triangle_blocks.cpp: see triangle_blocks.h (methods, error bound, why the clones agree bitwise).
#include <shadetool/normals/engine/triangle_blocks.h>

#include <shadetool/core/math_constants.h>
#include <shadetool/geometry/degenerate_face.h>

#include <cmath>
#include <limits>

namespace shadetool::normals_detail {

// GCC: one clone each for AVX-512, AVX2 and the baseline, picked at load time (ifunc). This file is built
// with -fno-math-errno -fno-trapping-math (CMakeLists.txt): a std::sqrt that may set errno, or a
// possibly-signalling comparison feeding a select, counts as control flow and stops GCC from
// vectorising; we never read errno or floating-point exception flags, and the values are the same.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SHADETOOL_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SHADETOOL_VECTOR_CLONES
#endif

namespace {

constexpr double kEighthPi = 0.39269908169872414;
constexpr double kTanPi8 = 0.41421356237309503;     // tan(pi/8), the middle centre
constexpr double kTanPi16 = 0.198912367379658;      // tan(pi/16), first interval's end
constexpr double kTan3Pi16 = 0.6681786379192989;    // tan(3 pi/16), second interval's end

// atan2(s, c) for s >= 0, steps 1-4 of triangle_blocks.h. Every value is computed
// unconditionally and then selected, so that a loop calling it has no control flow and vectorises.
inline __attribute__((always_inline)) double angle_of(double s, double c) {
  // (-1)^k / (2k + 1), k = 0 .. 9
  constexpr double c0 = 1.0, c1 = -1.0 / 3, c2 = 1.0 / 5, c3 = -1.0 / 7, c4 = 1.0 / 9, c5 = -1.0 / 11,
                   c6 = 1.0 / 13, c7 = -1.0 / 15, c8 = 1.0 / 17, c9 = -1.0 / 19;
  const double a = std::fabs(c);
  const double num = s < a ? s : a, den = s < a ? a : s;  // t = num / den in [0, 1]
  // centre tan(k pi/8), k = 0, 1, 2, nearest to t: x = (t - centre) / (1 + t centre)
  const bool k1 = num > kTanPi16 * den, k2 = num > kTan3Pi16 * den;
  const double centre = k2 ? 1.0 : (k1 ? kTanPi8 : 0.0), base = k2 ? kQuarterPi : (k1 ? kEighthPi : 0.0);
  const double d = den + centre * num;
  // d == 0 only when num == den == 0 (a degenerate corner): x = 0 / 1 (divisor checked)
  const double x = (num - centre * den) / (d > 0.0 ? d : 1.0), z = x * x;
  // Estrin's scheme: independent products instead of Horner's dependent chain
  const double z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double q0 = c0 + c1 * z, q1 = c2 + c3 * z, q2 = c4 + c5 * z, q3 = c6 + c7 * z, q4 = c8 + c9 * z;
  const double p = (q0 + q1 * z2) + (q2 + q3 * z2) * z4 + q4 * z8;
  const double t0 = base + x * p;
  const double t1 = s > a ? kHalfPi - t0 : t0;
  return c < 0.0 ? kPi - t1 : t1;
}

}  // namespace

SHADETOOL_VECTOR_CLONES
void interior_angles(std::size_t n, const double* __restrict sin_part, const double* __restrict cos_part,
                     double* __restrict theta) {
  for (std::size_t i = 0; i < n; ++i) theta[i] = angle_of(sin_part[i], cos_part[i]);
}

namespace {

constexpr std::size_t B = kTriangleBlock;

// The geometry of the block (see triangle_blocks.h): N, |N| (NaN where N . N is out of range),
// and what the weighting needs besides: the squared edge lengths (max) or the cos parts (angle).
template <bool Lengths, bool Cos>
inline __attribute__((always_inline)) void block_geometry(std::size_t n, const double* __restrict xyz, double* __restrict Nx,
                                                          double* __restrict Ny, double* __restrict Nz, double* __restrict L,
                                                          double* __restrict L0, double* __restrict L1, double* __restrict L2,
                                                          double* __restrict C0, double* __restrict C1) {
  const double *x0 = xyz, *y0 = x0 + B, *z0 = y0 + B, *x1 = z0 + B, *y1 = x1 + B, *z1 = y1 + B;
  const double *x2 = z1 + B, *y2 = x2 + B, *z2 = y2 + B;
  for (std::size_t i = 0; i < n; ++i) {
    const double e0x = x1[i] - x0[i], e0y = y1[i] - y0[i], e0z = z1[i] - z0[i];
    const double e1x = x2[i] - x1[i], e1y = y2[i] - y1[i], e1z = z2[i] - z1[i];
    const double e2x = x0[i] - x2[i], e2y = y0[i] - y2[i], e2z = z0[i] - z2[i];
    const double l0 = e0x * e0x + e0y * e0y + e0z * e0z;
    const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
    // the two shortest edges, as apex_corner / triangle_area_vector (same ties, same products):
    // e0 longest -> e1 x e2; e1 longest -> e2 x e0; else e0 x e1
    const bool k2 = (l0 >= l1) & (l0 >= l2), k0 = (l1 > l0) & (l1 >= l2);
    const double ax = k2 ? e1x : (k0 ? e2x : e0x), ay = k2 ? e1y : (k0 ? e2y : e0y), az = k2 ? e1z : (k0 ? e2z : e0z);
    const double bx = k2 ? e2x : (k0 ? e0x : e1x), by = k2 ? e2y : (k0 ? e0y : e1y), bz = k2 ? e2z : (k0 ? e0z : e1z);
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    const double nn = nx * nx + ny * ny + nz * nz;
    // Valid by the one degenerate-face rule's squares test (geometry/degenerate_face.h,
    // triangle_zero_area_by_squares: the same expression on the same values, so the same verdict);
    // faces outside its range, or degenerate, go to the scalar path, which asks the rule itself.
    const double la = k2 ? l1 : (k0 ? l2 : l0), lb = k2 ? l2 : (k0 ? l0 : l1);
    const bool valid = (la > kSquaresTestFrom) & (la < kSquaresTestTo) & (lb > kSquaresTestFrom) &
                       (lb < kSquaresTestTo) & (nn > kDegenerateTolerance2 * (la * lb));
    const bool in = (nn >= 1e-250) & (nn <= 1e250) & valid;
    Nx[i] = nx; Ny[i] = ny; Nz[i] = nz;
    L[i] = in ? std::sqrt(in ? nn : 1.0) : std::numeric_limits<double>::quiet_NaN();
    if constexpr (Lengths) { L0[i] = l0; L1[i] = l1; L2[i] = l2; }
    if constexpr (Cos) {
      C0[i] = in ? -(e0x * e2x + e0y * e2y + e0z * e2z) : 0.0;
      C1[i] = in ? -(e1x * e0x + e1y * e0y + e1z * e0z) : 0.0;
    }
  }
}

// contribution rows k = 0, 1, 2 (x, y, z each) from N and the three corner weights.
inline __attribute__((always_inline)) void store_corner(double* __restrict out, std::size_t k, std::size_t i, double nx,
                                                        double ny, double nz, double w) {
  out[(3 * k) * B + i] = nx * w;
  out[(3 * k + 1) * B + i] = ny * w;
  out[(3 * k + 2) * B + i] = nz * w;
}

}  // namespace

SHADETOOL_VECTOR_CLONES
void triangle_block_angle(std::size_t n, const double* __restrict corner_xyz, double* __restrict contribution) {
  // Separate loops over the block (geometry, each arctangent, contributions) hold fewer live
  // values than one loop would: fewer register spills (bench/normals/results/notes.md).
  if (n > B) n = B;
  alignas(64) double Nx[B], Ny[B], Nz[B], L[B], C0[B], C1[B], T0[B], T1[B];
  block_geometry<false, true>(n, corner_xyz, Nx, Ny, Nz, L, nullptr, nullptr, nullptr, C0, C1);
  for (std::size_t i = 0; i < n; ++i) T0[i] = angle_of(L[i] > 0.0 ? L[i] : 1.0, C0[i]);  // NaN L: flagged below
  for (std::size_t i = 0; i < n; ++i) T1[i] = angle_of(L[i] > 0.0 ? L[i] : 1.0, C1[i]);
  for (std::size_t i = 0; i < n; ++i) {
    const double len = L[i];
    const double inv = 1.0 / (len > 0.0 ? len : 1.0);  // divisor checked
    const double flag = len > 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    const double t0 = T0[i], t1 = T1[i];
    store_corner(contribution, 0, i, Nx[i], Ny[i], Nz[i], t0 * inv + flag);
    store_corner(contribution, 1, i, Nx[i], Ny[i], Nz[i], t1 * inv + flag);
    store_corner(contribution, 2, i, Nx[i], Ny[i], Nz[i], (kPi - t0 - t1) * inv + flag);
  }
}

SHADETOOL_VECTOR_CLONES
void triangle_block_max(std::size_t n, const double* __restrict corner_xyz, double* __restrict contribution) {
  if (n > B) n = B;
  alignas(64) double Nx[B], Ny[B], Nz[B], L[B], L0[B], L1[B], L2[B];
  block_geometry<true, false>(n, corner_xyz, Nx, Ny, Nz, L, L0, L1, L2, nullptr, nullptr);
  for (std::size_t i = 0; i < n; ++i) {
    // weights 1/(l0 l2), 1/(l1 l0), 1/(l2 l1) = (l1, l2, l0) / q, q = l0 l1 l2 (one division), as
    // corner_contributions.h's scalar code; q outside the normal range: NaN, the scalar path.
    const double l0 = L0[i], l1 = L1[i], l2 = L2[i], q = l0 * l1 * l2;
    const bool ok = (L[i] > 0.0) & (q > 2.2250738585072014e-308) & (q < 1.7976931348623157e308);
    const double inv = 1.0 / (ok ? q : 1.0);  // divisor checked
    const double flag = ok ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    store_corner(contribution, 0, i, Nx[i], Ny[i], Nz[i], l1 * inv + flag);
    store_corner(contribution, 1, i, Nx[i], Ny[i], Nz[i], l2 * inv + flag);
    store_corner(contribution, 2, i, Nx[i], Ny[i], Nz[i], l0 * inv + flag);
  }
}

SHADETOOL_VECTOR_CLONES
void triangle_block_uniform(std::size_t n, const double* __restrict corner_xyz, double* __restrict contribution) {
  if (n > B) n = B;
  alignas(64) double Nx[B], Ny[B], Nz[B], L[B];
  block_geometry<false, false>(n, corner_xyz, Nx, Ny, Nz, L, nullptr, nullptr, nullptr, nullptr, nullptr);
  for (std::size_t i = 0; i < n; ++i) {
    const double len = L[i];
    const double inv = 1.0 / (len > 0.0 ? len : 1.0) + (len > 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < 3; ++k) store_corner(contribution, k, i, Nx[i], Ny[i], Nz[i], inv);
  }
}

// N from the apex exactly as triangle_area_vector builds it (face_area_vector.h: points selected,
// then a = p_{k+1} - p_k, b = p_{k+2} - p_k): block_geometry's edge selection gives the same
// values but not always the same sign of a zero component (p1 - p2 is +0 where -(p2 - p1) is -0),
// and face normals are compared bit for bit, zeros included.
SHADETOOL_VECTOR_CLONES
void triangle_block_unit_normals(std::size_t n, const double* __restrict corner_xyz, double* __restrict unit) {
  if (n > B) n = B;
  const double *x0 = corner_xyz, *y0 = x0 + B, *z0 = y0 + B, *x1 = z0 + B, *y1 = x1 + B, *z1 = y1 + B;
  const double *x2 = z1 + B, *y2 = x2 + B, *z2 = y2 + B;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    const double e0x = x1[i] - x0[i], e0y = y1[i] - y0[i], e0z = z1[i] - z0[i];
    const double e1x = x2[i] - x1[i], e1y = y2[i] - y1[i], e1z = z2[i] - z1[i];
    const double e2x = x0[i] - x2[i], e2y = y0[i] - y2[i], e2z = z0[i] - z2[i];
    const double l0 = e0x * e0x + e0y * e0y + e0z * e0z;
    const double l1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const double l2 = e2x * e2x + e2y * e2y + e2z * e2z;
    // apex_corner: k = 2 (e0 longest), 0 (e1 longest), else 1; the apex p, then q = p_{k+1}, r = p_{k+2}
    const bool k2 = (l0 >= l1) & (l0 >= l2), k0 = (l1 > l0) & (l1 >= l2);
    const double px = k2 ? x2[i] : (k0 ? x0[i] : x1[i]), py = k2 ? y2[i] : (k0 ? y0[i] : y1[i]), pz = k2 ? z2[i] : (k0 ? z0[i] : z1[i]);
    const double qx = k2 ? x0[i] : (k0 ? x1[i] : x2[i]), qy = k2 ? y0[i] : (k0 ? y1[i] : y2[i]), qz = k2 ? z0[i] : (k0 ? z1[i] : z2[i]);
    const double rx = k2 ? x1[i] : (k0 ? x2[i] : x0[i]), ry = k2 ? y1[i] : (k0 ? y2[i] : y0[i]), rz = k2 ? z1[i] : (k0 ? z2[i] : z0[i]);
    const double ax = qx - px, ay = qy - py, az = qz - pz, bx = rx - px, by = ry - py, bz = rz - pz;
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    const double nn = nx * nx + ny * ny + nz * nz;
    // degenerate_face.h's squares test (same expression, same values); outside its range, or
    // N . N outside [1e-250, 1e250], the scalar path decides.
    const double la = k2 ? l1 : (k0 ? l2 : l0), lb = k2 ? l2 : (k0 ? l0 : l1);
    const bool valid = (la > kSquaresTestFrom) & (la < kSquaresTestTo) & (lb > kSquaresTestFrom) &
                       (lb < kSquaresTestTo) & (nn > kDegenerateTolerance2 * (la * lb));
    const bool in = (nn >= 1e-250) & (nn <= 1e250) & valid;
    const double len = std::sqrt(in ? nn : 1.0);  // checked_length's direct range: sqrt(N . N)
    const double x = nx / len, y = ny / len, z = nz / len;  // divisor checked: >= 1e-125
    unit[i] = in ? x : nan;  // a select, not "+ flag": keeps -0.0
    unit[B + i] = in ? y : nan;
    unit[2 * B + i] = in ? z : nan;
  }
}

}  // namespace shadetool::normals_detail
