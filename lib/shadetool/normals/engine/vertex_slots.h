// vertex_slots.h: the face-order pass of corner_normals' one-thread path (crease_paths.h) for triangle meshes
// (internal to lib/normals; header-only so that the contribution code inlines into its loop).
//
// What it computes, in one pass over the faces in ascending order, into one 128-byte VertexSlot
// per vertex:
//   s     the sum of the vertex's corner contributions (corner_contributions.h, weighting W,
//         rounded to T and added in T in ascending corner order): exactly the sum that
//         vertex_normals and corner_normals' group sums form for a vertex whose corners are one
//         group, bit for bit (the same vectorised block kernel, triangle_blocks.h, the same
//         additions in the same order as accumulate_by_vertex.h's serial loop);
//   u     the sum of the unit normals of its faces rounded to float, in float (SmoothCone's U,
//         as corner_normals.cpp's vertex_fans adds it up); a face's unit normal is read off its
//         contributions: for Angle (w0 + w1 + w2) / pi (w_k = theta_k n, theta_0 + theta_1 +
//         theta_2 = pi by construction, so within ~1e-13 of n: the angles' relative error bound,
//         triangle_blocks.h; SmoothCone allows 1e-6), for Uniform w0 = n itself; NaN once a face
//         at the vertex was not taken by the vector pass (degenerate, or out of its range:
//         triangle_scalar then adds the face's contributions to s if it has any), so that such a
//         vertex is never classified one-group here;
//   d     its corner count;
//   next, prev  the vertices after and before it in each of its first kSlotPairs faces (in face
//         order); a vertex with more corners keeps overwriting the last pair (it is left to the
//         general path: d > kSlotPairs).
// add_faces_to_slots adds faces [f_begin, f_end) to slots cleared by clear_vertex_slots.
// Inputs:  mesh     triangles (mesh.all_triangles()), positions #V by 3, corner_vertex #C
//          slots    #V + 1 slots (the last is padding for the ring test's vector loads)
// Returns the number of degenerate faces (as triangle_contributions counts them).
// Precision: contributions in double rounded once to T, sums in T (as everywhere in lib/normals);
// u in double. Only W = Angle and W = Uniform (their contributions carry the unit normal, and
// their scale is 1 for either T: corner_contributions.h's kScaledContributions).
//
// one_smooth_ring: whether the slot's d <= kSlotPairs corners form one closed ring (the fan
// test of corner_normals.cpp's closed_triangle_ring8, on 12 lanes): each corner's successor is
// the first corner arriving from the vertex it leaves to (three 4-lane compares), and walking the
// successor map from corner 0 must return to it first after exactly d steps. Such a walk visits
// all d corners once, so the successor map is a permutation of them: no far vertex is left twice
// (two corners leaving to w would have the same successor) nor reached twice (the successor is the
// first arriving corner, and every corner is some corner's successor): every edge at the vertex is
// manifold and consistently oriented, and its d edges link all d corners into one group, exactly
// as the edge-by-edge grouping would (given that no edge is a crease: SmoothCone's job).
//
// smooth_rings8 (x86-64 with AVX2, checked at run time by slot_ring_lanes_available): the same
// verdict as one_smooth_ring for the 8 consecutive vertices v0 .. v0 + 7 at once, one 32-bit lane
// per vertex: the slots' next and prev ids transposed into 12 + 12 vectors (4x4 transposes of
// loads), prev lanes of corners j >= d set to the vertex itself, each corner's successor the LAST
// corner arriving from the vertex it leaves to (a lane-wise max over j), and the walk from corner 0
// by compares and masks for as many steps as the block's largest d (<= kSlotPairs). Exact by
// one_smooth_ring's argument, which needs of the successor only that it arrive from the vertex
// left to and be chosen by that vertex alone (first or last alike): a walk that returns to corner
// 0 first after exactly d steps visits all d corners once, so the successor map is a permutation.
// Bit k of the result: lane k passes. Why: one vertex at a time, the test was the largest step of
// the one-thread path's pass 2 (figures: bench/normals/results/notes.md, sixth round). Requires
// slots v0 .. v0 + 8 to exist (the eighth lane reads the next slot, masked).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SHADETOOL_SLOT_RING_LANES 1
#include <immintrin.h>
#endif

#include <shadetool/core/math_constants.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/engine/corner_contributions.h>
#include <shadetool/normals/engine/triangle_blocks.h>
#include <shadetool/normals/weighting.h>

namespace shadetool::normals_detail {

// Measured on the irregular UV sphere of bench_crease (bench/normals/results/notes.md): 6 pairs
// left 36% of its vertices to the general path, 9 left 2.0%, 11 (all that fit in two lines) 0.6%.
constexpr std::uint32_t kSlotPairs = 11;

template <class T>
struct alignas(64) VertexSlot {
  float u[3];       // NaN after a face the vector pass did not take
  std::uint32_t d;  // corners
  T s[3];
  std::uint32_t next[kSlotPairs], prev[kSlotPairs];
};
static_assert(sizeof(VertexSlot<double>) == 128 && sizeof(VertexSlot<float>) == 128, "two cache lines per vertex");
static_assert(kSlotPairs < 12, "one_smooth_ring compares 12 lanes");

// The first cache line of slots [0, n): sums and counts zero (the pairs are written as they come).
template <class T>
void clear_vertex_slots(VertexSlot<T>* slots, std::size_t n) {
  for (std::size_t v = 0; v < n; ++v) {
    VertexSlot<T>& sl = slots[v];
    sl.u[0] = sl.u[1] = sl.u[2] = 0.0f;
    sl.s[0] = sl.s[1] = sl.s[2] = T(0);
    sl.d = 0;
  }
}

// Pass 1 (see the header block) over faces [f_begin, f_end), onto cleared slots (#V + 1).
template <class T, Weighting W>
std::size_t add_faces_to_slots(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, VertexSlot<T>* slots) {
  static_assert(W == Weighting::Angle || W == Weighting::Uniform, "the unit normal is read off the contributions");
  std::size_t degenerate = 0;
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  alignas(64) double xyz[9][kTriangleBlock];
  alignas(64) double w[9][kTriangleBlock];
  // Prefetched kPrefetchFaces ahead: positions, and both cache lines of the three slots.
  const RowHint hint{reinterpret_cast<const char*>(slots), sizeof(VertexSlot<T>)};
  const RowHint hint_pairs{reinterpret_cast<const char*>(slots) + 64, sizeof(VertexSlot<T>)};
  for (std::size_t b = f_begin; b < f_end; b += kTriangleBlock) {
    const std::size_t count = std::min(kTriangleBlock, f_end - b);
    gather_block_contributions<W>(P, cv, b, count, f_end, xyz, w);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t c = 3 * (b + i);
      if (b + i + kPrefetchFaces < f_end) {
        prefetch_face(P, cv + c + 3 * kPrefetchFaces, hint);
        prefetch_face(P, cv + c + 3 * kPrefetchFaces, hint_pairs);
      }
      const std::uint32_t v3[3] = {cv[c], cv[c + 1], cv[c + 2]};
      if (std::isnan(w[0][i])) {  // out of the vector pass's range: the scalar path; the vertices go to the general path
        auto sink = [&](std::size_t, std::uint32_t v, const Vec3<T>& n) {
          T* s = slots[v].s;
          s[0] += n.x; s[1] += n.y; s[2] += n.z;
        };
        degenerate += !triangle_scalar<T, W>(P, cv, c, sink, 1.0);
        for (int k = 0; k < 3; ++k) {
          slots[v3[k]].u[0] = std::numeric_limits<float>::quiet_NaN();  // SmoothCone fails
          ++slots[v3[k]].d;  // still a corner of the vertex (it has a row even when all its faces are degenerate)
        }
        continue;
      }
      float nx, ny, nz;
      if constexpr (W == Weighting::Angle) {
        constexpr double inv_pi = 1.0 / kPi;
        nx = float((w[0][i] + w[3][i] + w[6][i]) * inv_pi);
        ny = float((w[1][i] + w[4][i] + w[7][i]) * inv_pi);
        nz = float((w[2][i] + w[5][i] + w[8][i]) * inv_pi);
      } else {
        nx = float(w[0][i]); ny = float(w[1][i]); nz = float(w[2][i]);
      }
      for (int k = 0; k < 3; ++k) {
        VertexSlot<T>& sl = slots[v3[k]];
        const Vec3<T> n = to<T>(Vec3d{w[3 * k][i], w[3 * k + 1][i], w[3 * k + 2][i]});
        sl.s[0] += n.x; sl.s[1] += n.y; sl.s[2] += n.z;
        sl.u[0] += nx; sl.u[1] += ny; sl.u[2] += nz;
        const std::uint32_t d = sl.d;
        const std::uint32_t at = d < kSlotPairs ? d : kSlotPairs - 1;
        sl.next[at] = v3[k == 2 ? 0 : k + 1];
        sl.prev[at] = v3[k == 0 ? 2 : k - 1];
        sl.d = d + 1;
      }
    }
  }
  return degenerate;
}

// See the header block. Requires 1 <= d <= kSlotPairs < 12; reads the lane after prev (the next
// slot's first bytes, or the padding slot), masked.
template <class T>
inline bool one_smooth_ring(std::uint32_t v, const VertexSlot<T>& sl) {
  const std::uint32_t d = sl.d;
  std::uint32_t succ[16] = {};
#if defined(__SSE2__)
  const __m128i vv = _mm_set1_epi32(int(v)), count = _mm_set1_epi32(int(d));
  __m128i prev[3];
  for (int q = 0; q < 3; ++q) {
    const __m128i index = _mm_setr_epi32(4 * q, 4 * q + 1, 4 * q + 2, 4 * q + 3);
    const __m128i in_fan = _mm_cmplt_epi32(index, count);
    const __m128i lanes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(sl.prev + 4 * q));
    prev[q] = _mm_or_si128(_mm_and_si128(in_fan, lanes), _mm_andnot_si128(in_fan, vv));
  }
#endif
  bool linked = true;  // every corner leaves to a far vertex that some corner arrives from
  for (std::uint32_t i = 0; i < d; ++i) {
    const std::uint32_t w = sl.next[i];
#if defined(__SSE2__)
    const __m128i x = _mm_set1_epi32(int(w));
    const std::uint32_t m = std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(prev[0], x)))) |
                            std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(prev[1], x)))) << 4 |
                            std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(prev[2], x)))) << 8;
#else
    std::uint32_t m = 0;
    for (std::uint32_t j = 0; j < d; ++j) m |= std::uint32_t(sl.prev[j] == w) << j;
#endif
    linked &= (w != v) & (m != 0);
    succ[i] = std::uint32_t(__builtin_ctz(m | 0x8000u)) & 15u;
  }
  std::uint32_t k = 0, returns = 0;  // bit s: the walk is at corner 0 after s steps
  for (std::uint32_t step = 1; step <= kSlotPairs; ++step) {
    k = succ[k];
    returns |= std::uint32_t(k == 0) << step;
  }
  return linked & (std::uint32_t(__builtin_ctz(returns | (1u << (kSlotPairs + 1)))) == d);
}

#if defined(SHADETOOL_SLOT_RING_LANES)
inline bool slot_ring_lanes_available() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}

// See the header block.
template <class T>
__attribute__((target("avx2"))) std::uint32_t smooth_rings8(std::uint32_t v0, const VertexSlot<T>* sl) {
  __m128i col[2][24];  // [lanes 0-3 | 4-7][next 0..11, prev 0..11]
  alignas(32) std::int32_t dl[8];
  std::uint32_t dmax = 0;
  for (int r = 0; r < 8; ++r) {
    const std::uint32_t d = sl[r].d < kSlotPairs + 1 ? sl[r].d : kSlotPairs + 1;  // > kSlotPairs: never a ring
    dl[r] = std::int32_t(d);
    dmax = d > dmax ? d : dmax;
  }
  dmax = dmax < kSlotPairs ? dmax : kSlotPairs;
  for (int half = 0; half < 2; ++half)
    for (int q = 0; q < 6; ++q) {  // next 0-3, 4-7, 8-11, prev 0-3, 4-7, 8-11 (lane 11: the field after, masked)
      __m128i r[4];
      for (int k = 0; k < 4; ++k) {
        const std::uint32_t* base = q < 3 ? sl[4 * half + k].next : sl[4 * half + k].prev;
        r[k] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(base + 4 * (q % 3)));
      }
      const __m128i t0 = _mm_unpacklo_epi32(r[0], r[1]), t1 = _mm_unpacklo_epi32(r[2], r[3]);
      const __m128i t2 = _mm_unpackhi_epi32(r[0], r[1]), t3 = _mm_unpackhi_epi32(r[2], r[3]);
      __m128i* out = col[half] + 4 * q;
      out[0] = _mm_unpacklo_epi64(t0, t1); out[1] = _mm_unpackhi_epi64(t0, t1);
      out[2] = _mm_unpacklo_epi64(t2, t3); out[3] = _mm_unpackhi_epi64(t2, t3);
    }
  __m256i next[12], prev[12], succ[12];
  for (int i = 0; i < 12; ++i) {
    next[i] = _mm256_inserti128_si256(_mm256_castsi128_si256(col[0][i]), col[1][i], 1);
    prev[i] = _mm256_inserti128_si256(_mm256_castsi128_si256(col[0][12 + i]), col[1][12 + i], 1);
  }
  const __m256i d = _mm256_load_si256(reinterpret_cast<const __m256i*>(dl));
  const __m256i self = _mm256_add_epi32(_mm256_set1_epi32(int(v0)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
  const __m256i zero = _mm256_setzero_si256();
  for (std::uint32_t j = 0; j < dmax; ++j) {  // corners j >= d arrive from the vertex itself: no match
    const __m256i in_fan = _mm256_cmpgt_epi32(d, _mm256_set1_epi32(int(j)));
    prev[j] = _mm256_or_si256(_mm256_and_si256(in_fan, prev[j]), _mm256_andnot_si256(in_fan, self));
  }
  __m256i unlinked = zero;  // a corner of the fan leaving to the vertex itself or to no arriving corner
  for (std::uint32_t i = 0; i < dmax; ++i) {
    __m256i s = zero;  // 1 + the last corner arriving from next[i], or 0
    for (std::uint32_t j = 0; j < dmax; ++j)
      s = _mm256_max_epi32(s, _mm256_and_si256(_mm256_cmpeq_epi32(next[i], prev[j]), _mm256_set1_epi32(int(j + 1))));
    succ[i] = s;
    const __m256i in_fan = _mm256_cmpgt_epi32(d, _mm256_set1_epi32(int(i)));
    unlinked = _mm256_or_si256(
        unlinked, _mm256_and_si256(in_fan, _mm256_or_si256(_mm256_cmpeq_epi32(next[i], self), _mm256_cmpeq_epi32(s, zero))));
  }
  __m256i k = zero, returned = zero;  // the walk's corner; the first step at which it is back at 0
  for (std::uint32_t step = 1; step <= dmax; ++step) {
    __m256i k1 = zero;
    for (std::uint32_t j = 0; j < dmax; ++j)
      k1 = _mm256_or_si256(k1, _mm256_and_si256(_mm256_cmpeq_epi32(k, _mm256_set1_epi32(int(j))), succ[j]));
    k = _mm256_sub_epi32(k1, _mm256_set1_epi32(1));  // -1 (never 0 again) where no successor
    const __m256i first = _mm256_and_si256(_mm256_cmpeq_epi32(k, zero), _mm256_cmpeq_epi32(returned, zero));
    returned = _mm256_or_si256(returned, _mm256_and_si256(first, _mm256_set1_epi32(int(step))));
  }
  const __m256i ring = _mm256_andnot_si256(unlinked, _mm256_cmpeq_epi32(returned, d));
  return std::uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(ring)));
}
#endif

}  // namespace shadetool::normals_detail
