// depth_row_lanes.cpp (engine): see depth_row_lanes.h. Compiled with -ffp-contract=off
// (CMakeLists.txt).
#include <shadetool/render/engine/depth_row_lanes.h>

#include <cstdlib>
#include <limits>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

namespace shadetool::render_engine {

bool depth_row_lanes_exact(const ScreenTriangle& t) {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (!avx2) return false;
  constexpr std::int32_t limit = 1 << 25;
  for (int i = 0; i < 3; ++i)
    if (t.X[i] <= -limit || t.X[i] >= limit || t.Y[i] <= -limit || t.Y[i] >= limit) return false;
  return true;
}

__attribute__((target("avx2"))) void depth_row_lanes(const DepthRow& row, int count, const ScreenTriangle* triangle,
                                                     double* depth, const ScreenTriangle** owner, double* lambda1,
                                                     double* lambda2) {
  const __m256d lane = _mm256_set_pd(3, 2, 1, 0);
  __m256d e[3], step4[3], min_inside[3];
  for (int i = 0; i < 3; ++i) {
    const __m256d step = _mm256_set1_pd(row.step[i]);
    e[i] = _mm256_add_pd(_mm256_set1_pd(row.edge[i]), _mm256_mul_pd(lane, step));  // integers: exact
    step4[i] = _mm256_mul_pd(_mm256_set1_pd(4.0), step);
    min_inside[i] = _mm256_set1_pd(double(1 - row.bias[i]));  // E + bias - 1 >= 0
  }
  const __m256d inv_area = _mm256_set1_pd(row.inv_area);
  const __m256d z0 = _mm256_set1_pd(row.z[0]), z1 = _mm256_set1_pd(row.z[1]), z2 = _mm256_set1_pd(row.z[2]);
  const __m256d no_depth = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const __m256i tri = _mm256_set1_epi64x(static_cast<long long>(reinterpret_cast<std::uintptr_t>(triangle)));
  const __m256i zero = _mm256_setzero_si256();
  bool seen = false;
  for (int x = 0; x < count; x += 4) {
    const __m256i valid = _mm256_cmpgt_epi64(_mm256_set1_epi64x(count - x), _mm256_set_epi64x(3, 2, 1, 0));
    __m256d inside = _mm256_castsi256_pd(valid);
    for (int i = 0; i < 3; ++i) inside = _mm256_and_pd(inside, _mm256_cmp_pd(e[i], min_inside[i], _CMP_GE_OQ));
    const int any = _mm256_movemask_pd(inside);
    if (any == 0) {
      if (seen) return;  // past the interval
    } else {
      seen = true;
      const __m256d l0 = _mm256_mul_pd(e[0], inv_area), l1 = _mm256_mul_pd(e[1], inv_area);
      const __m256d l2 = _mm256_mul_pd(e[2], inv_area);
      const __m256d z = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(l0, z0), _mm256_mul_pd(l1, z1)), _mm256_mul_pd(l2, z2));
      const __m256i m = _mm256_castpd_si256(inside);
      const __m256i own = _mm256_maskload_epi64(reinterpret_cast<const long long*>(owner + x), m);
      const __m256d held = _mm256_maskload_pd(depth + x, m);
      const __m256d current = _mm256_blendv_pd(held, no_depth, _mm256_castsi256_pd(_mm256_cmpeq_epi64(own, zero)));
      const __m256i pass = _mm256_castpd_si256(_mm256_and_pd(inside, _mm256_cmp_pd(z, current, _CMP_LT_OQ)));
      if (!_mm256_testz_si256(pass, pass)) {
        _mm256_maskstore_pd(depth + x, pass, z);
        _mm256_maskstore_pd(lambda1 + x, pass, l1);
        _mm256_maskstore_pd(lambda2 + x, pass, l2);
        _mm256_maskstore_epi64(reinterpret_cast<long long*>(owner + x), pass, tri);
      }
    }
    for (int i = 0; i < 3; ++i) e[i] = _mm256_add_pd(e[i], step4[i]);
  }
}

}  // namespace shadetool::render_engine

#else

namespace shadetool::render_engine {
bool depth_row_lanes_exact(const ScreenTriangle&) { return false; }
void depth_row_lanes(const DepthRow&, int, const ScreenTriangle*, double*, const ScreenTriangle**, double*, double*) {
  std::abort();  // not reached: depth_row_lanes_exact is false
}
}  // namespace shadetool::render_engine

#endif
