// normalise_sums.h: per-vertex (or per-row) sums of contributions into unit normals (internal to
// lib/normals; vertex_normals and corner_normals share it, so that a corner normal with no crease
// in the way is its vertex normal bit for bit).
//
// Inputs:  sum     #rows by Stride sums, x y z first (T = double or float; a float sum is widened
//                  exactly); Stride 3, or 4 for padded float sums
// Outputs: out     #rows by 3 unit vectors (double); out may alias sum when T = double
//          failed  rows whose sum is zero or not finite (appended in ascending order; callers
//                  give them their documented fallback)
// Arithmetic in double: out = s / |s|, dividing rather than multiplying by 1/|s| (one rounding
// per component). |s| by the one safe length, geometry/scaled_length.h (sqrt(s . s) where s . s
// lies in [1e-280, 1e280], else scaled). normalise_range does two rows at a time in SSE2 (sqrtpd,
// divpd: the same IEEE operations as the scalar code, so the same bits) when both are in range.
#pragma once

#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/scaled_length.h>

namespace shadetool::normals_detail {

// o = s / |s| and true, or false (o untouched) when s is zero or not finite: the one safe
// normalise (geometry/scaled_length.h).
SHADETOOL_INLINE bool normalise_sum(double x, double y, double z, double* o) { return normalise_checked(x, y, z, o); }

template <class T, std::size_t Stride = 3>
void normalise_range(const T* sum, double* out, std::size_t v_begin, std::size_t v_end, std::vector<std::uint32_t>& failed) {
  std::size_t v = v_begin;
#if defined(__SSE2__)
  const __m128d lo = _mm_set1_pd(kSquaresFrom), hi = _mm_set1_pd(kSquaresTo);
  for (; v + 2 <= v_end; v += 2) {
    const T* s = sum + Stride * v;
    const double x0 = double(s[0]), y0 = double(s[1]), z0 = double(s[2]);
    const double x1 = double(s[Stride]), y1 = double(s[Stride + 1]), z1 = double(s[Stride + 2]);
    const __m128d x = _mm_set_pd(x1, x0), y = _mm_set_pd(y1, y0), z = _mm_set_pd(z1, z0);
    const __m128d l2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y)), _mm_mul_pd(z, z));
    const __m128d in = _mm_and_pd(_mm_cmpge_pd(l2, lo), _mm_cmple_pd(l2, hi));
    double* o = out + 3 * v;
    if (_mm_movemask_pd(in) == 3) {
      const __m128d len = _mm_sqrt_pd(l2);  // both lanes in range: divisor checked
      const __m128d X = _mm_div_pd(x, len), Y = _mm_div_pd(y, len), Z = _mm_div_pd(z, len);
      _mm_storeu_pd(o, _mm_unpacklo_pd(X, Y));        // x0 y0
      _mm_storeu_pd(o + 2, _mm_shuffle_pd(Z, X, 2));  // z0 x1
      _mm_storeu_pd(o + 4, _mm_unpackhi_pd(Y, Z));    // y1 z1
    } else {
      if (!normalise_sum(x0, y0, z0, o)) failed.push_back(std::uint32_t(v));
      if (!normalise_sum(x1, y1, z1, o + 3)) failed.push_back(std::uint32_t(v + 1));
    }
  }
#endif
  for (; v < v_end; ++v)
    if (!normalise_sum(double(sum[Stride * v]), double(sum[Stride * v + 1]), double(sum[Stride * v + 2]), out + 3 * v))
      failed.push_back(std::uint32_t(v));
}

}  // namespace shadetool::normals_detail
