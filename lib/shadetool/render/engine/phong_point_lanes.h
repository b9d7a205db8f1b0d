// phong_point_lanes.h (engine): Phong's world point and unit normal at a run of samples that one
// unclipped triangle (not a quad's half) owns, four samples at a time in AVX2 lanes where the CPU
// has it: the bits of tile_raster.cpp's phong_point, which is the definition. Internal to lib/render.
//
// Per sample, with screen barycentrics lambda = (1 - l1 - l2, l1, l2):
//   w = perspective_barycentrics(lambda, inv_w)            (perspective_barycentrics.h)
//   p = 0 + P0 w0 + P1 w1 + P2 w2,  n = 0 + N0 w0 + N1 w1 + N2 w2   (summed left to right)
//   n = unit_or_zero(n)                                     (below)
// The lanes repeat these operations in this order, without fused multiply-adds (the .cpp is
// compiled with -ffp-contract=off): the same doubles as the scalar loop.
//
// Inputs:  corner_p, corner_n  the triangle's corners in screen order (P_k, N_k: world space,
//                              3 doubles each), inv_w its 1/w (> 0)
//          lambda1, lambda2    #count screen barycentrics of the run's samples
// Outputs: px..nz              #count each: p and the unit (or zero) normal
// Precision: double.
#pragma once

#include <cmath>
#include <cstddef>

#include <shadetool/core/vec3.h>

namespace shadetool::render_engine {

// The interpolated normal made unit. Vertex normals are finite (checked on input) and usually
// unit, so the plain squared length is safe; outside [2^-1000, 2^1000] (opposite normals
// cancelling, absurd input lengths) the normal counts as zero and the lighting equation keeps only
// the ambient terms.
inline Vec3d unit_or_zero_normal(const Vec3d& n) {
  const double n2 = dot(n, n);
  return n2 > 0x1p-1000 && n2 <= 0x1p1000 ? n * (1.0 / std::sqrt(n2)) : Vec3d{0, 0, 0};  // divisor checked
}

struct PointRunOut {
  double *px, *py, *pz, *nx, *ny, *nz;
};

void phong_points_run(const Vec3d corner_p[3], const Vec3d corner_n[3], const double inv_w[3], const double* lambda1,
                      const double* lambda2, std::size_t count, const PointRunOut& out);

}  // namespace shadetool::render_engine
