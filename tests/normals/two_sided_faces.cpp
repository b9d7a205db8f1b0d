// Tests of normals/two_sided_faces and of update_mesh_normals on a two-sided surface (issue 27
// item 5: Blender 2.71's chair_model.obj has every triangle twice, once per winding, on shared
// vertices; summed, its vertex normals were noise).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include <shadetool/normals/two_sided_faces.h>
#include <shadetool/normals/update_mesh_normals.h>
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// The torus with every face written a second time, reversed, on the same vertices, the backs
// shuffled among the fronts as an exporter writes them (the front of each pair comes first).
Mesh two_sided(const Mesh& front, std::vector<std::uint32_t>& back_of_front) {
  const std::size_t F = front.num_faces();
  std::vector<std::uint32_t> order(2 * F);
  for (std::uint32_t i = 0; i < 2 * F; ++i) order[i] = i;  // < F: front i, >= F: back of i - F
  std::mt19937 rng(5);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<std::uint8_t> front_written(F, 0);
  Mesh m;
  m.positions = front.positions;
  back_of_front.assign(F, 0);
  std::vector<std::uint32_t> pending;  // backs whose front is not written yet: written after it
  auto write = [&](std::uint32_t i) {
    const std::size_t f = i % F;
    std::vector<std::uint32_t> c(front.corner_vertex.begin() + front.face_start[f], front.corner_vertex.begin() + front.face_start[f + 1]);
    if (i >= F) {
      std::reverse(c.begin(), c.end());
      std::rotate(c.begin(), c.begin() + (f % c.size()), c.end());  // any first corner
      back_of_front[f] = std::uint32_t(m.num_faces());
    }
    m.add_face(c);
  };
  for (std::uint32_t i : order) {
    if (i < F) { write(i); front_written[i] = 1; }
    else if (front_written[i - F]) write(i);
    else pending.push_back(i);
    for (std::size_t k = 0; k < pending.size();)
      if (front_written[pending[k] - F]) { write(pending[k]); pending.erase(pending.begin() + long(k)); } else ++k;
  }
  return m;
}

}  // namespace

TEST_CASE("two_sided_faces: every back found, paired with its own front; duplicates in the same order are not backs",
          "[two_sided]") {
  const AnalyticMesh am = torus(24, 12);
  std::vector<std::uint32_t> back_of_front;
  Mesh m = two_sided(am.mesh, back_of_front);
  const TwoSidedFaces two = two_sided_faces(m);
  CHECK(two.backs == am.mesh.num_faces());
  for (std::uint32_t b : back_of_front) REQUIRE(two.front_of[b] != TwoSidedFaces::kNotBack);
  CHECK(front_faces(m, two).num_faces() == am.mesh.num_faces());
  // The same triangle twice in the same order: a duplicate, not a back.
  Mesh dup = am.mesh;
  dup.add_face({dup.corner_vertex[0], dup.corner_vertex[1], dup.corner_vertex[2]});
  CHECK(two_sided_faces(dup).backs == 0);
  CHECK(two_sided_faces(am.mesh).backs == 0);
}

TEST_CASE("update_mesh_normals: a two-sided torus gets the one-sided torus's normals, not noise", "[two_sided]") {
  const AnalyticMesh am = torus(48, 24);
  std::vector<std::uint32_t> back_of_front;
  const Mesh m0 = two_sided(am.mesh, back_of_front);

  // Vertex normals: those of the one-sided torus (the same faces, summed in another order: equal
  // to rounding), so within the tessellation's error of the exact normals.
  Mesh one = am.mesh, m = m0;
  update_mesh_normals(one, NormalsRequest{});
  const NormalsReport rep = update_mesh_normals(m, NormalsRequest{});
  CHECK(rep.two_sided_faces == am.mesh.num_faces());
  double worst_vs_one_sided = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    worst_vs_one_sided = std::max(worst_vs_one_sided, angle_degrees(get3(m.vertex_normals, v), get3(one.vertex_normals, v)));
  CHECK(worst_vs_one_sided < 1e-9);
  double worst = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) worst = std::max(worst, angle_degrees(get3(m.vertex_normals, v), am.exact_normals[v]));
  CHECK(worst < 1.0);

  // Corner normals: each back corner is its front's reversed, so every corner faces its own face.
  Mesh c = m0;
  NormalsRequest crease;
  crease.kind = NormalKind::Corner;
  crease.crease_angle = 30 * kPi / 180;
  const NormalsReport rc = update_mesh_normals(c, crease);
  CHECK(rc.two_sided_faces == am.mesh.num_faces());
  for (std::size_t f = 0; f < c.num_faces(); ++f) {
    const std::uint32_t b = c.face_start[f];
    const Vec3d n = cross(c.position(c.corner_vertex[b + 1]) - c.position(c.corner_vertex[b]),
                          c.position(c.corner_vertex[b + 2]) - c.position(c.corner_vertex[b]));
    for (std::uint32_t k = b; k < c.face_start[f + 1]; ++k)
      REQUIRE(dot(get3(c.corner_normals, c.corner_normal_index[k]), normalized_or(n, Vec3d{})) > 0.9);
  }
}
