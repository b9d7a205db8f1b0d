// fast_edge_flips.h: random_edge_flips (tests/support/analytic_meshes.h) for meshes of millions of
// triangles: the same flips, in the same order, from the same random numbers, so a benchmark mesh
// equals the one the tests would build, but with the edge -> faces map as one sorted flat array
// (O(E log E) sort, 16 bytes per edge) instead of a std::map of vectors (~5 s and ~1 GB at 4M
// triangles; this takes ~0.5 s).
//
// Inputs:  am        triangle mesh with exact per-vertex normals (all_triangles())
//          fraction  probability that an interior edge is flipped
//          seed      std::mt19937 seed
// Output:  am.mesh.corner_vertex rewritten where flipped. As in random_edge_flips: a flip is made
//          only if both faces are untouched so far, the new diagonal is not an edge of the input,
//          and both new triangles are positively oriented against the exact normals.
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "support/analytic_meshes.h"

namespace shadetool::bench {

inline void random_edge_flips_sorted(testing::AnalyticMesh& am, double fraction, std::uint32_t seed) {
  Mesh& m = am.mesh;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  const std::uint32_t F = static_cast<std::uint32_t>(m.num_faces());
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
  };
  // (edge key, face), sorted by key then face: the order std::map iteration and push_back gave.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edge_face;
  edge_face.reserve(3 * std::size_t(F));
  for (std::uint32_t f = 0; f < F; ++f)
    for (int k = 0; k < 3; ++k)
      edge_face.emplace_back(key(m.corner_vertex[3 * f + k], m.corner_vertex[3 * f + (k + 1) % 3]), f);
  std::sort(edge_face.begin(), edge_face.end());
  auto is_edge = [&](std::uint64_t k) {
    auto it = std::lower_bound(edge_face.begin(), edge_face.end(), std::make_pair(k, std::uint32_t(0)));
    return it != edge_face.end() && it->first == k;
  };
  std::vector<char> touched(F, 0);
  for (std::size_t i = 0; i < edge_face.size();) {
    std::size_t j = i;
    while (j < edge_face.size() && edge_face[j].first == edge_face[i].first) ++j;
    const std::size_t count = j - i;
    const std::uint64_t e = edge_face[i].first;
    const std::uint32_t ea = std::uint32_t(e >> 32), eb = std::uint32_t(e & 0xffffffffu);
    const std::uint32_t f0 = edge_face[i].second, f1 = count == 2 ? edge_face[i + 1].second : 0;
    i = j;
    if (count != 2 || u01(rng) >= fraction) continue;
    if (touched[f0] || touched[f1]) continue;
    auto opposite = [&](std::uint32_t f) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = m.corner_vertex[3 * f + k];
        if (v != ea && v != eb) return std::make_pair(v, k);
      }
      return std::make_pair(std::uint32_t(-1), -1);
    };
    auto [c, kc] = opposite(f0);
    auto [d, kd] = opposite(f1);
    if (kc < 0 || kd < 0 || c == d || is_edge(key(c, d))) continue;
    const std::uint32_t a = m.corner_vertex[3 * f0 + (kc + 1) % 3], b = m.corner_vertex[3 * f0 + (kc + 2) % 3];
    const std::uint32_t t0[3] = {c, a, d}, t1[3] = {d, b, c};
    auto positive = [&](const std::uint32_t* t) {
      const Vec3d n = cross(m.position(t[1]) - m.position(t[0]), m.position(t[2]) - m.position(t[0]));
      const Vec3d ref = am.exact_normals[t[0]] + am.exact_normals[t[1]] + am.exact_normals[t[2]];
      return dot(n, ref) > 1e-3 * length(n) * length(ref);
    };
    if (!positive(t0) || !positive(t1)) continue;
    for (int k = 0; k < 3; ++k) { m.corner_vertex[3 * f0 + k] = t0[k]; m.corner_vertex[3 * f1 + k] = t1[k]; }
    touched[f0] = touched[f1] = 1;
  }
}

}  // namespace shadetool::bench
