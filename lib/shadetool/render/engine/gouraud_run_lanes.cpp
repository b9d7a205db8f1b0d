// gouraud_run_lanes.cpp (engine): see gouraud_run_lanes.h. Compiled with -ffp-contract=off
// (CMakeLists.txt).
#include <shadetool/render/engine/gouraud_run_lanes.h>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

#include <shadetool/render/engine/perspective_barycentrics_lanes.h>

namespace shadetool::render_engine {

namespace {

__attribute__((target("avx2"))) int gouraud_run_avx2(const Vec3d corner_rgb[3], const double inv_w[3],
                                                     const double* lambda1, const double* lambda2, int n,
                                                     double inv_samples, float* out) {
  const __m256d zero = _mm256_setzero_pd(), scale = _mm256_set1_pd(inv_samples);
  const __m256d iw[3] = {_mm256_set1_pd(inv_w[0]), _mm256_set1_pd(inv_w[1]), _mm256_set1_pd(inv_w[2])};
  __m256d rgb[3][3];  // rgb[k][c]: corner k's channel c in every lane
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) rgb[k][c] = _mm256_set1_pd(corner_rgb[k][c]);
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    __m256d w[3];
    perspective_barycentrics_lanes(_mm256_loadu_pd(lambda1 + i), _mm256_loadu_pd(lambda2 + i), iw, w);
    // blend_vertex_colors, then the box filter's 0 + c and scale, per channel
    alignas(16) float channel[3][4];
    for (int c = 0; c < 3; ++c) {
      __m256d acc = _mm256_add_pd(zero, _mm256_mul_pd(rgb[0][c], w[0]));
      acc = _mm256_add_pd(acc, _mm256_mul_pd(rgb[1][c], w[1]));
      acc = _mm256_add_pd(acc, _mm256_mul_pd(rgb[2][c], w[2]));
      _mm_store_ps(channel[c], _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_add_pd(zero, acc), scale)));
    }
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) out[3 * (i + k) + c] = channel[c][k];
  }
  return i;
}

}  // namespace

int gouraud_run_lanes(const Vec3d corner_rgb[3], const double inv_w[3], const double* lambda1, const double* lambda2,
                      int n, double inv_samples, float* out) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2 ? gouraud_run_avx2(corner_rgb, inv_w, lambda1, lambda2, n, inv_samples, out) : 0;
}

}  // namespace shadetool::render_engine

#else

namespace shadetool::render_engine {
int gouraud_run_lanes(const Vec3d*, const double*, const double*, const double*, int, double, float*) { return 0; }
}  // namespace shadetool::render_engine

#endif
