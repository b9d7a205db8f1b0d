// consistent_winding.cpp: BFS winding propagation over manifold edges (see the header).
#include "repair/consistent_winding.h"

#include <algorithm>

#include "core/error.h"
#include "io/bulk_reserve.h"

namespace shadetool {

ConsistentWinding consistent_winding(const Mesh& mesh, const EdgeAdjacency& adj, const std::vector<std::uint8_t>& skip) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners();
  if (adj.corner_face.size() != C || adj.corner_across.size() != C)
    fail("consistent_winding", 0, "adjacency was built for another mesh");
  if (!skip.empty() && skip.size() != F) fail("consistent_winding", 0, "skip flags size differs from the face count");
  if (F >= (std::size_t(1) << 31)) fail("consistent_winding", 0, "more than 2^31 - 1 faces");  // state packing
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const std::uint32_t* fs = mesh.face_start.data();
  constexpr std::uint32_t kNone = ConsistentWinding::kNoComponent;
  const bool triangles = mesh.all_triangles();  // corners 3f .. 3f+2: no face_start lookups

  const std::uint32_t* across = adj.corner_across.data();

  ConsistentWinding w;
  w.non_manifold_edges = adj.non_manifold_edges;
  // state[f] = (component << 1) | reverse while the BFS runs; split into the outputs at the end.
  std::vector<std::uint32_t> state;
  io::reserve_bulk(state, F);  // huge pages for large fresh arrays (io/bulk_reserve.h)
  state.assign(F, kNone);

  // (neighbour, tie-break key, corner, same direction) of the face being expanded, visited in
  // increasing (neighbour, key) order; key = the edge's vertex pair, which is winding-free.
  struct Step {
    std::uint32_t face;
    std::uint64_t key;
    std::uint32_t corner;
    std::uint8_t same_direction;
    bool operator<(const Step& o) const { return face != o.face ? face < o.face : key < o.key; }
  };
  std::vector<Step> steps;
  std::vector<std::uint32_t> queue;
  io::reserve_bulk(queue, F);

  for (std::size_t seed = 0; seed < F; ++seed) {
    if (state[seed] != kNone || (!skip.empty() && skip[seed])) continue;
    const std::uint32_t k = std::uint32_t(w.num_components++);
    bool non_orientable = false;
    state[seed] = k << 1;
    queue.clear();
    queue.push_back(std::uint32_t(seed));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t f = queue[head];
      const std::uint32_t reverse_f = state[f] & 1u;
      const std::uint32_t b = triangles ? 3 * f : fs[f], e = triangles ? 3 * f + 3 : fs[f + 1];
      steps.clear();
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t a = across[c];
        if (a == kNone) continue;
        steps.push_back({a >> 1, 0, c, std::uint8_t(a & 1u)});
      }
      if (steps.size() == 2) {
        if (steps[1] < steps[0]) std::swap(steps[0], steps[1]);
      } else if (steps.size() == 3) {  // a triangle: three compare-swaps
        if (steps[1] < steps[0]) std::swap(steps[0], steps[1]);
        if (steps[2] < steps[1]) std::swap(steps[1], steps[2]);
        if (steps[1] < steps[0]) std::swap(steps[0], steps[1]);
      } else if (steps.size() > 3) {
        std::sort(steps.begin(), steps.end());
      }
      // A neighbour met twice (two faces sharing two edges): order its steps by edge, i.e. by the
      // edge's vertex pair, which does not depend on the winding. Rare, so keys are made here only.
      for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
        if (steps[i].face != steps[i + 1].face) continue;
        std::size_t j = i;
        while (j < steps.size() && steps[j].face == steps[i].face) {
          const std::uint32_t c = steps[j].corner, u = cv[c], v = cv[c + 1 < e ? c + 1 : b];
          steps[j++].key = (std::uint64_t(std::min(u, v)) << 32) | std::max(u, v);
        }
        std::sort(steps.begin() + std::ptrdiff_t(i), steps.begin() + std::ptrdiff_t(j));
        i = j - 1;
      }
      for (const Step& s : steps) {
        const std::uint32_t wanted = reverse_f ^ s.same_direction;
        std::uint32_t& g = state[s.face];
        if (g == kNone) {
          g = (k << 1) | wanted;
          queue.push_back(s.face);
        } else if ((g & 1u) != wanted) {
          // A non-tree edge the labels leave inconsistent. It is met from both of its faces (the
          // neighbour is always labelled by then: expanding a face labels all its neighbours);
          // count it from the lower face only.
          non_orientable = true;
          if (f < s.face) ++w.inconsistent_edges;
        }
      }
    }
    w.component_seed.push_back(std::uint32_t(seed));
    w.component_non_orientable.push_back(non_orientable ? 1 : 0);
  }

  const std::size_t K = w.num_components;
  io::reserve_bulk(w.face_component, F);
  w.face_component.resize(F);
  w.face_reverse.resize(F);
  w.component_faces.assign(K, 0);
  w.component_reverse_count.assign(K, 0);
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t s = state[f];
    if (s == kNone) {
      w.face_component[f] = kNone;
      w.face_reverse[f] = 0;
      continue;
    }
    w.face_component[f] = s >> 1;
    w.face_reverse[f] = std::uint8_t(s & 1u);
    ++w.component_faces[s >> 1];
    w.component_reverse_count[s >> 1] += s & 1u;
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
