// Tests of lighting/lit_normals.h: the one choice of the normals a vertex is lit with (bake-lighting
// per vertex, render's Gouraud and Phong). Values written by hand for a flat quad in z = 0.
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/lighting/lit_normals.h>
#include <shadetool/render/lighting_adapter.h>

using namespace shadetool;

namespace {

Mesh two_triangle_quad() {  // (0,0) (2,0) (2,1) (0,1) in z = 0, counter-clockwise seen from +z
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({2, 0, 0});
  m.add_vertex({2, 1, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  return m;
}

}  // namespace

TEST_CASE("lit_vertex_normals: input vertex normals as given, agreeing corner normals, else angle-weighted",
          "[lighting][normals]") {
  Mesh m = two_triangle_quad();
  m.vertex_normals = {0, 0, 2, 0, 0, 1, 0, 0, 1, 1, 0, 1};  // not unit: used as given
  LitVertexNormals lit = lit_vertex_normals(m);
  CHECK(lit.source == "input vertex normals");
  CHECK(lit.normals == m.vertex_normals);

  m.vertex_normals.clear();
  m.corner_normals = {1, 0, 1, 0, 0, 1};
  m.corner_normal_index = {0, 1, 1, 0, 1, 1};  // vertex 0 always normal 0, the others normal 1
  lit = lit_vertex_normals(m);
  CHECK(lit.source == "input corner normals (one per vertex)");
  CHECK(lit.normals == std::vector<double>{1, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});

  m.corner_normal_index = {0, 1, 1, 1, 1, 1};  // vertex 0 has two normals: a crease
  lit = lit_vertex_normals(m);
  CHECK(lit.source == "computed (angle-weighted): the input's corner normals differ at some vertices");
  for (std::size_t v = 0; v < 4; ++v) {  // the flat quad's normal +z, unit
    CHECK(lit.normals[3 * v] == Approx(0).margin(1e-15));
    CHECK(lit.normals[3 * v + 2] == Approx(1));
  }
  m.corner_normal_index = {0, 1, 1, 0, 1, 9};  // an index out of range counts as a crease
  CHECK(lit_vertex_normals(m).source.rfind("computed", 0) == 0);
}

TEST_CASE("render's Phong normals are the baked ones (one function, not two kept in step)", "[lighting][normals]") {
  Mesh m = two_triangle_quad();
  m.corner_normals = {1, 0, 1, 0, 0, 1};
  m.corner_normal_index = {0, 1, 1, 0, 1, 1};
  CHECK(shading_vertex_normals(m) == lit_vertex_normals(m).normals);
}
