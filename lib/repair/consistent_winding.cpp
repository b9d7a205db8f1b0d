// consistent_winding.cpp: BFS winding propagation over manifold edges (see the header).
#include "repair/consistent_winding.h"

#include <algorithm>

#include "core/error.h"

namespace shadetool {

namespace {

// The other half-edge of a manifold edge, or kNoEdge when the edge does not propagate.
inline std::uint32_t mate(const EdgeAdjacency& adj, std::uint32_t c) {
  const std::uint32_t e = adj.corner_edge[c];
  if (e == EdgeAdjacency::kNoEdge || adj.edge_valence(e) != 2) return EdgeAdjacency::kNoEdge;
  const std::uint32_t h0 = adj.edge_corner[adj.edge_start[e]], h1 = adj.edge_corner[adj.edge_start[e] + 1];
  const std::uint32_t other = h0 == c ? h1 : h0;
  if (adj.corner_face[other] == adj.corner_face[c]) return EdgeAdjacency::kNoEdge;  // face uses the edge twice
  return other;
}

}  // namespace

ConsistentWinding consistent_winding(const Mesh& mesh, const EdgeAdjacency& adj, const std::vector<std::uint8_t>& skip) {
  const std::size_t F = mesh.num_faces();
  if (adj.corner_face.size() != mesh.num_corners())
    fail("consistent_winding", 0, "adjacency was built for another mesh");
  if (!skip.empty() && skip.size() != F) fail("consistent_winding", 0, "skip flags size differs from the face count");
  const std::vector<std::uint32_t>& cv = mesh.corner_vertex;

  ConsistentWinding w;
  w.face_component.assign(F, ConsistentWinding::kNoComponent);
  w.face_reverse.assign(F, 0);

  // (neighbour face, edge, same direction) of the face being expanded; sorted by face, then edge.
  struct Step { std::uint32_t face, edge; std::uint8_t same_direction; };
  std::vector<Step> steps;
  std::vector<std::uint32_t> queue;
  queue.reserve(F);

  for (std::size_t seed = 0; seed < F; ++seed) {
    if (w.face_component[seed] != ConsistentWinding::kNoComponent || (!skip.empty() && skip[seed])) continue;
    const std::uint32_t k = std::uint32_t(w.num_components++);
    w.component_seed.push_back(std::uint32_t(seed));
    w.component_faces.push_back(0);
    w.component_reverse_count.push_back(0);
    w.component_non_orientable.push_back(0);
    w.face_component[seed] = k;
    queue.clear();
    queue.push_back(std::uint32_t(seed));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t f = queue[head];
      ++w.component_faces[k];
      w.component_reverse_count[k] += w.face_reverse[f];
      steps.clear();
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
        const std::uint32_t o = mate(adj, c);
        if (o == EdgeAdjacency::kNoEdge) continue;
        steps.push_back({adj.corner_face[o], adj.corner_edge[c], std::uint8_t(cv[o] == cv[c])});
      }
      if (steps.size() > 1)
        std::sort(steps.begin(), steps.end(),
                  [](const Step& a, const Step& b) { return a.face != b.face ? a.face < b.face : a.edge < b.edge; });
      for (const Step& s : steps) {
        if (w.face_component[s.face] != ConsistentWinding::kNoComponent) continue;  // checked below, once per edge
        w.face_component[s.face] = k;
        w.face_reverse[s.face] = std::uint8_t(w.face_reverse[f] ^ s.same_direction);
        queue.push_back(s.face);
      }
    }
  }

  // One pass over the edges: count non-manifold edges and edges the labels leave inconsistent.
  for (std::size_t e = 0; e < adj.num_edges(); ++e) {
    const std::uint32_t valence = adj.edge_valence(e);
    if (valence >= 3) { ++w.non_manifold_edges; continue; }
    if (valence != 2) continue;
    const std::uint32_t c0 = adj.edge_corner[adj.edge_start[e]], c1 = adj.edge_corner[adj.edge_start[e] + 1];
    const std::uint32_t f0 = adj.corner_face[c0], f1 = adj.corner_face[c1];
    if (f0 == f1) continue;
    const std::uint8_t same_direction = cv[c0] == cv[c1];
    if ((w.face_reverse[f0] ^ w.face_reverse[f1]) != same_direction) {
      ++w.inconsistent_edges;
      w.component_non_orientable[w.face_component[f0]] = 1;
    }
  }
  return w;
}

ComponentFaces faces_by_component(const ConsistentWinding& winding) {
  const std::size_t K = winding.num_components, F = winding.face_component.size();
  ComponentFaces out;
  out.start.assign(K + 1, 0);
  for (std::size_t k = 0; k < K; ++k) out.start[k + 1] = out.start[k] + winding.component_faces[k];
  out.faces.resize(out.start[K]);
  std::vector<std::uint32_t> fill(out.start.begin(), out.start.end() - 1);
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t k = winding.face_component[f];
    if (k != ConsistentWinding::kNoComponent) out.faces[fill[k]++] = std::uint32_t(f);
  }
  return out;
}

}  // namespace shadetool
