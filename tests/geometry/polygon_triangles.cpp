// Tests of geometry/polygon_triangles.h: how a polygon is split into triangles (writers, render, occlusion, fit).
// Truth the code did not produce: the polygon's area by the shoelace formula (closed forms for the
// shapes below), each triangle's centroid inside the polygon by a crossing-number test, and, on a
// convex polygon, the fan from corner 0 that the writers wrote before.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
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

namespace reference_search {

// The search polygon_triangles made before its ear test looked only at reflex corners (commit
// c910f76), kept as the reference: every remaining corner is tested against every candidate ear.
struct P2 {
  double x, y;
};
double turn(const P2& a, const P2& b, const P2& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }
bool same(const P2& a, const P2& b) { return a.x == b.x && a.y == b.y; }
bool inside(const P2& p, const P2& a, const P2& b, const P2& c) {
  return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}
void fan(const std::vector<std::uint32_t>& idx, std::vector<std::uint32_t>& out) {
  for (std::size_t k = 1; k + 1 < idx.size(); ++k) out.insert(out.end(), {idx[0], idx[k], idx[k + 1]});
}

void polygon_triangles(const double* positions, const std::uint32_t* corners, std::uint32_t n, std::vector<std::uint32_t>& out) {
  if (n < 3) return;
  if (n == 3) {
    out.insert(out.end(), {0u, 1u, 2u});
    return;
  }
  // Newell's area vector about corner 0, written out.
  double N[3] = {0, 0, 0};
  const double* o = positions + 3 * std::size_t(corners[0]);
  for (std::uint32_t k = 0; k < n; ++k) {
    const double* a = positions + 3 * std::size_t(corners[k]);
    const double* b = positions + 3 * std::size_t(corners[(k + 1) % n]);
    const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2], bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
    N[0] += ay * bz - az * by;
    N[1] += az * bx - ax * bz;
    N[2] += ax * by - ay * bx;
  }
  const double ax = std::fabs(N[0]), ay = std::fabs(N[1]), az = std::fabs(N[2]);
  std::vector<std::uint32_t> remaining(n);
  for (std::uint32_t k = 0; k < n; ++k) remaining[k] = k;
  if (ax == 0 && ay == 0 && az == 0) {
    fan(remaining, out);
    return;
  }
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const double sign = N[drop];
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  std::vector<P2> p(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    const double* q = positions + 3 * std::size_t(corners[k]);
    p[k] = sign > 0 ? P2{q[u], q[v]} : P2{q[v], q[u]};
  }
  while (remaining.size() > 3) {
    const std::size_t m = remaining.size();
    bool clipped = false;
    for (std::size_t s = 1; s < m + 1 && !clipped; ++s) {
      const std::size_t i = s % m, h = (i + m - 1) % m, j = (i + 1) % m;
      const P2 &a = p[remaining[h]], &b = p[remaining[i]], &c = p[remaining[j]];
      if (!(turn(a, b, c) > 0)) continue;
      bool empty = true;
      for (std::size_t k = 0; k < m && empty; ++k) {
        if (k == h || k == i || k == j) continue;
        const P2& q = p[remaining[k]];
        if (same(q, a) || same(q, b) || same(q, c)) continue;
        empty = !inside(q, a, b, c);
      }
      if (!empty) continue;
      out.insert(out.end(), {remaining[h], remaining[i], remaining[j]});
      remaining.erase(remaining.begin() + std::ptrdiff_t(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  fan(remaining, out);
}

}  // namespace reference_search

namespace {

// The library's triangles and the reference search's, for the outline placed on `plane`, mirrored or not.
std::size_t differing(const std::vector<std::array<double, 2>>& uv, const std::vector<std::uint32_t>& order, int plane, bool mirror) {
  const Planar p = place(uv, order, plane, mirror);
  std::vector<std::uint32_t> now, before;
  polygon_triangles(p.positions.data(), p.corners.data(), std::uint32_t(order.size()), now);
  reference_search::polygon_triangles(p.positions.data(), p.corners.data(), std::uint32_t(order.size()), before);
  return now == before ? 0 : 1;
}

std::size_t differing_all(const std::vector<std::array<double, 2>>& uv, const std::vector<std::uint32_t>& order) {
  std::size_t d = 0;
  for (int plane = 0; plane < 3; ++plane)
    for (bool mirror : {false, true}) d += differing(uv, order, plane, mirror);
  return d;
}

std::vector<std::uint32_t> iota(std::size_t n, std::size_t start = 0) {
  std::vector<std::uint32_t> o(n);
  for (std::size_t k = 0; k < n; ++k) o[k] = std::uint32_t((start + k) % n);
  return o;
}

// A star-shaped outline: n angles 2 pi k / n jittered by up to `jitter` of a step, radii uniform in
// [r0, 1], coordinates rounded to `decimals` (none when negative).
std::vector<std::array<double, 2>> random_star(std::mt19937& rng, std::size_t n, double r0, double jitter, int decimals) {
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<std::array<double, 2>> uv;
  const double scale = decimals >= 0 ? std::pow(10.0, decimals) : 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * M_PI * (k + jitter * (U(rng) - 0.5)) / n, r = r0 + (1 - r0) * U(rng);
    double x = r * std::cos(a), y = r * std::sin(a);
    if (decimals >= 0) x = std::round(x * scale) / scale, y = std::round(y * scale) / scale;  // divisor: 10^decimals
    uv.push_back({x, y});
  }
  return uv;
}

// Whether the closed outline is simple: no two corners at one position, and no two edges that do
// not share a corner meet (orientation tests; touching counts as meeting).
bool simple(const std::vector<std::array<double, 2>>& uv) {
  const std::size_t n = uv.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (uv[a] == uv[b]) return false;
  auto sgn = [](double x) { return (x > 0) - (x < 0); };
  auto on = [](const std::array<double, 2>& p, const std::array<double, 2>& q, const std::array<double, 2>& r) {  // r on segment pq, given collinear
    return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
  };
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t f = e + 1; f < n; ++f) {
      if (f == e + 1 || (e == 0 && f == n - 1)) continue;  // neighbours share a corner
      const auto &p = uv[e], &q = uv[(e + 1) % n], &r = uv[f], &t = uv[(f + 1) % n];
      const int o1 = sgn(twice_area(p, q, r)), o2 = sgn(twice_area(p, q, t)), o3 = sgn(twice_area(r, t, p)), o4 = sgn(twice_area(r, t, q));
      if (o1 != o2 && o3 != o4) return false;
      if ((o1 == 0 && on(p, q, r)) || (o2 == 0 && on(p, q, t)) || (o3 == 0 && on(r, t, p)) || (o4 == 0 && on(r, t, q))) return false;
    }
  // Neighbouring edges folding back on each other (a corner turning by pi) also touch.
  for (std::size_t k = 0; k < n; ++k) {
    const auto &a = uv[k], &b = uv[(k + 1) % n], &c = uv[(k + 2) % n];
    if (twice_area(a, b, c) == 0 && (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) < 0) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("polygon_triangles: the reflex-corner ear search cuts exactly the ears the all-corner search cut, in the same order", "[geometry][polygon_triangles]") {
  // Every outline of these tests, from each corner, on 3 planes, both windings.
  const std::vector<std::array<double, 2>> l{{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}};
  const std::vector<std::array<double, 2>> comb{{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const std::vector<std::array<double, 2>> dart{{0, 0}, {2, 1}, {0, 2}, {0.5, 1}};
  const std::vector<std::array<double, 2>> star = [] {
    std::vector<std::array<double, 2>> s;
    for (int k = 0; k < 10; ++k) {
      const double r = k % 2 ? 0.4 : 1.0, a = M_PI / 2 + k * M_PI / 5;
      s.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return s;
  }();
  std::size_t d = 0, runs = 0;
  for (const auto* o : {&l, &comb, &dart, &star})
    for (std::size_t s = 0; s < o->size(); ++s, runs += 6) d += differing_all(*o, iota(o->size(), s));
  const std::vector<std::array<double, 2>> keyhole{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  d += differing_all(keyhole, {0, 1, 2, 3, 0, 4, 7, 6, 5, 4});
  runs += 6;
  {  // assimp's concave_polygon.obj (66 corners)
    ReadInfo info;
    const Mesh m = read_mesh(iotest::data_path("corpus_extra/concave_polygon.obj"), Format::Auto, &info);
    REQUIRE(m.face_size(0) == 66);
    std::vector<std::uint32_t> now, before;
    polygon_triangles(m.positions.data(), m.corner_vertex.data(), 66, now);
    reference_search::polygon_triangles(m.positions.data(), m.corner_vertex.data(), 66, before);
    CHECK(now == before);
  }
  // Random simple outlines: star-shaped with jittered angles and radii, exact and rounded to 1, 2 and
  // 3 decimals (collinear and coincident corners), 4 to 300 corners, one in 8 moved far from the origin.
  std::mt19937 rng(20261128);
  std::size_t not_simple = 0;
  for (int t = 0; t < 400; ++t) {
    const std::size_t n = 4 + rng() % (t < 300 ? 40 : 297);
    const int decimals = t % 4 == 0 ? -1 : int(t % 4);  // exact, 1, 2, 3 decimals
    auto uv = random_star(rng, n, t % 2 ? 0.2 : 0.7, 0.9, decimals);
    if (t % 8 == 3)  // far from the origin (a georeferenced file): the grid's cells are 1e-7 of the coordinates
      for (auto& c : uv) c = {c[0] + 1e5, c[1] - 3e5};
    if (!simple(uv)) {  // rounding made corners meet or edges cross: not what the claim is about
      ++not_simple;
      continue;
    }
    d += differing_all(uv, iota(n));
    runs += 6;
  }
  // A disc convex only up to rounding (6 decimals: some corners turn right), the case the grid is for.
  std::vector<std::array<double, 2>> disc;
  for (int k = 0; k < 3000; ++k)
    disc.push_back({std::round(1e6 * std::cos(2 * M_PI * k / 3000)) / 1e6, std::round(1e6 * std::sin(2 * M_PI * k / 3000)) / 1e6});
  d += differing(disc, iota(disc.size()), 0, false) + differing(disc, iota(disc.size()), 2, true);
  runs += 2;
  INFO(runs << " runs, " << not_simple << " random outlines not simple");
  CHECK(not_simple < 100);  // most random outlines are compared
  CHECK(d == 0);
}

TEST_CASE("quad_is_concave: a dart in any corner order, plane and winding is concave and split through its reflex corner; convex, straight-cornered and flat quads are not", "[geometry][polygon_triangles]") {
  // Dart (0,0) (2,1) (0,2) (0.5,1): its reflex corner (0.5,1) is inside the triangle of the other
  // three (by construction). Split through it: on 1-3 when it is corner 1 or 3 (the 0-2 diagonal
  // lies outside the dart, where Blender flips the split too), on 0-2 when it is corner 0 or 2.
  const std::vector<std::array<double, 2>> dart{{0, 0}, {2, 1}, {0, 2}, {0.5, 1}};
  for (std::uint32_t r = 0; r < 4; ++r)
    for (int plane = 0; plane < 3; ++plane)
      for (bool mirror : {false, true}) {
        const std::vector<std::uint32_t> order{r, (r + 1) % 4, (r + 2) % 4, (r + 3) % 4};
        const Planar p = place(dart, order, plane, mirror);
        const std::uint32_t reflex = (3 + 4 - r) % 4;  // the position of dart corner 3 in `order`
        INFO("reflex corner at " << reflex << ", plane " << plane << (mirror ? ", mirrored" : ""));
        CHECK(quad_is_concave(p.positions.data(), p.corners.data()));
        std::vector<std::uint32_t> tri;
        polygon_triangles(p.positions.data(), p.corners.data(), 4, tri);
        REQUIRE(tri.size() == 6);
        const std::uint32_t a = reflex % 2 ? 1 : 0, b = a + 2;  // the diagonal through the reflex corner
        for (int t = 0; t < 2; ++t) {
          const std::uint32_t* x = &tri[3 * t];
          CHECK(((x[0] == a || x[1] == a || x[2] == a) && (x[0] == b || x[1] == b || x[2] == b)));  // both triangles hold the diagonal
        }
      }
  const std::vector<std::array<double, 2>> convex{{0, 0}, {3, 0}, {2, 2}, {0, 1}};
  const std::vector<std::array<double, 2>> straight{{0, 0}, {1, 0}, {2, 0}, {1, 1}};  // corner 1 on the edge 0-2
  const std::vector<std::array<double, 2>> flat{{0, 0}, {1, 0}, {2, 0}, {3, 0}};      // no plane
  for (const auto* q : {&convex, &straight, &flat})
    for (int plane = 0; plane < 3; ++plane)
      for (bool mirror : {false, true}) {
        const Planar p = place(*q, {0, 1, 2, 3}, plane, mirror);
        CHECK_FALSE(quad_is_concave(p.positions.data(), p.corners.data()));
      }
}
