// edge_buckets.h: the bucket matching of core/edge_adjacency.cpp (machinery, not installed).
//
// A bucket holds the half-edges whose lower vertex is one vertex v: for each, its higher vertex and
// (corner << 1) | (1 when the half-edge runs from v). Equal higher vertices are one edge. Two ways
// to find them: sort_bucket (any bucket; the general path) and match_small_bucket (up to 8
// half-edges compared all at once with SSE2; only the all-manifold case, the common one, else it
// declines and the caller sorts). tests/core/edge_adjacency.cpp checks both paths against a
// map-based pairing.
#pragma once

#include <algorithm>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shadetool::engine {

// Sorts slot keys (higher vertex << 32 | corner << 1 | direction) ascending.
inline void sort_bucket(std::uint64_t* s, std::uint32_t n) {
  if (n > 32) {
    std::sort(s, s + n);  // a high-degree vertex (a fan's hub)
    return;
  }
  for (std::uint32_t i = 1; i < n; ++i) {  // buckets hold ~half a vertex degree: insertion sort
    const std::uint64_t x = s[i];
    std::uint32_t j = i;
    for (; j > 0 && s[j - 1] > x; --j) s[j] = s[j - 1];
    s[j] = x;
  }
}

// Pairs a bucket of n <= 8 half-edges (higher vertices hv, readable 8 past the start; corners
// with direction bits cd) when each higher vertex occurs exactly twice: writes both mates of every
// pair and returns true. Returns false, writing nothing, when some edge has valence other than 2.
inline bool match_small_bucket(const std::uint32_t* hv, const std::uint32_t* cd, std::uint32_t n, std::uint32_t* mate) {
  if (n % 2 != 0) return false;
  std::uint32_t partner[8];
  const unsigned valid = (1u << n) - 1u;
#if defined(__SSE2__)
  const __m128i h0 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(hv));
  const __m128i h1 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(hv + 4));
#endif
  unsigned bad = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    unsigned m;
#if defined(__SSE2__)
    const __m128i x = _mm_set1_epi32(int(hv[i]));
    m = unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(h0, x)))) |
        (unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(h1, x)))) << 4);
#else
    m = 0;
    for (std::uint32_t j = 0; j < 8; ++j) m |= unsigned(hv[j] == hv[i]) << j;
#endif
    m &= valid & ~(1u << i);
    bad |= unsigned(m == 0 || (m & (m - 1)) != 0);  // no other, or two or more others
    partner[i] = std::uint32_t(__builtin_ctz(m | 0x100u));
  }
  if (bad) return false;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t x = cd[i], y = cd[partner[i]];
    mate[x >> 1] = (y & ~1u) | ((x ^ y ^ 1u) & 1u);
  }
  return true;
}

}  // namespace shadetool::engine
