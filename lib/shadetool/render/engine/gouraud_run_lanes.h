// gouraud_run_lanes.h (engine): tile_raster.cpp's gouraud_run (one sample per pixel, a run of
// pixels one unclipped triangle owns) four pixels at a time in AVX2 lanes, the same IEEE
// operations in the same order as its scalar loop (lambda, perspective_barycentrics,
// blend_vertex_colors, the box filter's 0 + c and scale; no fused multiply-add: the .cpp is
// compiled with -ffp-contract=off), so the floats are bitwise the scalar loop's. Internal to
// lib/render.
//
// Inputs:  corner_rgb  the triangle's corner colours in screen order (linear, double)
//          inv_w       its corners' 1/w; lambda1, lambda2 #n screen barycentrics; inv_samples 1/N^2
// Output:  out         3 floats per pixel, for the first k pixels, k (a multiple of 4) returned;
//                      0 where the CPU has no AVX2 (the caller does the rest).
#pragma once

#include <shadetool/core/vec3.h>

namespace shadetool::render_engine {

int gouraud_run_lanes(const Vec3d corner_rgb[3], const double inv_w[3], const double* lambda1, const double* lambda2,
                      int n, double inv_samples, float* out);

}  // namespace shadetool::render_engine
