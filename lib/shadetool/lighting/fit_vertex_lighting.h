// fit_vertex_lighting.h: per-vertex lit colours chosen so that their Gouraud interpolation is
// closest to the per-point lighting (`bake-lighting --fit least-squares`, issue 30).
//
// The signal f at a point x of a face is what `render --shading phong` computes there: the world
// position and the world normal (the vertex normals bake_lighting lit with, through sign(det A)
// cof(A)) interpolated with the face's hat functions, the normal renormalised, and the lighting
// equation evaluated by lighting/shade_point.h (shade_point; with shadows shade_point_shadowed and
// a lighting/light_visibility.h row per point, seeds the point's index), clamped to the fit's
// bounds [lower, upper] (8-bit output: [0, 1], the colour a display shows, as render's Phong stores
// it; --hdr: [0, inf)). The quadrature, the normal
// equations, the regulariser and the clamping are fit/least_squares_fit.h's, in world space (areas
// as the scene places the mesh).
//
// Inputs:  mesh, scene, options, shadows  as lighting/bake_lighting.h
//          point    bake_lighting(..., PerVertex, ...)'s result: its vertex_normals the normals; its
//                   rgb (#V by 3) the point fit and the fallback nodes' values (least_squares_fit.h:
//                   the first guess is the lumped-mass projection, not these). rgb may be empty
//                   (VertexColors::None) for least squares: then the fallback nodes alone are lit
//                   (bake_vertex_colors, counted in fallback_counters) and error_point is NaN.
//          fit      method (point: the point colours returned unchanged, no error measured),
//                   samples per triangle (1, 3, 6, 12), the solve's options (lambda, tolerance, clamp)
// Output:  rgb #V by 3 linear doubles; error_fit and error_point: relative L2 distance of the
//          interpolated fitted and point colours (clamped to the same bounds, as written) to f, by the same quadrature (least_squares_fit.h's
//          relative_l2_error; NaN unless fit.measure_error); the solve's counts; shadow rays cast at
//          the quadrature points.
// Threads: f is evaluated in parallel, each point independently: the same bits for any count.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/fit/least_squares_fit.h>
#include <shadetool/fit/vertex_fit.h>
#include <shadetool/lighting/bake_lighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct VertexLightingFit {
  std::vector<double> rgb;
  LeastSquaresFit solve;         // values moved into rgb
  double error_fit = 0;
  double error_point = 0;
  std::size_t quadrature_points = 0;
  ShadowStats shadows;
  ShadeCounters fallback_counters;  // point.rgb empty: the shading counts of the fallback vertices lit here
};

VertexLightingFit fit_vertex_lighting(const Mesh& mesh, const Scene& scene, const BakeResult& point,
                                      const ShadeOptions& options, const ShadowOptions& shadows,
                                      const VertexFitOptions& fit);

// f at the sites of q (#sites by 3: a shared edge midpoint once), the per-point lighting described
// above, as fit_vertex_lighting fits it; lighting_at_quadrature: the same at every point (#points
// by 3), for benchmarks and tests to measure any colours against the same f. lower, upper: every
// value v is stored as min(max(v, lower), upper) (fit_vertex_lighting's target, the colour as it
// will be shown), clamped in the shading pass where it is still in cache (the defaults: unchanged).
std::vector<double> lighting_at_sites(const Mesh& mesh, const Scene& scene, const FitQuadrature& q,
                                      const std::vector<double>& positions_world,
                                      const std::vector<double>& vertex_normals_object, const ShadeOptions& options,
                                      const ShadowOptions& shadows, ShadowStats* shadow_stats = nullptr,
                                      double lower = -std::numeric_limits<double>::infinity(),
                                      double upper = std::numeric_limits<double>::infinity());
std::vector<double> lighting_at_quadrature(const Mesh& mesh, const Scene& scene, const FitQuadrature& q,
                                           const std::vector<double>& positions_world,
                                           const std::vector<double>& vertex_normals_object,
                                           const ShadeOptions& options, const ShadowOptions& shadows,
                                           ShadowStats* shadow_stats = nullptr);

// The mesh's positions placed in the world (#V by 3).
std::vector<double> world_positions(const Mesh& mesh, const Scene& scene);

}  // namespace shadetool
#pragma GCC visibility pop
