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
