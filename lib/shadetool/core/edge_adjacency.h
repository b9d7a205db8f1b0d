// edge_adjacency.h: the edges of a face list and the half-edges (face sides) around each edge, in
// flat arrays. The one home of these rules; used by `info` (info/edge_topology.h: edge counts,
// inconsistent edges, non-manifold vertices) and `repair` (winding, duplicate faces, seams,
// component boundaries).
//
// The rules:
// - A half-edge is named by its corner: corner c of face f runs from corner_vertex[c] (its tail) to
//   the vertex of the next corner of f, cyclically (its head).
// - An edge is an unordered vertex pair {lo, hi}, lo < hi: the set of half-edges between lo and hi
//   in either direction. A half-edge whose two ends are the same vertex (a repeated index next to
//   itself, e.g. side 0 of face (a, a, b)) is not an edge and belongs to none.
// - An edge's valence is its number of half-edges: 1 a boundary edge, 2 a manifold edge, 3 or more
//   a non-manifold edge. (Two half-edges of one face, e.g. the a -> b and b -> a of face (a, a, b),
//   make a manifold edge too; callers that propagate across faces check for that.)
// - Faces with a repeated vertex index (core/repeated_index.h) or fewer than 3 corners: by default
//   their sides count like any other (info counts every side: a user's file, as it is); with
//   skip_unwound_faces they contribute nothing (repair: such a face has no winding of its own).
//   face_is_unwound is the test.
// - A vertex no face refers to (an isolated vertex) is on no edge.
//
// Inputs:  mesh     faces (face_start #F+1, corner_vertex #C), polygons of any size; positions unused
//          options  skip     #F flags or empty: faces whose flag is nonzero contribute no half-edges
//                   skip_unwound_faces  also leave out the faces face_is_unwound names (the
//                            rules above): their (a, b), (b, a) sides would make a false
//                            non-manifold edge out of a manifold one (repair sets this; info does not)
// Outputs: EdgeAdjacency with
//   corner_mate   #C   for a half-edge on an edge of valence exactly 2: (m << 1) | s, m the corner
//                      of the other half-edge, s = 1 when both run the edge the same way (a -> b
//                      twice: the two faces are wound inconsistently). kUnpaired otherwise
//                      (boundary, non-manifold, not an edge, or a left-out face). The two half-edges
//                      may belong to one face (a face using an edge twice); callers check.
//   odd_edge_start  #O+1  the edges of valence other than 2, in increasing (lo, hi) order: edge i's
//   odd_edge_corner #H_O  half-edges are odd_edge_corner[odd_edge_start[i] .. odd_edge_start[i+1]),
//                         in increasing corner order
//   num_edges, boundary_edges (valence 1), non_manifold_edges (valence >= 3)
// Manifold edges are not listed: they are the pairs in corner_mate (one edge per pair).
//
// Method: a counting sort of the half-edges keyed on their lower vertex (counts, prefix sum,
// scatter of the higher vertex and (corner, direction) in corner order; the counts/offsets/data
// layout of meshoptimizer's adjacency), then in each small bucket (about half the vertex degree)
// equal higher vertices form one edge. A bucket of up to 8 half-edges is first matched without
// sorting: each higher vertex compared with all 8 at once (SSE2); when every one occurs exactly
// twice (all manifold, the common case) the pairs are written directly. Other buckets are sorted
// by (higher vertex, corner). On a mesh whose vertex order is coherent with its face order (what
// exporters and scanners write) every pass is nearly streaming. O(C + V) plus O(d log d) per
// unusual bucket of size d; no maps, no hashing. Threads (TBB, meshes of 32768+ faces): the count
// and scatter run on parts of the faces, each part with its own counts (a bucket holds part 0's
// half-edges, then part 1's, each in corner order: the same buckets for any number of parts), and
// the matching on blocks of vertices; the output depends on nothing but the faces' vertex
// indices. Large arrays are allocated unzeroed in huge pages (core/bulk_reserve.h BulkVector).
// The bucket matching (SSE2 compares, insertion sort) is in core/engine/edge_buckets.h.
// Times on 1 and 2 threads: bench/repair/results.md.
// Throws Error if a face refers to a vertex index >= #V, or with 2^31 - 1 corners or more
// (a corner and a flag share 32 bits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct EdgeAdjacencyOptions {
  std::vector<std::uint8_t> skip;
  bool skip_unwound_faces = false;
};

struct EdgeAdjacency {
  static constexpr std::uint32_t kUnpaired = std::numeric_limits<std::uint32_t>::max();

  BulkVector<std::uint32_t> corner_mate;  // std::vector, not zeroed on resize (core/bulk_reserve.h)
  std::vector<std::uint32_t> odd_edge_start{0};
  std::vector<std::uint32_t> odd_edge_corner;
  std::size_t num_edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t non_manifold_edges = 0;

  std::size_t num_odd_edges() const { return odd_edge_start.size() - 1; }
  std::uint32_t odd_edge_valence(std::size_t i) const { return odd_edge_start[i + 1] - odd_edge_start[i]; }
};

EdgeAdjacency edge_adjacency(const Mesh& mesh, const EdgeAdjacencyOptions& options = {});

// Whether face f has no winding of its own: fewer than 3 corners, or a repeated vertex index.
bool face_is_unwound(const Mesh& mesh, std::size_t f);

// The face of corner c: c / 3 on a triangle mesh, else a binary search of face_start (O(log F);
// for the few corners of odd edges; bulk users build a corner -> face array).
inline std::uint32_t corner_face(const Mesh& mesh, std::uint32_t c) {
  if (mesh.all_triangles()) return c / 3;
  std::size_t lo = 0, hi = mesh.num_faces();  // face_start[lo] <= c < face_start[hi]
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (mesh.face_start[mid] <= c ? lo : hi) = mid;
  }
  return std::uint32_t(lo);
}

// The corner after c in its face f, cyclically (the head of c's half-edge is its vertex).
inline std::uint32_t next_corner(const Mesh& mesh, std::uint32_t f, std::uint32_t c) {
  return c + 1 < mesh.face_start[f + 1] ? c + 1 : mesh.face_start[f];
}

// (lower, higher) vertex of the half-edge at corner c.
inline std::pair<std::uint32_t, std::uint32_t> half_edge_ends(const Mesh& mesh, std::uint32_t c) {
  const std::uint32_t a = mesh.corner_vertex[c], b = mesh.corner_vertex[next_corner(mesh, corner_face(mesh, c), c)];
  return {a < b ? a : b, a < b ? b : a};
}

}  // namespace shadetool
#pragma GCC visibility pop
