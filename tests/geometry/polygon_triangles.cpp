// Tests of geometry/polygon_triangles.h: how a polygon is split into triangles (writers, render, occlusion, fit).
// Truth the code did not produce: the polygon's area by the shoelace formula (closed forms for the
// shapes below), each triangle's centroid inside the polygon by a crossing-number test, and, on a
// convex polygon, the fan from corner 0 that the writers wrote before.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

#include "io/io_test_util.h"

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/polygon_triangles.h>

using namespace shadetool;

namespace {

struct Planar {
  std::vector<double> positions;  // #V by 3
  std::vector<std::uint32_t> corners;
  std::vector<std::array<double, 2>> uv;  // the outline in its own plane, as given
};

// The 2D outline (x, y) placed in 3D on the plane `plane` (0: z = 0.5, 1: y = -2, 2: x = 3), read
// in the given order or mirrored (the winding seen from +axis reversed), corners listed as given.
Planar place(const std::vector<std::array<double, 2>>& uv, const std::vector<std::uint32_t>& order, int plane, bool mirror) {
  Planar p;
  p.uv = uv;
  for (const auto& q : uv) {
    const double a = q[0], b = mirror ? -q[1] : q[1];
    if (plane == 0) p.positions.insert(p.positions.end(), {a, b, 0.5});
    if (plane == 1) p.positions.insert(p.positions.end(), {b, -2.0, a});
    if (plane == 2) p.positions.insert(p.positions.end(), {3.0, a, b});
  }
  p.corners = order;
  return p;
}

// Twice the signed area of a 2D triangle.
double twice_area(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Crossing-number point-in-polygon over the outline's edges (corner order), the bridge of a
// keyhole counted twice (it cancels).
bool inside(const std::array<double, 2>& p, const std::vector<std::array<double, 2>>& uv, const std::vector<std::uint32_t>& c) {
  bool in = false;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const auto& a = uv[c[k]];
    const auto& b = uv[c[(k + 1) % c.size()]];
    if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))  // divisor: b.y != a.y here
      in = !in;
  }
  return in;
}

// Every triangle wound as the outline (positive area in the outline's 2D frame when the outline
// is counter-clockwise there), the areas summing to `area`, each centroid inside the outline.
void check_cover(const std::vector<std::array<double, 2>>& uv, const std::vector<std::uint32_t>& c, double area) {
  for (int plane = 0; plane < 3; ++plane) {
    for (bool mirror : {false, true}) {
      const Planar p = place(uv, c, plane, mirror);
      std::vector<std::uint32_t> tri;
      polygon_triangles(p.positions.data(), p.corners.data(), std::uint32_t(c.size()), tri);
      REQUIRE(tri.size() == 3 * (c.size() - 2));
      double sum = 0;
      for (std::size_t t = 0; t < tri.size(); t += 3) {
        const auto &a = uv[c[tri[t]]], &b = uv[c[tri[t + 1]]], &d = uv[c[tri[t + 2]]];
        const double w = twice_area(a, b, d) / 2;
        CHECK(w > 0);  // wound as the polygon: no triangle turned over
        sum += w;
        const std::array<double, 2> g{(a[0] + b[0] + d[0]) / 3, (a[1] + b[1] + d[1]) / 3};
        CHECK(inside(g, uv, c));  // inside the outline (and not in a hole)
      }
      CHECK(sum == Approx(area).epsilon(1e-12));
    }
  }
}

}  // namespace

TEST_CASE("polygon_triangles: a convex polygon gives the fan from corner 0 (what the writers wrote before)", "[geometry][polygon_triangles]") {
  std::vector<std::array<double, 2>> hex;
  for (int k = 0; k < 6; ++k) hex.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  const Planar p = place(hex, {0, 1, 2, 3, 4, 5}, 1, true);
  std::vector<std::uint32_t> tri;
  polygon_triangles(p.positions.data(), p.corners.data(), 6, tri);
  CHECK(tri == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5});
  check_cover(hex, {0, 1, 2, 3, 4, 5}, 1.5 * std::sqrt(3.0));  // regular hexagon of circumradius 1: (3 sqrt 3 / 2) r^2
}

TEST_CASE("polygon_triangles: concave outlines are covered once, inside, none turned over", "[geometry][polygon_triangles]") {
  // An L of three unit squares, its reflex corner at (1, 1) placed where the fan from corner 0
  // would cut outside it: area 3.
  check_cover({{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}}, {0, 1, 2, 3, 4, 5}, 3.0);
  check_cover({{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}}, {0, 1, 2, 3, 4, 5}, 3.0);
  // A comb: base 0..5 x 0..1 with three teeth 1 high at x in [0,1], [2,3], [4,5]: area 5 + 3 = 8.
  check_cover({{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},
              {5, 6, 7, 8, 9, 10, 11, 0, 1, 2, 3, 4}, 8.0);
  // A five-pointed star (outer radius 1, inner 0.4): area 5 * (1 * 0.4 * sin 36 deg).
  std::vector<std::array<double, 2>> star;
  std::vector<std::uint32_t> order;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 ? 0.4 : 1.0, a = M_PI / 2 + k * M_PI / 5;
    star.push_back({r * std::cos(a), r * std::sin(a)});
    order.push_back(std::uint32_t((k + 1) % 10));  // starting at an inner (reflex) corner
  }
  check_cover(star, order, 5 * 1.0 * 0.4 * std::sin(M_PI / 5));
}

TEST_CASE("polygon_triangles: a concave quad (a dart) from each of its corners, and a convex one, by the quad path", "[geometry][polygon_triangles]") {
  // Dart (0,0) (2,1) (0,2) (0.5,1), reflex at (0.5,1): shoelace area (0 + 4 - 1 + 0) / 2 = 1.5.
  const std::vector<std::array<double, 2>> dart{{0, 0}, {2, 1}, {0, 2}, {0.5, 1}};
  for (std::uint32_t r = 0; r < 4; ++r) check_cover(dart, {r, (r + 1) % 4, (r + 2) % 4, (r + 3) % 4}, 1.5);
  // A convex quad: the fan from corner 0, area by shoelace (0 + 6 + 2 - 0) / 2 = 4.
  const std::vector<std::array<double, 2>> quad{{0, 0}, {3, 0}, {2, 2}, {0, 1}};
  check_cover(quad, {0, 1, 2, 3}, 4.0);
  const Planar p = place(quad, {0, 1, 2, 3}, 0, false);
  std::vector<std::uint32_t> tri;
  polygon_triangles(p.positions.data(), p.corners.data(), 4, tri);
  CHECK(tri == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
}

TEST_CASE("polygon_triangles: a square with a square hole joined by a bridge (repeated vertices) is covered around the hole", "[geometry][polygon_triangles]") {
  // blender_minimal/keyhole.obj: outer 4 x 4, hole 2 x 2, area 16 - 4 = 12; corners 0 and 4 repeat.
  const std::vector<std::array<double, 2>> uv{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  check_cover(uv, {0, 1, 2, 3, 0, 4, 7, 6, 5, 4}, 12.0);
}

TEST_CASE("polygon_triangles: assimp's concave_polygon.obj is covered by 64 triangles of its winding, summing to its Newell area", "[geometry][polygon_triangles][xcorpus]") {
  // The fan from corner 0 gave 29 of the 64 triangles turned over (Blender showed them, glb output).
  ReadInfo info;
  const Mesh m = read_mesh(iotest::data_path("corpus_extra/concave_polygon.obj"), Format::Auto, &info);
  REQUIRE(m.num_faces() == 1);
  REQUIRE(m.face_size(0) == 66);
  // The polygon's area vector by Newell's formula, written out here (not the library's).
  double N[3] = {0, 0, 0};
  for (std::uint32_t k = 0; k < 66; ++k) {
    const Vec3d a = m.position(m.corner_vertex[k]), b = m.position(m.corner_vertex[(k + 1) % 66]);
    N[0] += (a.y - b.y) * (a.z + b.z);
    N[1] += (a.z - b.z) * (a.x + b.x);
    N[2] += (a.x - b.x) * (a.y + b.y);
  }
  const double area = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]) / 2;
  std::vector<std::uint32_t> tri;
  polygon_triangles(m.positions.data(), m.corner_vertex.data(), 66, tri);
  REQUIRE(tri.size() == 3 * 64);
  double sum = 0;
  int turned = 0;
  for (std::size_t t = 0; t < tri.size(); t += 3) {
    const Vec3d a = m.position(m.corner_vertex[tri[t]]), b = m.position(m.corner_vertex[tri[t + 1]]),
                c = m.position(m.corner_vertex[tri[t + 2]]);
    const Vec3d x = cross(b - a, c - a);
    const double along = (x.x * N[0] + x.y * N[1] + x.z * N[2]) / (2 * area) / 2;  // divisor: area > 0 (REQUIREd below)
    turned += along < 0;
    sum += along;
  }
  REQUIRE(area > 0);
  CHECK(turned == 0);
  CHECK(sum == Approx(area).epsilon(1e-9));
}

TEST_CASE("polygon_triangles: a convex polygon of many corners takes the O(n) convex test and gives the fan", "[geometry][polygon_triangles]") {
  // A regular 5,000-gon (every corner turns left, the edge directions go round once): the fan from
  // corner 0, (0, k, k + 1), and the triangles' areas sum to the polygon's, (n / 2) sin(2 pi / n).
  const std::uint32_t n = 5000;
  std::vector<std::array<double, 2>> disc;
  std::vector<std::uint32_t> order;
  for (std::uint32_t k = 0; k < n; ++k) {
    disc.push_back({std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)});
    order.push_back(k);
  }
  const Planar p = place(disc, order, 0, false);
  std::vector<std::uint32_t> tri;
  polygon_triangles(p.positions.data(), p.corners.data(), n, tri);
  REQUIRE(tri.size() == 3 * std::size_t(n - 2));
  std::size_t not_fan = 0;
  double sum = 0;
  for (std::uint32_t k = 0; k + 2 < n; ++k) {
    if (tri[3 * k] != 0 || tri[3 * k + 1] != k + 1 || tri[3 * k + 2] != k + 2) ++not_fan;
    sum += twice_area(disc[tri[3 * k]], disc[tri[3 * k + 1]], disc[tri[3 * k + 2]]) / 2;
  }
  CHECK(not_fan == 0);
  CHECK(sum == Approx(0.5 * n * std::sin(2 * M_PI / n)).epsilon(1e-12));
}
