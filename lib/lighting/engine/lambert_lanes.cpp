// engine/lambert_lanes.cpp: see lambert_lanes.h.
#include <shadetool/lighting/engine/lambert_lanes.h>

#include <cmath>

namespace shadetool {
namespace lighting_engine {

// GCC: an AVX2 clone and the baseline, picked at load time (ifunc), as
// lib/normals/engine/triangle_blocks.cpp. This file is built with -fno-math-errno
// -fno-trapping-math (a sqrt that may set errno, or a comparison feeding a select, would stop the
// vectoriser; values unchanged) and -ffp-contract=off (no fused multiply-add in the AVX2 clone:
// the same bits as the baseline and as area_light.cpp's scalar formula). CMakeLists.txt.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SHADETOOL_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SHADETOOL_LANE_CLONES
#endif

namespace {

// The terms theta_i (n . c_i) / |c_i| of four edges q[0..3], d[0..3] (lambert_polygon_integral's
// edge, written out per component with cross and dot as core/vec3.h, so that the compiler puts
// the four edges in the lanes of one vector).
inline __attribute__((always_inline)) void edge_terms(const Vec3d* q, const Vec3d* d, const Vec3d& n, double term[4]) {
  for (int k = 0; k < 4; ++k) {
    const double cx = q[k].y * d[k].z - q[k].z * d[k].y, cy = q[k].z * d[k].x - q[k].x * d[k].z,
                 cz = q[k].x * d[k].y - q[k].y * d[k].x;
    const double s = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double qq = (q[k].x * q[k].x + q[k].y * q[k].y + q[k].z * q[k].z) +
                      (q[k].x * d[k].x + q[k].y * d[k].y + q[k].z * d[k].z);  // q_i . q_(i+1)
    const double theta = edge_angle(s, qq);
    const double nc = n.x * cx + n.y * cy + n.z * cz;
    term[k] = s > 0 ? theta * (nc / (s > 0 ? s : 1.0)) : 0.0;  // divisor checked; zero-length edge: 0
  }
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

}  // namespace lighting_engine
}  // namespace shadetool
