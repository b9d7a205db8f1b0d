// accumulate_by_vertex.h: sums per-corner vectors into per-vertex sums, in parallel, with a
// result that is bitwise the same as the serial loop whatever the number of threads
// (internal to lib/normals; a template so that each kernel's contribution code is inlined).
//
// Inputs:  mesh        faces (corner_vertex, face_start; a view, core/mesh_view.h)
//          contribute  contribute(f_begin, f_end, sink) calls sink(corner, vertex, Vec3<T>) for the
//                      corners of faces [f_begin, f_end) in corner order and returns a count
//                      (of degenerate faces skipped), summed over all faces and returned
// Output:  sum         #V by 3 (T) array, zero on entry; sum[v] = contributions of v's corners added in
//                      ascending corner order, exactly as the serial loop would add them.
//
// Method (why the result does not depend on the thread count): faces are cut into K contiguous
// chunks. Passes 1-2 find the rows `shared` by two or more chunks: with K <= 8 each chunk marks
// the rows of its corners in a bitmap of its own (#rows / 8 bytes, small enough to stay in cache)
// and a row is shared when two bitmaps have its bit; with more chunks, pass 1 writes each
// corner's chunk id into owner[row] (relaxed stores; the last writer wins) and pass 2 marks a row
// shared when some chunk touching it finds another chunk's id there. Either way shared[v] is set
// exactly when v's corners lie in two or more chunks. Pass 3 runs the chunks in parallel: a
// corner of an unshared row is added to sum[v] directly (only its own chunk writes there, in
// corner order); a corner of a shared row is appended to its chunk's side list. Pass 4 adds the
// side lists chunk by chunk, in order, on one thread, so shared rows too receive their terms in
// ascending corner order.
// Faces stored with locality (every mesh file we have seen) share only the vertices along chunk
// borders, so pass 4 is tiny. A reused plan (VertexNormalsPlan) also lists each chunk's border
// faces (flag_border_faces), so that pass 3 tests rows only there and runs every other face
// through the same plain sink as the serial loop. When the faces are in random order (more than
// a quarter of the corners, or with bitmaps an eighth of the rows, would go to side lists) the
// chunks are abandoned and the serial loop runs instead.
// Small meshes (< kSerialBelow faces) and one-thread runs take the serial loop directly.
// Memory: K / 8 bytes per row (K <= 8; else 3 bytes) plus the side lists. plan_chunks (passes
// 1, 2) and accumulate_by_target (passes 3, 4) are separate so callers can overlap the plan with
// allocating the sums.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <shadetool/core/mesh_view.h>
#include <shadetool/core/engine/usable_threads.h>
#include <shadetool/core/vec3.h>
#include <shadetool/geometry/face_area_vector.h>  // SHADETOOL_INLINE
#include <shadetool/core/engine/parallel.h>

namespace shadetool::normals_detail {

using engine::kSerialBelow;
using engine::parallel_blocks;
using engine::parallel_ranges;

// The chunks and the shared rows (passes 1 and 2), computed before the sums so that a caller can
// overlap them with allocating and zeroing `sum` (tbb::parallel_invoke). K == 0: serial loop.
struct ChunkPlan {
  std::size_t K = 0;
  std::vector<std::uint64_t> shared;  // bitmap: bit (v & 63) of word v >> 6 set when row v is shared
  // Optional (flag_border_faces): per chunk, ascending, the faces with a corner in a shared row.
  // With them, pass 3 runs every other face through the serial loop's plain sink (no per-corner
  // test); only these faces take the testing sink.
  std::vector<std::vector<std::uint32_t>> border_faces;

  bool is_shared(std::uint32_t v) const { return (shared[v >> 6] >> (v & 63)) & 1u; }
};

// Rows are target[c] (Target = true; corner normals use it with target = the corner's smooth
// group) or the corner's vertex (Target = false, target unused).
template <bool Target>
ChunkPlan plan_chunks(const MeshView& mesh, const std::uint32_t* target, std::size_t num_rows) {
  ChunkPlan plan;
  const std::size_t F = mesh.num_faces(), V = num_rows;
  const std::size_t threads = usable_threads();
  // One chunk per thread: every chunk border costs (its vertices' terms go through side lists), so
  // more chunks than threads measured slower (bench/normals/results/notes.md). The price: no load
  // balancing when another process holds one core.
  const std::size_t K = std::min<std::size_t>({F / 8192, threads, 65535});
  if (F < kSerialBelow || threads < 2 || K < 2) return plan;
  auto chunk_begin = [&](std::size_t k) { return std::size_t(mesh.face_begin(F * k / K)); };  // corner index
  const std::uint32_t* cv = Target ? target : mesh.corner_vertex;
  const std::size_t words = (V + 63) / 64;
  plan.shared.assign(words, 0);
  std::uint64_t* shared = plan.shared.data();

  if (K <= 8) {
    // Passes 1-2 by bitmaps: chunk k marks its rows in bits[k]; shared = set in two or more.
    std::vector<std::vector<std::uint64_t>> bits(K);
    tbb::parallel_for(std::size_t(0), K, [&](std::size_t k) {
      bits[k].assign(words, 0);
      std::uint64_t* b = bits[k].data();
      for (std::size_t c = chunk_begin(k), e = chunk_begin(k + 1); c < e; ++c) {
        const std::uint32_t v = cv[c];
        b[v >> 6] |= std::uint64_t(1) << (v & 63);
      }
    });
    std::size_t shared_rows = 0;
    for (std::size_t w = 0; w < words; ++w) {
      std::uint64_t once = 0, twice = 0;
      for (std::size_t k = 0; k < K; ++k) {
        twice |= once & bits[k][w];
        once |= bits[k][w];
      }
      shared[w] = twice;
      shared_rows += std::size_t(__builtin_popcountll(twice));
    }
    if (shared_rows > V / 8) {  // faces in random order: side lists would be huge
      plan.shared.clear();
      return plan;
    }
    plan.K = K;
    return plan;
  }

  // Pass 1: last chunk to touch each row.
  std::unique_ptr<std::atomic<std::uint16_t>[]> owner(new std::atomic<std::uint16_t>[V]());
  tbb::parallel_for(std::size_t(0), K, [&](std::size_t k) {
    const auto id = std::uint16_t(k);
    for (std::size_t c = chunk_begin(k), e = chunk_begin(k + 1); c < e; ++c)
      owner[cv[c]].store(id, std::memory_order_relaxed);
  });
  // Pass 2: rows touched by more than one chunk (bytes, packed into the bitmap afterwards).
  std::unique_ptr<std::atomic<std::uint8_t>[]> shared_byte(new std::atomic<std::uint8_t>[V]());
  std::vector<std::size_t> foreign(K, 0);
  tbb::parallel_for(std::size_t(0), K, [&](std::size_t k) {
    const auto id = std::uint16_t(k);
    std::size_t n = 0;
    for (std::size_t c = chunk_begin(k), e = chunk_begin(k + 1); c < e; ++c) {
      const std::uint32_t v = cv[c];
      if (owner[v].load(std::memory_order_relaxed) != id) {
        shared_byte[v].store(1, std::memory_order_relaxed);
        ++n;
      }
    }
    foreign[k] = n;
  });
  std::size_t foreign_corners = 0;
  for (auto n : foreign) foreign_corners += n;
  if (foreign_corners > mesh.num_corners() / 4) {  // faces in random order: side lists would be huge
    plan.shared.clear();
    return plan;
  }
  for (std::size_t v = 0; v < V; ++v)
    shared[v >> 6] |= std::uint64_t(shared_byte[v].load(std::memory_order_relaxed)) << (v & 63);
  plan.K = K;
  return plan;
}

// Fills plan.border_faces (a third pass over the corners; worth it for a plan that is reused).
template <bool Target>
void flag_border_faces(const MeshView& mesh, const std::uint32_t* target, ChunkPlan& plan) {
  const std::size_t F = mesh.num_faces(), K = plan.K;
  if (K == 0) return;
  const std::uint32_t* cv = Target ? target : mesh.corner_vertex;
  plan.border_faces.assign(K, {});
  tbb::parallel_for(std::size_t(0), K, [&](std::size_t k) {
    auto& list = plan.border_faces[k];
    for (std::size_t f = F * k / K, e = F * (k + 1) / K; f < e; ++f) {
      bool border = false;
      for (std::uint32_t c = mesh.face_begin(f), c_end = mesh.face_end(f); c < c_end; ++c)
        border = border || plan.is_shared(cv[c]);
      if (border) list.push_back(std::uint32_t(f));
    }
  });
}

// sum[row] += n for a row of Stride values (3, or 4 for float sums padded to 16 bytes: then one
// SSE addition of x, y, z, 0; the padding stays 0).
template <class T, std::size_t Stride>
SHADETOOL_INLINE void add_to_row(T* o, const Vec3<T>& n) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, float> && Stride == 4) {
    _mm_storeu_ps(o, _mm_add_ps(_mm_loadu_ps(o), _mm_setr_ps(n.x, n.y, n.z, 0.0f)));
    return;
  }
#endif
  o[0] += n.x; o[1] += n.y; o[2] += n.z;
}

// Passes 3 and 4 (sum: #rows by Stride, zero on entry; x, y, z first). Returns the sum of
// contribute's counts.
template <bool Target, class T, std::size_t Stride = 3, class Contribute>
std::size_t accumulate_by_target(const MeshView& mesh, const ChunkPlan& plan, const std::uint32_t* target,
                                 const Contribute& contribute, T* sum) {
  const std::size_t F = mesh.num_faces(), K = plan.K;
  T* s = sum;
  auto row = [target](std::size_t c, std::uint32_t v) -> std::uint32_t {
    if constexpr (Target) return target[c];
    else return v;
  };
  if (K == 0)
    return contribute(std::size_t(0), F, [s, row](std::size_t c, std::uint32_t v, const Vec3<T>& n) {
      add_to_row<T, Stride>(s + Stride * std::size_t(row(c, v)), n);
    });
  // Pass 3: chunks in parallel; shared rows' terms go to side lists, in corner order.
  struct Term { std::uint32_t v; T x, y, z; };
  std::vector<std::vector<Term>> side(K);
  std::vector<std::size_t> counts(K, 0);
  auto direct = [s, row](std::size_t c, std::uint32_t v, const Vec3<T>& n) {
    add_to_row<T, Stride>(s + Stride * std::size_t(row(c, v)), n);
  };
  tbb::parallel_for(std::size_t(0), K, [&](std::size_t k) {
    auto& list = side[k];
    auto testing = [&](std::size_t c, std::uint32_t vertex, const Vec3<T>& n) {
      const std::uint32_t v = row(c, vertex);
      if (plan.is_shared(v)) {
        list.push_back({v, n.x, n.y, n.z});
      } else {
        add_to_row<T, Stride>(s + Stride * std::size_t(v), n);
      }
    };
    const std::size_t f_begin = F * k / K, f_end = F * (k + 1) / K;
    if (plan.border_faces.empty()) {
      counts[k] = contribute(f_begin, f_end, testing);
    } else {
      // Faces in order: runs without a shared row through the plain sink, border faces through
      // the testing one (the order of every row's terms is the same as above).
      // Consecutive border faces (they cluster at the chunk's two ends) go as one run.
      const std::vector<std::uint32_t>& border = plan.border_faces[k];
      std::size_t n = 0, f = f_begin;
      for (std::size_t i = 0; i < border.size();) {
        std::size_t j = i + 1;
        while (j < border.size() && border[j] == border[j - 1] + 1) ++j;
        const std::size_t run_begin = border[i], run_end = std::size_t(border[j - 1]) + 1;
        if (run_begin > f) n += contribute(f, run_begin, direct);
        n += contribute(run_begin, run_end, testing);
        f = run_end;
        i = j;
      }
      if (f < f_end) n += contribute(f, f_end, direct);
      counts[k] = n;
    }
  });
  // Pass 4: shared rows, chunk by chunk in order.
  for (const auto& list : side)
    for (const Term& t : list) {
      add_to_row<T, Stride>(s + Stride * std::size_t(t.v), Vec3<T>{t.x, t.y, t.z});
    }
  std::size_t count = 0;
  for (auto n : counts) count += n;
  return count;
}

// Convenience: plan and sum into rows = vertices.
template <class T, class Contribute>
std::size_t accumulate_by_vertex(const MeshView& mesh, const Contribute& contribute, T* sum) {
  const ChunkPlan plan = plan_chunks<false>(mesh, nullptr, mesh.num_vertices());
  return accumulate_by_target<false>(mesh, plan, nullptr, contribute, sum);
}

}  // namespace shadetool::normals_detail
