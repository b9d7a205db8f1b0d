// Tests of transform/transform_mesh against analytic truth: a sphere mapped to an ellipsoid, a
// shear of a flat patch, a mirror, translations (bytes unchanged), rotations (unit length without
// renormalisation), the order of composition, and singular maps.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include <shadetool/core/error.h>
#include "support/analytic_meshes.h"
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/transform_mesh.h>

using namespace shadetool;
using shadetool::testing::AnalyticMesh;
using shadetool::testing::angle_degrees;

namespace {

std::vector<double> flatten(const std::vector<Vec3d>& v) {
  std::vector<double> a;
  for (const auto& x : v) a.insert(a.end(), {x.x, x.y, x.z});
  return a;
}

double signed_volume(const Mesh& m) {  // sum over triangles of p0 . (p1 x p2) / 6
  double vol = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t* c = &m.corner_vertex[m.face_start[f]];
    vol += dot(m.position(c[0]), cross(m.position(c[1]), m.position(c[2]))) / 6;
  }
  return vol;
}

Vec3d triangle_normal(const Mesh& m, std::size_t f) {
  const std::uint32_t* c = &m.corner_vertex[m.face_start[f]];
  const Vec3d p0 = m.position(c[0]);
  return normalized_or(cross(m.position(c[1]) - p0, m.position(c[2]) - p0), Vec3d{0, 0, 0});
}

// Unit face normals from the positions (the truth for a flat triangle).
std::vector<double> exact_face_normals(const Mesh& m) {
  std::vector<double> n;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const Vec3d x = triangle_normal(m, f);
    n.insert(n.end(), {x.x, x.y, x.z});
  }
  return n;
}

float to_float(double x) { return static_cast<float>(x); }

}  // namespace

TEST_CASE("transform_mesh: unit sphere scaled by (1,2,3) and rotated has the ellipsoid's normals",
          "[transform_mesh]") {
  // The sphere's exact normals, mapped by --scale 1,2,3 --rotate 30,1,1,1, must equal R times the
  // analytic normal of x^2 + y^2/4 + z^2/9 = 1 at the same parameter: uv_ellipsoid(.., 1, 2, 3)
  // generates exactly S p for every sphere vertex p, with its exact normal (x, y/4, z/9)/|.|.
  AnalyticMesh sphere = testing::uv_sphere(48, 24, 0.3, 5);
  const AnalyticMesh ellipsoid = testing::uv_ellipsoid(48, 24, 1, 2, 3, 0.3, 5);
  sphere.mesh.vertex_normals = flatten(sphere.exact_normals);
  sphere.mesh.face_normals = exact_face_normals(sphere.mesh);
  const Affine3d R = rotation_map(30, {1, 1, 1});
  const Affine3d M = compose_in_order({scale_map({1, 2, 3}), R});

  Mesh m = sphere.mesh;
  const TransformReport r = transform_mesh(m, M);
  CHECK(r.affine.path == TransformPath::General);
  CHECK_FALSE(r.winding_reversed);
  CHECK(std::string(r.normals) == "transformed");

  double worst = 0, worst_face = 0, worst_position = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d truth = R.A * ellipsoid.exact_normals[v];
    const Vec3d got = get3(m.vertex_normals, v);
    worst = std::max(worst, length(got - truth));
    worst_position = std::max(worst_position, length(m.position(v) - R.A * ellipsoid.mesh.position(v)));
  }
  // Face normals: a flat triangle's normal is the normal of its mapped plane (from the new positions).
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    worst_face = std::max(worst_face, length(get3(m.face_normals, f) - triangle_normal(m, f)));
  INFO("max |n - exact| over vertices: " << worst << ", faces: " << worst_face);
  CHECK(worst_position < 1e-14);
  CHECK(worst < 1e-9);       // the bound in double
  CHECK(worst < 1e-14);      // what the cofactor actually achieves (a few roundings)
  CHECK(worst_face < 1e-9);  // faces: the truth is itself computed from rounded positions
}

TEST_CASE("transform_mesh: the ellipsoid test with float data stays within 1e-5 degrees", "[transform_mesh]") {
  // Input positions and normals rounded to float (as read from a binary PLY), output rounded to
  // float (as written): the angle to the exact ellipsoid normal stays below 1e-5 degrees.
  AnalyticMesh sphere = testing::uv_sphere(48, 24, 0.3, 5);
  const AnalyticMesh ellipsoid = testing::uv_ellipsoid(48, 24, 1, 2, 3, 0.3, 5);
  Mesh m = sphere.mesh;
  m.precision = ValuePrecision::Float;
  m.vertex_normals = flatten(sphere.exact_normals);
  for (auto& x : m.positions) x = to_float(x);
  for (auto& x : m.vertex_normals) x = to_float(x);
  const Affine3d R = rotation_map(30, {1, 1, 1});
  transform_mesh(m, compose_in_order({scale_map({1, 2, 3}), R}));
  double worst = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d got{to_float(m.vertex_normals[3 * v]), to_float(m.vertex_normals[3 * v + 1]),
                    to_float(m.vertex_normals[3 * v + 2])};
    worst = std::max(worst, angle_degrees(got, R.A * ellipsoid.exact_normals[v]));
  }
  INFO("max angle to the exact ellipsoid normal (float in and out): " << worst << " degrees");
  CHECK(worst < 1e-5);
}

TEST_CASE("transform_mesh: after a shear, normals stay perpendicular to every transformed edge of a flat patch",
          "[transform_mesh]") {
  // A hexagonal fan in the plane through c with normal m: every edge t at the centre has t.m = 0.
  // After any A, the edges are A t and the normal must satisfy (A t).n' = 0 (the seeds' argument).
  const Vec3d m_dir = normalized_or(Vec3d{1, 2, 3}, Vec3d{0, 0, 1});
  const Vec3d u = normalized_or(cross(m_dir, Vec3d{0, 0, 1}), Vec3d{1, 0, 0}), w = cross(m_dir, u);
  const Vec3d c{0.5, -1, 2};
  Mesh mesh;
  mesh.add_vertex(c);
  for (int k = 0; k < 6; ++k) {
    const double a = k * testing::kPi / 3 + 0.1 * k * k;  // irregular spokes
    mesh.add_vertex(c + u * ((1 + 0.2 * k) * std::cos(a)) + w * ((1 + 0.2 * k) * std::sin(a)));
  }
  for (std::uint32_t k = 0; k < 6; ++k) mesh.add_face({0, 1 + k, 1 + (k + 1) % 6});
  mesh.vertex_normals.assign(7 * 3, 0);
  for (std::size_t v = 0; v < 7; ++v) set3(mesh.vertex_normals, v, m_dir);
  mesh.face_normals = exact_face_normals(mesh);
  mesh.corner_normals = {m_dir.x, m_dir.y, m_dir.z};
  mesh.corner_normal_index.assign(mesh.num_corners(), 0);

  Affine3d shear_xy;
  shear_xy.A.m = {{{1, 0.8, 0}, {0, 1, 0}, {0, 0, 1}}};
  Affine3d shear_mixed;
  shear_mixed.A.m = {{{1, 0.8, -0.3}, {0.1, 1, 0.5}, {-0.7, 0.2, 1}}};
  shear_mixed.t = {3, -2, 1};
  Affine3d shear_mirror;
  shear_mirror.A.m = {{{-1, 2.5, 0}, {0, 1, 0}, {0.4, 0, 1}}};
  for (const Affine3d& A : {shear_xy, shear_mixed, shear_mirror}) {
    Mesh m = mesh;
    const TransformReport r = transform_mesh(m, A);
    REQUIRE(r.affine.path == TransformPath::General);
    const Vec3d centre = m.position(0);
    double worst = 0;
    for (std::size_t k = 1; k <= 6; ++k) {
      const Vec3d t = m.position(k) - centre;
      for (const Vec3d& n : {get3(m.vertex_normals, 0), get3(m.vertex_normals, k), get3(m.corner_normals, 0)})
        worst = std::max(worst, std::fabs(dot(n, t)) / length(t));
    }
    for (std::size_t f = 0; f < m.num_faces(); ++f) {
      const Vec3d n = get3(m.face_normals, f);
      // Faces agree with their recomputed normal, including after the mirror's re-winding.
      CHECK(dot(n, triangle_normal(m, f)) > 1 - 1e-14);
      for (std::size_t k = 1; k <= 6; ++k) {
        const Vec3d t = m.position(k) - centre;
        worst = std::max(worst, std::fabs(dot(n, t)) / length(t));
      }
    }
    INFO("max |n.t| / |t| = " << worst);
    CHECK(worst < 1e-14);
    CHECK(r.winding_reversed == (A.A.m[0][0] < 0));
  }
}

TEST_CASE("transform_mesh: mirror --scale -1,1,1 reverses winding, keeps volume positive, normals outward",
          "[transform_mesh]") {
  AnalyticMesh ico = testing::icosphere(3, 0.2, 3);
  Mesh m = ico.mesh;
  m.vertex_normals = flatten(ico.exact_normals);
  m.face_normals = exact_face_normals(m);
  const double volume_before = signed_volume(m);
  REQUIRE(volume_before > 4.0);  // ~ 4/3 pi for a fine icosphere

  const TransformReport r = transform_mesh(m, scale_map({-1, 1, 1}));
  CHECK(r.affine.path == TransformPath::Rotation);
  CHECK(r.affine.mirror);
  CHECK(r.winding_reversed);
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t* before = &ico.mesh.corner_vertex[3 * f];
    const std::uint32_t* after = &m.corner_vertex[3 * f];
    CHECK((after[0] == before[0] && after[1] == before[2] && after[2] == before[1]));
  }
  CHECK(signed_volume(m) == Approx(volume_before).epsilon(1e-14));
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    // Unit sphere: the outward normal at p' is p' itself; exact here (a sign flip is exact).
    const Vec3d n = get3(m.vertex_normals, v), p = m.position(v);
    CHECK(n == Vec3d(-ico.exact_normals[v].x, ico.exact_normals[v].y, ico.exact_normals[v].z));
    CHECK(dot(n, p) > 0.99);
  }
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const Vec3d n = get3(m.face_normals, f);
    CHECK(dot(n, triangle_normal(m, f)) > 1 - 1e-14);  // agrees with the re-wound face
    const std::uint32_t* c = &m.corner_vertex[3 * f];
    CHECK(dot(n, m.position(c[0]) + m.position(c[1]) + m.position(c[2])) > 0);  // outward
  }
}

TEST_CASE("transform_mesh: a mirror of a mesh without faces reports no winding reversed (nothing to re-wind)",
          "[transform_mesh]") {
  Mesh points;
  points.positions = {1, 2, 3, -4, 5, 6};
  points.vertex_normals = {0, 0, 1, 1, 0, 0};
  const TransformReport r = transform_mesh(points, scale_map({-1, 1, 1}));
  CHECK(r.affine.mirror);
  CHECK_FALSE(r.winding_reversed);
  CHECK(points.num_faces() == 0);
  CHECK(points.positions == std::vector<double>{-1, 2, 3, 4, 5, 6});
  // Normals of a mirror: sign(det) cof(A) n = (-n_x, n_y, n_z) for diag(-1, 1, 1).
  CHECK(points.vertex_normals == std::vector<double>{0, 0, 1, -1, 0, 0});
}

TEST_CASE("transform_mesh: a general mirror (--scale -2,1,3) keeps volume sign and outward normals",
          "[transform_mesh]") {
  AnalyticMesh ico = testing::icosphere(3);
  Mesh m = ico.mesh;
  m.vertex_normals = flatten(ico.exact_normals);
  const double volume_before = signed_volume(m);
  const TransformReport r = transform_mesh(m, scale_map({-2, 1, 3}));
  CHECK(r.affine.path == TransformPath::General);
  CHECK(r.winding_reversed);
  CHECK(signed_volume(m) == Approx(6 * volume_before).epsilon(1e-13));  // |det| = 6
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    // Ellipsoid x^2/4 + y^2 + z^2/9 = 1: outward normal (x/4, y, z/9) at p'.
    const Vec3d p = m.position(v);
    const Vec3d truth = normalized_or(Vec3d{p.x / 4, p.y, p.z / 9}, Vec3d{0, 0, 0});
    CHECK(length(get3(m.vertex_normals, v) - truth) < 1e-14);
  }
}

TEST_CASE("transform_mesh: translation moves positions only; normal bytes are unchanged", "[transform_mesh]") {
  AnalyticMesh sphere = testing::uv_sphere(16, 8, 0.3, 9);
  Mesh m = sphere.mesh;
  m.vertex_normals = flatten(sphere.exact_normals);
  m.face_normals = exact_face_normals(m);
  m.corner_normals = m.vertex_normals;
  m.corner_normal_index = m.corner_vertex;
  const Mesh before = m;
  const TransformReport r = transform_mesh(m, translation_map({0.1, -2, 1e6}));
  CHECK(r.affine.path == TransformPath::Translation);
  CHECK(std::string(r.normals) == "untouched");
  REQUIRE(m.vertex_normals.size() == before.vertex_normals.size());
  CHECK(std::memcmp(m.vertex_normals.data(), before.vertex_normals.data(), m.vertex_normals.size() * 8) == 0);
  CHECK(std::memcmp(m.face_normals.data(), before.face_normals.data(), m.face_normals.size() * 8) == 0);
  CHECK(std::memcmp(m.corner_normals.data(), before.corner_normals.data(), m.corner_normals.size() * 8) == 0);
  CHECK(m.corner_vertex == before.corner_vertex);
  CHECK(m.corner_normal_index == before.corner_normal_index);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    CHECK(m.positions[3 * v] == before.positions[3 * v] + 0.1);  // one addition, nothing else
    CHECK(m.positions[3 * v + 1] == before.positions[3 * v + 1] - 2);
    CHECK(m.positions[3 * v + 2] == before.positions[3 * v + 2] + 1e6);
  }
}

TEST_CASE("transform_mesh: identity is a copy", "[transform_mesh]") {
  AnalyticMesh sphere = testing::icosphere(1);
  Mesh m = sphere.mesh;
  m.vertex_normals = flatten(sphere.exact_normals);
  const Mesh before = m;
  const TransformReport r = transform_mesh(m, compose_in_order({rotation_map(90, {0, 0, 1}), rotation_map(270, {0, 0, 1})}));
  CHECK(r.affine.path == TransformPath::Identity);
  CHECK(std::memcmp(m.positions.data(), before.positions.data(), m.positions.size() * 8) == 0);
  CHECK(std::memcmp(m.vertex_normals.data(), before.vertex_normals.data(), m.vertex_normals.size() * 8) == 0);
}

TEST_CASE("transform_mesh: rotation keeps unit normals unit to 1e-7 without renormalising", "[transform_mesh]") {
  AnalyticMesh torus = testing::torus(40, 20, 1.0, 0.4, 0.3, 4);
  Mesh m = torus.mesh;
  m.vertex_normals = flatten(torus.exact_normals);
  // Five composed rotations about skew axes; angles between normals must be preserved too.
  std::vector<Affine3d> maps;
  for (int i = 0; i < 5; ++i) maps.push_back(rotation_map(23.0 + 41 * i, {1.0 + i, -2.0, 0.5 * i}));
  const Affine3d M = compose_in_order(maps);
  const TransformReport r = transform_mesh(m, M);
  REQUIRE(r.affine.path == TransformPath::Rotation);
  double worst_length = 0, worst_truth = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d n = get3(m.vertex_normals, v);
    worst_length = std::max(worst_length, std::fabs(length(n) - 1));
    worst_truth = std::max(worst_truth, length(n - M.A * torus.exact_normals[v]));
  }
  INFO("max ||n| - 1| = " << worst_length);
  CHECK(worst_length < 1e-7);   // the bound
  CHECK(worst_length < 1e-14);  // measured: a few roundings
  CHECK(worst_truth < 1e-14);
  // Angle between two normals is unchanged (a rotation is an isometry).
  const Vec3d a0 = torus.exact_normals[0], a1 = torus.exact_normals[7];
  CHECK(angle_degrees(get3(m.vertex_normals, 0), get3(m.vertex_normals, 7)) == Approx(angle_degrees(a0, a1)).margin(1e-12));
}

TEST_CASE("transform_mesh: uniform scale with rotation rotates normals only", "[transform_mesh]") {
  AnalyticMesh ico = testing::icosphere(2);
  Mesh a = ico.mesh, b = ico.mesh;
  a.vertex_normals = b.vertex_normals = flatten(ico.exact_normals);
  const Affine3d R = rotation_map(70, {0, 1, 1});
  const TransformReport ra = transform_mesh(a, compose_in_order({R, scale_map({2.5, 2.5, 2.5})}));
  transform_mesh(b, R);
  CHECK(ra.affine.path == TransformPath::UniformScale);
  for (std::size_t i = 0; i < a.vertex_normals.size(); ++i) CHECK(a.vertex_normals[i] == Approx(b.vertex_normals[i]).margin(1e-15));
  for (std::size_t i = 0; i < a.positions.size(); ++i) CHECK(a.positions[i] == Approx(2.5 * b.positions[i]).margin(1e-14));
}

TEST_CASE("transform_mesh: --rotate 90,0,0,1 --translate 1,0,0 differs from the reverse order", "[transform_mesh]") {
  // Documented in the man page: the first flag acts first. Vertex (1,0,0):
  //   rotate then translate: (0,1,0) + (1,0,0) = (1,1,0);   translate then rotate: R (2,0,0) = (0,2,0).
  Mesh mesh;
  mesh.add_vertex({1, 0, 0}); mesh.add_vertex({0, 1, 0}); mesh.add_vertex({0, 0, 1});
  mesh.add_face({0, 1, 2});
  mesh.vertex_normals = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  Mesh rt = mesh, tr = mesh;
  transform_mesh(rt, compose_in_order({rotation_map(90, {0, 0, 1}), translation_map({1, 0, 0})}));
  transform_mesh(tr, compose_in_order({translation_map({1, 0, 0}), rotation_map(90, {0, 0, 1})}));
  CHECK(rt.position(0) == Vec3d(1, 1, 0));
  CHECK(tr.position(0) == Vec3d(0, 2, 0));
  CHECK(rt.position(1) == Vec3d(0, 0, 0));   // (0,1,0) -> (-1,0,0) -> (0,0,0)
  CHECK(tr.position(1) == Vec3d(-1, 1, 0));  // (1,1,0) -> (-1,1,0)
  // Normals do not see translations: both orders rotate them the same way, exactly.
  CHECK(rt.vertex_normals == std::vector<double>{0, 1, 0, -1, 0, 0, 0, 0, 1});
  CHECK(tr.vertex_normals == rt.vertex_normals);
}

TEST_CASE("transform_mesh: singular maps are refused unless normals are dropped", "[transform_mesh]") {
  AnalyticMesh ico = testing::icosphere(1);
  Mesh m = ico.mesh;
  m.vertex_normals = flatten(ico.exact_normals);
  for (const Affine3d& M : {scale_map({1, 1, 0}), scale_map({1, 1, 1e-11})}) {
    Mesh x = m;
    CHECK_THROWS_WITH(transform_mesh(x, M, {}, "in.obj"),
                      Catch::StartsWith("in.obj: the transform is singular or nearly so") &&
                          Catch::Contains("--normals drop"));
    CHECK(x.positions == m.positions);  // refused before touching anything
    TransformOptions drop;
    drop.normals = NormalsPolicy::Drop;
    const TransformReport r = transform_mesh(x, M, drop, "in.obj");
    CHECK(r.affine.path == TransformPath::Singular);
    CHECK(std::string(r.normals) == "dropped");
    CHECK(x.vertex_normals.empty());
    CHECK(x.position(0).z == M.A.m[2][2] * m.position(0).z);
  }
}

TEST_CASE("transform_mesh: non-finite positions are refused with the input's name", "[transform_mesh]") {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({0, std::nan(""), 0});
  m.add_face({0, 1, 2});
  CHECK_THROWS_WITH(transform_mesh(m, scale_map({2, 2, 2}), {}, "bad.ply"), Catch::StartsWith("bad.ply: 1 vertex has NaN"));
}

TEST_CASE("transform_mesh: zero and NaN input normals are left as read and counted", "[transform_mesh]") {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({0, 1, 0});
  m.add_face({0, 1, 2});
  m.vertex_normals = {0, 0, 0, std::nan(""), 0, 1, 0, 0, 1};
  const TransformReport r = transform_mesh(m, scale_map({1, 2, 3}));
  CHECK(r.normals_left == 2);
  CHECK(r.normals_mapped == 1);
  CHECK((m.vertex_normals[0] == 0 && m.vertex_normals[1] == 0 && m.vertex_normals[2] == 0));
  CHECK(std::isnan(m.vertex_normals[3]));
  CHECK(get3(m.vertex_normals, 2) == Vec3d(0, 0, 1));
}

TEST_CASE("transform_mesh: a uniform mirror (--scale -2) turns the sphere inside out and back outward",
          "[transform_mesh]") {
  // -2 I = 2 (-I): uniform scale times an improper orthogonal matrix (det -8 < 0). Normals are
  // mapped by Q = A / s = -I, the faces are re-wound, and the result is outward: n' = p' / |p'|.
  AnalyticMesh ico = testing::icosphere(2);
  Mesh m = ico.mesh;
  m.vertex_normals = flatten(ico.exact_normals);
  const double volume_before = signed_volume(m);
  const TransformReport r = transform_mesh(m, scale_map({-2, -2, -2}));
  CHECK(r.affine.path == TransformPath::UniformScale);
  CHECK(r.affine.mirror);
  CHECK(r.winding_reversed);
  CHECK(signed_volume(m) == Approx(8 * volume_before).epsilon(1e-14));
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d p = m.position(v);
    CHECK(length(get3(m.vertex_normals, v) - p * 0.5) < 1e-15);  // |p'| = 2
    CHECK(get3(m.vertex_normals, v) == -ico.exact_normals[v]);
  }
}

TEST_CASE("transform_mesh: PLY tangents tx ty tz tw follow the map (A t, w flipped by a mirror) or go with recomputed normals",
          "[transform][tangents]") {
  // One triangle whose vertices carry the normal n = (0, 0.6, 0.8) and the tangent t = (1, 0, 0)
  // (orthogonal, as tangent_vertices.h stores them), w = +1. They were kept as read before, stale
  // after any rotation.
  auto make = [] {
    Mesh m;
    m.add_vertex({0, 0, 0});
    m.add_vertex({1, 0, 0});
    m.add_vertex({0, -0.8, 0.6});
    m.add_face({0, 1, 2});
    m.vertex_normals = {0, 0.6, 0.8, 0, 0.6, 0.8, 0, 0.6, 0.8};
    for (const char* n : {"tx", "ty", "tz", "tw"})
      m.vertex_properties.push_back(MeshProperty{n, "float", std::vector<double>(3, std::string(n) == "tx" || std::string(n) == "tw" ? 1.0 : 0.0)});
    return m;
  };
  auto prop = [](const Mesh& m, const char* n) -> const std::vector<double>* {
    for (const MeshProperty& p : m.vertex_properties)
      if (p.name == n) return &p.values;
    return nullptr;
  };
  SECTION("a rotation by 90 degrees about z turns t into (0, 1, 0)") {
    Mesh m = make();
    const TransformReport r = transform_mesh(m, rotation_map(90, {0, 0, 1}));
    CHECK(std::string(r.tangents) == "mapped");
    CHECK(r.tangents_mapped == 3);
    CHECK((*prop(m, "tx"))[0] == Approx(0).margin(1e-15));
    CHECK((*prop(m, "ty"))[0] == Approx(1).epsilon(1e-15));
    CHECK((*prop(m, "tw"))[0] == 1.0);
  }
  SECTION("a mirror x -> -x: t = (-1, 0, 0) and w = -1") {
    Mesh m = make();
    transform_mesh(m, scale_map({-1, 1, 1}));
    CHECK((*prop(m, "tx"))[1] == -1.0);
    CHECK((*prop(m, "tw"))[1] == -1.0);
  }
  SECTION("a shear with non-uniform scale: t' = A t / |A t|, still orthogonal to the mapped normal") {
    Mesh m = make();
    Affine3d M;
    M.A.m = {{{2, 1, 0.5}, {0, 1, 0.3}, {0.2, 0, 3}}};
    transform_mesh(m, M);
    const Vec3d at{2, 0, 0.2};  // A (1, 0, 0)
    const double len = std::sqrt(dot(at, at));
    const Vec3d t{(*prop(m, "tx"))[2], (*prop(m, "ty"))[2], (*prop(m, "tz"))[2]};
    CHECK(t.x == Approx(at.x / len).epsilon(1e-14));
    CHECK(t.z == Approx(at.z / len).epsilon(1e-14));
    const Vec3d n{m.vertex_normals[6], m.vertex_normals[7], m.vertex_normals[8]};
    CHECK(std::fabs(dot(t, n)) < 1e-14);
  }
  SECTION("recomputed normals: the tangents that belonged to the old ones are removed") {
    Mesh m = make();
    TransformOptions o;
    o.normals = NormalsPolicy::Recompute;
    const TransformReport r = transform_mesh(m, rotation_map(30, {1, 0, 0}), o);
    CHECK(std::string(r.tangents) == "dropped");
    CHECK(prop(m, "tx") == nullptr);
    CHECK(prop(m, "tw") == nullptr);
  }
}
