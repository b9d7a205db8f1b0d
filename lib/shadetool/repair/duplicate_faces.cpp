// duplicate_faces.cpp: same-vertex-set faces among those on non-manifold edges (see the header).
#include <shadetool/repair/duplicate_faces.h>

#include <algorithm>

namespace shadetool {

DuplicateFaces duplicate_faces(const Mesh& mesh, const EdgeAdjacency& adj) {
  return duplicate_faces(mesh, adj, consistent_winding(mesh, adj));
}

DuplicateFaces duplicate_faces(const Mesh& mesh, const EdgeAdjacency& adj, const ConsistentWinding& winding) {
  const std::size_t F = mesh.num_faces();
  DuplicateFaces out;
  std::vector<std::uint32_t> candidates;
  for (std::size_t e = 0; e < adj.num_odd_edges(); ++e)
    if (adj.odd_edge_valence(e) >= 3)
      for (std::uint32_t i = adj.odd_edge_start[e]; i < adj.odd_edge_start[e + 1]; ++i)
        candidates.push_back(corner_face(mesh, adj.odd_edge_corner[i]));
  // A lone pair (every edge of a face shared with one and the same other face, of the same size)
  // is a component of exactly two faces: found from the component sizes, without a pass over
  // the edges; the faces are listed only when such a component exists.
  bool pairs = false;
  for (std::uint32_t n : winding.component_faces) pairs = pairs || n == 2;
  if (pairs)
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t k = winding.face_component[f];
      if (k != ConsistentWinding::kNoComponent && winding.component_faces[k] == 2) candidates.push_back(std::uint32_t(f));
    }
  if (candidates.empty()) return out;
  out.original.assign(F, DuplicateFaces::kNone);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

  // Each candidate's sorted vertex list; group equal lists, lowest face first.
  std::vector<std::vector<std::uint32_t>> key(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const std::uint32_t f = candidates[i];
    key[i].assign(mesh.corner_vertex.begin() + mesh.face_start[f], mesh.corner_vertex.begin() + mesh.face_start[f + 1]);
    std::sort(key[i].begin(), key[i].end());
  }
  std::vector<std::uint32_t> order(candidates.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return key[a] != key[b] ? key[a] < key[b] : candidates[a] < candidates[b];
  });
  for (std::size_t i = 1; i < order.size(); ++i) {
    const std::uint32_t prev = order[i - 1], cur = order[i];
    if (key[cur] != key[prev]) continue;
    const std::uint32_t first = out.original[candidates[prev]] != DuplicateFaces::kNone ? out.original[candidates[prev]] : candidates[prev];
    out.original[candidates[cur]] = first;
    ++out.count;
  }
  return out;
}

}  // namespace shadetool
