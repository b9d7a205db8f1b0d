// triangle_quadrature.h: symmetric quadrature rules on a triangle, in barycentric coordinates.
//
//   integral over T of g dA  ~=  area(T) * sum_k w_k g(l1_k p0 + l2_k p1 + l3_k p2),   sum_k w_k = 1
//
//   points  degree (exact for polynomials up to)   rule
//   1       1                                       centroid
//   3       2                                       the edge midpoints (0, 1/2, 1/2), w = 1/3 (Strang
//                                                   & Fix 1973, table 4.1): on a mesh each midpoint
//                                                   is shared by the two triangles of its edge, so
//                                                   the signal is evaluated about 1.5 times per
//                                                   triangle (fit_quadrature's sites)
//   6       4                                       Dunavant (1985), "High degree efficient symmetrical
//                                                   Gaussian quadrature rules for the triangle", IJNME
//                                                   21, table degree 4
//   12      6                                       Dunavant (1985), degree 6 (tests and benchmarks:
//                                                   a reference finer than what --fit-samples offers)
// Inputs:  points (1, 3, 6 or 12)
// Output:  the rule's nodes (3 barycentric coordinates each) and weights summing to 1, or an empty
//          rule for any other count (triangle_quadrature_supported says which counts exist).
// Precision: the published 15-digit constants, in double.
#pragma once

#include <array>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct QuadraturePoint {
  std::array<double, 3> barycentric;  // weights of corners 0, 1, 2; sum 1
  double weight;                      // fraction of the triangle's area; the rule's weights sum to 1
};

bool triangle_quadrature_supported(int points);
// The rule's degree (1, 2, 4, 6); 0 for an unsupported count.
int triangle_quadrature_degree(int points);
std::vector<QuadraturePoint> triangle_quadrature(int points);

// Gauss-Legendre nodes on [0, 1] (n = 1, 2 or 3; exact to degree 2n - 1), for quads' bilinear map.
struct GaussPoint {
  double t;
  double weight;  // sum 1
};
std::vector<GaussPoint> gauss_legendre_unit(int n);

}  // namespace shadetool
#pragma GCC visibility pop
