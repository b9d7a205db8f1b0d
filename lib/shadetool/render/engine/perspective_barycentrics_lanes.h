// perspective_barycentrics_lanes.h (engine): render/perspective_barycentrics.h's weights for four
// samples at once in AVX2 lanes, with the same IEEE operations in the same order, so each lane is
// the scalar function's bits: m_k = lambda_k * inv_w_k, sum = (m0 + m1) + m2, b_k = m_k * (1 / sum)
// where sum > 0, else lambda_k (the divisor checked by a select, as there). lambda0 = (1 - l1) - l2,
// as the callers form it per sample. For the lanes files of lib/render (gouraud_run_lanes.cpp,
// phong_point_lanes.cpp), which are compiled with -ffp-contract=off: no multiply-add is fused.
// Internal: not installed.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

namespace shadetool::render_engine {

// l1, l2: four samples' screen barycentrics; iw: the corners' 1/w, each broadcast; b: the weights.
__attribute__((target("avx2"), always_inline)) inline void perspective_barycentrics_lanes(__m256d l1, __m256d l2,
                                                                                          const __m256d iw[3],
                                                                                          __m256d b[3]) {
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d l0 = _mm256_sub_pd(_mm256_sub_pd(one, l1), l2);
  const __m256d m0 = _mm256_mul_pd(l0, iw[0]), m1 = _mm256_mul_pd(l1, iw[1]), m2 = _mm256_mul_pd(l2, iw[2]);
  const __m256d sum = _mm256_add_pd(_mm256_add_pd(m0, m1), m2);
  const __m256d positive = _mm256_cmp_pd(sum, _mm256_setzero_pd(), _CMP_GT_OQ);
  const __m256d inv = _mm256_div_pd(one, sum);
  b[0] = _mm256_blendv_pd(l0, _mm256_mul_pd(m0, inv), positive);
  b[1] = _mm256_blendv_pd(l1, _mm256_mul_pd(m1, inv), positive);
  b[2] = _mm256_blendv_pd(l2, _mm256_mul_pd(m2, inv), positive);
}

}  // namespace shadetool::render_engine
#endif
