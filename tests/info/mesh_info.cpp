// Tests of info/mesh_info on the sample meshes in data/, whose contents are known by
// construction (data/generate/make_data.cpp), and on hand-made defects.
#include <cmath>

#include <catch2/catch.hpp>

#include <shadetool/info/mesh_info.h>
#include <shadetool/files/mesh_files.h>
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::info;

namespace {
Mesh sample(const std::string& name) { return read_mesh(std::string(SHADETOOL_SOURCE_DIR) + "/data/" + name); }
}  // namespace

TEST_CASE("info: the cube", "[mesh_info]") {
  const MeshInfo m = mesh_info(sample("cube.obj"));
  CHECK(m.vertices == 8);
  CHECK(m.faces == 12);
  CHECK(m.corners == 36);
  CHECK(m.triangles == 12);
  CHECK(m.faces_by_size == std::vector<std::pair<std::size_t, std::size_t>>{{3, 12}});
  REQUIRE(m.has_bbox);
  CHECK(m.bbox_min == Vec3d{-1, -1, -1});
  CHECK(m.bbox_max == Vec3d{1, 1, 1});
  CHECK(m.topology.edges == 18);  // 12 cube edges + 6 diagonals
  CHECK(m.closed_manifold());
  CHECK(m.components == 1);
  CHECK(!m.vertex_normals);
  CHECK(!m.double_precision);
}

TEST_CASE("info: the dodecahedron: 12 pentagons, bbox [-phi, phi]^3, face colours", "[mesh_info]") {
  const MeshInfo m = mesh_info(sample("dodecahedron.off"));
  const double phi = (1 + std::sqrt(5.0)) / 2;
  CHECK(m.faces_by_size == std::vector<std::pair<std::size_t, std::size_t>>{{5, 12}});
  CHECK(m.polygons == 12);
  CHECK(m.topology.edges == 30);
  CHECK(m.bbox_max.x == Approx(phi).epsilon(1e-15));
  CHECK(m.bbox_min.z == Approx(-phi).epsilon(1e-15));
  CHECK(m.face_colors);
  CHECK(m.color_channels == 3);
  CHECK(m.closed_manifold());
}

TEST_CASE("info: the quad sphere and the torus are closed and have Euler characteristic 2 and 0", "[mesh_info]") {
  const MeshInfo q = mesh_info(sample("quad_sphere.obj"));
  CHECK(q.quads == 384);
  CHECK(long(q.vertices) - long(q.topology.edges) + long(q.faces) == 2);
  const MeshInfo t = mesh_info(sample("torus.obj"));
  CHECK(t.vertices == 48 * 24);
  CHECK(long(t.vertices) - long(t.topology.edges) + long(t.faces) == 0);
  CHECK(t.double_precision);
}

TEST_CASE("info: the inconsistently wound icosphere", "[mesh_info]") {
  const MeshInfo m = mesh_info(sample("inconsistent_winding.obj"));
  // 12 reversed faces (0, 7, ..., 77). Checked here on the original icosphere: no two of them
  // share an edge, so each of their 3 edges meets an unreversed neighbour running the same way.
  const Mesh ico = testing::icosphere(1).mesh;
  for (std::size_t f = 0; f < 80; f += 7)
    for (std::size_t g = f + 7; g < 80; g += 7) {
      int shared = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) shared += ico.corner_vertex[3 * f + i] == ico.corner_vertex[3 * g + j];
      CHECK(shared < 2);
    }
  CHECK(m.topology.inconsistent_edges == 12 * 3);
  CHECK(m.topology.boundary_edges == 0);
}

TEST_CASE("info: the non-manifold sample", "[mesh_info]") {
  const MeshInfo m = mesh_info(sample("non_manifold.obj"));
  CHECK(m.topology.non_manifold_edges == 1);   // the fin
  CHECK(m.topology.non_manifold_vertices == 3);  // the fin's two ends and the bow-tie centre
  CHECK(m.topology.inconsistent_edges == 3);   // the duplicated triangle runs its 3 edges twice
  CHECK(m.unreferenced_vertices == 1);
  CHECK(m.components == 3);  // fin, bow-tie, duplicated triangle
  CHECK(!m.closed_manifold());
}

TEST_CASE("info: NaN and Inf are counted and kept out of the bounding box", "[mesh_info]") {
  Mesh mesh;
  mesh.add_vertex({0, 0, 0});
  mesh.add_vertex({1, 2, 3});
  mesh.add_vertex({NAN, 0, 0});
  mesh.add_vertex({0, INFINITY, 0});
  mesh.add_face({0, 1, 2});
  mesh.vertex_normals = {0, 0, 1, NAN, 0, 1, 0, 0, 1, 0, 0, 1};
  const MeshInfo m = mesh_info(mesh);
  CHECK(m.nonfinite_vertices == 2);
  CHECK(m.nonfinite_values == 1);
  CHECK(m.bbox_min == Vec3d{0, 0, 0});
  CHECK(m.bbox_max == Vec3d{1, 2, 3});
  CHECK(m.unreferenced_vertices == 1);
  CHECK(m.degenerate.non_finite == 1);
  Mesh all_nan;
  all_nan.add_vertex({NAN, NAN, NAN});
  CHECK(!mesh_info(all_nan).has_bbox);
}
