// consistent_winding.cpp: winding by union-find with parity, canonical depth-first search for
// non-orientable components (see the header).
#include <shadetool/core/engine/parallel.h>
#include <shadetool/geometry/union_find.h>
#include <shadetool/repair/consistent_winding.h>

#include <algorithm>
#include <memory>

#include <tbb/parallel_for.h>

#include <shadetool/core/error.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/engine/usable_threads.h>

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

// Union-find with parity over the faces (geometry/union_find.h): node[f] = (parent << 1) |
// parity, the parity of f's reversal relative to its parent's; union by lower index, so each set's
// root is its lowest face: the seed. Every link points to a lower face.
// The edge (f, g) says reverse[f] XOR reverse[g] = same. f's root and parity (rf, pf) are given
// and updated: a union either hangs g's root under f's, or f's under g's (then f's parity to its
// new root is its old one XOR the link's). An edge inside one set with the wrong parity is a
// conflict: its component is non-orientable (settled by the canonical search).
inline void unite_edge(std::uint32_t* node, std::uint32_t f, std::uint32_t& rf, std::uint32_t& pf, std::uint32_t g,
                       std::uint32_t same, std::vector<std::uint32_t>& conflicts) {
  std::uint32_t pg;
  const std::uint32_t rg = union_find_root_with_parity(node, g, pg);
  const std::uint32_t parity = pf ^ pg ^ same;
  if (rf == rg) {
    if (parity) conflicts.push_back(f);
  } else if (rf < rg) {
    node[rg] = (rf << 1) | parity;
  } else {
    node[rf] = (rg << 1) | parity;
    rf = rg;
    pf ^= parity;
  }
}

// The manifold edges of faces [lo, hi), each once from its lower corner; f's root is found once
// per face. Edges to a face at or beyond hi are deferred (their corner listed), so that only
// nodes in [lo, hi) are touched.
template <bool kTriangles>
void unite_faces(std::uint32_t lo, std::uint32_t hi, const std::uint32_t* fs, const std::uint32_t* face_of,
                 const std::uint32_t* mate, std::uint32_t* node, std::vector<std::uint32_t>& deferred,
                 std::vector<std::uint32_t>& conflicts) {
  constexpr std::uint32_t kUnpaired = EdgeAdjacency::kUnpaired;
  for (std::uint32_t f = lo; f < hi; ++f) {
    const std::uint32_t b = kTriangles ? 3 * f : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
    std::uint32_t rf = 0, pf = 0;
    bool found = false;
    for (std::uint32_t c = b; c < e; ++c) {
      const std::uint32_t m = mate[c];
      if (m == kUnpaired || (m >> 1) < c) continue;
      const std::uint32_t g = kTriangles ? (m >> 1) / 3 : face_of[m >> 1];
      if (g == f) continue;  // a face using an edge twice is no bridge
      if (g >= hi) {  // (g > f >= lo: only the upper bound can be crossed)
        deferred.push_back(c);
        continue;
      }
      if (!found) {
        rf = union_find_root_with_parity(node, f, pf);
        found = true;
      }
      unite_edge(node, f, rf, pf, g, m & 1u, conflicts);
    }
  }
}

// The faces on the other side of each manifold edge, for triangles (face = corner / 3) or
// polygons (face_of, one entry per corner).
struct FaceMates {
  bool triangles;
  const std::uint32_t* fs;       // face_start
  const std::uint32_t* cv;       // corner_vertex
  const std::uint32_t* mate;     // EdgeAdjacency::corner_mate: (mate corner << 1) | same direction
  const std::uint32_t* face_of;  // polygons only
  std::uint32_t begin(std::uint32_t f) const { return triangles ? 3 * f : fs[f]; }
  std::uint32_t end(std::uint32_t f) const { return triangles ? 3 * f + 3 : fs[f + 1]; }
  std::uint32_t face_of_corner(std::uint32_t c) const { return triangles ? c / 3 : face_of[c]; }
};

// Step 1, union: every manifold edge (f, g), once, from its lower corner (unite_faces). Threads:
// the faces are cut into P contiguous parts; part p unites only edges whose two faces both lie in
// it (every link and every path then stays inside the part: no two threads touch one node) and
// defers the rest, which one thread unites afterwards, in part order. The sets, their roots (the
// lowest face of each: union by lower index) and, on an orientable component, every parity are
// the same in any order of union; so is which components have a conflict. Returns the faces of
// the conflicting edges.
std::vector<std::uint32_t> unite_all_faces(const FaceMates& fm, std::size_t F, std::uint32_t* node) {
  for (std::size_t f = 0; f < F; ++f) node[f] = std::uint32_t(f) << 1;
  const std::size_t parts = F >= engine::kSerialBelow && usable_threads() >= 2 ? 2 : 1;
  std::vector<std::vector<std::uint32_t>> deferred(parts), conflicts(parts);
  auto unite_part = [&](std::size_t p) {
    const std::uint32_t lo = std::uint32_t(F * p / parts), hi = std::uint32_t(F * (p + 1) / parts);
    if (fm.triangles) unite_faces<true>(lo, hi, fm.fs, nullptr, fm.mate, node, deferred[p], conflicts[p]);
    else unite_faces<false>(lo, hi, fm.fs, fm.face_of, fm.mate, node, deferred[p], conflicts[p]);
  };
  if (parts == 1) unite_part(0);
  else tbb::parallel_for(std::size_t(0), parts, unite_part);
  std::vector<std::uint32_t> conflict_faces;
  for (std::size_t p = 0; p < parts; ++p) {
    for (std::uint32_t c : deferred[p]) {
      const std::uint32_t m = fm.mate[c];
      const std::uint32_t f = fm.face_of_corner(c), g = fm.face_of_corner(m >> 1);
      std::uint32_t pf;
      std::uint32_t rf = union_find_root_with_parity(node, f, pf);
      unite_edge(node, f, rf, pf, g, m & 1u, conflicts[p]);
    }
    conflict_faces.insert(conflict_faces.end(), conflicts[p].begin(), conflicts[p].end());
  }
  return conflict_faces;
}

// Step 2, labelling: components numbered by their lowest face; reversal relative to it. In face
// order a face's parent is lower, so already final: one step, no search. Faces left out are roots
// of nothing (they have no manifold edges) and get no component. `node` is the storage of
// w.face_component, overwritten in face order. The per-component counts are summed over runs of
// faces of one component in registers (an increment in memory per face would chain every face to
// the previous one's store).
void label_components(const Mesh& mesh, const EdgeAdjacencyOptions& left_out, ConsistentWinding& w) {
  constexpr std::uint32_t kNone = ConsistentWinding::kNoComponent;
  const std::size_t F = mesh.num_faces();
  std::uint32_t* component = w.face_component.data();
  const std::uint32_t* node = component;
  std::uint8_t* reverse = w.face_reverse.data();
  std::uint32_t run = kNone, run_faces = 0, run_reversed = 0;
  auto flush = [&]() {
    if (run == kNone) return;
    w.component_faces[run] += run_faces;
    w.component_reverse_count[run] += run_reversed;
    run_faces = run_reversed = 0;
  };
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t n = node[f], parent = n >> 1;
    std::uint32_t k, r;
    if (parent == f) {
      const bool out = (!left_out.skip.empty() && left_out.skip[f]) || (left_out.skip_unwound_faces && face_is_unwound(mesh, f));
      reverse[f] = 0;
      if (out) {
        component[f] = kNone;
        continue;
      }
      k = std::uint32_t(w.num_components++);
      r = 0;
      w.component_seed.push_back(std::uint32_t(f));
      w.component_faces.push_back(0);
      w.component_reverse_count.push_back(0);
      w.component_non_orientable.push_back(0);
    } else {
      k = component[parent];
      r = (n & 1u) ^ reverse[parent];
    }
    component[f] = k;
    reverse[f] = std::uint8_t(r);
    if (k != run) {
      flush();
      run = k;
    }
    ++run_faces;
    run_reversed += r;
  }
  flush();
}

// Labels of component k (reached from seed) undone, before the canonical search. `stack` holds F
// entries (each face is pushed once).
void clear_component(const FaceMates& fm, std::uint32_t seed, std::uint32_t k, ConsistentWinding& w,
                     std::uint32_t* stack) {
  constexpr std::uint32_t kNone = ConsistentWinding::kNoComponent;
  std::uint32_t* component = w.face_component.data();
  std::uint8_t* reverse = w.face_reverse.data();
  std::size_t top = 0;
  stack[top++] = seed;
  component[seed] = kNone;
  reverse[seed] = 0;
  while (top > 0) {
    const std::uint32_t f = stack[--top];
    for (std::uint32_t c = fm.begin(f), e = fm.end(f); c < e; ++c) {
      const std::uint32_t m = fm.mate[c];
      if (m == EdgeAdjacency::kUnpaired) continue;
      const std::uint32_t g = fm.face_of_corner(m >> 1);
      if (component[g] != k) continue;
      component[g] = kNone;
      reverse[g] = 0;
      stack[top++] = g;
    }
  }
}

// Step 3, canonical search of a non-orientable component: depth-first from its seed, neighbours
// in increasing (face, edge's vertex pair) order, so the labels do not depend on the input
// winding; counts the inconsistent edges (into w.inconsistent_edges) and sets the component's
// face and reversal counts.
void canonical_search(const FaceMates& fm, std::uint32_t seed, std::uint32_t k, ConsistentWinding& w,
                      std::uint32_t* stack, std::vector<Step>& steps) {
  constexpr std::uint32_t kNone = ConsistentWinding::kNoComponent;
  std::uint32_t* component = w.face_component.data();
  std::uint8_t* reverse = w.face_reverse.data();
  std::size_t top = 0;
  stack[top++] = seed;
  component[seed] = k;
  std::uint32_t faces = 1, reversed = 0;
  while (top > 0) {
    const std::uint32_t f = stack[--top];
    const std::uint32_t reverse_f = reverse[f];
    const std::uint32_t b = fm.begin(f), e = fm.end(f);
    steps.clear();
    for (std::uint32_t c = b; c < e; ++c) {
      const std::uint32_t m = fm.mate[c];
      if (m == EdgeAdjacency::kUnpaired) continue;
      const std::uint32_t g = fm.face_of_corner(m >> 1);
      if (g == f) continue;
      steps.push_back({g, m & 1u, c});  // key = corner for now, replaced on a tie below
    }
    const std::size_t n = steps.size();
    std::sort(steps.begin(), steps.end(), [](const Step& x, const Step& y) { return x.face < y.face; });
    // A neighbour met twice (two faces sharing two edges): order its steps by the edge's vertex
    // pair, which does not depend on the winding (the corner does).
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (steps[i].face != steps[i + 1].face) continue;
      std::size_t j = i;
      for (; j < n && steps[j].face == steps[i].face; ++j) {
        const std::uint32_t c = std::uint32_t(steps[j].key), u = fm.cv[c], v = fm.cv[c + 1 < e ? c + 1 : b];
        steps[j].key = (std::uint64_t(std::min(u, v)) << 32) | std::max(u, v);
      }
      std::sort(steps.begin() + std::ptrdiff_t(i), steps.begin() + std::ptrdiff_t(j));
      i = j - 1;
    }
    for (const Step& s : steps) {
      const std::uint32_t wanted = reverse_f ^ s.same_direction;
      if (component[s.face] == kNone) {
        component[s.face] = k;
        reverse[s.face] = std::uint8_t(wanted);
        ++faces;
        reversed += wanted;
        stack[top++] = s.face;
      } else if (reverse[s.face] != wanted) {
        // A non-tree edge the labels leave inconsistent. It is met from both of its faces
        // (expanding a face labels all its neighbours, and every labelled face is expanded);
        // count it from the lower face only.
        if (f < s.face) ++w.inconsistent_edges;
      }
    }
  }
  w.component_faces[k] = faces;
  w.component_reverse_count[k] = reversed;
}

}  // namespace

ConsistentWinding consistent_winding(const Mesh& mesh, const EdgeAdjacency& adj, const EdgeAdjacencyOptions& left_out) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners();
  if (adj.corner_mate.size() != C) fail("consistent_winding", 0, "adjacency was built for another mesh");
  if (!left_out.skip.empty() && left_out.skip.size() != F)
    fail("consistent_winding", 0, "skip flags size differs from the face count");
  if (F >= (std::size_t(1) << 31)) fail("consistent_winding", 0, "2^31 faces or more");  // (parent << 1) | parity

  FaceMates fm{mesh.all_triangles(), mesh.face_start.data(), mesh.corner_vertex.data(), adj.corner_mate.data(), nullptr};
  std::vector<std::uint32_t> face_of;  // polygons: the face of each corner, for the mates
  if (!fm.triangles) {
    face_of.resize(C);
    for (std::size_t f = 0; f < F; ++f)
      for (std::uint32_t c = fm.fs[f]; c < fm.fs[f + 1]; ++c) face_of[c] = std::uint32_t(f);
    fm.face_of = face_of.data();
  }

  ConsistentWinding w;
  w.non_manifold_edges = adj.non_manifold_edges;
  w.face_component.resize(F);  // huge pages, unzeroed: the union-find's first pass writes every entry
  reserve_bulk(w.face_reverse, F);
  w.face_reverse.resize(F);

  // The union-find's nodes live in the storage of face_component, which labelling overwrites.
  const std::vector<std::uint32_t> conflict_faces = unite_all_faces(fm, F, w.face_component.data());
  label_components(mesh, left_out, w);

  // Non-orientable components: labelled again by the canonical search, which does not depend on
  // the input winding and counts the inconsistent edges.
  for (std::uint32_t f : conflict_faces) w.component_non_orientable[w.face_component[f]] = 1;
  std::unique_ptr<std::uint32_t[]> stack;  // uninitialised: touched only as deep as a search goes
  std::vector<Step> steps;
  for (std::size_t k = 0; k < w.num_components; ++k) {
    if (!w.component_non_orientable[k]) continue;
    if (!stack) stack.reset(new std::uint32_t[F + 1]);
    const std::uint32_t seed = w.component_seed[k];
    clear_component(fm, seed, std::uint32_t(k), w, stack.get());
    canonical_search(fm, seed, std::uint32_t(k), w, stack.get(), steps);
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
