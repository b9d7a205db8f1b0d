// Tests of repair_mesh: the scenarios, each with its expected result and report counts.
// The truth is the mesh as built (every face wound to face outward, see repair_test_meshes.h),
// damaged by swapping two corners of chosen faces; "restored exactly" means the same corner
// arrays, face for face, in the same order.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include <shadetool/repair/repair_mesh.h>
#include "repair_test_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// Repairs `mesh`, then repairs the result again and requires zero changes (idempotence).
RepairReport repair_twice(Mesh& mesh, const RepairOptions& options = {}) {
  const std::size_t faces_in = mesh.num_faces();
  const RepairReport first = repair_mesh(mesh, options);
  if (!options.remove_degenerate) CHECK(mesh.num_faces() == faces_in);
  CHECK(first.faces_in == faces_in);
  CHECK(first.faces_out == mesh.num_faces());
  Mesh again = mesh;
  const RepairReport second = repair_mesh(again, options);
  CHECK(second.changes() == 0);
  CHECK(second.faces_flipped == 0);
  CHECK(second.normals.total() == 0);
  CHECK(again.corner_vertex == mesh.corner_vertex);
  return first;
}

// Drops normals the repair adds, so corner arrays can be compared with the untouched original.
bool same_faces(const Mesh& a, const Mesh& b) {
  return a.face_start == b.face_start && a.corner_vertex == b.corner_vertex;
}

}  // namespace

TEST_CASE("closed meshes with 30% of faces flipped are restored exactly", "[repair][closed]") {
  const Mesh sphere = uv_sphere(48, 24).mesh, torus = testing::torus(48, 24).mesh, genus3 = genus3_slab();
  REQUIRE(euler_characteristic(genus3) == -4);  // the fixture really is genus 3 (2 - 2g)
  const Mesh* meshes[] = {&sphere, &torus, &genus3};
  const char* names[] = {"sphere", "torus", "genus-3"};
  for (int i = 0; i < 3; ++i) {
    INFO(names[i]);
    const Mesh& truth = *meshes[i];
    REQUIRE(volume_from_origin(truth) > 0);  // built outward
    Mesh m = truth;
    const std::size_t flipped = flip_random_faces(m, 0.3, 11 + i).size();
    REQUIRE(flipped == std::size_t(std::llround(0.3 * double(truth.num_faces()))));
    const RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.faces_flipped == flipped);
    CHECK(r.faces_flipped_for_consistency == flipped);
    CHECK(r.components_inverted == 0);
    CHECK(r.components == 1);
    CHECK(r.closed_components == 1);
    CHECK(r.open_components == 0);
    CHECK(r.boundary_loops == 0);
    CHECK(r.non_manifold_edges == 0);
    CHECK(r.non_orientable_components == 0);
    CHECK(r.oriented_by_volume == 1);
    CHECK(r.normals.missing == truth.num_vertices());
  }
}

TEST_CASE("wholly inverted closed meshes (and inverted plus 30% flipped) are restored exactly", "[repair][closed]") {
  const Mesh sphere = uv_sphere(48, 24).mesh, torus = testing::torus(48, 24).mesh, genus3 = genus3_slab();
  const Mesh* meshes[] = {&sphere, &torus, &genus3};
  for (int i = 0; i < 3; ++i) {
    const Mesh& truth = *meshes[i];
    const std::size_t F = truth.num_faces();
    Mesh m = truth;
    invert_all(m);
    RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.faces_flipped == F);
    CHECK(r.faces_flipped_for_consistency == 0);
    CHECK(r.components_inverted == 1);

    // 30% flipped on top of the inversion: 70% of the faces are wrong.
    m = truth;
    invert_all(m);
    const std::size_t back = flip_random_faces(m, 0.3, 5 + i).size();
    r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.faces_flipped == F - back);
    CHECK(r.faces_flipped_for_consistency == back);
    CHECK(r.components_inverted == 1);
  }
}

TEST_CASE("a closed mesh far from the origin is oriented by its volume about its own centroid", "[repair][closed]") {
  // At 1e7 the volume spanned from the origin would cancel catastrophically (terms ~1e21 for a
  // volume ~4); spanned from the centroid the sign is unambiguous.
  Mesh truth = icosphere(3).mesh;
  transform_positions(truth, 1.0, {1e7, -2e7, 3e7});
  Mesh m = truth;
  invert_all(m);
  flip_random_faces(m, 0.3, 3);
  repair_twice(m);
  CHECK(same_faces(m, truth));
}

TEST_CASE("two disjoint components with opposite orientations both end up outward", "[repair][components]") {
  Mesh a = icosphere(3).mesh, b = testing::torus(40, 20).mesh;
  transform_positions(a, 1.0, {-3, 0, 0});
  transform_positions(b, 1.0, {3, 0, 0});
  Mesh truth = a;
  append(truth, b);
  Mesh m = a;
  Mesh b_inverted = b;
  invert_all(b_inverted);
  append(m, b_inverted);
  const RepairReport r = repair_twice(m);
  CHECK(same_faces(m, truth));
  CHECK(r.components == 2);
  CHECK(r.closed_components == 2);
  CHECK(r.components_inverted == 1);
  CHECK(r.faces_flipped == b.num_faces());
  CHECK(r.nested_shells == 0);
}

TEST_CASE("a hollow ball: the inner shell faces into the cavity", "[repair][nested]") {
  // Outer unit sphere facing out; inner sphere of radius 0.5 facing the centre (into the cavity).
  Mesh outer = icosphere(3).mesh, inner = icosphere(2).mesh;
  transform_positions(inner, 0.5, {0, 0, 0});
  invert_all(inner);
  Mesh truth = outer;
  append(truth, inner);
  REQUIRE(volume_from_origin(truth) > 0);  // 4/3 pi (1 - 1/8) > 0 with the cavity subtracted

  SECTION("inner shell wound outward (the usual export mistake)") {
    Mesh m = outer;
    Mesh inner_out = inner;
    invert_all(inner_out);
    append(m, inner_out);
    const RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.components == 2);
    CHECK(r.closed_components == 2);
    CHECK(r.nested_shells == 1);
    CHECK(r.components_inverted == 1);
    CHECK(r.faces_flipped == inner.num_faces());
  }
  SECTION("both shells inverted and 30% of all faces flipped") {
    Mesh m = truth;
    invert_all(m);
    flip_random_faces(m, 0.3, 17);
    const RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.nested_shells == 1);
    CHECK(r.components_inverted == 2);
  }
  SECTION("already right: nothing changes") {
    Mesh m = truth;
    const RepairReport r = repair_mesh(m);
    CHECK(same_faces(m, truth));
    CHECK(r.faces_flipped == 0);
    CHECK(r.nested_shells == 1);
  }
}

TEST_CASE("two intersecting spheres are not nested: both face outward", "[repair][nested]") {
  Mesh a = icosphere(3).mesh, b = icosphere(3).mesh;
  transform_positions(b, 0.6, {0.7, 0, 0});  // b's bounding box lies inside a's, b pokes out of a
  Mesh truth = a;
  append(truth, b);
  Mesh m = truth;
  invert_all(m);
  const RepairReport r = repair_twice(m);
  CHECK(same_faces(m, truth));
  CHECK(r.nested_shells == 0);
}

TEST_CASE("an open hemisphere faces away from the region it wraps around", "[repair][open]") {
  const Mesh truth = hemisphere(48, 24);
  SECTION("30% flipped") {
    Mesh m = truth;
    const std::size_t flipped = flip_random_faces(m, 0.3, 23).size();
    const RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.faces_flipped == flipped);
    CHECK(r.open_components == 1);
    CHECK(r.closed_components == 0);
    CHECK(r.boundary_loops == 1);
    CHECK(r.oriented_by_vote == 1);
  }
  SECTION("wholly inverted, and inverted with 30% flipped: the vote, not the majority, decides") {
    Mesh m = truth;
    invert_all(m);
    RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.components_inverted == 1);
    CHECK(r.oriented_by_vote == 1);
    m = truth;
    invert_all(m);
    flip_random_faces(m, 0.3, 29);
    r = repair_twice(m);
    CHECK(same_faces(m, truth));
  }
}

TEST_CASE("a bumpy terrain patch: consistent winding, majority kept when the shape has no side", "[repair][open]") {
  const Mesh truth = bumpy_terrain(40);
  SECTION("30% flipped: the 70% majority (up) is restored exactly") {
    Mesh m = truth;
    const std::size_t flipped = flip_random_faces(m, 0.3, 31).size();
    const RepairReport r = repair_twice(m);
    CHECK(same_faces(m, truth));
    CHECK(r.faces_flipped == flipped);
    CHECK(r.open_components == 1);
    CHECK(r.boundary_loops == 1);
    CHECK(r.oriented_by_vote == 0);
    CHECK(r.oriented_by_majority == 1);
  }
  SECTION("wholly inverted: nothing to go on, nothing is reversed") {
    Mesh m = truth;
    invert_all(m);
    const Mesh before = m;
    const RepairReport r = repair_twice(m);
    CHECK(same_faces(m, before));
    CHECK(r.faces_flipped == 0);
    CHECK(r.oriented_by_majority == 1);
  }
}

TEST_CASE("a Möbius strip is detected as non-orientable and wound consistently but for one seam", "[repair][mobius]") {
  const int n = 60;
  const Mesh strip = mobius_strip(n);
  REQUIRE(same_direction_edges(strip) == 1);  // as built, only the closing edge disagrees
  Mesh m = strip;
  flip_random_faces(m, 0.3, 37);
  const RepairReport r = repair_twice(m);
  CHECK(r.non_orientable_components == 1);
  CHECK(r.inconsistent_edges == 1);
  CHECK(same_direction_edges(m) == 1);  // the minimum: a Möbius strip cannot do with zero
  CHECK(r.components == 1);
  CHECK(r.open_components == 1);
  CHECK(r.boundary_loops == 1);  // a Möbius strip has a single boundary curve
  CHECK(r.oriented_by_majority == 1);
  CHECK(m.num_faces() == std::size_t(2 * n));
}

TEST_CASE("three triangles on one edge: a non-manifold edge that does not propagate", "[repair][nonmanifold]") {
  const Mesh truth = three_triangles_on_one_edge();
  Mesh m = truth;
  const RepairReport r = repair_twice(m);
  CHECK(same_faces(m, truth));  // three flat pieces, no evidence: each keeps its winding
  CHECK(r.non_manifold_edges == 1);
  CHECK(r.components == 3);
  CHECK(r.open_components == 3);
  CHECK(r.boundary_loops == 3);
  CHECK(r.faces_flipped == 0);
}

TEST_CASE("a closed mesh with a fin on one edge: the fin does not disturb the body", "[repair][nonmanifold]") {
  Mesh truth = icosphere(2).mesh;
  const std::uint32_t a = truth.corner_vertex[0], b = truth.corner_vertex[1];
  const std::uint32_t tip = truth.add_vertex((truth.position(a) + truth.position(b)) * 1.5);
  truth.add_face({a, b, tip});
  Mesh m = truth;
  invert_all(m);
  flip_random_faces(m, 0.3, 41);
  const RepairReport r = repair_twice(m);
  // The body is restored; the fin (flat, its own component) keeps the winding it came in with.
  Mesh body_truth = truth, body = m;
  body_truth.corner_vertex.resize(body_truth.corner_vertex.size() - 3);
  body_truth.face_start.pop_back();
  body.corner_vertex.resize(body.corner_vertex.size() - 3);
  body.face_start.pop_back();
  CHECK(same_faces(body, body_truth));
  CHECK(r.non_manifold_edges == 1);
  CHECK(r.components == 2);
  CHECK(r.closed_components == 1);
  CHECK(r.open_components == 1);
}

TEST_CASE("degenerate faces are reported, kept by default and removed only on request", "[repair][degenerate]") {
  Mesh truth = icosphere(2).mesh;
  const std::size_t F = truth.num_faces();
  const std::uint32_t a = truth.corner_vertex[0], b = truth.corner_vertex[1];
  truth.add_face({a, a, b});  // repeated index
  const std::uint32_t mid = truth.add_vertex((truth.position(a) + truth.position(b)) * 0.5);
  truth.add_face({a, mid, b});  // zero area (collinear)
  Mesh m = truth;
  invert_all(m);
  RepairReport r = repair_twice(m);
  CHECK(m.num_faces() == F + 2);
  CHECK(r.degenerate_faces == 2);
  CHECK(r.degenerate_repeated_index == 1);
  CHECK(r.degenerate_zero_area == 1);
  CHECK(r.degenerate_faces_removed == 0);
  CHECK(std::vector<std::uint32_t>(m.corner_vertex.begin(), m.corner_vertex.begin() + 3 * F) ==
        std::vector<std::uint32_t>(truth.corner_vertex.begin(), truth.corner_vertex.begin() + 3 * F));

  RepairOptions o;
  o.remove_degenerate = true;
  Mesh n = truth;
  r = repair_mesh(n, o);
  CHECK(r.degenerate_faces_removed == 2);
  CHECK(n.num_faces() == F);
  CHECK(r.faces_out == F);
  CHECK(std::vector<std::uint32_t>(n.corner_vertex.begin(), n.corner_vertex.end()) ==
        std::vector<std::uint32_t>(truth.corner_vertex.begin(), truth.corner_vertex.begin() + 3 * F));
  for (double x : n.vertex_normals) CHECK(std::isfinite(x));
}

TEST_CASE("--weld merges split vertices before orientation, so the pieces orient as one", "[repair][weld]") {
  // A sphere whose faces each have their own three vertices (a triangle soup, as STL without
  // merging): 1280 components until welded, one closed component after.
  const Mesh truth = icosphere(3).mesh;
  Mesh soup;
  for (std::size_t f = 0; f < truth.num_faces(); ++f) {
    std::uint32_t v[3];
    for (int k = 0; k < 3; ++k) v[k] = soup.add_vertex(truth.position(truth.corner_vertex[3 * f + k]) + Vec3d{1e-9, 0, 0} * double(k));
    soup.add_face({v[0], v[1], v[2]});
  }
  invert_all(soup);
  RepairOptions o;
  o.weld_eps = 1e-6;
  const RepairReport r = repair_twice(soup, o);
  CHECK(r.vertices_welded == 3 * truth.num_faces() - truth.num_vertices());
  CHECK(soup.num_vertices() == truth.num_vertices());
  CHECK(r.components == 1);
  CHECK(r.closed_components == 1);
  CHECK(r.components_inverted == 1);
  CHECK(volume_from_origin(soup) > 0);
}

TEST_CASE("stored normals: NaN, Inf, zero and flipped ones are recomputed, valid ones kept bitwise", "[repair][normals]") {
  AnalyticMesh am = icosphere(3);
  Mesh m = am.mesh;
  for (const Vec3d& n : am.exact_normals) { m.vertex_normals.push_back(n.x); m.vertex_normals.push_back(n.y); m.vertex_normals.push_back(n.z); }
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  set3(m.vertex_normals, 0, {nan, 0, 1});
  set3(m.vertex_normals, 1, {0, inf, 0});
  set3(m.vertex_normals, 2, {0, 0, 0});
  set3(m.vertex_normals, 3, -am.exact_normals[3]);
  set3(m.vertex_normals, 4, -am.exact_normals[4]);
  const std::vector<double> stored = m.vertex_normals;
  flip_random_faces(m, 0.3, 43);  // the stored normals are right; 30% of the faces are not
  const RepairReport r = repair_twice(m);
  CHECK(r.normals.nan == 1);
  CHECK(r.normals.inf == 1);
  CHECK(r.normals.zero == 1);
  CHECK(r.normals.flipped == 2);
  CHECK(r.normals.missing == 0);
  CHECK(r.normals.vertex == 5);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (v < 5) {
      // Recomputed (angle-weighted on an icosphere of level 3: within 1 degree of exact).
      CHECK(angle_degrees(get3(m.vertex_normals, v), am.exact_normals[v]) < 1.0);
    } else {
      CHECK(std::memcmp(&m.vertex_normals[3 * v], &stored[3 * v], 3 * sizeof(double)) == 0);
    }
  }
}

TEST_CASE("an inside-out shell whose normals agree with its winding is kept as authored; one whose normals say "
          "outward is turned (issue 27 item 1)", "[repair][normals][authored]") {
  // Normals that agree with the winding are the author's statement of which side is out (a room, a
  // sky box): the volume does not overrule them. Normals that contradict the winding are not a
  // statement: the volume decides, and the normals then agree with the turned faces.
  AnalyticMesh am = icosphere(2);
  for (double sign : {-1.0, 1.0}) {
    Mesh m = am.mesh;
    for (const Vec3d& n : am.exact_normals) { m.vertex_normals.push_back(sign * n.x); m.vertex_normals.push_back(sign * n.y); m.vertex_normals.push_back(sign * n.z); }
    invert_all(m);
    const std::vector<double> stored = m.vertex_normals;
    const RepairReport r = repair_twice(m);
    CHECK(r.normals.total() == 0);
    CHECK(m.vertex_normals == stored);
    CHECK(r.orientation_by.faces_agreeing_reversed == 0);
    if (sign < 0) {
      CHECK(r.faces_flipped == 0);
      CHECK(r.oriented_by_agreement == 1);
      CHECK(r.orientation_by.geometry_overruled == 1);
      CHECK(r.orientation_by.faces_agreeing == m.num_faces());
    } else {
      CHECK(r.faces_flipped == m.num_faces());
      CHECK(r.oriented_by_volume == 1);
      CHECK(r.orientation_by.faces_disagreeing == m.num_faces());
      CHECK(r.orientation_by.volume.faces_reversed == m.num_faces());
    }
  }
}

TEST_CASE("corner normals: a flat-shaded cube's broken shared normals are rebuilt from their faces", "[repair][normals]") {
  // Unit cube, 12 triangles, one pool normal per side (as an OBJ exporter writes `vn`).
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const double side_normal[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (int s = 0; s < 6; ++s) {
    m.corner_normals.insert(m.corner_normals.end(), side_normal[s], side_normal[s] + 3);
    const std::uint32_t* q = quads[s];
    m.add_face({q[0], q[1], q[2]});
    m.add_face({q[0], q[2], q[3]});
    for (int k = 0; k < 6; ++k) m.corner_normal_index.push_back(std::uint32_t(s));
  }
  for (int s = 0; s < 6; ++s)  // each side wound to face its normal
    for (int t = 0; t < 2; ++t) {
      const std::size_t f = 2 * s + t;
      const Vec3d n = cross(m.position(m.corner_vertex[3 * f + 1]) - m.position(m.corner_vertex[3 * f]),
                            m.position(m.corner_vertex[3 * f + 2]) - m.position(m.corner_vertex[3 * f]));
      REQUIRE(dot(n, Vec3d{side_normal[s][0], side_normal[s][1], side_normal[s][2]}) > 0);
    }
  const std::vector<double> truth = m.corner_normals;
  m.corner_normals[0] = std::numeric_limits<double>::quiet_NaN();  // side 0: NaN
  for (int i = 3; i < 6; ++i) m.corner_normals[i] = -m.corner_normals[i];  // side 1: flipped
  flip_random_faces(m, 0.3, 47);
  const RepairReport r = repair_twice(m);
  CHECK(r.normals.nan == 1);
  CHECK(r.normals.flipped == 1);
  CHECK(r.normals.corner == 2);
  CHECK(!m.has_vertex_normals());  // corner normals are the mesh's normals: none added
  for (std::size_t i = 0; i < truth.size(); ++i) CHECK(m.corner_normals[i] == Approx(truth[i]).margin(1e-15));
  CHECK(std::memcmp(&m.corner_normals[6], &truth[6], 12 * sizeof(double)) == 0);  // sides 2..5 untouched
}

TEST_CASE("polygons: a quad mesh with 30% of its quads reversed is restored exactly", "[repair][polygons]") {
  // The genus-3 slab with each pair of triangles (q0,q1,q2), (q0,q2,q3) merged back into its quad.
  const Mesh tri = genus3_slab();
  Mesh truth;
  truth.positions = tri.positions;
  for (std::size_t f = 0; f < tri.num_faces(); f += 2)
    truth.add_face({tri.corner_vertex[3 * f], tri.corner_vertex[3 * f + 1], tri.corner_vertex[3 * f + 2],
                    tri.corner_vertex[3 * f + 5]});
  Mesh m = truth;
  std::mt19937 rng(59);
  std::size_t reversed = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    if (std::uniform_real_distribution<double>(0, 1)(rng) < 0.3) {
      std::swap(m.corner_vertex[4 * f + 1], m.corner_vertex[4 * f + 3]);  // (q0,q1,q2,q3) -> (q0,q3,q2,q1)
      ++reversed;
    }
  REQUIRE(reversed > 0);
  const RepairReport r = repair_twice(m);
  CHECK(same_faces(m, truth));
  CHECK(r.faces_flipped == reversed);
  CHECK(r.closed_components == 1);
}

TEST_CASE("empty and face-less meshes are repaired to nothing without fault", "[repair][edge]") {
  Mesh empty;
  RepairReport r = repair_mesh(empty);
  CHECK(r.components == 0);
  CHECK(r.changes() == 0);
  Mesh points;
  points.add_vertex({0, 0, 0});
  points.add_vertex({1, 0, 0});
  r = repair_mesh(points);
  CHECK(r.components == 0);
  CHECK(r.normals.missing == 2);  // every vertex gets a (fallback) normal, never NaN
  for (double x : points.vertex_normals) CHECK(std::isfinite(x));
}
