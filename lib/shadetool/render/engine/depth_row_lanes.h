// depth_row_lanes.h (engine): the depth test of one triangle over one row of a tile's samples,
// four samples at a time in AVX2 lanes where the CPU has it, with the bits of tile_raster.cpp's
// scalar loop (its definition). Internal to lib/render.
//
// Per sample s of the row, with E_i the edge functions (fill_rule.h) at s and bias_i their
// top-left biases:
//   inside  E_i + bias_i - 1 >= 0 for i = 0, 1, 2
//   l_i     E_i * inv_area;  z = l0 z0 + l1 z1 + l2 z2 (left to right)
//   if inside and z < (owner[s] set ? depth[s] : +inf): depth[s] = z, owner[s] = triangle,
//   lambda1[s] = l1, lambda2[s] = l2
// The covered samples of a row are one interval (the triangle is convex): the walk stops after it.
//
// The lanes hold E_i as doubles: exact, because the caller passes only triangles whose fixed-point
// coordinates are below 2^25 in magnitude (depth_row_lanes_exact), so that every E_i is an integer
// below 2^53; E_i * inv_area is then the scalar loop's double(E_i) * inv_area. No fused multiply-
// add (the .cpp is compiled with -ffp-contract=off).
//
// Inputs:  edge[3]   E_i at the row's first sample (integers, exact in double)
//          step[3]   E_i's change from one sample to the next (integers)
//          bias[3]   0 or 1
//          count     samples in the row (>= 0); depth, owner, lambda1, lambda2 point at its first
// Precision: double, as the scalar loop.
#pragma once

#include <cstdint>

#include <shadetool/render/engine/screen_triangle.h>

namespace shadetool::render_engine {

// Whether the lanes may take this triangle: AVX2 here and |X|, |Y| < 2^25.
bool depth_row_lanes_exact(const ScreenTriangle& t);

struct DepthRow {
  double edge[3], step[3];
  std::int64_t bias[3];
  double inv_area;
  double z[3];
};

void depth_row_lanes(const DepthRow& row, int count, const ScreenTriangle* triangle, double* depth,
                     const ScreenTriangle** owner, double* lambda1, double* lambda2);

}  // namespace shadetool::render_engine
