// engine/lambert_lanes.cpp: see lambert_lanes.h.
#include <shadetool/lighting/engine/lambert_lanes.h>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace shadetool {
namespace lighting_engine {

// GCC: an AVX2 clone and the baseline, picked at load time (ifunc), as
// lib/shadetool/normals/engine/triangle_blocks.cpp. This file is built with -fno-math-errno
// -fno-trapping-math (a sqrt that may set errno, or a comparison feeding a select, would stop the
// vectoriser; values unchanged) and -ffp-contract=off (no fused multiply-add in the AVX2 clone:
// the same bits as the baseline and as area_light.cpp's scalar formula). CMakeLists.txt.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SHADETOOL_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#define SHADETOOL_POINT_LANE_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SHADETOOL_LANE_CLONES
#define SHADETOOL_POINT_LANE_CLONES
#endif

namespace {

// One edge's term theta (n . c) / |c|, c = q x d (lambert_polygon_integral's edge, written out per
// component with cross and dot as core/vec3.h, so that the compiler puts edges or points in the
// lanes of a vector). A zero-length edge (|c| = 0) gives exactly 0.
inline __attribute__((always_inline)) double edge_term(double qx, double qy, double qz, double dx, double dy,
                                                       double dz, double nx, double ny, double nz) {
  const double cx = qy * dz - qz * dy, cy = qz * dx - qx * dz, cz = qx * dy - qy * dx;
  const double s = std::sqrt(cx * cx + cy * cy + cz * cz);
  const double qq = (qx * qx + qy * qy + qz * qz) + (qx * dx + qy * dy + qz * dz);  // q_i . q_(i+1)
  const double theta = edge_angle(s, qq);
  const double nc = nx * cx + ny * cy + nz * cz;
  return s > 0 ? theta * (nc / (s > 0 ? s : 1.0)) : 0.0;  // divisor checked; zero-length edge: 0
}

// The terms of four edges q[0..3], d[0..3] of one point.
inline __attribute__((always_inline)) void edge_terms(const Vec3d* q, const Vec3d* d, const Vec3d& n, double term[4]) {
  for (int k = 0; k < 4; ++k) term[k] = edge_term(q[k].x, q[k].y, q[k].z, d[k].x, d[k].y, d[k].z, n.x, n.y, n.z);
}

}  // namespace

SHADETOOL_LANE_CLONES
double lambert_polygon_integral_lanes(const SphericalPolygon& P, const Vec3d& n) {
  const int count = P.count;
  double term[4];
  if (count < 4) {  // a triangle (or less): the last edge repeated in the spare lanes
    if (count <= 0) return 0;
    Vec3d q[4], d[4];
    for (int k = 0; k < 4; ++k) q[k] = P.q[k < count ? k : count - 1], d[k] = P.d[k < count ? k : count - 1];
    edge_terms(q, d, n, term);
    double sum = 0;
    for (int k = 0; k < count; ++k) sum += term[k];
    return 0.5 * std::fabs(sum);
  }
  // Blocks of four edges read straight from P; the last block is the last four edges (it may
  // overlap the one before: only its edges from `first` on are added). Edge order is kept.
  double sum = 0;
  for (int first = 0; first < count; first += 4) {
    const int base = first + 4 <= count ? first : count - 4;
    edge_terms(&P.q[base], &P.d[base], n, term);
    for (int k = first - base; k < 4; ++k) sum += term[k];
  }
  return 0.5 * std::fabs(sum);
}

// Every loop below runs over the lanes k (the vectoriser's loop); the per-lane arithmetic is
// polygon_light_terms' and clip_to_hemisphere's, operation for operation, and where they return
// early the lane's values are selected away instead (they are computed, never added). Flags and
// counters are 64-bit integers, the width of a double's lane.
SHADETOOL_POINT_LANE_CLONES
void polygon_diffuse_lanes(const Vec3d* v, int count, const Vec3d& e, bool two_sided, const PointLanes& pt,
                           PolygonLaneTerms& out) {
  using I64 = std::int64_t;
  constexpr int W = kPointLanes;
  const double* __restrict px = pt.px;
  const double* __restrict py = pt.py;
  const double* __restrict pz = pt.pz;
  const double* __restrict nx = pt.nx;
  const double* __restrict ny = pt.ny;
  const double* __restrict nz = pt.nz;
  const I64 both_sides = two_sided;
  // The side of the light's plane (behind a one-sided light, or on its plane: P = 0), and the
  // largest component of the directions v_i - p.
  I64 lit[W], inside[W];
  double big[W];
  for (int k = 0; k < W; ++k) {
    const double side = e.x * (px[k] - v[0].x) + e.y * (py[k] - v[0].y) + e.z * (pz[k] - v[0].z);
    lit[k] = side > 0 || (both_sides && side < 0);
    inside[k] = !lit[k] && side == 0;
    big[k] = 0;
  }
  for (int i = 0; i < count; ++i) {
    const double vx = v[i].x, vy = v[i].y, vz = v[i].z;
#pragma GCC unroll 1  // unrolled first, the lanes were not put in a vector
    for (int k = 0; k < W; ++k) {
      const double qx = std::fabs(vx - px[k]), qy = std::fabs(vy - py[k]), qz = std::fabs(vz - pz[k]);
      const double m = qx > qy ? qx : qy;
      const double mz = qz > m ? qz : m;
      big[k] = mz > big[k] ? mz : big[k];
    }
  }
  // The power of two 2^-e, big in [2^e, 2^(e+1)), from the exponent field E = e + 1023 of big:
  // 2^-e has the field 2046 - E. Only E in [2, 2045] (e in (-1022, 1023), as polygon_light_terms'
  // fast path); the rest (and big zero or not finite) goes to the scalar function.
  double f[W];
  I64 scalar[W];
  for (int k = 0; k < W; ++k) {
    I64 bits;
    std::memcpy(&bits, &big[k], sizeof bits);
    const I64 E = (bits >> 52) & 0x7ff;
    const I64 normal = big[k] > 0 && E >= 2 && E <= 2045;
    const I64 f_bits = (normal ? 2046 - E : 1023) << 52;
    std::memcpy(&f[k], &f_bits, sizeof f_bits);
    scalar[k] = lit[k] && !normal;
  }
  // The horizon: vertex i above when n.q_i >= 0 (as polygon_light_terms and clip_to_hemisphere).
  double above[kMaxAreaVertices][W];  // n.q_i
  I64 n_above[W];
  for (int k = 0; k < W; ++k) n_above[k] = 0;
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < W; ++k) {
      const double qx = (v[i].x - px[k]) * f[k], qy = (v[i].y - py[k]) * f[k], qz = (v[i].z - pz[k]) * f[k];
      above[i][k] = nx[k] * qx + ny[k] * qy + nz[k] * qz;
      n_above[k] += above[i][k] >= 0;
    }
  // What the block needs (points along a mesh come in runs: most blocks are one case): Lambert's
  // sum where a lane sees some of the light, and the clipping where a lane's horizon crosses it.
  bool any_sum = false, any_crossing = false;
  for (int k = 0; k < W; ++k) {
    any_sum |= lit[k] && !scalar[k] && n_above[k] > 0;
    any_crossing |= lit[k] && !scalar[k] && n_above[k] > 0 && n_above[k] < count;
  }
  double sum[W];
  for (int k = 0; k < W; ++k) sum[k] = 0;
  I64 n_exit[W], n_entry[W];
  for (int k = 0; k < W; ++k) n_exit[k] = n_entry[k] = 0;
  if (any_sum && !any_crossing) {
    // Lambert's sum over the whole polygon, in edge order (area_light.cpp's lambert_polygon_integral).
    for (int i = 0; i < count; ++i) {
      const Vec3d& a = v[i];
      const Vec3d& b = v[i + 1 < count ? i + 1 : 0];
      for (int k = 0; k < W; ++k) {
        const double qx = (a.x - px[k]) * f[k], qy = (a.y - py[k]) * f[k], qz = (a.z - pz[k]) * f[k];
        const double dx = (b.x - a.x) * f[k], dy = (b.y - a.y) * f[k], dz = (b.z - a.z) * f[k];
        sum[k] += edge_term(qx, qy, qz, dx, dy, dz, nx[k], ny[k], nz[k]);
      }
    }
  } else if (any_sum) {
    // The edges that leave and enter the upper half-space, where they cross it (x = q_a + d t,
    // t = a / (a - b); kept per edge for the sum), and the index of the edge that leaves.
    I64 exit_edge[W];
    double xx[W], xy[W], xz[W], ex[W], ey[W], ez[W];  // the exit and entry points on the horizon
    double t_edge[kMaxAreaVertices][W];
    for (int k = 0; k < W; ++k) exit_edge[k] = -1;
    for (int k = 0; k < W; ++k) xx[k] = xy[k] = xz[k] = ex[k] = ey[k] = ez[k] = 0;
    for (int i = 0; i < count; ++i) {
      const Vec3d& a = v[i];
      const Vec3d& b = v[i + 1 < count ? i + 1 : 0];
      const int j = i + 1 < count ? i + 1 : 0;
      for (int k = 0; k < W; ++k) {
        const double qx = (a.x - px[k]) * f[k], qy = (a.y - py[k]) * f[k], qz = (a.z - pz[k]) * f[k];
        const double dx = (b.x - a.x) * f[k], dy = (b.y - a.y) * f[k], dz = (b.z - a.z) * f[k];
        const double da = above[i][k], db = above[j][k];
        const I64 a_in = da >= 0, b_in = db >= 0;
        const I64 leaves = a_in & (b_in ^ 1), enters = (a_in ^ 1) & b_in;
        const double t = da / (leaves | enters ? da - db : 1.0);  // the signs differ: da - db != 0
        const double x = qx + dx * t, y = qy + dy * t, z = qz + dz * t;
        t_edge[i][k] = t;
        n_exit[k] += leaves;
        n_entry[k] += enters;
        exit_edge[k] = leaves ? I64(i) : exit_edge[k];
        xx[k] = leaves ? x : xx[k], xy[k] = leaves ? y : xy[k], xz[k] = leaves ? z : xz[k];
        ex[k] = enters ? x : ex[k], ey[k] = enters ? y : ey[k], ez[k] = enters ? z : ez[k];
      }
    }
    // The edge along the horizon, from the exit point to the entry point (clip_to_hemisphere's
    // d = q_next - q).
    double horizon[W];
    for (int k = 0; k < W; ++k)
      horizon[k] = edge_term(xx[k], xy[k], xz[k], ex[k] - xx[k], ey[k] - xy[k], ez[k] - xz[k], nx[k], ny[k], nz[k]);
    // Lambert's sum in the clipped polygon's edge order: both above (q, d); leaves (q, d t), then
    // the horizon edge; enters (x, d (1 - t)); both below d = 0, a term of exactly 0.
    for (int i = 0; i < count; ++i) {
      const Vec3d& a = v[i];
      const Vec3d& b = v[i + 1 < count ? i + 1 : 0];
      const int j = i + 1 < count ? i + 1 : 0;
      for (int k = 0; k < W; ++k) {
        const double qx = (a.x - px[k]) * f[k], qy = (a.y - py[k]) * f[k], qz = (a.z - pz[k]) * f[k];
        const double dx = (b.x - a.x) * f[k], dy = (b.y - a.y) * f[k], dz = (b.z - a.z) * f[k];
        const double da = above[i][k], db = above[j][k];
        const double t = t_edge[i][k];
        const double s = da >= 0 ? (db >= 0 ? 1.0 : t) : (db >= 0 ? 1 - t : 0.0);
        const double ux = da >= 0 ? qx : qx + dx * t, uy = da >= 0 ? qy : qy + dy * t,
                     uz = da >= 0 ? qz : qz + dz * t;
        sum[k] += edge_term(ux, uy, uz, dx * s, dy * s, dz * s, nx[k], ny[k], nz[k]);  // d * 1 = d exactly
        sum[k] = exit_edge[k] == i ? sum[k] + horizon[k] : sum[k];
      }
    }
  }
  for (int k = 0; k < W; ++k) {
    const bool below = n_above[k] == 0;
    const bool whole = n_above[k] == count;
    const bool one_crossing = n_exit[k] == 1 && n_entry[k] == 1;
    const bool to_scalar = scalar[k] || (lit[k] && !below && !whole && !one_crossing);
    out.scalar[k] = to_scalar;
    out.inside[k] = inside[k];
    out.below_horizon[k] = lit[k] && !to_scalar && below;
    out.P[k] = lit[k] && !to_scalar && !below ? 0.5 * std::fabs(sum[k]) : 0.0;
  }
}

}  // namespace lighting_engine
}  // namespace shadetool
