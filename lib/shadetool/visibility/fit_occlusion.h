// fit_occlusion.h: per-vertex open fractions whose Gouraud interpolation is closest, in L2 over
// the surface, to the open fraction at every point (`occlusion --fit least-squares`, issue 30).
//
// f at a point x of a face: the open fraction (ambient_occlusion.h) at x about the interpolated
// vertex axis (occlusion_vertex_axes, renormalised), with the same fixed ray count as the vertices
// (ambient_occlusion_at_points) or to the same target error (occlusion_to_error.h), cast once per
// quadrature site (least_squares_fit.h: an edge midpoint of the 3-point rule serves both its
// triangles); the sites' seeds are V + their index, so they are independent of the vertices'. The quadrature, normal
// equations, regulariser and clamp to [0, 1] are fit/least_squares_fit.h's, in the mesh's space.
//
// Inputs:  mesh, point_open (#V, the per-vertex result: first guess and fallback), the ray options
//          (adaptive null: fixed), fit (samples, regularisation), source (for errors)
// Output:  open_fraction #V; error_fit, error_point (relative L2 to f by the same quadrature;
//          NaN unless fit.measure_error);
//          rays cast at the quadrature sites; the solve's counts.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/fit/least_squares_fit.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/occlusion_to_error.h>
#include <shadetool/visibility/visibility_scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct OcclusionFit {
  std::vector<float> open_fraction;
  LeastSquaresFit solve;  // values moved into open_fraction
  double error_fit = 0;
  double error_point = 0;
  std::size_t quadrature_points = 0;
  std::uint64_t rays = 0;
};

OcclusionFit fit_occlusion(const Mesh& mesh, const std::vector<float>& point_open, const AmbientOcclusionOptions& fixed,
                           const OcclusionToErrorOptions* adaptive, const VertexFitOptions& fit, const std::string& source);

// The same fit for `mesh` against a scene built from another mesh (a glTF document's whole scene
// in world space, gltf/gltf_occlusion.h: `mesh` is then the primitive placed in that world); the
// quadrature points' rays meet `scene`, areas are measured in mesh's own coordinates.
OcclusionFit fit_occlusion(const VisibilityScene& scene, const Mesh& mesh, const std::vector<float>& point_open,
                           const AmbientOcclusionOptions& fixed, const OcclusionToErrorOptions* adaptive,
                           const VertexFitOptions& fit, const std::string& source);

}  // namespace shadetool
#pragma GCC visibility pop
