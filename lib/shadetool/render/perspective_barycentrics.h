// perspective_barycentrics.h: barycentric coordinates that are correct under perspective.
//
// Screen-space barycentrics lambda_i (affine in the image) do not interpolate attributes of a
// perspective projection; 1/w and attr/w do (Heckbert and Moreton 1991, "Interpolation for
// polygon texture mapping and shading", Technical Report, 1991). So
//
//   b_i = (lambda_i / w_i) / sum_j (lambda_j / w_j),   given inv_w_i = 1 / w_i > 0
//
// and the original triangle's barycentrics are sum_i b_i B_i (B_i: each screen vertex's
// barycentrics with respect to the original triangle, clip_polygon.h). Orthographic views have
// w = 1 and b = lambda.
// Degenerate input: lambda = 0 everywhere cannot occur inside a triangle (they sum to 1); the sum
// is checked anyway and b = lambda returned if it is not positive. Precision: double.
#pragma once

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

inline void perspective_barycentrics(const double lambda[3], const double inv_w[3], double b[3]) {
  const double m0 = lambda[0] * inv_w[0], m1 = lambda[1] * inv_w[1], m2 = lambda[2] * inv_w[2];
  const double sum = m0 + m1 + m2;
  // Selects rather than an early return, so that loops over samples vectorise: the quotient is
  // used only where sum > 0 (divisor checked), else b = lambda.
  const bool positive = sum > 0;
  const double inv = 1.0 / sum;
  b[0] = positive ? m0 * inv : lambda[0];
  b[1] = positive ? m1 * inv : lambda[1];
  b[2] = positive ? m2 * inv : lambda[2];
}

}  // namespace shadetool
#pragma GCC visibility pop
