// --flat-patches (normals/flat_patches.h): a vertex whose faces lie in one plane gets exactly the
// plane's normal; a vertex off the plane keeps its weighted normal.
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/normals/flat_patches.h>
#include <shadetool/normals/update_mesh_normals.h>

using namespace shadetool;

namespace {

// An irregular fan in the plane through `o` spanned by e1, e2: a ring of 7 unequal triangles
// around vertex 0, plus (apex) one vertex lifted off the plane joined to the ring's first edge.
Mesh tilted_fan(Vec3d o, Vec3d e1, Vec3d e2, bool apex) {
  Mesh m;
  m.add_vertex(o);
  const double radius[7] = {1.0, 0.3, 2.5, 0.9, 1.7, 0.45, 3.0};
  for (int k = 0; k < 7; ++k) {
    const double a = 2 * 3.141592653589793 * (k + 0.37 * (k % 3)) / 7;
    m.add_vertex(o + e1 * (radius[k] * std::cos(a)) + e2 * (radius[k] * std::sin(a)));
  }
  for (std::uint32_t k = 0; k < 7; ++k) m.add_face({0u, 1 + k, 1 + (k + 1) % 7});
  if (apex) {
    m.add_vertex(o + cross(e1, e2) * 0.5 + e1 * 1.0);
    m.add_face({1u, 8u, 2u});
  }
  return m;
}

}  // namespace

TEST_CASE("Flat patches: an axis-aligned plane gives exactly (0, 0, 1)", "[flat_patches]") {
  Mesh m = tilted_fan({0.1, 0.2, 0.3}, {1, 0, 0}, {0, 1, 0}, false);
  NormalsRequest r;
  r.flat_patches = true;
  update_mesh_normals(m, r);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(get3(m.vertex_normals, v) == Vec3d{0, 0, 1});
}

TEST_CASE("Flat patches: a tilted plane gives every vertex the same normal, the plane's", "[flat_patches]") {
  const Vec3d e1 = normalized_or(Vec3d{1, 2, 3}, Vec3d{}), e2 = normalized_or(cross(e1, Vec3d{0.3, -1, 0.2}), Vec3d{});
  const Vec3d plane = normalized_or(cross(e1, e2), Vec3d{});
  Mesh m = tilted_fan({0.7, -1.1, 2.9}, e1, e2, false);
  Mesh plain = m;
  NormalsRequest r;
  update_mesh_normals(plain, r);
  r.flat_patches = true;
  const NormalsReport rep = update_mesh_normals(m, r);
  const Vec3d n0 = get3(m.vertex_normals, 0);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(get3(m.vertex_normals, v) == n0);  // one vector, bit for bit
  CHECK(std::acos(std::min(1.0, dot(n0, plane))) < 1e-14);
  // Without the flag the rounded weighted sums differ in the last bits somewhere (what the flag fixes).
  std::size_t differ = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) differ += get3(plain.vertex_normals, v) != n0;
  INFO("vertices whose weighted normal is not the plane's to the bit: " << differ << ", replaced " << rep.flat_patches);
  CHECK(rep.flat_patches == differ);
}

TEST_CASE("Flat patches: a vertex with a face off the plane keeps its weighted normal", "[flat_patches]") {
  Mesh m = tilted_fan({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, true);
  Mesh plain = m;
  NormalsRequest r;
  update_mesh_normals(plain, r);
  r.flat_patches = true;
  update_mesh_normals(m, r);
  CHECK(get3(m.vertex_normals, 1) == get3(plain.vertex_normals, 1));  // vertex 1 touches the lifted face
  CHECK(get3(m.vertex_normals, 1) != Vec3d{0, 0, 1});
  CHECK(get3(m.vertex_normals, 0) == Vec3d{0, 0, 1});
}
