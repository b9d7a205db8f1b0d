// edge_adjacency.cpp: half-edges paired by a counting sort on their lower vertex (see the header).
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

// Whether a face of n corners has fewer than 3 corners or repeats a vertex index (the rule of
// core/repeated_index.h; triangles, the bulk, inline).
bool unwound(const std::uint32_t* v, std::uint32_t n) {
  if (n < 3) return true;
  if (n == 3) return v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
  std::vector<std::uint32_t> scratch;  // allocates only beyond 16 corners
  return has_repeated_index(v, n, scratch);
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
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const std::uint32_t* fs = mesh.face_start.data();
  const bool triangles = mesh.all_triangles();
  constexpr std::uint32_t kUnpaired = EdgeAdjacency::kUnpaired;

  EdgeAdjacency adj;
  // Large fresh arrays: huge pages first (core/bulk_reserve.h); page faults are much of the cost.
  adj.corner_mate.resize(C);  // every entry is written below
  std::uint32_t* mate = adj.corner_mate.data();

  // Whether face f contributes half-edges.
  auto takes_part = [&](std::size_t f, std::uint32_t b, std::uint32_t e) {
    if (!skip.empty() && skip[f]) return false;
    if (!options.skip_unwound_faces) return true;
    return !unwound(cv + b, e - b);
  };

  // Parts of the faces counted and scattered in parallel, each with its own cursor per vertex:
  // within a bucket, part p's half-edges follow part p-1's, each part's in corner order, so the
  // buckets (and everything after) are the same for any number of parts. One part below
  // kParallelFaces faces or on one thread.
  const std::size_t threads = usable_threads();
  const std::size_t parts = F >= kParallelFaces && threads >= 2 ? std::min<std::size_t>(threads, 4) : 1;
  auto part_faces = [&](std::size_t p) { return std::pair<std::size_t, std::size_t>{F * p / parts, F * (p + 1) / parts}; };
  auto for_parts = [&](auto&& body) {
    if (parts == 1) body(std::size_t(0));
    else tbb::parallel_for(std::size_t(0), parts, body);
  };

  // Pass 1: range check; half-edges per lower vertex and part: cursor[p][v].
  std::vector<BulkVector<std::uint32_t>> cursor(parts);
  std::vector<std::uint8_t> out_of_range(parts, 0);
  // (Both face passes are compiled twice: for a triangle mesh the corner loops have a constant
  // trip count of 3 and unroll.)
  auto count_pass = [&](auto all_triangles, std::size_t p) {
    constexpr bool kTriangles = decltype(all_triangles)::value;
    BulkVector<std::uint32_t>& count = cursor[p];
    count.assign(V, 0);
    std::uint32_t* n = count.data();
    const auto [f0, f1] = part_faces(p);
    for (std::size_t f = f0; f < f1; ++f) {
      const std::uint32_t b = kTriangles ? std::uint32_t(3 * f) : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
      std::uint32_t highest = 0;
      for (std::uint32_t c = b; c < e; ++c) highest = std::max(highest, cv[c]);
      if (highest >= V && e > b) {
        out_of_range[p] = 1;
        return;
      }
      if (!takes_part(f, b, e)) continue;
      for (std::uint32_t c = b; c < e; ++c) {
        const std::uint32_t t = cv[c], h = cv[c + 1 < e ? c + 1 : b];
        if (t != h) ++n[std::min(t, h)];
      }
    }
  };
  for_parts([&](std::size_t p) {
    if (triangles) count_pass(std::true_type{}, p);
    else count_pass(std::false_type{}, p);
  });
  for (std::uint8_t bad : out_of_range)
    if (bad) fail("edge_adjacency", 0, "a face refers to a vertex index beyond the vertex count");
  // Prefix sum: bucket v is [end[v-1], end[v]); part p's cursor starts after parts < p.
  BulkVector<std::uint32_t> bucket_end(V);
  std::uint32_t* end = bucket_end.data();
  std::uint32_t* cur[4];
  for (std::size_t p = 0; p < parts; ++p) cur[p] = cursor[p].data();
  std::uint32_t H = 0;  // < 2^31 (corners)
  for (std::size_t v = 0; v < V; ++v) {
    for (std::size_t p = 0; p < parts; ++p) {
      const std::uint32_t n = cur[p][v];
      cur[p][v] = H;
      H += n;
    }
    end[v] = H;
  }

  // Pass 2: scatter each half-edge's higher vertex and (corner << 1 | tail is the lower vertex)
  // in corner order; corners that are no half-edge get kUnpaired now. The higher vertices are an
  // array of their own (padded by 8) so that pass 3 compares 8 of them at a time.
  BulkVector<std::uint32_t> slot_hi(H + 8), slot_corner(H);  // written in full below: not zeroed first
  std::fill(slot_hi.begin() + std::ptrdiff_t(H), slot_hi.end(), 0u);
  std::uint32_t* his = slot_hi.data();
  std::uint32_t* cds = slot_corner.data();
  auto scatter_pass = [&](auto all_triangles, std::size_t p) {
    constexpr bool kTriangles = decltype(all_triangles)::value;
    std::uint32_t* at = cur[p];
    const auto [f0, f1] = part_faces(p);
    for (std::size_t f = f0; f < f1; ++f) {
      const std::uint32_t b = kTriangles ? std::uint32_t(3 * f) : fs[f], e = kTriangles ? b + 3 : fs[f + 1];
      if (!takes_part(f, b, e)) {
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
  };
  for_parts([&](std::size_t p) {
    if (triangles) scatter_pass(std::true_type{}, p);
    else scatter_pass(std::false_type{}, p);
  });
  cursor.clear();
  cursor.shrink_to_fit();

  // Pass 3: in each bucket, equal higher vertices form one edge; edges of valence 2 are paired,
  // the rest listed in increasing (lo, hi) order with their corners in increasing order. A bucket
  // of up to 8 half-edges is first tried without sorting: each higher vertex is compared with all
  // 8 at once (SSE2); when every one of them equals exactly one other (all edges manifold, the
  // common case) the pairs are written directly. Otherwise the bucket is sorted by (higher vertex,
  // corner) (insertion sort; std::sort beyond 32) and scanned. Blocks of vertices on 2+ threads
  // (each block with its own list, joined in block order, so the output is the same for any
  // number of threads).
  struct Odd {
    std::vector<std::uint32_t> start, corner;
    std::vector<std::uint64_t> keys;  // a bucket being sorted
    std::size_t pairs = 0, boundary = 0, non_manifold = 0;
  };
  const std::size_t blocks = F >= kParallelFaces && threads >= 2 ? std::max<std::size_t>(1, std::min<std::size_t>(16, V / 4096)) : 1;
  std::vector<Odd> odd(blocks);
  auto match_sorted = [&](Odd& o, std::uint32_t b, std::uint32_t n) {
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
  };
  auto match = [&](std::size_t blk) {
    Odd& o = odd[blk];
    for (std::size_t v = V * blk / blocks; v < V * (blk + 1) / blocks; ++v) {
      const std::uint32_t b = v == 0 ? 0 : end[v - 1], n = end[v] - b;
      if (n == 0) continue;
      if (n <= 8 && engine::match_small_bucket(his + b, cds + b, n, mate)) {
        o.pairs += n / 2;
        continue;
      }
      match_sorted(o, b, n);
    }
  };
  if (blocks == 1) match(0);
  else tbb::parallel_for(std::size_t(0), blocks, match);
  std::size_t pairs = 0;
  for (const Odd& o : odd) {
    const std::uint32_t base = std::uint32_t(adj.odd_edge_corner.size());
    adj.odd_edge_corner.insert(adj.odd_edge_corner.end(), o.corner.begin(), o.corner.end());
    for (std::uint32_t x : o.start) adj.odd_edge_start.push_back(base + x);
    pairs += o.pairs;
    adj.boundary_edges += o.boundary;
    adj.non_manifold_edges += o.non_manifold;
  }
  adj.num_edges = pairs + adj.num_odd_edges();
  return adj;
}

}  // namespace shadetool
