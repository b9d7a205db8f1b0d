// duplicate_faces.cpp: same-vertex-set faces among those on non-manifold edges (see the header).
#include "repair/duplicate_faces.h"

#include <algorithm>

namespace shadetool {

DuplicateFaces duplicate_faces(const Mesh& mesh, const EdgeAdjacency& adj) {
  const std::size_t F = mesh.num_faces();
  DuplicateFaces out;
  std::vector<std::uint32_t> candidates;
  for (std::size_t e = 0; e < adj.num_odd_edges(); ++e)
    if (adj.odd_edge_valence(e) >= 3)
      for (std::uint32_t i = adj.odd_edge_start[e]; i < adj.odd_edge_start[e + 1]; ++i)
        candidates.push_back(corner_face(mesh, adj.odd_edge_corner[i]));
  // A lone pair: every edge of the face is shared with one and the same other face. Its mates
  // then lie within one face of the same size, so they span fewer corners than the face has: a
  // cheap filter before the face is looked up.
  const std::uint32_t* mate = adj.corner_mate.data();
  const bool triangles = mesh.all_triangles();
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    if (e - b < 3) continue;
    std::uint32_t lo = EdgeAdjacency::kUnpaired, hi = 0;
    bool paired = true;
    for (std::uint32_t c = b; c < e && paired; ++c) {
      paired = mate[c] != EdgeAdjacency::kUnpaired;
      lo = std::min(lo, mate[c] >> 1);
      hi = std::max(hi, mate[c] >> 1);
    }
    if (!paired || hi - lo >= e - b) continue;
    const std::uint32_t g = triangles ? lo / 3 : corner_face(mesh, lo);
    if (g != f && (triangles ? hi / 3 == g : hi < mesh.face_start[g + 1])) candidates.push_back(std::uint32_t(f));
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
