// Numerical stress tests of lib/transform: near-singular and mirror maps, rotations by 1e-9
// degrees, maps that would send positions beyond double's range. Expected outcomes are written
// beside each case, with the arithmetic.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include <shadetool/core/affine.h>
#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/normals/face_normals.h>
#include "stress/stress_util.h"
#include "support/analytic_meshes.h"
#include <shadetool/transform/affine_maps.h>
#include <shadetool/transform/transform_mesh.h>

using namespace shadetool;
using namespace shadetool::stress;

namespace {

// A unit sphere whose vertex normals are its exact normals (n = p / |p|).
Mesh sphere_with_normals(int levels = 2) {
  testing::AnalyticMesh am = testing::icosphere(levels);
  Mesh m = am.mesh;
  m.precision = ValuePrecision::Double;
  m.vertex_normals.clear();
  for (const Vec3d& n : am.exact_normals) m.vertex_normals.insert(m.vertex_normals.end(), {n.x, n.y, n.z});
  return m;
}

Vec3d normalized_ld(long double x, long double y, long double z) {
  const long double l = std::sqrt(x * x + y * y + z * z);
  return {double(x / l), double(y / l), double(z / l)};
}

}  // namespace

TEST_CASE("stress: a map squashing z by 1e-8 transforms normals to the ellipsoid's exact normals", "[stress][transform]") {
  // A = diag(1, 1, e), e = 1e-8: relative_det = e / ((2 + e^2) / 3)^(3/2) = 1.84e-8 > 1e-9, so the
  // map is General (not refused). The unit sphere becomes the ellipsoid x^2 + y^2 + (z/e)^2 = 1,
  // whose normal at the image (x, y, e z) of p = (x, y, z) is grad = (x, y, z / e), i.e. along
  // (e x, e y, z) -- exactly cof(A) n = diag(e, e, 1) n with n = p. Truth computed in long double
  // from the stored normal; expected angle error <= 8 u (one rounding per component, then a
  // normalisation).
  const double e = 1e-8;
  Mesh m = sphere_with_normals();
  const Mesh before = m;
  const TransformReport rep = transform_mesh(m, scale_map({1, 1, e}));
  CHECK(rep.affine.path == TransformPath::General);
  CHECK_FALSE(rep.winding_reversed);
  REQUIRE(all_finite(m.vertex_normals));
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d n = get3(before.vertex_normals, v);
    const Vec3d truth = normalized_ld((long double)e * n.x, (long double)e * n.y, n.z);
    INFO("vertex " << v << " normal " << n.x << " " << n.y << " " << n.z);
    CHECK(angle_between(get3(m.vertex_normals, v), truth) <= 8 * kU);
    CHECK(std::fabs(length(get3(m.vertex_normals, v)) - 1) <= 4 * kU);
    CHECK(m.positions[3 * v + 2] == before.positions[3 * v + 2] * e);  // one rounding: a product
  }
  CHECK(m.corner_vertex == before.corner_vertex);
}

TEST_CASE("stress: a map squashing z by 1e-10 is refused for normals, recompute gives finite unit normals",
          "[stress][transform]") {
  // relative_det = 1.84e-10 < 1e-9 (kSingularTolerance): the normal transform is unreliable, so
  // transform_mesh refuses (Error) with the normals policy Transform; with Recompute the normals
  // come from the squashed faces (areas ~1e-10 x edge^2: well inside double), all finite and unit.
  const Mesh original = sphere_with_normals();
  {
    Mesh m = original;
    CHECK_THROWS_AS(transform_mesh(m, scale_map({1, 1, 1e-10})), Error);
  }
  Mesh m = original;
  TransformOptions options;
  options.normals = NormalsPolicy::Recompute;
  const TransformReport rep = transform_mesh(m, scale_map({1, 1, 1e-10}), options);
  CHECK(rep.affine.path == TransformPath::Singular);
  REQUIRE(all_finite(m.vertex_normals));
  for (std::size_t v = 0; v < m.num_vertices(); ++v) CHECK(std::fabs(length(get3(m.vertex_normals, v)) - 1) <= 4 * kU);
  // Away from the equator (|z| > 0.5 on the unit sphere) every face has |n_z| >= 0.4 before the
  // squash; after it its normal is along (e n_x, e n_y, n_z), tilted from +-z by at most
  // e |n_xy| / |n_z| <= 1e-10 * 2.5: expected |n_z| >= 1 - 1e-8 there. (Faces straddling the
  // equator stay steep: (e n_x, e n_y, n_z) with n_z ~ 0 is still horizontal.)
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    if (std::fabs(original.positions[3 * v + 2]) > 0.5) CHECK(std::fabs(m.vertex_normals[3 * v + 2]) >= 1 - 1e-8);
  CHECK(m.num_faces() == original.num_faces());
}

TEST_CASE("stress: a fully singular map (rank 2) keeps positions finite and refuses to invent normals", "[stress][transform]") {
  // A = diag(1, 1, 0): projection onto z = 0. Normals: refused (Transform) -- there is no normal
  // transform; with Drop the mesh loses its normals and keeps every face; nothing is NaN.
  Mesh m = sphere_with_normals();
  CHECK_THROWS_AS(transform_mesh(m, scale_map({1, 1, 0})), Error);
  TransformOptions drop;
  drop.normals = NormalsPolicy::Drop;
  Mesh d = sphere_with_normals();
  const std::size_t faces = d.num_faces();
  transform_mesh(d, scale_map({1, 1, 0}), drop);
  CHECK(d.num_faces() == faces);
  CHECK(all_finite(d.positions));
  CHECK(d.vertex_normals.empty());
  for (std::size_t v = 0; v < d.num_vertices(); ++v) CHECK(d.positions[3 * v + 2] == 0);
}

TEST_CASE("stress: mirrors flip exactly one normal component and re-wind every face", "[stress][transform]") {
  // A = diag(-1, 1, 1): sign(det) cof(A) = -1 * diag(1 * 1, -1 * 1, -1 * 1) = diag(-1, 1, 1), so
  // n' = (-nx, ny, nz) exactly (a Rotation-path map with mirror = true: n' = A n, no rounding).
  // The faces are re-wound (reversed), so face normals recomputed from the new faces point the
  // way the transformed vertex normals do: outward, positive dot everywhere.
  // Also a general mirror, A = diag(-2, 3, 0.5) (det -3): cof(diag(a, b, c)) = diag(bc, ac, ab) =
  // diag(1.5, -1, -6), times sign(det) = -1: n' ~ (-1.5 nx, ny, 6 nz), checked in long double.
  for (const Vec3d s : {Vec3d{-1, 1, 1}, Vec3d{-2, 3, 0.5}}) {
    Mesh m = sphere_with_normals();
    const Mesh before = m;
    const TransformReport rep = transform_mesh(m, scale_map(s));
    INFO("scale " << s.x << " " << s.y << " " << s.z);
    CHECK(rep.affine.mirror);
    CHECK(rep.winding_reversed);
    REQUIRE(m.num_faces() == before.num_faces());
    for (std::size_t f = 0; f < m.num_faces(); ++f) {
      // same corners, reversed order (the first corner may stay first)
      std::vector<std::uint32_t> a(before.corner_vertex.begin() + before.face_start[f],
                                   before.corner_vertex.begin() + before.face_start[f + 1]);
      std::vector<std::uint32_t> b(m.corner_vertex.begin() + m.face_start[f], m.corner_vertex.begin() + m.face_start[f + 1]);
      std::reverse(b.begin(), b.end());
      bool same = false;
      for (std::size_t r = 0; r < b.size() && !same; ++r) {
        same = a == b;
        std::rotate(b.begin(), b.begin() + 1, b.end());
      }
      CHECK(same);
    }
    const auto fn = face_normals(m);
    for (std::size_t f = 0; f < m.num_faces(); ++f) {
      const std::uint32_t v = m.corner_vertex[m.face_start[f]];
      CHECK(dot(get3(fn, f), get3(m.vertex_normals, v)) > 0);
    }
    // cof(diag(a,b,c)) = diag(bc, ac, ab); times sign(det).
    const long double sg = s.x * s.y * s.z < 0 ? -1 : 1;
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      const Vec3d n = get3(before.vertex_normals, v);
      const Vec3d truth = normalized_ld(sg * s.y * s.z * n.x, sg * s.x * s.z * n.y, sg * s.x * s.y * n.z);
      CHECK(angle_between(get3(m.vertex_normals, v), truth) <= 8 * kU);
    }
    if (s.y == 1) {  // the pure reflection: exact
      for (std::size_t v = 0; v < m.num_vertices(); ++v) {
        CHECK(m.vertex_normals[3 * v] == -before.vertex_normals[3 * v]);
        CHECK(m.vertex_normals[3 * v + 1] == before.vertex_normals[3 * v + 1]);
        CHECK(m.vertex_normals[3 * v + 2] == before.vertex_normals[3 * v + 2]);
      }
    }
  }
}

TEST_CASE("stress: a rotation by 1e-9 degrees turns every normal by exactly that angle", "[stress][transform]") {
  // theta = 1e-9 deg = 1.745e-11 rad about z. A normal n turns by the angle theta * |n_xy| / |n|...
  // more precisely the angle between n and R n is 2 asin(sin(theta / 2) |n_xy|) for unit n,
  // = theta |n_xy| to within theta^3. The computed R n has rounding ~u per component, so the
  // measured angle (atan2 of |n x n'|, whose O(1) terms cancel to O(theta) with an absolute error
  // of a few u) is within 8u = 8.9e-16 rad absolute, i.e. a relative error of 5e-5 at
  // |n_xy| = 1. Positions move by theta |p_xy| to within 4u |p|; z is untouched (R's last row is
  // exactly 0 0 1: cos(theta) rounds to 1).
  const double deg = 1e-9;
  const double theta = deg * 3.14159265358979323846 / 180;
  Mesh m = sphere_with_normals();
  const Mesh before = m;
  const TransformReport rep = transform_mesh(m, rotation_map(deg, {0, 0, 1}));
  CHECK(rep.affine.path == TransformPath::Rotation);  // not mistaken for the identity
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d n = get3(before.vertex_normals, v);
    const double nxy = std::hypot(n.x, n.y);
    INFO("vertex " << v);
    CHECK(std::fabs(angle_between(get3(m.vertex_normals, v), n) - theta * nxy) <= 8 * kU);
    const Vec3d p = get3(before.positions, v), q = get3(m.positions, v);
    CHECK(std::fabs(length(q - p) - theta * std::hypot(p.x, p.y)) <= 4 * kU * length(p));
    CHECK(q.z == p.z);
  }
  // A thousand such rotations composed: 1e-6 degrees in all; 1000 matrix products add ~1000 u of
  // rounding to the entries: expected within 1e-12 rad of 1000 theta |n_xy|.
  std::vector<Affine3d> steps(1000, rotation_map(deg, {0, 0, 1}));
  Mesh k = sphere_with_normals();
  transform_mesh(k, compose_in_order(steps));
  for (std::size_t v = 0; v < k.num_vertices(); ++v) {
    const Vec3d n = get3(before.vertex_normals, v);
    CHECK(std::fabs(angle_between(get3(k.vertex_normals, v), n) - 1000 * theta * std::hypot(n.x, n.y)) <= 1e-12);
  }
}

TEST_CASE("stress: a transform that would overflow the positions is refused, not written as Inf", "[stress][transform]") {
  // Positions of size 1e30 scaled by 1e300: 1e330 is beyond double (1.8e308). Expected: an Error
  // naming the problem (exit 1 at the command line); never a mesh holding Inf.
  Mesh m = sphere_with_normals(1);
  for (double& x : m.positions) x *= 1e30;
  Mesh copy = m;
  bool threw = false;
  try {
    transform_mesh(copy, scale_map({1e300, 1e300, 1e300}));
  } catch (const Error&) {
    threw = true;
  }
  CHECK((threw || (all_finite(copy.positions) && all_finite(copy.vertex_normals))));
  CHECK(threw);
}
