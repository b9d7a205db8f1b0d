// phong_point_lanes.cpp (engine): see phong_point_lanes.h. Compiled with -ffp-contract=off
// (CMakeLists.txt).
#include <shadetool/render/engine/phong_point_lanes.h>

#include <shadetool/render/perspective_barycentrics.h>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SHADETOOL_PHONG_LANES 1
#include <immintrin.h>

#include <shadetool/render/engine/perspective_barycentrics_lanes.h>
#endif

namespace shadetool::render_engine {

namespace {

// One sample: the definition (tile_raster.cpp's phong_point on a direct triangle).
void phong_point_scalar(const Vec3d corner_p[3], const Vec3d corner_n[3], const double inv_w[3], double l1, double l2,
                        Vec3d& p, Vec3d& n) {
  const double lambda[3] = {1.0 - l1 - l2, l1, l2};
  double w[3];
  perspective_barycentrics(lambda, inv_w, w);
  p = {0, 0, 0}, n = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    p += corner_p[k] * w[k];
    n += corner_n[k] * w[k];
  }
  n = unit_or_zero_normal(n);
}

#if defined(SHADETOOL_PHONG_LANES)
bool lanes_available() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}

__attribute__((target("avx2"))) std::size_t phong_points_avx2(const Vec3d corner_p[3], const Vec3d corner_n[3],
                                                               const double inv_w[3], const double* lambda1,
                                                               const double* lambda2, std::size_t count,
                                                               const PointRunOut& out) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const __m256d lo = _mm256_set1_pd(0x1p-1000), hi = _mm256_set1_pd(0x1p1000);
  const __m256d iw[3] = {_mm256_set1_pd(inv_w[0]), _mm256_set1_pd(inv_w[1]), _mm256_set1_pd(inv_w[2])};
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    __m256d w[3];
    perspective_barycentrics_lanes(_mm256_loadu_pd(lambda1 + i), _mm256_loadu_pd(lambda2 + i), iw, w);
    __m256d p[3], n[3];
    for (int c = 0; c < 3; ++c) {
      p[c] = n[c] = zero;
      for (int k = 0; k < 3; ++k) {
        p[c] = _mm256_add_pd(p[c], _mm256_mul_pd(_mm256_set1_pd(corner_p[k][c]), w[k]));
        n[c] = _mm256_add_pd(n[c], _mm256_mul_pd(_mm256_set1_pd(corner_n[k][c]), w[k]));
      }
    }
    // unit_or_zero_normal
    const __m256d n2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(n[0], n[0]), _mm256_mul_pd(n[1], n[1])),
                                     _mm256_mul_pd(n[2], n[2]));
    const __m256d ok = _mm256_and_pd(_mm256_cmp_pd(n2, lo, _CMP_GT_OQ), _mm256_cmp_pd(n2, hi, _CMP_LE_OQ));
    const __m256d scale = _mm256_div_pd(one, _mm256_sqrt_pd(n2));
    _mm256_storeu_pd(out.px + i, p[0]);
    _mm256_storeu_pd(out.py + i, p[1]);
    _mm256_storeu_pd(out.pz + i, p[2]);
    _mm256_storeu_pd(out.nx + i, _mm256_and_pd(ok, _mm256_mul_pd(n[0], scale)));
    _mm256_storeu_pd(out.ny + i, _mm256_and_pd(ok, _mm256_mul_pd(n[1], scale)));
    _mm256_storeu_pd(out.nz + i, _mm256_and_pd(ok, _mm256_mul_pd(n[2], scale)));
  }
  return i;
}
#endif

}  // namespace

void phong_points_run(const Vec3d corner_p[3], const Vec3d corner_n[3], const double inv_w[3], const double* lambda1,
                      const double* lambda2, std::size_t count, const PointRunOut& out) {
  std::size_t i = 0;
#if defined(SHADETOOL_PHONG_LANES)
  if (lanes_available()) i = phong_points_avx2(corner_p, corner_n, inv_w, lambda1, lambda2, count, out);
#endif
  for (; i < count; ++i) {
    Vec3d p, n;
    phong_point_scalar(corner_p, corner_n, inv_w, lambda1[i], lambda2[i], p, n);
    out.px[i] = p.x, out.py[i] = p.y, out.pz[i] = p.z;
    out.nx[i] = n.x, out.ny[i] = n.y, out.nz[i] = n.z;
  }
}

}  // namespace shadetool::render_engine
