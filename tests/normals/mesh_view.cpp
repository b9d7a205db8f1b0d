// Tests of core/mesh_view.h through the normals entry points: a MeshView over arrays that are not
// a Mesh's (as the Python module hands over NumPy memory) gives the same bits as the Mesh holding
// the same values, under every weighting, precision, thread split and scale, and leaves the
// arrays untouched; and it is right on its own, against analytic sphere normals.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include <tbb/task_arena.h>

#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include "normals_test_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

const Weighting kAll[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
const Precision kPrecisions[] = {Precision::Double, Precision::Float};

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A mesh's arrays held outside any Mesh (as a caller's own buffers are): positions (V, 3),
// corners, and face starts for polygons.
struct ExternalArrays {
  std::vector<double> positions;
  std::vector<std::uint32_t> corners, face_start;

  explicit ExternalArrays(const Mesh& m)
      : positions(m.positions), corners(m.corner_vertex), face_start(m.face_start) {}
  MeshView triangles() const {
    return MeshView::triangles(positions.data(), positions.size() / 3, corners.data(), corners.size() / 3);
  }
  MeshView polygons() const {
    return MeshView::polygons(positions.data(), positions.size() / 3, corners.data(), face_start.data(),
                              face_start.size() - 1);
  }
};

// Every normals result of `view` equals the Mesh's bit for bit (vertex normals with and without a
// plan, face normals, corner normals at a crease and without one).
void check_view_equals_mesh(const Mesh& mesh, const MeshView& view) {
  for (Precision p : kPrecisions) {
    INFO("precision " << (p == Precision::Double ? "double" : "float"));
    CHECK(same_bits(face_normals(view, p), face_normals(mesh, p)));
    for (Weighting w : kAll) {
      INFO("weighting " << int(w));
      const VertexNormals a = vertex_normals(view, w, p), b = vertex_normals(mesh, w, p);
      CHECK(same_bits(a.normals, b.normals));
      CHECK(a.fallback_vertices == b.fallback_vertices);
      CHECK(a.degenerate_faces == b.degenerate_faces);
      VertexNormals planned;
      vertex_normals(view, VertexNormalsPlan(view), w, p, planned);
      CHECK(same_bits(planned.normals, b.normals));
      for (double crease : {0.5, 4.0}) {
        const CornerNormals c = corner_normals(view, crease, w, p), d = corner_normals(mesh, crease, w, p);
        CHECK(same_bits(c.normals, d.normals));
        CHECK(c.corner_index == d.corner_index);
        CHECK(c.fallback_corners == d.fallback_corners);
      }
    }
  }
}

}  // namespace

TEST_CASE("A triangle view of external arrays gives the Mesh's normals bit for bit, on 1 and 2 threads",
          "[mesh_view]") {
  // 2 x 128 x 130 = 33280 faces: above the parallel threshold (kSerialBelow), so the chunked sums
  // run over the view's implicit face starts (corner 3 f).
  const AnalyticMesh am = irregular(uv_sphere(128, 130, 0.3));
  REQUIRE(am.mesh.all_triangles());
  const ExternalArrays arrays(am.mesh);
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    tbb::task_arena(threads).execute([&] { check_view_equals_mesh(am.mesh, arrays.triangles()); });
  }
}

TEST_CASE("A polygon view (quads, a fan of triangles and a degenerate face) gives the Mesh's normals bit for bit",
          "[mesh_view]") {
  AnalyticMesh quads, fan;
  quad_uv_sphere(24, 12, quads, fan);
  Mesh m = quads.mesh;
  m.add_face({0u, 0u, 1u});  // repeated index: no area, contributes nothing
  const ExternalArrays arrays(m);
  check_view_equals_mesh(m, arrays.polygons());
}

TEST_CASE("A view of a mesh outside the kernels' range (scaled by 2^600 and 2^-600) gives the Mesh's bits and "
          "leaves the arrays untouched", "[mesh_view]") {
  for (int e : {600, -600}) {
    Mesh m = uv_sphere(40, 20, 0.2).mesh;
    for (double& x : m.positions) x = std::ldexp(x, e);
    const ExternalArrays arrays(m);
    const ExternalArrays before = arrays;
    check_view_equals_mesh(m, arrays.triangles());
    // The scaled copy is the kernels' own: the caller's positions are read, never written.
    CHECK(std::memcmp(arrays.positions.data(), before.positions.data(), arrays.positions.size() * sizeof(double)) == 0);
    CHECK(arrays.corners == before.corners);
  }
}

TEST_CASE("Max-weighted normals from a triangle view are exact on a sphere (analytic truth, not the Mesh path)",
          "[mesh_view]") {
  // Max 1999: exact when a vertex's neighbours lie on a sphere through it.
  const AnalyticMesh am = uv_sphere(64, 32, 0.3);
  const ExternalArrays arrays(am.mesh);
  const VertexNormals vn = vertex_normals(arrays.triangles(), Weighting::Max);
  CHECK(angular_error(vn.normals, am.exact_normals).max_deg < 1e-6);  // as vertex_normals.cpp asserts for the Mesh
  CHECK(vn.fallback_vertices == 0);
}
