// edge_adjacency.cpp: half-edges paired by a counting sort on their lower vertex (see the header),
// in the header's steps: 1 count_part (half-edges per lower vertex), 2 bucket_offsets (prefix sum),
// 3 scatter_part (half-edges into their buckets), 4 match_buckets (equal higher vertices form an
// edge), 5 join_odd_edges (the blocks' lists in order); edge_adjacency runs them.
#include <shadetool/core/edge_adjacency.h>

#include <algorithm>
#include <type_traits>

#include <tbb/parallel_for.h>

#include <shadetool/core/error.h>
#include <shadetool/core/repeated_index.h>
#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/engine/edge_buckets.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/core/engine/usable_threads.h>

namespace shadetool {

namespace {

constexpr std::size_t kParallelFaces = engine::kSerialBelow;

// Whether a polygon of n > 3 corners repeats a vertex index (core/repeated_index.h), out of line.
bool polygon_unwound(const std::uint32_t* v, std::uint32_t n) {
  std::vector<std::uint32_t> scratch;  // allocates only beyond 16 corners
  return has_repeated_index(v, n, scratch);
}

// Whether a face of n corners has fewer than 3 corners or repeats a vertex index (the rule of
// core/repeated_index.h). Triangles, the bulk, inline and without branches on the compares (the
// polygon path's vector kept GCC from inlining it: a call per face in both face passes).
inline bool unwound(const std::uint32_t* v, std::uint32_t n) {
  if (n == 3) return (v[0] == v[1]) | (v[1] == v[2]) | (v[0] == v[2]);
  if (n < 3) return true;
  return polygon_unwound(v, n);
}

// The faces whose half-edges are sorted, split into `parts` ranges that the count and scatter
// passes run on in parallel (each part with its own cursor per vertex: within a bucket, part p's
// half-edges follow part p-1's, each part's in corner order, so the buckets, and everything after,
// are the same for any number of parts). One part below kParallelFaces faces or on one thread.
struct FaceParts {
  const std::uint32_t* cv;
  const std::uint32_t* fs;
  std::size_t F, V;
  const std::vector<std::uint8_t>& skip;
  bool skip_unwound_faces;
  std::size_t parts;

  // Whether face f (corners b..e) contributes half-edges.
  bool takes_part(std::size_t f, std::uint32_t b, std::uint32_t e) const {
    if (!skip.empty() && skip[f]) return false;
    if (!skip_unwound_faces) return true;
    return !unwound(cv + b, e - b);
  }
  std::pair<std::size_t, std::size_t> faces_of(std::size_t p) const { return {F * p / parts, F * (p + 1) / parts}; }
  template <class Body>
  void for_parts(Body&& body) const {
    if (parts == 1) body(std::size_t(0));
    else tbb::parallel_for(std::size_t(0), parts, body);
  }
};

// Step 1, count: half-edges per lower vertex in part p's faces, into count (#V). False when a
// face refers to a vertex index >= #V. (Both face passes are compiled twice: for a triangle mesh
// the corner loops have a constant trip count of 3 and unroll.)
template <bool kTriangles>
bool count_part(const FaceParts& faces, std::size_t p, BulkVector<std::uint32_t>& count) {
  const std::uint32_t* cv = faces.cv;
  const std::uint32_t* fs = faces.fs;
  const std::size_t V = faces.V;
  count.assign(V, 0);
  std::uint32_t* n = count.data();
  const auto [f0, f1] = faces.faces_of(p);
  for (std::size_t f = f0; f < f1; ++f) {
    const std::uint32_t b = kTriangles ? std::uint32_t(3 * f) : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
    std::uint32_t highest = 0;
    for (std::uint32_t c = b; c < e; ++c) highest = std::max(highest, cv[c]);
    if (highest >= V && e > b) return false;
    if (!faces.takes_part(f, b, e)) continue;
    for (std::uint32_t c = b; c < e; ++c) {
      const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
      if (t != h) ++n[std::min(t, h)];
    }
  }
  return true;
}

// Step 2, prefix sum: bucket v is [end[v-1], end[v]); part p's cursor cur[p][v] starts after the
// parts < p. Returns the number of half-edges H (< 2^31: corners).
std::uint32_t bucket_offsets(std::uint32_t* const* cur, std::size_t parts, std::size_t V, std::uint32_t* end) {
  std::uint32_t H = 0;
  for (std::size_t v = 0; v < V; ++v) {
    for (std::size_t p = 0; p < parts; ++p) {
      const std::uint32_t n = cur[p][v];
      cur[p][v] = H;
      H += n;
    }
    end[v] = H;
  }
  return H;
}

// Step 3, scatter: each half-edge of part p's faces puts its higher vertex in his and
// (corner << 1 | tail is the lower vertex) in cds at its bucket's cursor `at`, in corner order;
// corners that are no half-edge get kUnpaired in mate now.
template <bool kTriangles>
void scatter_part(const FaceParts& faces, std::size_t p, std::uint32_t* at, std::uint32_t* his, std::uint32_t* cds,
                  std::uint32_t* mate) {
  constexpr std::uint32_t kUnpaired = EdgeAdjacency::kUnpaired;
  const std::uint32_t* cv = faces.cv;
  const std::uint32_t* fs = faces.fs;
  const auto [f0, f1] = faces.faces_of(p);
  for (std::size_t f = f0; f < f1; ++f) {
    const std::uint32_t b = kTriangles ? std::uint32_t(3 * f) : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
    if (!faces.takes_part(f, b, e)) {
      for (std::uint32_t c = b; c < e; ++c) mate[c] = kUnpaired;
      continue;
    }
    for (std::uint32_t c = b; c < e; ++c) {
      const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
      if (t == h) {
        mate[c] = kUnpaired;
        continue;
      }
      const std::uint32_t lo = std::min(t, h), hi = std::max(t, h);
      const std::uint32_t i = at[lo]++;
      his[i] = hi;
      cds[i] = (c << 1) | std::uint32_t(t == lo);
    }
  }
}

// The edges of valence other than 2 that one block of vertices found, and its counts.
struct OddEdges {
  std::vector<std::uint32_t> start, corner;
  std::vector<std::uint64_t> keys;  // a bucket being sorted
  std::size_t pairs = 0, boundary = 0, non_manifold = 0;
};

// Step 4b, a bucket that is not all manifold pairs of up to 8: sorted by (higher vertex, corner)
// (insertion sort; std::sort beyond 32) and scanned; equal higher vertices form one edge, paired
// in mate when of valence 2, else listed in o.
void match_sorted_bucket(OddEdges& o, const std::uint32_t* his, const std::uint32_t* cds, std::uint32_t b,
                         std::uint32_t n, std::uint32_t* mate) {
  constexpr std::uint32_t kUnpaired = EdgeAdjacency::kUnpaired;
  o.keys.resize(n);
  std::uint64_t* s = o.keys.data();
  for (std::uint32_t i = 0; i < n; ++i) s[i] = (std::uint64_t(his[b + i]) << 32) | cds[b + i];
  engine::sort_bucket(s, n);
  for (std::uint32_t i = 0; i < n;) {
    const std::uint32_t hi = std::uint32_t(s[i] >> 32);
    std::uint32_t j = i + 1;
    while (j < n && std::uint32_t(s[j] >> 32) == hi) ++j;
    if (j - i == 2) {
      const std::uint32_t x = std::uint32_t(s[i]), y = std::uint32_t(s[i + 1]);  // (c << 1) | dir
      const std::uint32_t same = (x ^ y ^ 1u) & 1u;
      mate[x >> 1] = (y & ~1u) | same;
      mate[y >> 1] = (x & ~1u) | same;
      ++o.pairs;
    } else {
      for (std::uint32_t k = i; k < j; ++k) {
        mate[std::uint32_t(s[k]) >> 1] = kUnpaired;
        o.corner.push_back(std::uint32_t(s[k]) >> 1);
      }
      o.start.push_back(std::uint32_t(o.corner.size()));
      (j - i == 1 ? o.boundary : o.non_manifold) += 1;
    }
    i = j;
  }
}

// Step 4, match the buckets of vertices [v0, v1): a bucket of up to 8 half-edges is first tried
// without sorting (engine/edge_buckets.h: each higher vertex compared with all 8 at once, SSE2;
// when every one equals exactly one other, the common all-manifold case, the pairs are written
// directly); any other goes to match_sorted_bucket.
void match_buckets(std::size_t v0, std::size_t v1, const std::uint32_t* end, const std::uint32_t* his,
                   const std::uint32_t* cds, std::uint32_t* mate, OddEdges& o) {
  for (std::size_t v = v0; v < v1; ++v) {
    const std::uint32_t b = v == 0 ? 0 : end[v - 1], n = end[v] - b;
    if (n == 0) continue;
    if (n <= 8 && engine::match_small_bucket(his + b, cds + b, n, mate)) {
      o.pairs += n / 2;
      continue;
    }
    match_sorted_bucket(o, his, cds, b, n, mate);
  }
}

// Step 5, join: the blocks' odd edges appended in block order (so the list is in increasing
// (lo, hi) order for any number of blocks), and the counts.
void join_odd_edges(const std::vector<OddEdges>& odd, EdgeAdjacency& adj) {
  std::size_t pairs = 0;
  for (const OddEdges& o : odd) {
    const std::uint32_t base = std::uint32_t(adj.odd_edge_corner.size());
    adj.odd_edge_corner.insert(adj.odd_edge_corner.end(), o.corner.begin(), o.corner.end());
    for (std::uint32_t x : o.start) adj.odd_edge_start.push_back(base + x);
    pairs += o.pairs;
    adj.boundary_edges += o.boundary;
    adj.non_manifold_edges += o.non_manifold;
  }
  adj.num_edges = pairs + adj.num_odd_edges();
}

}  // namespace

bool face_is_unwound(const Mesh& mesh, std::size_t f) {
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  return unwound(mesh.corner_vertex.data() + b, e - b);
}

EdgeAdjacency edge_adjacency(const Mesh& mesh, const EdgeAdjacencyOptions& options) {
  const std::size_t F = mesh.num_faces(), C = mesh.num_corners(), V = mesh.num_vertices();
  const std::vector<std::uint8_t>& skip = options.skip;
  if (!skip.empty() && skip.size() != F) fail("edge_adjacency", 0, "skip flags size differs from the face count");
  if (C >= (std::size_t(1) << 31) - 1) fail("edge_adjacency", 0, "2^31 - 1 corners or more");  // (m << 1) | s
  const bool triangles = mesh.all_triangles();
  const std::size_t threads = usable_threads();
  const FaceParts faces{mesh.corner_vertex.data(), mesh.face_start.data(), F, V, skip, options.skip_unwound_faces,
                        F >= kParallelFaces && threads >= 2 ? std::min<std::size_t>(threads, 4) : 1};
  const std::size_t parts = faces.parts;

  EdgeAdjacency adj;
  // Large fresh arrays: huge pages first (core/bulk_reserve.h); page faults are much of the cost.
  adj.corner_mate.resize(C);  // every entry is written below
  std::uint32_t* mate = adj.corner_mate.data();

  // 1. Count: range check; half-edges per lower vertex and part: cursor[p][v].
  std::vector<BulkVector<std::uint32_t>> cursor(parts);
  std::vector<std::uint8_t> out_of_range(parts, 0);
  faces.for_parts([&](std::size_t p) {
    const bool in_range = triangles ? count_part<true>(faces, p, cursor[p]) : count_part<false>(faces, p, cursor[p]);
    out_of_range[p] = !in_range;
  });
  for (std::uint8_t bad : out_of_range)
    if (bad) fail("edge_adjacency", 0, "a face refers to a vertex index beyond the vertex count");

  // 2. Prefix sum: the buckets' ends, and each part's cursor into them.
  BulkVector<std::uint32_t> bucket_end(V);
  std::uint32_t* end = bucket_end.data();
  std::uint32_t* cur[4];
  for (std::size_t p = 0; p < parts; ++p) cur[p] = cursor[p].data();
  const std::uint32_t H = bucket_offsets(cur, parts, V, end);

  // 3. Scatter the half-edges into their buckets. The higher vertices are an array of their own
  // (padded by 8) so that step 4 compares 8 of them at a time.
  BulkVector<std::uint32_t> slot_hi(H + 8), slot_corner(H);  // written in full below: not zeroed first
  std::fill(slot_hi.begin() + std::ptrdiff_t(H), slot_hi.end(), 0u);
  std::uint32_t* his = slot_hi.data();
  std::uint32_t* cds = slot_corner.data();
  faces.for_parts([&](std::size_t p) {
    if (triangles) scatter_part<true>(faces, p, cur[p], his, cds, mate);
    else scatter_part<false>(faces, p, cur[p], his, cds, mate);
  });
  cursor.clear();
  cursor.shrink_to_fit();

  // 4. Match: in each bucket, equal higher vertices form one edge; edges of valence 2 are paired,
  // the rest listed in increasing (lo, hi) order with their corners in increasing order. Blocks
  // of vertices on 2+ threads, each block with its own list.
  const std::size_t blocks = F >= kParallelFaces && threads >= 2 ? std::max<std::size_t>(1, std::min<std::size_t>(16, V / 4096)) : 1;
  std::vector<OddEdges> odd(blocks);
  auto match = [&](std::size_t blk) { match_buckets(V * blk / blocks, V * (blk + 1) / blocks, end, his, cds, mate, odd[blk]); };
  if (blocks == 1) match(0);
  else tbb::parallel_for(std::size_t(0), blocks, match);

  // 5. Join the blocks' lists in block order (the output is the same for any number of threads).
  join_odd_edges(odd, adj);
  return adj;
}

}  // namespace shadetool
