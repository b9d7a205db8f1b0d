// Baking onto meshes: per-vertex (Gouraud) and per-face (flat) colours, where normals come from,
// and how colours are stored in the mesh.
#include <catch2/catch.hpp>

#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include "lighting_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

Mesh flat_quad() {  // 2 x 1 in the plane z = 0, counter-clockwise seen from +z
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({2, 0, 0});
  m.add_vertex({2, 1, 0});
  m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2, 3});
  return m;
}

Mesh two_triangle_quad() {
  Mesh m = flat_quad();
  m.face_start = {0};
  m.corner_vertex.clear();
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  return m;
}

}  // namespace

TEST_CASE("a flat quad lit by a directional light has every vertex the same colour", "[lighting][bake]") {
  // Gouraud shading interpolates the baked colours across the face, so the renderer shows one
  // flat colour, as a flat surface under a light at infinity must look.
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {0.8, 0.5, 0.2};
  s.lights = {directional({0, -3, -4})};  // L = (0, .6, .8): n.L = 0.8 -> 0.8 * kd = (0.64, 0.40, 0.16)
  for (const Mesh& mesh : {flat_quad(), two_triangle_quad()}) {
    const BakeResult r = bake_lighting(mesh, s, ShadingFrequency::PerVertex);
    REQUIRE(r.rgb.size() == 12);
    CHECK(r.normals_source == "computed (angle-weighted)");
    for (int v = 0; v < 4; ++v) {
      CHECK(r.rgb[3 * v] == Approx(0.64).margin(1e-12));
      CHECK(r.rgb[3 * v + 1] == Approx(0.40).margin(1e-12));
      CHECK(r.rgb[3 * v + 2] == Approx(0.16).margin(1e-12));
    }
    // Flat shading gives the same single colour.
    const BakeResult f = bake_lighting(mesh, s, ShadingFrequency::PerFace);
    REQUIRE(f.rgb.size() == 3 * mesh.num_faces());
    for (std::size_t k = 0; k < f.rgb.size(); ++k) CHECK(f.rgb[k] == Approx(r.rgb[k % 3]).margin(1e-12));
  }
}

TEST_CASE("a flat quad stays one colour under a sheared, scaled, mirrored M in every space", "[lighting][bake]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {1, 1, 1};
  s.lights = {directional({0.3, -0.2, -1})};
  s.world_from_object.A.m = {{{-2, 0.5, 0.1}, {0.3, 0.5, 0.7}, {0.2, 0, 1.5}}};
  s.world_from_object.t = {3, -1, 2};
  for (ShadingSpace space : {ShadingSpace::World, ShadingSpace::Camera, ShadingSpace::Object}) {
    ShadeOptions o;
    o.space = space;
    const BakeResult r = bake_lighting(flat_quad(), s, ShadingFrequency::PerVertex, o);
    for (int v = 1; v < 4; ++v)
      for (int k = 0; k < 3; ++k) CHECK(r.rgb[3 * v + k] == Approx(r.rgb[k]).margin(1e-12));
    CHECK(r.rgb[0] > 0.05);  // lit (not a vacuous comparison of zeros)
  }
}

TEST_CASE("per face: the face normal at the centroid", "[lighting][bake]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {0.5, 0.5, 0.5};
  s.lights = {point_light({1, 0.5, 2})};  // 2 above the quad's centroid (1, 0.5, 0)
  // centroid: d = 2, L = n = (0,0,1), att = 1: colour = kd = 0.5
  const BakeResult f = bake_lighting(flat_quad(), s, ShadingFrequency::PerFace);
  REQUIRE(f.rgb.size() == 3);
  CHECK(f.rgb[0] == Approx(0.5).margin(1e-12));
  CHECK(f.normals_source == "computed face normals");
  // vertex (0,0,0): to light (1, 0.5, 2), d^2 = 5.25, n.L = 2/sqrt(5.25): colour 0.5 * 2/sqrt(5.25)
  const BakeResult v = bake_lighting(flat_quad(), s, ShadingFrequency::PerVertex);
  CHECK(v.rgb[0] == Approx(0.5 * 2 / std::sqrt(5.25)).margin(1e-12));
}

TEST_CASE("normals: the input's vertex normals, consistent corner normals, else computed", "[lighting][bake]") {
  Scene s = dark_scene(ShadingModel::Lambert);
  s.material.diffuse = {1, 1, 1};
  s.lights = {directional({0, 0, -1})};  // L = +z

  Mesh m = flat_quad();
  // Given vertex normals tilted 60 degrees from z at vertex 0 (n.L = 0.5), z elsewhere.
  m.vertex_normals = {std::sqrt(3.0), 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 2};
  BakeResult r = bake_lighting(m, s, ShadingFrequency::PerVertex);
  CHECK(r.normals_source == "input vertex normals");
  CHECK(r.rgb[0] == Approx(0.5).margin(1e-12));
  CHECK(r.rgb[9] == Approx(1.0).margin(1e-12));

  // Corner normals, one value per vertex (an OBJ with smooth `vn`): used as vertex normals.
  m.vertex_normals.clear();
  m.corner_normals = {std::sqrt(3.0), 0, 1, 0, 0, 1};
  m.corner_normal_index = {0, 1, 1, 1};
  r = bake_lighting(m, s, ShadingFrequency::PerVertex);
  CHECK(r.normals_source == "input corner normals (one per vertex)");
  CHECK(r.rgb[0] == Approx(0.5).margin(1e-12));

  // Two triangles sharing vertex 0 with different corner normals (a crease): computed instead.
  Mesh t = two_triangle_quad();
  t.corner_normals = {std::sqrt(3.0), 0, 1, 0, 0, 1};
  t.corner_normal_index = {0, 1, 1, 1, 1, 1};
  r = bake_lighting(t, s, ShadingFrequency::PerVertex);
  CHECK(r.normals_source == "computed (angle-weighted): the input's corner normals differ at some vertices");
  CHECK(r.rgb[0] == Approx(1.0).margin(1e-12));  // the computed normal of the flat quad is +z

  // Face normals given in the input are used for flat shading.
  Mesh f = flat_quad();
  f.face_normals = {std::sqrt(3.0), 0, 1};
  r = bake_lighting(f, s, ShadingFrequency::PerFace);
  CHECK(r.normals_source == "input face normals");
  CHECK(r.rgb[0] == Approx(0.5).margin(1e-12));
}

TEST_CASE("store_baked_colors fills one colour array and clears the other", "[lighting][bake]") {
  Mesh m = flat_quad();
  m.face_colors = {1, 0, 0, 1};
  m.color_channels = 4;
  store_baked_colors(m, std::vector<float>(12, 0.5f), ShadingFrequency::PerVertex, false);
  CHECK(m.vertex_colors.size() == 12);
  CHECK(m.face_colors.empty());
  CHECK(m.color_channels == 3);
  CHECK_FALSE(m.colors_are_float);
  store_baked_colors(m, std::vector<float>(3, 0.25f), ShadingFrequency::PerFace, true);
  CHECK(m.face_colors.size() == 3);
  CHECK(m.vertex_colors.empty());
  CHECK(m.colors_are_float);
  CHECK(m.positions == flat_quad().positions);
  CHECK(m.corner_vertex == flat_quad().corner_vertex);
}

TEST_CASE("store_baked_colors names every colour of the input it drops (face colours, alpha)", "[lighting][bake][issue27]") {
  // issue 27, item 10: cycloidal.ply (VCG) has rgba vertex and face colours; bake-lighting per
  // vertex dropped the face colours and both alphas without a word.
  Mesh m = flat_quad();
  m.vertex_colors.assign(16, 0.5f);
  m.face_colors = {1, 0, 0, 0.5f};
  m.color_channels = 4;
  const auto notes = store_baked_colors(m, std::vector<float>(12, 0.5f), ShadingFrequency::PerVertex, false);
  REQUIRE(notes.size() == 2);
  CHECK(notes[0] == "the input's face colours dropped: the lighting is baked per vertex (--per face bakes into them instead)");
  CHECK(notes[1] == "the input's colour alpha dropped: baked colours are rgb");
  // Nothing dropped: no note.
  Mesh plain = flat_quad();
  CHECK(store_baked_colors(plain, std::vector<float>(12, 0.5f), ShadingFrequency::PerVertex, false).empty());
}
