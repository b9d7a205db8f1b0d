// Tests of normals/accumulate_by_vertex.h: the chunked parallel scatter adds every row's terms in
// ascending corner order, exactly as the serial loop, for any thread count and face order.
#include <catch2/catch.hpp>

#include <tbb/task_arena.h>

#include "normals/accumulate_by_vertex.h"
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

TEST_CASE("accumulate_by_vertex: bitwise the serial order on 1 and 2 threads, ordered and shuffled faces", "[accumulate_by_vertex]") {
  AnalyticMesh quads, fan;
  quad_uv_sphere(300, 150, quads, fan);
  const Mesh meshes[] = {irregular(uv_sphere(300, 150, 0.15, 2)).mesh, quads.mesh, shuffle_faces(fan.mesh, 3)};
  for (const Mesh& m : meshes) {
    REQUIRE(m.num_faces() > 40000);  // above the serial threshold: the chunks are used
    const std::vector<double> expected = serial_sums(m);
    for (int threads : {1, 2}) {
      std::size_t count = 0;
      CHECK(chunked_sums(m, threads, count) == expected);
      CHECK(count == m.num_faces());  // contribute's counts summed over the chunks
    }
  }
}

TEST_CASE("accumulate_by_vertex: the order-sensitive term really is order-sensitive", "[accumulate_by_vertex]") {
  // Guard for the test above: adding the three terms of a row in another order changes the sum.
  const double a = term(0).x, b = term(1).x, c = term(2).x;
  CHECK(((a + b) + c) != ((a + c) + b));
}
