// consistent_winding.cpp: depth-first winding propagation over manifold edges (see the header).
#include "repair/consistent_winding.h"

#include <algorithm>

#include "core/error.h"
#include "io/bulk_reserve.h"

namespace shadetool {

namespace {

// One manifold edge of the face being expanded: the face across it, the edge's vertex pair (a
// winding-free tie-break, filled only when one neighbour is met twice) and whether both faces run
// the edge the same way.
struct Step {
  std::uint32_t face;
  std::uint32_t same_direction;
  std::uint64_t key;
  bool operator<(const Step& o) const { return face != o.face ? face < o.face : key < o.key; }
};

}  // namespace

ConsistentWinding consistent_winding(const Mesh& mesh, const EdgeAdjacency& adj, const EdgeAdjacencyOptions& left_out) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners();
  if (adj.corner_mate.size() != C) fail("consistent_winding", 0, "adjacency was built for another mesh");
  if (!left_out.skip.empty() && left_out.skip.size() != F)
    fail("consistent_winding", 0, "skip flags size differs from the face count");
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const std::uint32_t* fs = mesh.face_start.data();
  const std::uint32_t* mate = adj.corner_mate.data();
  constexpr std::uint32_t kNone = ConsistentWinding::kNoComponent;
  constexpr std::uint32_t kUnpaired = EdgeAdjacency::kUnpaired;
  const bool triangles = mesh.all_triangles();  // corners 3f .. 3f+2, the face of corner c is c / 3

  // Polygons: the face of each corner, for the mates.
  std::vector<std::uint32_t> face_of;
  if (!triangles) {
    face_of.resize(C);
    for (std::size_t f = 0; f < F; ++f)
      for (std::uint32_t c = fs[f]; c < fs[f + 1]; ++c) face_of[c] = std::uint32_t(f);
  }

  ConsistentWinding w;
  w.non_manifold_edges = adj.non_manifold_edges;
  io::reserve_bulk(w.face_component, F);  // huge pages for large fresh arrays (io/bulk_reserve.h)
  w.face_component.assign(F, kNone);
  io::reserve_bulk(w.face_reverse, F);
  w.face_reverse.assign(F, 0);
  std::uint32_t* component = w.face_component.data();
  std::uint8_t* reverse = w.face_reverse.data();

  std::vector<Step> steps;
  Step tri[3];
  std::vector<std::uint32_t> stack;
  for (std::size_t seed = 0; seed < F; ++seed) {
    if (component[seed] != kNone) continue;
    if (!left_out.skip.empty() && left_out.skip[seed]) continue;
    if (left_out.skip_unwound_faces && face_is_unwound(mesh, seed)) continue;
    const std::uint32_t k = std::uint32_t(w.num_components++);
    std::uint32_t faces = 1, reversed = 0;
    bool non_orientable = false;
    component[seed] = k;
    stack.push_back(std::uint32_t(seed));
    while (!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      const std::uint32_t reverse_f = reverse[f];
      const std::uint32_t b = triangles ? 3 * f : fs[f], e = triangles ? 3 * f + 3 : fs[f + 1];
      std::size_t n = 0;
      if (triangles) {  // the common case: at most three neighbours, no allocation, a sorting network
        Step* t = tri;
        for (std::uint32_t c = b; c < e; ++c) {
          const std::uint32_t m = mate[c];
          const std::uint32_t g = (m >> 1) / 3;
          if (m == kUnpaired || g == f) continue;  // no manifold edge / a face using an edge twice
          t[n++] = {g, m & 1u, c};  // key = corner for now, replaced on a tie below
        }
        if (n >= 2 && t[1].face < t[0].face) std::swap(t[0], t[1]);
        if (n == 3) {
          if (t[2].face < t[1].face) std::swap(t[1], t[2]);
          if (t[1].face < t[0].face) std::swap(t[0], t[1]);
        }
      } else {
        steps.clear();
        for (std::uint32_t c = b; c < e; ++c) {
          const std::uint32_t m = mate[c];
          if (m == kUnpaired) continue;
          const std::uint32_t g = face_of[m >> 1];
          if (g == f) continue;  // a face using an edge twice is no bridge
          steps.push_back({g, m & 1u, c});
        }
        n = steps.size();
        std::sort(steps.begin(), steps.end(), [](const Step& x, const Step& y) { return x.face < y.face; });
      }
      Step* const step = triangles ? tri : steps.data();
      // A neighbour met twice (two faces sharing two edges): order its steps by the edge's vertex
      // pair, which does not depend on the winding (the corner does). Rare.
      for (std::size_t i = 0; i + 1 < n; ++i) {
        if (step[i].face != step[i + 1].face) continue;
        std::size_t j = i;
        for (; j < n && step[j].face == step[i].face; ++j) {
          const std::uint32_t c = std::uint32_t(step[j].key), u = cv[c], v = cv[c + 1 < e ? c + 1 : b];
          step[j].key = (std::uint64_t(std::min(u, v)) << 32) | std::max(u, v);
        }
        std::sort(step + i, step + j);
        i = j - 1;
      }
      for (std::size_t i = 0; i < n; ++i) {
        const Step& s = step[i];
        const std::uint32_t wanted = reverse_f ^ s.same_direction;
        if (component[s.face] == kNone) {
          component[s.face] = k;
          reverse[s.face] = std::uint8_t(wanted);
          ++faces;
          reversed += wanted;
          stack.push_back(s.face);
        } else if (reverse[s.face] != wanted) {
          // A non-tree edge the labels leave inconsistent. It is met from both of its faces
          // (expanding a face labels all its neighbours, and every labelled face is expanded);
          // count it from the lower face only.
          non_orientable = true;
          if (f < s.face) ++w.inconsistent_edges;
        }
      }
    }
    w.component_seed.push_back(std::uint32_t(seed));
    w.component_faces.push_back(faces);
    w.component_reverse_count.push_back(reversed);
    w.component_non_orientable.push_back(non_orientable ? 1 : 0);
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
