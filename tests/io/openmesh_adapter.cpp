// Tests of io/openmesh_adapter.h: a mesh with polygons and every attribute survives the trip to
// OpenMesh and back; what OpenMesh cannot hold is counted, not silently lost.
#include <shadetool/io/openmesh_adapter.h>  // includes OpenMesh's PolyMesh and TriMesh
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {
using Poly = OpenMesh::PolyMesh_ArrayKernelT<>;
using Tri = OpenMesh::TriMesh_ArrayKernelT<>;

// Face f of `b` is face f of `a` with its corners rotated by some k (OpenMesh starts a face at
// its own halfedge); returns that k, or -1 when the faces differ.
int rotation(const Mesh& a, const Mesh& b, std::size_t f) {
  const std::size_t n = a.face_size(f);
  if (b.face_size(f) != n) return -1;
  for (std::size_t k = 0; k < n; ++k) {
    bool same = true;
    for (std::size_t i = 0; i < n; ++i)
      same = same && a.corner_vertex[a.face_start[f] + i] == b.corner_vertex[b.face_start[f] + (i + k) % n];
    if (same) return int(k);
  }
  return -1;
}
}  // namespace

TEST_CASE("OpenMesh adapter: polygons, corner normals, texcoords, colours and back", "[openmesh]") {
  Mesh m = rich_mesh();
  m.face_normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::size_t skipped = 99;
  const Poly om = to_openmesh<Poly>(m, &skipped);
  CHECK(skipped == 0);
  CHECK(om.n_vertices() == m.num_vertices());
  CHECK(om.n_faces() == m.num_faces());
  const Mesh back = from_openmesh(om);
  CHECK(back.precision == ValuePrecision::Float);
  CHECK(back.positions == m.positions);  // rich_mesh holds float values: exact
  CHECK(back.vertex_colors == m.vertex_colors);
  CHECK(back.face_colors == m.face_colors);
  CHECK(back.face_normals == m.face_normals);
  REQUIRE(back.face_start == m.face_start);
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const int k = rotation(m, back, f);
    REQUIRE(k >= 0);
    const std::size_t n = m.face_size(f);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t ca = m.face_start[f] + i, cb = back.face_start[f] + (i + std::size_t(k)) % n;
      CHECK(get3(back.corner_normals, back.corner_normal_index[cb]) == get3(m.corner_normals, m.corner_normal_index[ca]));
      for (int d = 0; d < 2; ++d)
        CHECK(back.texcoords[2 * back.corner_texcoord_index[cb] + std::size_t(d)] ==
              m.texcoords[2 * m.corner_texcoord_index[ca] + std::size_t(d)]);
    }
  }
}

TEST_CASE("OpenMesh adapter: a TriMesh triangulates polygons (3 + 2 + 3 triangles)", "[openmesh]") {
  const Tri om = to_openmesh<Tri>(rich_mesh());
  CHECK(om.n_faces() == 1 + 2 + 3);
  CHECK(from_openmesh(om).all_triangles());
}

TEST_CASE("OpenMesh adapter: what OpenMesh refuses is counted", "[openmesh]") {
  const Mesh m = read_mesh(data_path("non_manifold.obj"));
  std::size_t skipped = 0;
  const Poly om = to_openmesh<Poly>(m, &skipped);
  // The third triangle on the fin edge and the duplicated triangle cannot be added (their
  // halfedges are taken); the bow-tie is a non-manifold vertex OpenMesh can hold.
  CHECK(skipped == 2);
  CHECK(om.n_faces() == m.num_faces() - 2);
  CHECK(om.n_vertices() == m.num_vertices());  // the isolated vertex is kept
}
