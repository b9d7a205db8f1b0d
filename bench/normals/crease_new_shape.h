// crease_new_shape.h (bench only): the experiment behind issue 31 goal 3, round 4 -- how fast can a
// crease path be that does no vertex-major gathering for smooth vertices? Angle weighting, double,
// triangle meshes only; the hard vertices are counted, not computed (so this is a floor, not a
// crease path).
//
// Pass 1, in face order (the vertex-normal kernel's own pass, with more per corner): per block of
// kTriangleBlock faces the vectorised angle contributions (triangle_blocks.h, the same bits as
// vertex_normals), then per corner: the sum S[v] += contribution (ascending corner order, as the
// crease path's group sum), the smooth-cone test of the face's unit normal against the vertex's
// first face (n = (w0 + w1 + w2) / pi: the three angles sum to pi by construction), and the
// corner's (next, prev) vertex pair appended to a fixed 64-byte slot of the vertex (no counting
// pass, no prefix sum): {axis x, y, z as float, count, 6 pairs}.
// Pass 2, in vertex order (sequential over the slots): a cone vertex with <= 6 corners whose pairs
// form one closed ring is one group: its row is S[v] normalised. Every other vertex is "hard"
// (counted; the real path would group it edge by edge).
// Pass 3, in corner order: corner_index[c] = row of its vertex.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/mesh.h>
#include <shadetool/normals/engine/corner_contributions.h>
#include <shadetool/normals/engine/normalise_sums.h>
#include <shadetool/normals/engine/triangle_blocks.h>
#include <shadetool/normals/engine/smooth_cone.h>
#include <shadetool/normals/engine/vertex_slots.h>

#include <emmintrin.h>
#include <immintrin.h>

namespace crease_new_shape {

using namespace shadetool;
using namespace shadetool::normals_detail;

constexpr std::uint32_t kSlotPairs = 6;
struct alignas(64) Slot {
  float ax, ay, az;
  std::uint32_t d;
  std::uint32_t pair[2 * kSlotPairs];  // next, prev of each corner
};

struct Result {
  std::vector<double> normals;             // one row per easy vertex (hard vertices: no row)
  std::vector<std::uint32_t> corner_index;  // row of each corner of an easy vertex, else ~0u
  std::size_t hard = 0, used = 0;
};

// SmoothCone's threshold (corner_normals.cpp), for crease angles in (0.6 deg, pi).
inline double cone_min_dot(double crease_angle) {
  const double cos_2alpha = std::cos(crease_angle) + 5e-5;
  return std::cos(0.5 * std::acos(cos_2alpha)) + 1e-5;
}

// Whether d <= kSlotPairs (next, prev) pairs of vertex v form one closed ring: every corner's next
// vertex is exactly one corner's previous vertex, and following those links from corner 0 returns
// to it after exactly d steps.
inline bool one_ring(std::uint32_t v, const std::uint32_t* pair, std::uint32_t d) {
  std::uint32_t succ[16];
  std::uint32_t covered = 0;
  for (std::uint32_t i = 0; i < d; ++i) {
    const std::uint32_t w = pair[2 * i];
    std::uint32_t m = 0;
    for (std::uint32_t j = 0; j < d; ++j) m |= std::uint32_t(pair[2 * j + 1] == w) << j;
    if (w == v || m == 0 || (m & (m - 1)) != 0) return false;
    covered |= m;
    succ[i] = std::uint32_t(__builtin_ctz(m));
  }
  if (covered != (1u << d) - 1) return false;
  std::uint32_t k = 0;
  for (std::uint32_t step = 1; step <= d; ++step) {
    k = succ[k];
    if ((k == 0) != (step == d)) return false;
  }
  return true;
}

// Pass 1's front, shared by both variants: the faces in blocks of kTriangleBlock, positions
// gathered (prefetched kPrefetchFaces ahead, with the vertex records `rows` of `row_bytes` each),
// the vectorised angle contributions w (triangle_blocks.h), then per face either
// degenerate(v3) (scalar path or degenerate face: NaN weights) or
// face(v3, w, i, nx, ny, nz) with the face's unit normal n = (w0 + w1 + w2) / pi (the three
// angles sum to pi by construction).
template <class Degenerate, class Face>
inline void for_each_angle_face(const Mesh& mesh, const void* rows, std::size_t row_bytes, Degenerate&& degenerate,
                                Face&& face) {
  const std::size_t F = mesh.num_faces();
  const double* P = mesh.positions.data();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  alignas(64) double xyz[9][kTriangleBlock];
  alignas(64) double w[9][kTriangleBlock];
  const double inv_pi = 1.0 / kPi;
  for (std::size_t b = 0; b < F; b += kTriangleBlock) {
    const std::size_t count = std::min(kTriangleBlock, F - b);
    gather_block_contributions<Weighting::Angle>(P, cv, b, count, F, xyz, w);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t c = 3 * (b + i);
      if (b + i + kPrefetchFaces < F)
        prefetch_face(P, cv + c + 3 * kPrefetchFaces, RowHint{reinterpret_cast<const char*>(rows), row_bytes});
      const std::uint32_t v3[3] = {cv[c], cv[c + 1], cv[c + 2]};
      if (std::isnan(w[0][i])) {
        degenerate(v3);
        continue;
      }
      const double nx = (w[0][i] + w[3][i] + w[6][i]) * inv_pi, ny = (w[1][i] + w[4][i] + w[7][i]) * inv_pi,
                   nz = (w[2][i] + w[5][i] + w[8][i]) * inv_pi;
      face(v3, w, i, nx, ny, nz);
    }
  }
}

// passes: 1 = pass 1 only, 3 = all three. Parts (pass 1): 0 sums only, 1 sums + cone, 2 everything.
template <int Parts = 2>
inline Result run(const Mesh& mesh, double crease_angle, int passes, BulkVector<Slot>& slots, std::vector<double>& S) {
  Result out;
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const double min_dot = cone_min_dot(crease_angle);
  slots.resize(V);
  for (std::size_t v = 0; v < V; ++v) slots[v].d = 0;
  S.assign(3 * V, 0.0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for_each_angle_face(
      mesh, slots.data(), sizeof(Slot),
      [&](const std::uint32_t* v3) {  // the experiment marks a degenerate face's vertices hard
        for (int k = 0; k < 3; ++k) { slots[v3[k]].ax = nan; slots[v3[k]].d = 99; }
      },
      [&](const std::uint32_t* v3, const double (*w)[kTriangleBlock], std::size_t i, double nx, double ny, double nz) {
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t v = v3[k];
          double* s = &S[3 * std::size_t(v)];
          s[0] += w[3 * k][i]; s[1] += w[3 * k + 1][i]; s[2] += w[3 * k + 2][i];
          if constexpr (Parts == 0) continue;
          Slot& sl = slots[v];
          const std::uint32_t d = sl.d;
          const bool first = d == 0;
          const float ax = first ? float(nx) : sl.ax, ay = first ? float(ny) : sl.ay, az = first ? float(nz) : sl.az;
          const bool inside = nx * double(ax) + ny * double(ay) + nz * double(az) > min_dot;
          sl.ax = inside ? ax : nan; sl.ay = ay; sl.az = az;
          if constexpr (Parts == 1) { sl.d = d + 1; continue; }
          const std::uint32_t slot = d < kSlotPairs ? d : kSlotPairs - 1;
          sl.pair[2 * slot] = v3[(k + 1) % 3];
          sl.pair[2 * slot + 1] = v3[(k + 2) % 3];
          sl.d = d + 1;
        }
      });
  if (passes == 1) return out;
  std::vector<std::uint32_t> row(V, ~0u);
  reserve_bulk(out.normals, 3 * V);
  out.normals.resize(3 * V);
  std::uint32_t rows = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const Slot& sl = slots[v];
    if (sl.d == 0) continue;
    ++out.used;
    if (std::isnan(sl.ax) || sl.d > kSlotPairs || !one_ring(std::uint32_t(v), sl.pair, sl.d)) {
      ++out.hard;
      continue;
    }
    const double* s = &S[3 * v];
    double* o = &out.normals[3 * std::size_t(rows)];
    if (!normalise_sum(s[0], s[1], s[2], o)) { ++out.hard; continue; }
    row[v] = rows++;
  }
  out.normals.resize(3 * std::size_t(rows));
  reserve_bulk(out.corner_index, C);
  out.corner_index.resize(C);
  for (std::size_t c = 0; c < C; ++c) out.corner_index[c] = row[cv[c]];
  return out;
}

}  // namespace crease_new_shape

namespace crease_new_shape {

// Variant B: the cone test without a per-corner compare. Each vertex accumulates U = sum of its
// faces' unit normals (and d, its corner count) beside its angle-weighted sum S, all in one 128-byte
// slot with up to 9 (next, prev) pairs. Afterwards, with m = U / |U|: sum_i (1 - u_i . m) =
// d - |U| for unit u_i, every term >= 0, so every face is within alpha of m when d - |U| (plus a
// rounding margin) < 1 - cos(alpha) -- SmoothCone's alpha: every pair of faces then lies within
// 2 alpha, which CreaseTest's fast path calls smooth. (The library's SmoothCone allows twice that
// room by a sharper argument, corner_normals.cpp; here the simpler bound, which only makes a few
// more vertices hard.)
constexpr std::uint32_t kSlotPairsB = 9;
struct alignas(64) SlotB {
  double s[3], u[3];
  std::uint32_t d, bad;
  std::uint32_t pair[2 * kSlotPairsB];
};
static_assert(sizeof(SlotB) == 128, "two cache lines");

// Passes: 1 = pass 1 only; 3 = all three; 4 = all three with the ring test taken as passed (not
// a correct result: the cost of everything but the ring test).
template <int Passes>
inline Result run_b(const Mesh& mesh, double crease_angle, BulkVector<SlotB>& slots) {
  Result out;
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const double cos_alpha = cone_min_dot(crease_angle) - 1e-5;
  slots.resize(V);
  for (std::size_t v = 0; v < V; ++v) slots[v] = SlotB{};
  for_each_angle_face(
      mesh, slots.data(), sizeof(SlotB), [&](const std::uint32_t* v3) { for (int k = 0; k < 3; ++k) slots[v3[k]].bad = 1; },
      [&](const std::uint32_t* v3, const double (*w)[kTriangleBlock], std::size_t i, double nx, double ny, double nz) {
        for (int k = 0; k < 3; ++k) {
          SlotB& sl = slots[v3[k]];
          sl.s[0] += w[3 * k][i]; sl.s[1] += w[3 * k + 1][i]; sl.s[2] += w[3 * k + 2][i];
          sl.u[0] += nx; sl.u[1] += ny; sl.u[2] += nz;
          const std::uint32_t d = sl.d;
          const std::uint32_t slot = d < kSlotPairsB ? d : kSlotPairsB - 1;
          sl.pair[2 * slot] = v3[k == 2 ? 0 : k + 1];
          sl.pair[2 * slot + 1] = v3[k == 0 ? 2 : k - 1];
          sl.d = d + 1;
        }
      });
  if (Passes == 1) return out;
  std::vector<std::uint32_t> row(V, ~0u);
  reserve_bulk(out.normals, 3 * V);
  out.normals.resize(3 * V);
  std::uint32_t rows = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const SlotB& sl = slots[v];
    if (sl.d == 0) continue;
    ++out.used;
    const double d = double(sl.d);
    const double spread = d - std::sqrt(sl.u[0] * sl.u[0] + sl.u[1] * sl.u[1] + sl.u[2] * sl.u[2]) + 4e-6 * d;
    if (sl.bad || !(spread < 1.0 - cos_alpha) || sl.d > kSlotPairsB || (Passes != 4 && !one_ring(std::uint32_t(v), sl.pair, sl.d))) {
      ++out.hard;
      continue;
    }
    double* o = &out.normals[3 * std::size_t(rows)];
    if (!normalise_sum(sl.s[0], sl.s[1], sl.s[2], o)) { ++out.hard; continue; }
    row[v] = rows++;
  }
  out.normals.resize(3 * std::size_t(rows));
  reserve_bulk(out.corner_index, C);
  out.corner_index.resize(C);
  for (std::size_t c = 0; c < C; ++c) out.corner_index[c] = row[cv[c]];
  return out;
}

}  // namespace crease_new_shape

namespace crease_new_shape {

// Round 6 (branch crease6): the library's one-thread path (corner_normals.cpp, engine/vertex_slots.h)
// up to its hard vertices, in two slot layouts, so that the layouts are timed side by side:
//   L (the library's): one 128-byte VertexSlot per vertex {U float x3, d, S in T x3, 11 (next, prev)
//     pairs of 32-bit ids}, a fresh pool written in pass 2;
//   C (compact): S in a dense #V by 3 array of double (the sums vertex_normals keeps) and a 64-byte
//     slot {U float x3, d, 12 (next, prev) pairs of 16-bit offsets w - v}; a corner whose offsets do
//     not fit int16 makes U NaN (the vertex is hard, as a vertex with too many corners is); pass 2
//     normalises S in place into the pool (row r <= v is written after row v is read), so the pool
//     is the S array itself: no second array, no fresh pool pages.
// Both: pass 1 in face order, pass 2 in vertex order (SmoothCone as the library's, ring test,
// normalise), corner_index; hard vertices counted, not computed. `fresh`: the scratch is allocated
// per call (as the library does); else the caller's buffers are reused (no page faults after the
// first call).
struct CompactSlot {
  float u[3];
  std::uint32_t d;
  std::int16_t next[12], prev[12];
};
static_assert(sizeof(CompactSlot) == 64, "one cache line per vertex");
constexpr std::uint32_t kCompactPairs = 12;

using Cone = SmoothCone;  // engine/smooth_cone.h, the library's test

// one_smooth_ring (vertex_slots.h) on 16-bit offsets: lanes >= d hold 0 (the vertex itself, which
// no next offset of a ring is).
// Packed: the successor map in one 64-bit register, 4 bits per corner, walked by shifts (no
// store and reload per step), and the successor search run over 8 corners whatever d (12 when d >
// 8, a branch that almost never goes that way), lanes >= d masked out: no loop exit that depends
// on d; else the library's one_smooth_ring's form (a loop of d, an array walked).
template <bool Packed = false>
inline bool one_compact_ring(const CompactSlot& sl) {
  const std::uint32_t d = sl.d;
  std::uint32_t succ[16] = {};
  std::uint64_t packed = 0;
  const __m128i count = _mm_set1_epi16(short(d));
  const __m128i lo = _mm_and_si128(_mm_cmplt_epi16(_mm_setr_epi16(0, 1, 2, 3, 4, 5, 6, 7), count),
                                   _mm_loadu_si128(reinterpret_cast<const __m128i*>(sl.prev)));
  const __m128i hi = _mm_and_si128(_mm_cmplt_epi16(_mm_setr_epi16(8, 9, 10, 11, 12, 13, 14, 15), count),
                                   _mm_loadl_epi64(reinterpret_cast<const __m128i*>(sl.prev + 8)));
  bool linked = true;
  auto corner = [&](std::uint32_t i) {
    const std::int16_t w = sl.next[i];
    const __m128i x = _mm_set1_epi16(w);
    const std::uint32_t m = std::uint32_t(_mm_movemask_epi8(_mm_packs_epi16(_mm_cmpeq_epi16(lo, x), _mm_cmpeq_epi16(hi, x))));
    const std::uint32_t next = std::uint32_t(__builtin_ctz(m | 0x8000u)) & 15u;
    if constexpr (Packed) {
      linked &= (i >= d) | ((w != 0) & (m != 0));
      packed |= std::uint64_t(i < d ? next : 0u) << (4 * i);
    } else {
      linked &= (w != 0) & (m != 0);
      succ[i] = next;
    }
  };
  if constexpr (Packed) {
    for (std::uint32_t i = 0; i < 8; ++i) corner(i);
    if (d > 8)
      for (std::uint32_t i = 8; i < kCompactPairs; ++i) corner(i);
  } else {
    for (std::uint32_t i = 0; i < d; ++i) corner(i);
  }
  std::uint32_t k = 0, returns = 0;
  for (std::uint32_t step = 1; step <= kCompactPairs; ++step) {
    if constexpr (Packed) k = std::uint32_t(packed >> (4 * k)) & 15u;
    else k = succ[k];
    returns |= std::uint32_t(k == 0) << step;
  }
  return linked & (std::uint32_t(__builtin_ctz(returns | (1u << (kCompactPairs + 1)))) == d);
}

// The ring test as one walk: from corner 0, each step finds the corners arriving from the vertex
// the current corner leaves to (one 16-lane compare); exactly one must, and it is the next corner.
// One closed ring through all d corners when the walk returns to corner 0 first after exactly d
// steps, having found exactly one corner at every step: then every corner was visited once, the
// successor map is a permutation (as in one_smooth_ring's argument), and no search had two
// candidates. d searches in all, no separate successor table and walk; but each search waits for
// the one before (a dependent chain of about d x 15 cycles).
inline bool one_compact_ring_walk(const CompactSlot& sl) {
  const std::uint32_t d = sl.d;
  const __m128i count = _mm_set1_epi16(short(d));
  const __m128i lo = _mm_and_si128(_mm_cmplt_epi16(_mm_setr_epi16(0, 1, 2, 3, 4, 5, 6, 7), count),
                                   _mm_loadu_si128(reinterpret_cast<const __m128i*>(sl.prev)));
  const __m128i hi = _mm_and_si128(_mm_cmplt_epi16(_mm_setr_epi16(8, 9, 10, 11, 12, 13, 14, 15), count),
                                   _mm_loadl_epi64(reinterpret_cast<const __m128i*>(sl.prev + 8)));
  bool ok = true;
  std::uint32_t k = 0, returned_at = 0;
  for (std::uint32_t step = 1; step <= d; ++step) {
    const std::int16_t w = sl.next[k];
    const __m128i x = _mm_set1_epi16(w);
    const std::uint32_t m = std::uint32_t(_mm_movemask_epi8(_mm_packs_epi16(_mm_cmpeq_epi16(lo, x), _mm_cmpeq_epi16(hi, x))));
    ok &= (w != 0) & (m != 0) & ((m & (m - 1)) == 0);
    k = std::uint32_t(__builtin_ctz(m | 0x8000u)) & 15u;
    returned_at = (k == 0 && returned_at == 0) ? step : returned_at;
  }
  return ok & (returned_at == d);
}

// The ring test of 8 consecutive vertices at once (SSE2, one int16 lane per vertex): the slots'
// 24 offsets transposed into 12 "next" and 12 "prev" vectors (8x8 transposes by unpacks); corner j
// of a lane exists when j < d (prev lanes beyond d set to 0, the vertex itself); each corner's
// successor is the LAST corner arriving from the vertex it leaves to (a max over j: any choice that
// depends only on that vertex keeps one_smooth_ring's argument: a walk that visits all d corners
// once makes the successor map a permutation, so no far vertex is left or reached twice), then the
// walk from corner 0 by compares and masks, up to the block's largest d (at most 12). Returns bit k
// set when lane k's corners form one closed ring, exactly as one_compact_ring decides.
inline void transpose8x8_epi16(const __m128i* r, __m128i* out) {
  const __m128i a0 = _mm_unpacklo_epi16(r[0], r[1]), a1 = _mm_unpackhi_epi16(r[0], r[1]);
  const __m128i a2 = _mm_unpacklo_epi16(r[2], r[3]), a3 = _mm_unpackhi_epi16(r[2], r[3]);
  const __m128i a4 = _mm_unpacklo_epi16(r[4], r[5]), a5 = _mm_unpackhi_epi16(r[4], r[5]);
  const __m128i a6 = _mm_unpacklo_epi16(r[6], r[7]), a7 = _mm_unpackhi_epi16(r[6], r[7]);
  const __m128i b0 = _mm_unpacklo_epi32(a0, a2), b1 = _mm_unpackhi_epi32(a0, a2);
  const __m128i b2 = _mm_unpacklo_epi32(a1, a3), b3 = _mm_unpackhi_epi32(a1, a3);
  const __m128i b4 = _mm_unpacklo_epi32(a4, a6), b5 = _mm_unpackhi_epi32(a4, a6);
  const __m128i b6 = _mm_unpacklo_epi32(a5, a7), b7 = _mm_unpackhi_epi32(a5, a7);
  out[0] = _mm_unpacklo_epi64(b0, b4); out[1] = _mm_unpackhi_epi64(b0, b4);
  out[2] = _mm_unpacklo_epi64(b1, b5); out[3] = _mm_unpackhi_epi64(b1, b5);
  out[4] = _mm_unpacklo_epi64(b2, b6); out[5] = _mm_unpackhi_epi64(b2, b6);
  out[6] = _mm_unpacklo_epi64(b3, b7); out[7] = _mm_unpackhi_epi64(b3, b7);
}

inline std::uint32_t compact_rings8(const CompactSlot* sl) {
  __m128i rows[8], cols[24];
  std::uint32_t dmax = 0;
  alignas(16) std::int16_t dl[8];
  for (int r = 0; r < 8; ++r) {
    const std::uint32_t d = sl[r].d < 13u ? sl[r].d : 13u;
    dl[r] = std::int16_t(d);
    dmax = d > dmax ? d : dmax;
  }
  dmax = dmax < kCompactPairs ? dmax : kCompactPairs;
  const __m128i D = _mm_load_si128(reinterpret_cast<const __m128i*>(dl));
  for (int part = 0; part < 3; ++part) {  // bytes 16-31, 32-47, 48-63 of each slot
    for (int r = 0; r < 8; ++r) rows[r] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(sl[r].next) + part);
    transpose8x8_epi16(rows, cols + 8 * part);
  }
  const __m128i* N = cols;       // N[i]: next offset of corner i, 8 lanes
  __m128i* P = cols + 12;        // P[j]: prev offset of corner j
  const __m128i zero = _mm_setzero_si128();
  __m128i S[kCompactPairs];
  __m128i bad = zero;
  for (std::uint32_t j = 0; j < dmax; ++j) P[j] = _mm_and_si128(P[j], _mm_cmpgt_epi16(D, _mm_set1_epi16(short(j))));
  for (std::uint32_t i = 0; i < dmax; ++i) {
    __m128i s = zero;
    for (std::uint32_t j = 0; j < dmax; ++j)
      s = _mm_max_epi16(s, _mm_and_si128(_mm_cmpeq_epi16(N[i], P[j]), _mm_set1_epi16(short(j + 1))));
    S[i] = s;
    const __m128i has = _mm_cmpgt_epi16(D, _mm_set1_epi16(short(i)));
    bad = _mm_or_si128(bad, _mm_and_si128(has, _mm_or_si128(_mm_cmpeq_epi16(N[i], zero), _mm_cmpeq_epi16(s, zero))));
  }
  __m128i K = zero, R = zero;
  for (std::uint32_t step = 1; step <= dmax; ++step) {
    __m128i k1 = zero;
    for (std::uint32_t j = 0; j < dmax; ++j) k1 = _mm_or_si128(k1, _mm_and_si128(_mm_cmpeq_epi16(K, _mm_set1_epi16(short(j))), S[j]));
    K = _mm_sub_epi16(k1, _mm_set1_epi16(1));
    const __m128i first = _mm_and_si128(_mm_cmpeq_epi16(K, zero), _mm_cmpeq_epi16(R, zero));
    R = _mm_or_si128(R, _mm_and_si128(first, _mm_set1_epi16(short(step))));
  }
  const __m128i ok = _mm_andnot_si128(bad, _mm_cmpeq_epi16(R, D));
  const std::uint32_t bytes = std::uint32_t(_mm_movemask_epi8(_mm_packs_epi16(ok, zero)));
  return bytes & 0xffu;
}

// compact_rings8 on 16 consecutive vertices in AVX2 (16 int16 lanes; the transposes as two SSE2
// 8x8 blocks joined): bit k of the result for lane k. Callers check __builtin_cpu_supports("avx2").
__attribute__((target("avx2"))) inline std::uint32_t compact_rings16(const CompactSlot* sl) {
  __m128i rows[8], lo[24], hi[24];
  std::uint32_t dmax = 0;
  alignas(32) std::int16_t dl[16];
  for (int r = 0; r < 16; ++r) {
    const std::uint32_t d = sl[r].d < 13u ? sl[r].d : 13u;
    dl[r] = std::int16_t(d);
    dmax = d > dmax ? d : dmax;
  }
  dmax = dmax < kCompactPairs ? dmax : kCompactPairs;
  const __m256i D = _mm256_load_si256(reinterpret_cast<const __m256i*>(dl));
  for (int half = 0; half < 2; ++half)
    for (int part = 0; part < 3; ++part) {
      for (int r = 0; r < 8; ++r) rows[r] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(sl[8 * half + r].next) + part);
      transpose8x8_epi16(rows, (half ? hi : lo) + 8 * part);
    }
  __m256i N[12], P[12], S[12];
  for (int i = 0; i < 12; ++i) {
    N[i] = _mm256_inserti128_si256(_mm256_castsi128_si256(lo[i]), hi[i], 1);
    P[i] = _mm256_inserti128_si256(_mm256_castsi128_si256(lo[12 + i]), hi[12 + i], 1);
  }
  const __m256i zero = _mm256_setzero_si256();
  __m256i bad = zero;
  for (std::uint32_t j = 0; j < dmax; ++j) P[j] = _mm256_and_si256(P[j], _mm256_cmpgt_epi16(D, _mm256_set1_epi16(short(j))));
  for (std::uint32_t i = 0; i < dmax; ++i) {
    __m256i s = zero;
    for (std::uint32_t j = 0; j < dmax; ++j)
      s = _mm256_max_epi16(s, _mm256_and_si256(_mm256_cmpeq_epi16(N[i], P[j]), _mm256_set1_epi16(short(j + 1))));
    S[i] = s;
    const __m256i has = _mm256_cmpgt_epi16(D, _mm256_set1_epi16(short(i)));
    bad = _mm256_or_si256(bad, _mm256_and_si256(has, _mm256_or_si256(_mm256_cmpeq_epi16(N[i], zero), _mm256_cmpeq_epi16(s, zero))));
  }
  __m256i K = zero, R = zero;
  for (std::uint32_t step = 1; step <= dmax; ++step) {
    __m256i k1 = zero;
    for (std::uint32_t j = 0; j < dmax; ++j)
      k1 = _mm256_or_si256(k1, _mm256_and_si256(_mm256_cmpeq_epi16(K, _mm256_set1_epi16(short(j))), S[j]));
    K = _mm256_sub_epi16(k1, _mm256_set1_epi16(1));
    const __m256i first = _mm256_and_si256(_mm256_cmpeq_epi16(K, zero), _mm256_cmpeq_epi16(R, zero));
    R = _mm256_or_si256(R, _mm256_and_si256(first, _mm256_set1_epi16(short(step))));
  }
  const __m256i ok = _mm256_andnot_si256(bad, _mm256_cmpeq_epi16(R, D));
  const std::uint32_t m = std::uint32_t(_mm256_movemask_epi8(_mm256_packs_epi16(ok, zero)));  // bytes 0-7 and 16-23
  return (m & 0xffu) | ((m >> 8) & 0xff00u);
}

struct Round6Scratch {
  BulkVector<VertexSlot<double>> slots;
  BulkVector<CompactSlot> compact;
  std::vector<double> pool;
  BulkVector<std::uint32_t> row;
};

// Layout L's ring test on 8 vertices at once: the library's smooth_rings8 (engine/vertex_slots.h).
inline std::uint32_t slot_rings8(std::uint32_t v0, const VertexSlot<double>* sl) { return smooth_rings8(v0, sl); }

// Layout L. passes: 1 = pass 1 only; 2 = all.
// ring: 0 the library's one_smooth_ring; 4 slot_rings8 (AVX2).
inline Result run_layout_l(const Mesh& mesh, double crease_angle, int passes, bool fresh, Round6Scratch& scratch, int ring = 0) {
  Result out;
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners(), F = mesh.num_faces();
  const Cone cone(crease_angle);
  Round6Scratch local;
  Round6Scratch& s = fresh ? local : scratch;
  s.slots.resize(V + 1);
  clear_vertex_slots(s.slots.data(), V + 1);
  add_faces_to_slots<double, Weighting::Angle>(MeshView(mesh), 0, F, s.slots.data());
  if (passes == 1) return out;
  s.row.resize(V);
  reserve_bulk(s.pool, 3 * V);
  s.pool.resize(3 * V);
  std::uint32_t used = 0, block = 0;
  for (std::uint32_t v = 0; v < V; ++v) {
    const VertexSlot<double>& sl = s.slots[v];
    if (ring == 4 && (v & 7) == 0) block = v + 8 <= V ? slot_rings8(v, &sl) : 0;
    s.row[v] = used;
    if (sl.d == 0) continue;
    double* o = &s.pool[3 * std::size_t(used)];
    const bool ring_ok = ring == 4 && v + 8 - (v & 7) <= V ? ((block >> (v & 7)) & 1u) != 0 : one_smooth_ring(v, sl);
    const bool easy = sl.d <= normals_detail::kSlotPairs && cone.passes(sl.d, sl.u[0], sl.u[1], sl.u[2]) && ring_ok &&
                      normalise_sum(sl.s[0], sl.s[1], sl.s[2], o);
    if (!easy) { ++out.hard; s.row[v] = ~0u; }
    ++used;
  }
  out.used = used;
  reserve_bulk(out.corner_index, C);
  out.corner_index.resize(C);
  const std::uint32_t* cv = mesh.corner_vertex.data();
  for (std::size_t c = 0; c < C; ++c) out.corner_index[c] = s.row[cv[c]];
  if (fresh) out.normals.swap(s.pool);  // else the pool stays in the caller's scratch (not copied out)
  return out;
}

// Floor (ii)'s per-vertex state: the cone evidence alone (U, d), 16 bytes.
struct ConeRecord {
  float u[3];
  std::uint32_t d;
};

// Pass 1 of layout C (add_faces_to_slots with the sums in S and 16-bit offsets in the slot); with
// Slot = ConeRecord, floor (ii)'s pass: sums and cone evidence, no pairs.
template <class Slot>
inline std::size_t add_faces_to_compact_slots(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, double* S,
                                              Slot* slots) {
  constexpr bool kPairs = std::is_same_v<Slot, CompactSlot>;
  std::size_t degenerate = 0;
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  alignas(64) double xyz[9][kTriangleBlock];
  alignas(64) double w[9][kTriangleBlock];
  const RowHint hint{reinterpret_cast<const char*>(slots), sizeof(Slot)};
  const RowHint hint_sums{reinterpret_cast<const char*>(S), 3 * sizeof(double)};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t b = f_begin; b < f_end; b += kTriangleBlock) {
    const std::size_t count = std::min(kTriangleBlock, f_end - b);
    gather_block_contributions<Weighting::Angle>(P, cv, b, count, f_end, xyz, w);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t c = 3 * (b + i);
      if (b + i + kPrefetchFaces < f_end) {
        prefetch_face(P, cv + c + 3 * kPrefetchFaces, hint);
        prefetch_face(P, cv + c + 3 * kPrefetchFaces, hint_sums);
      }
      const std::uint32_t v3[3] = {cv[c], cv[c + 1], cv[c + 2]};
      if (std::isnan(w[0][i])) {
        auto sink = [&](std::size_t, std::uint32_t v, const Vec3<double>& n) {
          double* s = S + 3 * std::size_t(v);
          s[0] += n.x; s[1] += n.y; s[2] += n.z;
        };
        degenerate += !triangle_scalar<double, Weighting::Angle>(P, cv, c, sink, 1.0);
        for (int k = 0; k < 3; ++k) {
          slots[v3[k]].u[0] = nan;
          ++slots[v3[k]].d;
        }
        continue;
      }
      constexpr double inv_pi = 1.0 / kPi;
      const float nx = float((w[0][i] + w[3][i] + w[6][i]) * inv_pi);
      const float ny = float((w[1][i] + w[4][i] + w[7][i]) * inv_pi);
      const float nz = float((w[2][i] + w[5][i] + w[8][i]) * inv_pi);
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = v3[k];
        Slot& sl = slots[v];
        double* s = S + 3 * std::size_t(v);
        s[0] += w[3 * k][i]; s[1] += w[3 * k + 1][i]; s[2] += w[3 * k + 2][i];
        if constexpr (!kPairs) {
          sl.u[0] += nx; sl.u[1] += ny; sl.u[2] += nz;
          ++sl.d;
          continue;
        }
        const std::uint32_t on = v3[k == 2 ? 0 : k + 1] - v, op = v3[k == 0 ? 2 : k - 1] - v;  // mod 2^32
        const bool fits = ((on + 32768u) | (op + 32768u)) < 65536u;
        sl.u[0] += fits ? nx : nan; sl.u[1] += ny; sl.u[2] += nz;
        const std::uint32_t d = sl.d;
        const std::uint32_t at = d < kCompactPairs ? d : kCompactPairs - 1;
        if constexpr (kPairs) {
          sl.next[at] = std::int16_t(on);
          sl.prev[at] = std::int16_t(op);
        }
        sl.d = d + 1;
      }
    }
  }
  return degenerate;
}

// Layout C. passes: 1 = pass 1 only; 2 = all; 3 = all with the ring test taken as passed (not a
// correct result: what everything but the ring test costs).
inline Result run_layout_c(const Mesh& mesh, double crease_angle, int passes, bool fresh, Round6Scratch& scratch,
                           int ring = 0) {
  Result out;
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners(), F = mesh.num_faces();
  const Cone cone(crease_angle);
  Round6Scratch local;
  Round6Scratch& s = fresh ? local : scratch;
  s.compact.resize(V);
  std::vector<double>& S = s.pool;
  reserve_bulk(S, 3 * V);
  S.resize(3 * V);
  std::fill(S.begin(), S.end(), 0.0);
  for (std::size_t v = 0; v < V; ++v) {
    CompactSlot& sl = s.compact[v];
    sl.u[0] = sl.u[1] = sl.u[2] = 0.0f;
    sl.d = 0;
  }
  add_faces_to_compact_slots(MeshView(mesh), 0, F, S.data(), s.compact.data());
  if (passes == 1) return out;
  s.row.resize(V);
  std::uint32_t used = 0, block = 0;
  for (std::uint32_t v = 0; v < V; ++v) {
    const CompactSlot& sl = s.compact[v];
    if (ring == 3 && (v & 7) == 0) block = v + 8 <= V ? compact_rings8(&sl) : 0;
    if (ring == 4 && (v & 15) == 0) block = v + 16 <= V ? compact_rings16(&sl) : 0;
    s.row[v] = used;
    if (sl.d == 0) continue;
    const double* sv = &S[3 * std::size_t(v)];
    double* o = &S[3 * std::size_t(used)];  // used <= v: row v read before row `used` is written
    const bool easy = sl.d <= kCompactPairs && cone.passes(sl.d, sl.u[0], sl.u[1], sl.u[2]) && (passes == 3 || (ring == 4   ? (v + 16 - (v & 15) <= V ? ((block >> (v & 15)) & 1u) != 0 : one_compact_ring(sl))
                                      : ring == 3 ? (v + 8 - (v & 7) <= V ? ((block >> (v & 7)) & 1u) != 0 : one_compact_ring(sl))
                                      : ring == 2 ? one_compact_ring_walk(sl)
                                      : ring == 1 ? one_compact_ring<true>(sl)
                                                  : one_compact_ring(sl))) &&
                      normalise_sum(sv[0], sv[1], sv[2], o);
    if (!easy) { ++out.hard; s.row[v] = ~0u; }
    ++used;
  }
  out.used = used;
  reserve_bulk(out.corner_index, C);
  out.corner_index.resize(C);
  const std::uint32_t* cv = mesh.corner_vertex.data();
  for (std::size_t c = 0; c < C; ++c) out.corner_index[c] = s.row[cv[c]];
  if (fresh) out.normals.swap(S);  // else the pool stays in the caller's scratch (not copied out)
  return out;
}

// Floor (ii): the output (pool, corner_index) and each vertex's cone evidence (one scatter of
// (contribution, unit normal, 1) per corner into S and a 16-byte record), pass 2 the cone test and
// the in-place normalisation; no ring evidence at all (so not exact: a pinch inside the cone is
// taken as one group). Hard vertices (cone failed) counted.
inline Result run_floor_cone(const Mesh& mesh, double crease_angle) {
  Result out;
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners(), F = mesh.num_faces();
  const Cone cone(crease_angle);
  BulkVector<ConeRecord> rec(V);
  std::fill(rec.begin(), rec.end(), ConeRecord{{0.0f, 0.0f, 0.0f}, 0});
  std::vector<double> S;
  reserve_bulk(S, 3 * V);
  S.assign(3 * V, 0.0);
  add_faces_to_compact_slots(MeshView(mesh), 0, F, S.data(), rec.data());
  BulkVector<std::uint32_t> row(V);
  std::uint32_t used = 0;
  for (std::uint32_t v = 0; v < V; ++v) {
    const ConeRecord& r = rec[v];
    row[v] = used;
    if (r.d == 0) continue;
    const double* sv = &S[3 * std::size_t(v)];
    double* o = &S[3 * std::size_t(used)];
    if (!(cone.passes(r.d, r.u[0], r.u[1], r.u[2]) && normalise_sum(sv[0], sv[1], sv[2], o))) {
      ++out.hard;
      row[v] = ~0u;
    }
    ++used;
  }
  out.used = used;
  reserve_bulk(out.corner_index, C);
  out.corner_index.resize(C);
  const std::uint32_t* cv = mesh.corner_vertex.data();
  for (std::size_t c = 0; c < C; ++c) out.corner_index[c] = row[cv[c]];
  out.normals.swap(S);
  return out;
}

}  // namespace crease_new_shape
