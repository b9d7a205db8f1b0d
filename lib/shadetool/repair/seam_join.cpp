// seam_join.cpp: coincident boundary vertices joined for the orientation decision (see the header).
#include <shadetool/repair/seam_join.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace shadetool {

SeamJoin seam_join(const Mesh& mesh, const EdgeAdjacency& adj) {
  SeamJoin out;
  // The vertices of boundary edges (valence 1), each once.
  std::vector<std::uint32_t> boundary;
  for (std::size_t e = 0; e < adj.num_odd_edges(); ++e) {
    if (adj.odd_edge_valence(e) != 1) continue;
    const auto [a, b] = half_edge_ends(mesh, adj.odd_edge_corner[adj.odd_edge_start[e]]);
    boundary.push_back(a);
    boundary.push_back(b);
  }
  if (boundary.size() < 2) return out;
  std::sort(boundary.begin(), boundary.end());
  boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());

  // Sorted by position, then index: equal positions form runs whose first is the lowest vertex.
  const double* P = mesh.positions.data();
  auto key = [P](std::uint32_t v) { return std::make_tuple(P[3 * v], P[3 * v + 1], P[3 * v + 2]); };
  std::vector<std::uint32_t> order(boundary);
  // NaN positions compare false both ways and would break the ordering: they take no part.
  order.erase(std::remove_if(order.begin(), order.end(),
                             [P](std::uint32_t v) { return !(std::isfinite(P[3 * v]) && std::isfinite(P[3 * v + 1]) && std::isfinite(P[3 * v + 2])); }),
              order.end());
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const auto ka = key(a), kb = key(b);
    return ka != kb ? ka < kb : a < b;
  });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> replace;  // (vertex, lowest coincident vertex)
  for (std::size_t i = 1; i < order.size(); ++i) {
    std::size_t first = i - 1;
    while (i < order.size() && key(order[i]) == key(order[first])) {
      replace.emplace_back(order[i], order[first]);
      ++i;
    }
  }
  if (replace.empty()) return out;
  std::vector<std::uint32_t> canonical(mesh.num_vertices());
  for (std::uint32_t v = 0; v < canonical.size(); ++v) canonical[v] = v;
  for (auto [v, to] : replace) canonical[v] = to;
  out.joined = replace.size();
  out.corner_vertex.resize(mesh.num_corners());
  for (std::size_t c = 0; c < mesh.num_corners(); ++c) out.corner_vertex[c] = canonical[mesh.corner_vertex[c]];
  return out;
}

}  // namespace shadetool
