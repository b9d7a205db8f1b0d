// Tests of normals/face_normals: unit normals of triangles and polygons against hand values.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <shadetool/normals/face_normals.h>

using namespace shadetool;

TEST_CASE("face_normals: a right triangle in the xy plane has normal +z, reversed -z", "[face_normals]") {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({2, 0, 0}); m.add_vertex({0, 3, 0});
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 1});
  for (Precision p : {Precision::Double, Precision::Float}) {
    const auto n = face_normals(m, p);
    REQUIRE(n.size() == 6);
    CHECK(n[0] == 0.0); CHECK(n[1] == 0.0); CHECK(n[2] == 1.0);
    CHECK(n[3] == 0.0); CHECK(n[4] == 0.0); CHECK(n[5] == -1.0);
  }
}

TEST_CASE("face_normals: tilted triangle (1,0,0),(0,1,0),(0,0,1) has normal (1,1,1)/sqrt3", "[face_normals]") {
  Mesh m;
  m.add_vertex({1, 0, 0}); m.add_vertex({0, 1, 0}); m.add_vertex({0, 0, 1});
  m.add_face({0, 1, 2});
  const auto n = face_normals(m);
  const double s = 1 / std::sqrt(3.0);
  CHECK(n[0] == Approx(s).epsilon(1e-15)); CHECK(n[1] == Approx(s).epsilon(1e-15)); CHECK(n[2] == Approx(s).epsilon(1e-15));
}

TEST_CASE("face_normals: degenerate faces get (0,0,0), never NaN", "[face_normals]") {
  Mesh m;
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({2, 0, 0});  // collinear
  m.add_vertex({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  m.add_face({0, 1, 2});     // zero area (collinear)
  m.add_face({0, 1, 1});     // repeated index
  m.add_face({0, 1, 3});     // NaN position
  m.add_face({0, 1, 2, 0});  // degenerate quad
  m.add_face({0, 1});        // two corners
  const auto n = face_normals(m);
  REQUIRE(n.size() == 15);
  for (double x : n) CHECK(x == 0.0);
}

TEST_CASE("face_normals: Newell's method on a planar quad and a non-planar (twisted) quad", "[face_normals]") {
  Mesh m;
  // Unit square in the plane x + y + z = 3 seen as a quad; its normal is (1,1,1)/sqrt3.
  m.add_vertex({3, 0, 0}); m.add_vertex({0, 3, 0}); m.add_vertex({0, 0, 3}); m.add_vertex({1.5, -1.5, 3});
  // Check planarity by hand: 1.5 - 1.5 + 3 = 3.
  m.add_face({0, 1, 2, 3});
  // Twisted quad (0,0,0),(1,0,0),(1,1,h),(0,1,-h)... hand value: Newell sum of p_i x p_{i+1}:
  // about p0 = 0: (1,0,0)x(1,1,h) + (1,1,h)x(0,1,-h) = (0,-h,1) + (-h-h, h, 1) = (-2h, 0, 2);
  // with h = 0.5: (-1, 0, 2)/sqrt5.
  m.add_vertex({0, 0, 0}); m.add_vertex({1, 0, 0}); m.add_vertex({1, 1, 0.5}); m.add_vertex({0, 1, -0.5});
  m.add_face({4, 5, 6, 7});
  const auto n = face_normals(m);
  const double s = 1 / std::sqrt(3.0);
  CHECK(n[0] == Approx(s).epsilon(1e-15)); CHECK(n[1] == Approx(s).epsilon(1e-15)); CHECK(n[2] == Approx(s).epsilon(1e-15));
  CHECK(n[3] == Approx(-1 / std::sqrt(5.0)).epsilon(1e-15));
  CHECK(std::fabs(n[4]) < 1e-16);
  CHECK(n[5] == Approx(2 / std::sqrt(5.0)).epsilon(1e-15));
}

TEST_CASE("face_normals: a sliver far from the origin keeps its exact normal (shortest edges)", "[face_normals]") {
  // Triangle in the plane z = 1e6 with a 1e-7 high sliver: the exact normal is +z.
  Mesh m;
  m.add_vertex({1e6, 1e6, 1e6}); m.add_vertex({1e6 + 1, 1e6, 1e6}); m.add_vertex({1e6 + 0.5, 1e6 + 1e-7, 1e6});
  m.add_face({0, 1, 2});
  const auto n = face_normals(m);
  CHECK(n[0] == 0.0); CHECK(n[1] == 0.0); CHECK(n[2] == 1.0);
}

TEST_CASE("face_normals: the two shortest edges beat the two long ones on a needle", "[face_normals]") {
  // Needle in a tilted plane: p1 = p0 + u, p2 = p1 + 1e-7 (w - u/2) with u = (1, 2, 3) and
  // w = (-2, 1, 0): one edge 1e-7 long, making a wide angle with the long edges at p1 and p2.
  // Truth: the normal of the stored (rounded) positions, from the two short edges at p2 in long
  // double (64-bit significand). The long edges p0p1, p0p2 meet at an angle ~1e-7, so their
  // double cross product loses ~7 digits; the shortest pair (at p1 or p2) keeps ~1e-15.
  Mesh m;
  const Vec3d p0{0.3, -0.7, 1.9};
  const Vec3d p1 = p0 + Vec3d{1, 2, 3};
  const Vec3d p2 = p1 + Vec3d{-2.5e-7, 0, -1.5e-7};
  m.add_vertex(p0); m.add_vertex(p1); m.add_vertex(p2);
  m.add_face({0, 1, 2});
  using L = long double;  // truth from the short edge p2 - p1 and p0 - p1 (apex p1 or p2)
  const L a[3] = {L(p2.x) - L(p1.x), L(p2.y) - L(p1.y), L(p2.z) - L(p1.z)};
  const L b[3] = {L(p0.x) - L(p1.x), L(p0.y) - L(p1.y), L(p0.z) - L(p1.z)};
  const L x[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const L len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  const Vec3d exact{double(x[0] / len), double(x[1] / len), double(x[2] / len)};
  const Vec3d n = get3(face_normals(m), 0);
  const Vec3d naive = normalized_or(cross(p1 - p0, p2 - p0), Vec3d{});
  const double err = std::atan2(length(cross(n, exact)), dot(n, exact));
  const double naive_err = std::atan2(length(cross(naive, exact)), dot(naive, exact));
  INFO("shortest-edge error " << err << " rad, long-edge error " << naive_err << " rad");
  CHECK(err < 1e-14);
  CHECK(naive_err > 1e-11);  // the long pair is measurably worse (guards the test's premise)
}
