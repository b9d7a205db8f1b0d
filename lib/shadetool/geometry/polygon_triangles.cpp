// polygon_triangles.cpp: see polygon_triangles.h.
#include <shadetool/geometry/polygon_triangles.h>

#include <cmath>

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/face_area_vector.h>

namespace shadetool {
namespace {

struct P2 {
  double x, y;
};

// Twice the signed area of triangle (a, b, c): > 0 when it turns counter-clockwise.
double turn(const P2& a, const P2& b, const P2& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool same(const P2& a, const P2& b) { return a.x == b.x && a.y == b.y; }

// Whether p lies inside or on triangle (a, b, c), counter-clockwise.
bool inside(const P2& p, const P2& a, const P2& b, const P2& c) {
  return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

void fan(const std::vector<std::uint32_t>& idx, std::vector<std::uint32_t>& out) {
  for (std::size_t k = 1; k + 1 < idx.size(); ++k) {
    out.push_back(idx[0]);
    out.push_back(idx[k]);
    out.push_back(idx[k + 1]);
  }
}

}  // namespace

void polygon_triangles(const double* positions, const std::uint32_t* corners, std::uint32_t n,
                       std::vector<std::uint32_t>& out) {
  if (n < 3) return;
  if (n == 3) {
    out.insert(out.end(), {0u, 1u, 2u});
    return;
  }
  const Vec3d N = newell_area_vector(positions, corners, n);
  const double ax = std::fabs(N.x), ay = std::fabs(N.y), az = std::fabs(N.z);
  // Scratch reused across calls (a writer calls this once per face): no allocation per polygon.
  thread_local std::vector<std::uint32_t> remaining;
  thread_local std::vector<P2> p;
  if (!(std::isfinite(ax) && std::isfinite(ay) && std::isfinite(az)) || (ax == 0 && ay == 0 && az == 0)) {
    remaining.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) remaining[k] = k;
    fan(remaining, out);  // no plane to clip in: the fan from corner 0
    return;
  }
  // Drop the axis of N's largest component; (u, v) in the order that makes the outline turn
  // counter-clockwise seen from N's side.
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const double sign = drop == 0 ? N.x : drop == 1 ? N.y : N.z;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  auto project = [&](std::uint32_t k) {
    const double* q = positions + 3 * std::size_t(corners[k]);
    return sign > 0 ? P2{q[u], q[v]} : P2{q[v], q[u]};
  };
  if (n == 4) {  // the common quad: the fan when both its triangles turn as the quad
    const P2 q0 = project(0), q1 = project(1), q2 = project(2), q3 = project(3);
    // turn(0,2,3) > 0 puts corner 3 outside triangle (0,1,2): the ear clipping below would cut
    // corner 1 first and leave (0,2,3), the same triangles.
    if (turn(q0, q1, q2) > 0 && turn(q0, q2, q3) > 0) {
      out.insert(out.end(), {0u, 1u, 2u, 0u, 2u, 3u});
      return;
    }
  }
  remaining.resize(n);
  p.resize(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    remaining[k] = k;
    p[k] = project(k);
  }
  // A convex polygon in O(n): every corner turns left (turn > 0) and the edge directions go round
  // once (turning number 1: the direction enters the half-plane of angles [0, pi) exactly once; a
  // locally convex closed polygon turning once is convex and simple). Every corner is then an
  // ear, so the ear clipping below would cut corner 1, then 2, ...: the fan from corner 0. Without
  // this test that search is O(n^2) on a convex polygon (a 20,000-corner disc took 0.8 s).
  {
    auto upper = [](const P2& a, const P2& b) {  // the direction a -> b has its angle in [0, pi)
      const double dx = b.x - a.x, dy = b.y - a.y;
      return dy > 0 || (dy == 0 && dx > 0);
    };
    bool convex = true;
    std::uint32_t entries = 0;
    for (std::uint32_t k = 0; k < n && convex; ++k) {
      const P2 &a = p[k], &b = p[(k + 1) % n], &c = p[(k + 2) % n];
      convex = turn(a, b, c) > 0;
      if (!upper(a, b) && upper(b, c)) ++entries;
    }
    if (convex && entries == 1) {
      fan(remaining, out);
      return;
    }
  }
  while (remaining.size() > 3) {
    const std::size_t m = remaining.size();
    bool clipped = false;
    for (std::size_t s = 1; s < m + 1 && !clipped; ++s) {  // from the second remaining corner: the fan when convex
      const std::size_t i = s % m, h = (i + m - 1) % m, j = (i + 1) % m;
      const P2 &a = p[remaining[h]], &b = p[remaining[i]], &c = p[remaining[j]];
      if (!(turn(a, b, c) > 0)) continue;  // reflex or straight: not an ear
      bool empty = true;
      for (std::size_t k = 0; k < m && empty; ++k) {
        if (k == h || k == i || k == j) continue;
        const P2& q = p[remaining[k]];
        if (same(q, a) || same(q, b) || same(q, c)) continue;  // a bridge end or repeated vertex
        empty = !inside(q, a, b, c);
      }
      if (!empty) continue;
      out.push_back(remaining[h]);
      out.push_back(remaining[i]);
      out.push_back(remaining[j]);
      remaining.erase(remaining.begin() + std::ptrdiff_t(i));
      clipped = true;
    }
    if (!clipped) break;  // no ear (a self-intersecting outline): the rest as a fan, below
  }
  fan(remaining, out);
}

}  // namespace shadetool
