// component_boundaries.cpp: closed components and boundary loops (see the header).
#include <shadetool/repair/component_boundaries.h>

#include <algorithm>
#include <numeric>

#include <shadetool/geometry/union_find.h>

namespace shadetool {

ComponentBoundaries component_boundaries(const Mesh& mesh, const EdgeAdjacency& adj, const ConsistentWinding& winding) {
  const std::size_t K = winding.num_components;
  ComponentBoundaries b;
  b.component_boundary_edges.assign(K, 0);
  b.component_loops.assign(K, 0);
  b.component_closed.assign(K, 1);

  // (component, edge) pairs where the component meets the edge an odd number of times. Only
  // edges of valence other than 2 can be such: the two faces of a manifold edge are joined
  // through it into one component, or are one face using the edge twice.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
  std::vector<std::uint32_t> comps;
  for (std::size_t e = 0; e < adj.num_odd_edges(); ++e) {
    const std::uint32_t s = adj.odd_edge_start[e], n = adj.odd_edge_valence(e);
    comps.clear();
    for (std::uint32_t i = s; i < s + n; ++i) comps.push_back(winding.face_component[corner_face(mesh, adj.odd_edge_corner[i])]);
    std::sort(comps.begin(), comps.end());
    for (std::size_t i = 0; i < comps.size();) {
      std::size_t j = i;
      while (j < comps.size() && comps[j] == comps[i]) ++j;
      if ((j - i) % 2 == 1) boundary.emplace_back(comps[i], std::uint32_t(e));
      i = j;
    }
  }

  // Boundary vertices are per component: key (component, vertex).
  std::vector<std::uint64_t> keys;
  keys.reserve(2 * boundary.size());
  for (auto [k, e] : boundary) {
    ++b.component_boundary_edges[k];
    b.component_closed[k] = 0;
    const auto [v0, v1] = half_edge_ends(mesh, adj.odd_edge_corner[adj.odd_edge_start[e]]);
    keys.push_back((std::uint64_t(k) << 32) | v0);
    keys.push_back((std::uint64_t(k) << 32) | v1);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  auto id = [&](std::uint32_t k, std::uint32_t v) {
    return std::uint32_t(std::lower_bound(keys.begin(), keys.end(), (std::uint64_t(k) << 32) | v) - keys.begin());
  };
  std::vector<std::uint32_t> parent(keys.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (auto [k, e] : boundary) {
    const auto [v0, v1] = half_edge_ends(mesh, adj.odd_edge_corner[adj.odd_edge_start[e]]);
    union_find_unite(parent.data(), id(k, v0), id(k, v1));
  }
  // Cycle rank per component: E_b - V_b + (pieces).
  std::vector<std::int64_t> rank(K, 0);
  for (auto [k, e] : boundary) { (void)e; ++rank[k]; }
  for (std::uint32_t i = 0; i < keys.size(); ++i) {
    const std::uint32_t k = std::uint32_t(keys[i] >> 32);
    --rank[k];
    if (union_find_root(parent.data(), i) == i) ++rank[k];
  }
  for (std::size_t k = 0; k < K; ++k) {
    b.component_loops[k] = std::uint32_t(std::max<std::int64_t>(rank[k], 0));
    b.boundary_loops += b.component_loops[k];
  }
  return b;
}

}  // namespace shadetool
