// Tests of visibility/ambient_occlusion.h against closed forms the code does not compute: convex
// and flat meshes see the whole sky at any scale and distance from the origin; a disc over a plane
// and the inside corner of a cube have known open fractions (Lambert's polygon form factor, and
// sqrt(3)/4 for the corner, checked here by an independent Monte Carlo).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include <tbb/global_control.h>

#include <shadetool/core/error.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/visibility_scene.h>
#include "support/analytic_meshes.h"
#include "visibility_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

void require_fully_open(const Mesh& mesh, const std::vector<double>& normals, std::uint32_t samples) {
  const VisibilityScene scene(mesh);
  AmbientOcclusionOptions o;
  o.samples = samples;
  const AmbientOcclusion ao = ambient_occlusion_per_vertex(scene, mesh, normals, o);
  REQUIRE(ao.skipped == 0);
  REQUIRE(ao.rays == std::uint64_t(mesh.num_vertices()) * samples);
  REQUIRE(ao.hits == 0);
  for (float v : ao.open_fraction) REQUIRE(v == 1.0f);
  // The same normals rounded to float (what the CLI keeps when it computes them): still no hit.
  const AmbientOcclusion af =
      ambient_occlusion_per_vertex(scene, mesh, std::vector<float>(normals.begin(), normals.end()), o);
  REQUIRE(af.skipped == 0);
  REQUIRE(af.hits == 0);
}

std::vector<double> flat(const std::vector<Vec3d>& v) {
  std::vector<double> a;
  for (const Vec3d& p : v) a.insert(a.end(), {p.x, p.y, p.z});
  return a;
}

}  // namespace

TEST_CASE("A closed convex mesh has zero occlusion and zero hits at every vertex, at any scale and offset",
          "[visibility][ao]") {
  const double scales[] = {1e-3, 1.0, 1e6, 1e8};
  for (const double s : scales) {
    for (int variant = 0; variant < 3; ++variant) {
      INFO("scale " << s << " variant " << variant);
      AnalyticMesh am = variant == 2 ? uv_sphere(64, 32) : icosphere(4);
      // variant 0: radius s about the origin; 1 and 2: radius 1 centred s away (1e8: one double
      // ulp of the centre is 1.5e-8 of the radius).
      const double radius = variant == 0 ? s : 1.0;
      const Vec3d centre = variant == 0 ? Vec3d{0, 0, 0} : Vec3d{s, -s, s};
      transform_positions(am.mesh, radius, centre);
      require_fully_open(am.mesh, vertex_normals(am.mesh).normals, 256);
      require_fully_open(am.mesh, flat(am.exact_normals), 64);
    }
  }
}

TEST_CASE("A flat grid has zero occlusion on both sides at any scale and offset", "[visibility][ao]") {
  for (const double s : {1e-3, 1.0, 1e6, 1e8}) {
    for (const bool quads : {false, true}) {
      INFO("scale " << s << (quads ? " quads" : " triangles"));
      Mesh m = plane_grid(1.0, 24, quads);
      transform_positions(m, s, {s, s, -s});
      std::vector<double> up(3 * m.num_vertices(), 0.0), down = up;
      for (std::size_t v = 0; v < m.num_vertices(); ++v) up[3 * v + 2] = 1, down[3 * v + 2] = -1;
      require_fully_open(m, up, 128);
      require_fully_open(m, down, 128);
    }
  }
}

TEST_CASE("Lambert's polygon form factor reproduces the disc's h^2/(r^2+h^2) (checks the test's truth)",
          "[visibility][ao]") {
  for (const double r : {0.5, 1.0, 2.0}) {
    const double h = 1.0;
    const double disc = h * h / (r * r + h * h);
    const double polygon_open = 1 - polygon_form_factor({0, 0, 0}, {0, 0, 1}, disc_polygon(r, h, 4096));
    REQUIRE(polygon_open == Approx(disc).margin(1e-6));  // inscribed 4096-gon: O((2pi/n)^2) less area
  }
}

TEST_CASE("A point on a plane under a disc sees the open fraction h^2/(r^2+h^2)", "[visibility][ao]") {
  const double r = 1.0, h = 1.0;
  Mesh m = plane_grid(8.0, 4, true);
  const auto disc = disc_polygon(r, h, 256);
  add_polygon(m, disc);  // one 256-corner polygon: fanned for the BVH only
  const VisibilityScene scene(m);
  REQUIRE(scene.stats().triangles == 16 * 2 + 254);
  const double truth = 1 - polygon_form_factor({0, 0, 0}, {0, 0, 1}, disc);
  REQUIRE(truth == Approx(h * h / (r * r + h * h)).margin(2e-4));  // the 256-gon vs the disc
  // Many seeds at one point: the mean is unbiased (scrambling) and each estimate is close.
  const std::size_t seeds = 512;
  std::vector<double> points(3 * seeds, 0.0), normals(3 * seeds, 0.0);
  std::vector<std::uint64_t> ids(seeds);
  for (std::size_t i = 0; i < seeds; ++i) normals[3 * i + 2] = 1, ids[i] = i;
  AmbientOcclusionOptions o;
  o.samples = 1024;
  const AmbientOcclusion ao = ambient_occlusion_at_points(scene, points, normals, ids, o);
  double mean = 0, worst = 0;
  for (float v : ao.open_fraction) {
    mean += v;
    worst = std::max(worst, std::fabs(v - truth));
  }
  mean /= seeds;
  // Independent samples would give sd sqrt(p(1-p)/N) = 0.0156 per estimate; the scrambled net is far
  // better (convergence.cpp measures it): each estimate within 0.01, the mean within 1e-3.
  REQUIRE(worst < 0.01);
  REQUIRE(mean == Approx(truth).margin(1e-3));
}

TEST_CASE("The inside corner of a cube has open fraction sqrt(3)/4", "[visibility][ao]") {
  // Derivation: about n = (1,1,1)/sqrt(3) every direction in the positive octant escapes and every
  // other one hits a wall. (1/pi) int_octant n.w dw = (1/pi) sum_i n_i int_octant w_i dw, and
  // int_octant w_x dw is the area of the octant's projection onto the yz plane, a quarter of the
  // unit disc, pi/4: open = (1/pi) * 3 * (1/sqrt(3)) * pi/4 = sqrt(3)/4.
  const double truth = std::sqrt(3.0) / 4;
  {  // An independent Monte Carlo of the derivation (std::mt19937, polar map, not the library's).
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> U(0, 1);
    const Vec3d n = Vec3d{1, 1, 1} * (1 / std::sqrt(3.0));
    const Vec3d t = Vec3d{1, -1, 0} * (1 / std::sqrt(2.0)), b = cross(n, t);
    const int M = 2000000;
    int open = 0;
    for (int i = 0; i < M; ++i) {
      const double r = std::sqrt(U(rng)), phi = 2 * 3.14159265358979323846 * U(rng);
      const double z = std::sqrt(std::max(0.0, 1 - r * r));
      const Vec3d w = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * z;
      open += (w.x > 0 && w.y > 0 && w.z > 0) ? 1 : 0;
    }
    const double p = double(open) / M, sd = std::sqrt(truth * (1 - truth) / M);
    REQUIRE(std::fabs(p - truth) < 5 * sd);
  }
  const std::vector<double> inward = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  AmbientOcclusionOptions o;
  o.samples = 4096;
  SECTION("three walls, unlimited distance") {
    const Mesh m = unit_cube(true);
    const VisibilityScene scene(m);
    const AmbientOcclusion ao = ambient_occlusion_at_points(scene, {0, 0, 0}, inward, {}, o);
    REQUIRE(ao.open_fraction[0] == Approx(truth).margin(2e-3));
    // The vertex itself (its angle-weighted normal is the same diagonal, for walls facing in).
    Mesh in = m;
    const std::vector<double> vn = vertex_normals(in).normals;
    const Vec3d n0 = get3(vn, 0);
    REQUIRE(std::fabs(std::fabs(dot(n0, Vec3d{1, 1, 1})) - std::sqrt(3.0)) < 1e-12);
    std::vector<double> axis(3 * m.num_vertices(), 0.0);
    for (int k = 0; k < 3; ++k) axis[k] = inward[k];
    axis[3 * 7 + 2] = 1;  // vertex 7 is unused by the walls: any axis
    const AmbientOcclusion av = ambient_occlusion_per_vertex(scene, m, axis, o);
    REQUIRE(av.open_fraction[0] == Approx(truth).margin(2e-3));
    // The axis rounded to float (as the CLI keeps computed normals): the same bound holds.
    const AmbientOcclusion af = ambient_occlusion_per_vertex(scene, m, std::vector<float>(axis.begin(), axis.end()), o);
    REQUIRE(af.open_fraction[0] == Approx(truth).margin(2e-3));
  }
  SECTION("closed cube: open only within a distance shorter than the walls") {
    const Mesh m = unit_cube(false);
    const VisibilityScene scene(m);
    const AmbientOcclusion unlimited = ambient_occlusion_at_points(scene, {0, 0, 0}, inward, {}, o);
    REQUIRE(unlimited.hits == o.samples);  // watertight: no ray leaks through an edge
    REQUIRE(unlimited.open_fraction[0] == 0.0f);
    o.max_distance = 0.5;
    const AmbientOcclusion near = ambient_occlusion_at_points(scene, {0, 0, 0}, inward, {}, o);
    REQUIRE(near.open_fraction[0] == Approx(truth).margin(2e-3));
  }
}

TEST_CASE("Ambient occlusion is the same bits for 1 and 2 threads and for repeated runs", "[visibility][ao]") {
  AnalyticMesh am = torus(96, 48, 1.0, 0.45);
  Mesh m = am.mesh;
  add_polygon(m, disc_polygon(1.2, 0.3, 64));  // an occluder over the torus: real concavities
  const std::vector<double> n = vertex_normals(m).normals;
  const std::vector<float> n_float(n.begin(), n.end());  // the CLI's computed normals
  AmbientOcclusionOptions o;
  o.samples = 32;
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    const VisibilityScene scene(m);
    AmbientOcclusion a = ambient_occlusion_per_vertex(scene, m, n, o);
    AmbientOcclusion f = ambient_occlusion_per_face(scene, m, o);
    AmbientOcclusion v = ambient_occlusion_per_vertex(scene, m, n_float, o);
    a.open_fraction.insert(a.open_fraction.end(), f.open_fraction.begin(), f.open_fraction.end());
    a.open_fraction.insert(a.open_fraction.end(), v.open_fraction.begin(), v.open_fraction.end());
    a.hits += f.hits + v.hits;
    return a;
  };
  const AmbientOcclusion one = run(1), two = run(2), again = run(2);
  REQUIRE(one.hits > 0);
  REQUIRE(one.hits < one.rays);
  REQUIRE(one.open_fraction.size() == two.open_fraction.size());
  REQUIRE(std::memcmp(one.open_fraction.data(), two.open_fraction.data(), 4 * one.open_fraction.size()) == 0);
  REQUIRE(std::memcmp(two.open_fraction.data(), again.open_fraction.data(), 4 * two.open_fraction.size()) == 0);
  REQUIRE(one.hits == two.hits);
}

TEST_CASE("mesh_occlusion: the mesh's normals, else the library's computed block by block (same bits as all at once); "
          "invalid normals name the source",
          "[visibility][ao]") {
  AnalyticMesh am = torus(48, 24, 1.0, 0.45);
  Mesh m = am.mesh;
  add_polygon(m, disc_polygon(1.2, 0.3, 32));
  AmbientOcclusionOptions o;
  o.samples = 16;
  const std::vector<double> n = vertex_normals(m).normals;
  const VisibilityScene scene(m);
  const AmbientOcclusion by_double = ambient_occlusion_per_vertex(scene, m, n, o);
  const AmbientOcclusion by_face = ambient_occlusion_per_face(scene, m, o);

  const MeshOcclusion computed = mesh_occlusion(m, false, o, "knot.ply");  // m has no vertex normals
  REQUIRE(computed.normals_computed);
  REQUIRE(computed.ao.hits > 0);
  REQUIRE(computed.ao.open_fraction == by_double.open_fraction);
  REQUIRE(computed.ao.hits == by_double.hits);
  REQUIRE(computed.ao.rays == by_double.rays);
  REQUIRE(computed.scene.faces_used == m.num_faces());
  const MeshOcclusion faces = mesh_occlusion(m, true, o, "knot.ply");
  REQUIRE_FALSE(faces.normals_computed);
  REQUIRE(faces.ao.open_fraction == by_face.open_fraction);

  Mesh given = m;
  given.vertex_normals = n;
  const MeshOcclusion own = mesh_occlusion(given, false, o, "knot.ply");
  REQUIRE_FALSE(own.normals_computed);
  REQUIRE(own.ao.open_fraction == ambient_occlusion_per_vertex(scene, m, n, o).open_fraction);

  Mesh short_normals = given;
  short_normals.vertex_normals.resize(3 * (m.num_vertices() - 1));  // one row missing: refused, not read past
  REQUIRE_THROWS_AS(mesh_occlusion(short_normals, false, o, "knot.ply"), Error);
  given.vertex_normals[3] = given.vertex_normals[4] = given.vertex_normals[5] = 0;  // vertex 1: zero length
  REQUIRE_THROWS_WITH(mesh_occlusion(given, false, o, "knot.ply"),
                      Catch::StartsWith("knot.ply: 1 of " + std::to_string(m.num_vertices()) + " vertex normals are invalid"));
}

TEST_CASE("mesh_occlusion over several blocks of computed normals, and with hits kept in 1, 2 or 4 bytes, "
          "gives the double overload's bits", "[visibility][ao]") {
  const Mesh big = torus(128, 72, 1.0, 0.45).mesh;  // 9216 vertices: three blocks of 4096
  AmbientOcclusionOptions o;
  o.samples = 4;
  const VisibilityScene scene(big);
  const AmbientOcclusion whole = ambient_occlusion_per_vertex(scene, big, vertex_normals(big).normals, o);
  const MeshOcclusion blocked = mesh_occlusion(big, false, o, "big.ply");
  REQUIRE(whole.hits > 0);
  REQUIRE(blocked.ao.hits == whole.hits);
  REQUIRE(blocked.ao.open_fraction == whole.open_fraction);

  Mesh small = torus(8, 6, 1.0, 0.45).mesh;
  add_polygon(small, disc_polygon(1.2, 0.3, 16));
  const VisibilityScene small_scene(small);
  const std::vector<double> n = vertex_normals(small).normals;
  for (std::uint32_t samples : {255u, 256u, 65535u, 65536u}) {  // the edges of uint8, uint16 and uint32
    INFO("N = " << samples);
    o.samples = samples;
    const AmbientOcclusion direct = ambient_occlusion_per_vertex(small_scene, small, n, o);
    const MeshOcclusion counted = mesh_occlusion(small, false, o, "small.ply");
    REQUIRE(direct.hits > 0);
    REQUIRE(counted.ao.hits == direct.hits);
    REQUIRE(counted.ao.open_fraction == direct.open_fraction);
  }
}

TEST_CASE("Polygons are fanned for the BVH only, degenerate faces take no part, non-manifold edges work",
          "[visibility][ao]") {
  // Three fins on one spine (a non-manifold edge) standing on a floor of quads.
  Mesh m = plane_grid(2.0, 4, true);
  const std::uint32_t a = m.add_vertex({0, 0, 0}), b = m.add_vertex({0, 0, 1});
  for (int k = 0; k < 3; ++k) {
    const double ang = 2 * 3.14159265358979323846 * k / 3;
    const std::uint32_t c = m.add_vertex({std::cos(ang), std::sin(ang), 0.5});
    m.add_face({a, b, c});
  }
  std::vector<double> n(3 * m.num_vertices(), 0.0);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) n[3 * v + 2] = 1;
  AmbientOcclusionOptions o;
  o.samples = 64;
  const VisibilityScene scene(m);
  const AmbientOcclusion ao = ambient_occlusion_per_vertex(scene, m, n, o);
  REQUIRE(ao.hits > 0);
  // The same triangles given as triangles (quads fanned by hand): the same bits.
  Mesh fanned;
  fanned.positions = m.positions;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t s = m.face_start[f];
    for (std::uint32_t c = s + 1; c + 1 < m.face_start[f + 1]; ++c)
      fanned.add_face({m.corner_vertex[s], m.corner_vertex[c], m.corner_vertex[c + 1]});
  }
  const VisibilityScene fanned_scene(fanned);
  REQUIRE(fanned_scene.stats().triangles == scene.stats().triangles);
  const AmbientOcclusion af = ambient_occlusion_per_vertex(fanned_scene, fanned, n, o);
  REQUIRE(af.open_fraction == ao.open_fraction);
  // Degenerate faces added (repeated index, zero area, a NaN corner): left out, results unchanged.
  Mesh d = m;
  d.add_face({0u, 0u, 1u});
  d.add_face({0u, 1u, 2u});  // three collinear grid vertices: zero area
  const std::uint32_t bad = d.add_vertex({std::nan(""), 0, 0});
  d.add_face({0u, 6u, bad});
  std::vector<double> nd = n;
  nd.insert(nd.end(), {0, 0, 1});
  const VisibilityScene dscene(d);
  REQUIRE(dscene.stats().degenerate_faces == 2);
  REQUIRE(dscene.stats().nonfinite_faces == 1);
  REQUIRE(dscene.stats().triangles == scene.stats().triangles);
  const AmbientOcclusion ad = ambient_occlusion_per_vertex(dscene, d, nd, o);
  REQUIRE(std::vector<float>(ad.open_fraction.begin(), ad.open_fraction.end() - 1) == ao.open_fraction);
  REQUIRE(ad.skipped == 1);  // the NaN vertex: value 1, no ray
  REQUIRE(ad.open_fraction.back() == 1.0f);
  // Per face: every face gets a value; degenerate ones are skipped (1).
  const AmbientOcclusion fd = ambient_occlusion_per_face(dscene, d, o);
  REQUIRE(fd.open_fraction.size() == d.num_faces());
  REQUIRE(fd.skipped == 3);
}

TEST_CASE("Bad inputs are refused with an Error", "[visibility][ao]") {
  const Mesh m = unit_cube(false);
  const VisibilityScene scene(m);
  const std::vector<double> n(3 * m.num_vertices(), 1.0);
  AmbientOcclusionOptions o;
  o.samples = 0;
  REQUIRE_THROWS_AS(ambient_occlusion_per_vertex(scene, m, n, o), Error);
  o.samples = kMaxOcclusionSamples + 1;  // the one limit, which the CLI and Python relay
  REQUIRE_THROWS_WITH(ambient_occlusion_per_vertex(scene, m, n, o),
                      "ambient occlusion: samples must be 1..1048576, got 1048577");
  o.samples = kMaxOcclusionSamples;
  CHECK_NOTHROW(check_occlusion_options(o, "x"));
  o.samples = 4;
  o.max_distance = 0;
  REQUIRE_THROWS_WITH(check_occlusion_options(o, "occlusion"), "occlusion: distance must be > 0 (default: unlimited)");
  REQUIRE_THROWS_AS(ambient_occlusion_per_vertex(scene, m, n, o), Error);
  o.max_distance = std::nan("");
  REQUIRE_THROWS_AS(ambient_occlusion_per_vertex(scene, m, n, o), Error);
  o.max_distance = 1;
  REQUIRE_THROWS_AS(ambient_occlusion_per_vertex(scene, m, std::vector<double>(3, 0.0), o), Error);
  const Mesh other = unit_cube(true);
  std::vector<double> n_other = n;
  n_other.resize(3 * other.num_vertices());
  Mesh fewer = m;
  fewer.positions.resize(3 * 7);
  REQUIRE_THROWS_AS(ambient_occlusion_per_vertex(scene, fewer, std::vector<double>(21, 1.0), o), Error);
  REQUIRE_THROWS_AS(ambient_occlusion_at_points(scene, {0, 0, std::nan("")}, {0, 0, 1}, {}, o), Error);
  REQUIRE_THROWS_AS(ambient_occlusion_at_points(scene, {0, 0, 0}, {0, 0}, {}, o), Error);
  REQUIRE_THROWS_AS(ambient_occlusion_at_points(scene, {0, 0, 1e300}, {0, 0, 1}, {}, o), Error);  // beyond float
  // An empty mesh builds an empty scene: every ray escapes.
  const Mesh empty;
  const VisibilityScene es(empty);
  REQUIRE(es.stats().triangles == 0);
  const AmbientOcclusion e = ambient_occlusion_at_points(es, {0, 0, 0}, {0, 0, 1}, {}, o);
  REQUIRE(e.open_fraction[0] == 1.0f);
  REQUIRE(e.hits == 0);
}

TEST_CASE("The BVH's size is reported and bounded by the mesh's arrays", "[visibility][ao]") {
  const AnalyticMesh am = torus(200, 100);
  const VisibilityScene scene(am.mesh);
  const std::size_t arrays = am.mesh.positions.size() * 8 + am.mesh.corner_vertex.size() * 4;
  REQUIRE(scene.stats().bvh_bytes > 0);
  REQUIRE(scene.stats().bvh_bytes + scene.stats().buffer_bytes < 3 * arrays);
  // All triangles, none degenerate: the mesh's corner array is Embree's index buffer, not copied.
  REQUIRE(scene.stats().shared_indices);
  REQUIRE(scene.stats().buffer_bytes == (3 * am.mesh.num_vertices() + 1) * 4);
}

TEST_CASE("A degenerate face makes a filtered index copy that gives the shared buffer's bits", "[visibility][ao]") {
  const AnalyticMesh am = torus(40, 20);
  Mesh with_degenerate = am.mesh;
  // One face with a repeated index, in the middle of the face list: it must take no part.
  const std::size_t middle = with_degenerate.num_faces() / 2;
  const std::uint32_t c = with_degenerate.face_start[middle];
  with_degenerate.corner_vertex[c + 2] = with_degenerate.corner_vertex[c + 1];
  Mesh without = with_degenerate;  // the same mesh with that face removed: shares its indices
  without.corner_vertex.erase(without.corner_vertex.begin() + c, without.corner_vertex.begin() + c + 3);
  without.face_start.pop_back();
  const VisibilityScene copied(with_degenerate), shared(without);
  REQUIRE_FALSE(copied.stats().shared_indices);
  REQUIRE(shared.stats().shared_indices);
  REQUIRE(copied.stats().degenerate_faces == 1);
  REQUIRE(copied.stats().triangles == shared.stats().triangles);
  REQUIRE(copied.stats().buffer_bytes == shared.stats().buffer_bytes + 12 * shared.stats().triangles);
  AmbientOcclusionOptions o;
  o.samples = 64;
  const std::vector<double> n = vertex_normals(without).normals;
  const AmbientOcclusion a = ambient_occlusion_per_vertex(copied, with_degenerate, n, o);
  const AmbientOcclusion b = ambient_occlusion_per_vertex(shared, without, n, o);
  REQUIRE(a.hits > 0);
  REQUIRE(a.hits == b.hits);
  REQUIRE(std::memcmp(a.open_fraction.data(), b.open_fraction.data(), 4 * a.open_fraction.size()) == 0);
}
