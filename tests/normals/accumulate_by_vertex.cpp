// Tests of normals/engine/accumulate_by_vertex.h: the chunked parallel scatter adds every row's terms in
// ascending corner order, exactly as the serial loop, for any thread count and face order.
#include <catch2/catch.hpp>

#include <set>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <shadetool/normals/engine/accumulate_by_vertex.h>
#include "normals_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;
using namespace shadetool::normals_detail;

namespace {

// A contribution whose floating-point sum depends on the order of addition: 1e16 and 1 and -1e16
// cancel differently in different orders.
Vec3d term(std::size_t corner) {
  const double big = (corner % 3 == 0) ? 1e16 : (corner % 3 == 1 ? 1.0 : -1e16);
  return {big, double(corner) * 1e-3, 1.0 / double(corner + 1)};
}

std::vector<double> serial_sums(const Mesh& m) {
  std::vector<double> s(3 * m.num_vertices(), 0.0);
  for (std::size_t c = 0; c < m.num_corners(); ++c) {
    const Vec3d t = term(c);
    double* o = &s[3 * std::size_t(m.corner_vertex[c])];
    o[0] += t.x; o[1] += t.y; o[2] += t.z;
  }
  return s;
}

std::vector<double> chunked_sums(const Mesh& m, int threads, std::size_t& count) {
  std::vector<double> s(3 * m.num_vertices(), 0.0);
  tbb::task_arena(threads).execute([&] {
    count = accumulate_by_vertex<double>(m, [&](std::size_t f_begin, std::size_t f_end, auto&& sink) {
      for (std::size_t f = f_begin; f < f_end; ++f)
        for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) sink(c, m.corner_vertex[c], term(c));
      return f_end - f_begin;
    }, s.data());
  });
  return s;
}

}  // namespace

TEST_CASE("accumulate_by_vertex: bitwise the serial order on 1, 2, 3 and 10 threads, ordered and shuffled faces", "[accumulate_by_vertex]") {
  // Up to 8 chunks find their shared rows by bitmaps, more by owner ids: 10 threads (allowed
  // above the core count here) take the second way.
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 16);
  AnalyticMesh quads, fan;
  quad_uv_sphere(300, 150, quads, fan);
  const Mesh meshes[] = {irregular(uv_sphere(300, 150, 0.15, 2)).mesh, quads.mesh, shuffle_faces(fan.mesh, 3)};
  for (const Mesh& m : meshes) {
    REQUIRE(m.num_faces() > 40000);  // above the serial threshold: the chunks are used
    const std::vector<double> expected = serial_sums(m);
    for (int threads : {1, 2, 3, 10}) {
      std::size_t count = 0;
      CHECK(chunked_sums(m, threads, count) == expected);
      CHECK(count == m.num_faces());  // contribute's counts summed over the chunks
    }
  }
}

TEST_CASE("plan_chunks: one chunk per thread on ordered faces, exactly the rows of two or more chunks shared", "[accumulate_by_vertex]") {
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 16);
  const Mesh m = irregular(uv_sphere(300, 150, 0.15, 2)).mesh;
  for (int threads : {2, 3, 10}) {
    const ChunkPlan plan = tbb::task_arena(threads).execute([&] { return plan_chunks<false>(m, nullptr, m.num_vertices()); });
    REQUIRE(plan.K == std::size_t(threads));
    // Reference: the chunks touching each vertex, from the chunk bounds plan_chunks uses.
    const std::size_t F = m.num_faces(), K = plan.K;
    std::vector<std::set<std::size_t>> chunks(m.num_vertices());
    for (std::size_t k = 0; k < K; ++k)
      for (std::size_t f = F * k / K; f < F * (k + 1) / K; ++f)
        for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) chunks[m.corner_vertex[c]].insert(k);
    std::size_t shared = 0;
    for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
      CHECK(plan.is_shared(v) == (chunks[v].size() >= 2));
      shared += plan.is_shared(v);
    }
    CHECK(shared >= std::size_t(threads - 1) * 300);  // at least one ring of the 300 x 150 sphere per border
  }
}

TEST_CASE("accumulate_by_vertex: the order-sensitive term really is order-sensitive", "[accumulate_by_vertex]") {
  // Guard for the test above: adding the three terms of a row in another order changes the sum.
  const double a = term(0).x, b = term(1).x, c = term(2).x;
  CHECK(((a + b) + c) != ((a + c) + b));
}
