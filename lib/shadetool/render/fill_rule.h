// fill_rule.h: which samples a triangle covers, so that a sample on an edge shared by two triangles
// is drawn by exactly one of them (no crack, no double blend): edge functions on a fixed-point
// grid, exact in 64-bit integers, and the top-left rule (Pineda 1988, "A parallel algorithm for
// polygon rasterization"; Direct3D's rasterisation rules).
//
// Coordinates: x right, y down, in fixed-point units of 1/256 of the sample spacing; sample
// (sx, sy) of the sample grid lies at (256 sx + 128, 256 sy + 128) (its stratum's centre).
//
//   orient(a, b, p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)
//
// The rasteriser orders every triangle so that orient(v0, v1, v2) > 0 (clockwise on screen).
// Then p is inside when each edge function E_i > 0, or E_i = 0 on a "top-left" edge: a top edge
// (horizontal, running in +x) or a left edge (running upward, d.y < 0). Two triangles sharing an
// edge traverse it in opposite directions, so exactly one of them owns it (d = 0 cannot occur on
// a triangle of positive area).
//
// Range: |coordinates| < 2^28 (the guard band of clip_polygon.h is chosen for it), so each
// product is below 2^58 and E below 2^59: no overflow.
#pragma once

#include <cstdint>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

inline std::int64_t orient(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t px,
                           std::int64_t py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// 1 when the edge a -> b of a positively oriented triangle owns the samples exactly on it.
inline std::int64_t top_left_bias(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) {
  const std::int64_t dx = bx - ax, dy = by - ay;
  return (dy < 0 || (dy == 0 && dx > 0)) ? 1 : 0;
}

}  // namespace shadetool
#pragma GCC visibility pop
