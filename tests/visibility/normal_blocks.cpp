// normal_blocks.cpp: vertex and face normals made block by block are the library's normals of the
// whole mesh, bit for bit (lib/shadetool/visibility/engine/vertex_normal_blocks.h, face_normal_blocks.h),
// whatever the block size, the face order, polygons, isolated vertices, degenerate faces or
// cancelling sums.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>

#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/engine/face_normal_blocks.h>
#include <shadetool/visibility/engine/vertex_normal_blocks.h>
#include "support/analytic_meshes.h"
#include "visibility_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// The rows of every block, gathered, must equal vertex_normals(mesh) bit for bit.
void require_blocks_equal_whole(const Mesh& m, unsigned block_log2) {
  const std::vector<double> whole = vertex_normals(m).normals;
  visibility_engine::VertexNormalBlocks blocks(m, block_log2);
  REQUIRE(blocks.blocks() == (m.num_vertices() + (std::size_t(1) << block_log2) - 1) >> block_log2);
  std::vector<double> gathered;
  VertexNormals rows;
  for (std::size_t k = 0; k < blocks.blocks(); ++k) {
    blocks.compute(k, rows);
    const std::size_t n = blocks.end(k) - blocks.begin(k);
    REQUIRE(rows.normals.size() >= 3 * n);
    gathered.insert(gathered.end(), rows.normals.begin(), rows.normals.begin() + 3 * n);
  }
  REQUIRE(gathered.size() == whole.size());
  REQUIRE(std::memcmp(gathered.data(), whole.data(), 8 * whole.size()) == 0);
}

// The rows of every face block, gathered, must equal face_normals(mesh) bit for bit.
void require_face_blocks_equal_whole(const Mesh& m, std::size_t block) {
  const std::vector<double> whole = face_normals(m);
  std::vector<double> gathered;
  std::vector<std::uint32_t> starts;
  for (std::size_t first = 0; first < m.num_faces(); first += block) {
    const std::vector<double> rows = visibility_engine::face_normal_block(m, first, std::min(m.num_faces(), first + block), starts);
    REQUIRE(rows.size() == 3 * (std::min(m.num_faces(), first + block) - first));
    gathered.insert(gathered.end(), rows.begin(), rows.end());
  }
  REQUIRE(gathered.size() == whole.size());
  REQUIRE(std::memcmp(gathered.data(), whole.data(), 8 * whole.size()) == 0);
}

// The same faces in a shuffled order (no locality: every block scans all faces).
Mesh shuffled_faces(const Mesh& m, std::uint32_t seed) {
  std::vector<std::size_t> order(m.num_faces());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  Mesh out;
  out.positions = m.positions;
  out.face_start.assign(1, 0);
  for (std::size_t f : order)
    out.add_face(std::vector<std::uint32_t>(m.corner_vertex.begin() + m.face_start[f],
                                            m.corner_vertex.begin() + m.face_start[f + 1]));
  return out;
}

}  // namespace

TEST_CASE("Vertex and face normals made block by block are the whole mesh's, bit for bit", "[visibility][normals]") {
  const Mesh torus_mesh = irregular(torus(40, 24, 1.0, 0.4, 0.2, 3)).mesh;
  for (unsigned log2 : {0u, 3u, 6u, 9u, 14u}) {
    INFO("block 2^" << log2);
    require_blocks_equal_whole(torus_mesh, log2);
    require_blocks_equal_whole(shuffled_faces(torus_mesh, 5 + log2), log2);
    require_face_blocks_equal_whole(torus_mesh, std::size_t(1) << log2);
  }
}

TEST_CASE("Blocks keep polygons, isolated vertices, degenerate faces and cancelling sums as the whole mesh does",
          "[visibility][normals]") {
  Mesh m = plane_grid(1.0, 12, true);  // quads
  add_polygon(m, disc_polygon(0.7, 0.5, 9));
  m.add_vertex({3, 3, 3});  // isolated: the fallback (0, 0, 1)
  const std::uint32_t a = m.add_vertex({0, 0, 2}), b = m.add_vertex({1, 0, 2}), c = m.add_vertex({0, 1, 2});
  m.add_face({a, b, c});
  m.add_face({a, c, b});  // two-sided sheet: sums cancel, the first valid face's normal
  const std::uint32_t d = m.add_vertex({2, 0, 2}), e = m.add_vertex({4, 0, 2});
  m.add_face({a, d, e});  // collinear: degenerate, contributes nothing
  m.add_face({d, d, e});  // repeated index
  for (unsigned log2 : {0u, 1u, 2u, 5u, 8u}) {
    INFO("block 2^" << log2);
    require_blocks_equal_whole(m, log2);
    require_blocks_equal_whole(shuffled_faces(m, 11 + log2), log2);
    require_face_blocks_equal_whole(m, std::size_t(1) << log2);
    require_face_blocks_equal_whole(shuffled_faces(m, 11 + log2), std::size_t(1) << log2);
  }
}

TEST_CASE("Blocks of a mesh at 1e-15, 1e-3, 1e8 and 1e15 give the whole mesh's normals (the outer two are "
          "scaled into the kernels' range, per block)", "[visibility][normals]") {
  for (double s : {1e-15, 1e-3, 1e8, 1e15}) {
    INFO("scale " << s);
    Mesh m = torus(24, 12, 1.0, 0.4, 0.1, 9).mesh;
    for (double& x : m.positions) x = x * s + (s > 1 ? s : 0);
    require_blocks_equal_whole(m, 5);
    require_face_blocks_equal_whole(m, 32);
  }
}
