// polygon_triangles.cpp: see polygon_triangles.h.
#include <shadetool/geometry/polygon_triangles.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

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

// The polygon's own plane as a coordinate plane: the axis of its Newell normal's largest component
// dropped, (u, v) in the order that makes the outline turn counter-clockwise seen from the
// normal's side. ok is false when the normal is zero or not finite (no plane).
struct PlaneFrame {
  bool ok = false;
  bool swap = false;
  int u = 0, v = 1;
  P2 project(const double* q) const { return swap ? P2{q[v], q[u]} : P2{q[u], q[v]}; }
};

PlaneFrame plane_frame(const double* positions, const std::uint32_t* corners, std::uint32_t n) {
  const Vec3d N = newell_area_vector(positions, corners, n);
  const double ax = std::fabs(N.x), ay = std::fabs(N.y), az = std::fabs(N.z);
  PlaneFrame f;
  if (!(std::isfinite(ax) && std::isfinite(ay) && std::isfinite(az)) || (ax == 0 && ay == 0 && az == 0)) return f;
  const int drop = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const double sign = drop == 0 ? N.x : drop == 1 ? N.y : N.z;
  f.ok = true;
  f.u = (drop + 1) % 3;
  f.v = (drop + 2) % 3;
  f.swap = !(sign > 0);
  return f;
}

void fan(const std::vector<std::uint32_t>& idx, std::vector<std::uint32_t>& out) {
  for (std::size_t k = 1; k + 1 < idx.size(); ++k) {
    out.push_back(idx[0]);
    out.push_back(idx[k]);
    out.push_back(idx[k + 1]);
  }
}


// The ear search on the projected outline p[0..n-1] (counter-clockwise): the same ears in the same
// order as testing every remaining corner against every candidate (the reference search kept in
// tests/geometry/polygon_triangles.cpp), but only reflex corners are tested, found through a grid.
//   Order: from the second remaining corner (in corner order) round to the first, the first corner
//   that turns left (turn > 0) and whose triangle (prev, corner, next) holds no other remaining
//   corner (closed triangle; a corner at the position of one of the three does not block) is cut;
//   then the search starts again from the second remaining corner.
//   Why only reflex corners: in a simple polygon, when any corner lies in a candidate's triangle a
//   reflex one (turn <= 0) does too (Eberly, "Triangulation by ear clipping", 2002, sec. 2; the
//   test mapbox/earcut makes), so the answer is the same. (On a self-intersecting outline the
//   ears may differ from testing every corner; either way every corner is kept.) A corner's turn
//   changes only when a neighbour is cut: the two neighbours of each cut corner are re-tested.
//   The grid: the reflex corners bucketed in about one cell per reflex corner over the outline's
//   bounding box; a candidate visits, row by row, the cells its triangle crosses, widened by one
//   cell each way (a corner's cell and the triangle's extent are computed with rounding far
//   smaller than a cell: an axis whose cells would be within 1e-9 of the coordinates' size has one
//   cell). Entries of corners cut or turned convex are unlinked when met.
// Output: the triangles cut, appended to `out`; `rest` the corners left (3, or more when no ear is
// found: a self-intersecting outline), in corner order.
void clip_ears(const std::vector<P2>& p, std::uint32_t n, std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& rest) {
  thread_local std::vector<std::uint32_t> next, prev, link, cell_head;
  thread_local std::vector<unsigned char> alive, reflex, in_grid;
  next.resize(n);
  prev.resize(n);
  alive.assign(n, 1);
  reflex.resize(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    next[k] = k + 1 == n ? 0 : k + 1;
    prev[k] = k == 0 ? n - 1 : k - 1;
  }
  auto left = [&](std::uint32_t k) { return turn(p[prev[k]], p[k], p[next[k]]) > 0; };
  std::uint32_t reflex_count = 0;
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
  for (std::uint32_t k = 0; k < n; ++k) {
    reflex[k] = !left(k);
    reflex_count += reflex[k];
    x0 = std::min(x0, p[k].x), x1 = std::max(x1, p[k].x), y0 = std::min(y0, p[k].y), y1 = std::max(y1, p[k].y);
  }
  // Cells per axis: about sqrt(reflex corners) each; one where the cell would be too small.
  const std::uint32_t g = std::max<std::uint32_t>(1, std::uint32_t(std::sqrt(double(reflex_count))));
  auto cells = [&](double lo, double hi) {
    const double size = (hi - lo) / g, scale = std::max(std::fabs(lo), std::fabs(hi));
    return size > 1e-9 * scale && std::isfinite(size) ? g : 1u;
  };
  const std::uint32_t gx = cells(x0, x1), gy = cells(y0, y1);
  const double sx = gx > 1 ? gx / (x1 - x0) : 0, sy = gy > 1 ? gy / (y1 - y0) : 0;  // divisors > 0 when g > 1 (checked in cells)
  const double ch = gy > 1 ? (y1 - y0) / gy : 0;  // divisor: gy >= 1
  auto cx = [&](double x) { return std::uint32_t(std::min<double>(gx - 1, std::max(0.0, std::floor((x - x0) * sx)))); };
  auto cy = [&](double y) { return std::uint32_t(std::min<double>(gy - 1, std::max(0.0, std::floor((y - y0) * sy)))); };
  cell_head.assign(std::size_t(gx) * gy, UINT32_MAX);
  link.resize(n);
  in_grid.assign(n, 0);
  auto insert = [&](std::uint32_t k) {
    if (in_grid[k]) return;
    in_grid[k] = 1;
    const std::size_t c = std::size_t(cy(p[k].y)) * gx + cx(p[k].x);
    link[k] = cell_head[c];
    cell_head[c] = k;
  };
  for (std::uint32_t k = 0; k < n; ++k)
    if (reflex[k]) insert(k);
  // Whether a reflex remaining corner other than h, i, j (and not at one of their positions) lies
  // in the closed triangle (a, b, c).
  auto blocked = [&](std::uint32_t h, std::uint32_t i, std::uint32_t j) {
    const P2 &a = p[h], &b = p[i], &c = p[j];
    const double ty0 = std::min({a.y, b.y, c.y}), ty1 = std::max({a.y, b.y, c.y});
    const std::uint32_t r0 = cy(ty0) - (cy(ty0) > 0), r1 = std::min(gy - 1, cy(ty1) + 1);
    for (std::uint32_t r = r0; r <= r1; ++r) {
      // The triangle's x extent within this row's slab widened by half a cell each way (the whole
      // triangle when the axis has one cell): the ends of its edges clipped to the slab.
      double lo = std::min({a.x, b.x, c.x}), hi = std::max({a.x, b.x, c.x});
      if (gy > 1) {
        const double s0 = y0 + (r - 0.5) * ch, s1 = y0 + (r + 1.5) * ch;
        lo = INFINITY, hi = -INFINITY;
        for (const auto& e : {std::make_pair(&a, &b), std::make_pair(&b, &c), std::make_pair(&c, &a)}) {
          const P2 &u = *e.first, &v = *e.second;
          const double e0 = std::max(std::min(u.y, v.y), s0), e1 = std::min(std::max(u.y, v.y), s1);
          if (e0 > e1) continue;  // the edge misses the slab
          if (v.y == u.y) {  // a horizontal edge inside the slab: both ends
            lo = std::min({lo, u.x, v.x}), hi = std::max({hi, u.x, v.x});
            continue;
          }
          for (double y : {e0, e1}) {
            const double x = u.x + (y - u.y) * (v.x - u.x) / (v.y - u.y);  // divisor: v.y != u.y here
            lo = std::min(lo, x), hi = std::max(hi, x);
          }
        }
        if (!(lo <= hi)) continue;  // the triangle misses this slab
      }
      const std::uint32_t c0 = cx(lo) - (cx(lo) > 0), c1 = std::min(gx - 1, cx(hi) + 1);
      for (std::uint32_t col = c0; col <= c1; ++col) {
        std::uint32_t* slot = &cell_head[std::size_t(r) * gx + col];
        while (*slot != UINT32_MAX) {
          const std::uint32_t k = *slot;
          if (!alive[k] || !reflex[k]) {  // cut, or turned convex: unlink
            in_grid[k] = 0;
            *slot = link[k];
            continue;
          }
          slot = &link[k];
          if (k == h || k == i || k == j) continue;
          const P2& q = p[k];
          if (same(q, a) || same(q, b) || same(q, c)) continue;  // a bridge end or repeated vertex
          if (inside(q, a, b, c)) return true;
        }
      }
    }
    return false;
  };
  std::uint32_t head = 0, m = n;
  while (m > 3) {
    bool clipped = false;
    std::uint32_t i = next[head];
    for (std::uint32_t s = 1; s <= m && !clipped; ++s, i = next[i]) {  // from the second remaining corner: the fan when convex
      if (reflex[i]) continue;  // reflex or straight: not an ear
      const std::uint32_t h = prev[i], j = next[i];
      if (blocked(h, i, j)) continue;
      out.push_back(h);
      out.push_back(i);
      out.push_back(j);
      alive[i] = 0;
      next[h] = j;
      prev[j] = h;
      if (i == head) head = j;
      --m;
      for (std::uint32_t k : {h, j}) {
        reflex[k] = !left(k);
        if (reflex[k]) insert(k);
      }
      clipped = true;
    }
    if (!clipped) break;  // no ear (a self-intersecting outline): the rest as a fan
  }
  rest.clear();
  for (std::uint32_t s = 0, k = head; s < m; ++s, k = next[k]) rest.push_back(k);
}

}  // namespace

void polygon_triangles(const double* positions, const std::uint32_t* corners, std::uint32_t n,
                       std::vector<std::uint32_t>& out) {
  if (n < 3) return;
  if (n == 3) {
    out.insert(out.end(), {0u, 1u, 2u});
    return;
  }
  const PlaneFrame frame = plane_frame(positions, corners, n);
  // Scratch reused across calls (a writer calls this once per face): no allocation per polygon.
  thread_local std::vector<std::uint32_t> remaining;
  thread_local std::vector<P2> p;
  if (!frame.ok) {
    remaining.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) remaining[k] = k;
    fan(remaining, out);  // no plane to clip in: the fan from corner 0
    return;
  }
  auto project = [&](std::uint32_t k) { return frame.project(positions + 3 * std::size_t(corners[k])); };
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
  clip_ears(p, n, out, remaining);
  fan(remaining, out);
}

bool quad_is_concave(const double* positions, const std::uint32_t* corners) {
  const PlaneFrame frame = plane_frame(positions, corners, 4);
  if (!frame.ok) return false;  // no plane: kept on its 0-2 diagonal
  P2 q[4];
  for (int k = 0; k < 4; ++k) q[k] = frame.project(positions + 3 * std::size_t(corners[k]));
  for (int k = 0; k < 4; ++k)
    if (turn(q[(k + 3) % 4], q[k], q[(k + 1) % 4]) < 0) return true;
  return false;
}

}  // namespace shadetool
