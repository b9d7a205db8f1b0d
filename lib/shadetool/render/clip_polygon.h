// clip_polygon.h: a triangle in homogeneous clip space, clipped against planes (Sutherland and
// Hodgman 1974, "Reentrant polygon clipping"; Blinn and Newell 1978, "Clipping using homogeneous
// coordinates"): the near plane z + w >= 0, the far plane w - z >= 0 and the guard band
// g w -+ x >= 0, g w -+ y >= 0 (far enough outside the image that no visible edge is cut there;
// it only keeps screen coordinates inside the rasteriser's fixed-point range).
//
// Each vertex carries its barycentric coordinates with respect to the ORIGINAL triangle, so the
// attributes of a clipped vertex are interpolated from the original corners, never re-clipped.
//
// A triangle crossing the near plane is clipped, not dropped: the result is a convex polygon of up
// to 3 + (number of planes) vertices, fanned by the caller.
//
// Determinism across triangles: an edge shared by two triangles is clipped at the same point in
// both (bitwise): the intersection is always computed from the lexicographically smaller endpoint,
// so the two triangles' opposite traversals give the same arithmetic. Without this the shared edge
// would be cut at two points a rounding apart and the fill rule could leave a crack.
//
// Degenerate input: a vertex exactly on a plane (distance 0) counts as inside; an intersection is
// formed only between endpoints of opposite strict sign, so its divisor d_a - d_b is never 0.
// Precision: double.
#pragma once

#include <cstddef>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct ClipVertex {
  double x, y, z, w;
  double b[3];  // barycentrics w.r.t. the original triangle's corners
};

// Signed distance to plane k of the seven: 0 near, 1 far, 2..5 guard band +-x, +-y (band g).
inline double clip_distance(const ClipVertex& v, int plane, double g) {
  switch (plane) {
    case 0: return v.z + v.w;
    case 1: return v.w - v.z;
    case 2: return g * v.w - v.x;
    case 3: return g * v.w + v.x;
    case 4: return g * v.w - v.y;
    default: return g * v.w + v.y;
  }
}

inline bool lexicographically_less(const ClipVertex& a, const ClipVertex& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  if (a.z != b.z) return a.z < b.z;
  return a.w < b.w;
}

// The point where edge (a, b) crosses plane k; d_a and d_b of opposite strict sign.
inline ClipVertex clip_intersection(const ClipVertex& a, const ClipVertex& b, double d_a, double d_b) {
  const bool from_a = !lexicographically_less(b, a);
  const ClipVertex& p = from_a ? a : b;
  const ClipVertex& q = from_a ? b : a;
  const double dp = from_a ? d_a : d_b, dq = from_a ? d_b : d_a;
  const double t = dp / (dp - dq);  // opposite strict signs: dp - dq != 0
  ClipVertex r;
  r.x = p.x + t * (q.x - p.x);
  r.y = p.y + t * (q.y - p.y);
  r.z = p.z + t * (q.z - p.z);
  r.w = p.w + t * (q.w - p.w);
  for (int i = 0; i < 3; ++i) r.b[i] = p.b[i] + t * (q.b[i] - p.b[i]);
  return r;
}

constexpr int kMaxClipVertices = 3 + 6;

// Clips polygon `in` (n vertices) against plane k into `out`; returns the new count (0: gone).
inline int clip_against(const ClipVertex* in, int n, int plane, double g, ClipVertex* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % n];
    const double da = clip_distance(a, plane, g), db = clip_distance(b, plane, g);
    if (da >= 0) out[m++] = a;
    if ((da >= 0 && db < 0) || (da < 0 && db >= 0)) {
      if (da != 0 && db != 0) out[m++] = clip_intersection(a, b, da, db);
    }
  }
  return m;
}

}  // namespace shadetool
#pragma GCC visibility pop
