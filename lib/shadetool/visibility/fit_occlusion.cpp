// fit_occlusion.cpp: see fit_occlusion.h.
#include <shadetool/visibility/fit_occlusion.h>

#include <limits>
#include <memory>

#include <shadetool/core/error.h>

namespace shadetool {

namespace {

// given: the scene the rays meet (null: the mesh's own BVH, built here and freed before the solve).
OcclusionFit fit_against(const VisibilityScene* given, const Mesh& mesh, const std::vector<float>& point_open,
                         const AmbientOcclusionOptions& fixed, const OcclusionToErrorOptions* adaptive,
                         const VertexFitOptions& fit, const std::string& source) {
  const std::size_t V = mesh.num_vertices();
  if (point_open.size() != V) throw Error("fit_occlusion: " + std::to_string(point_open.size()) + " values for " + std::to_string(V) + " vertices");
  bool computed = false;
  const std::vector<double> axes = occlusion_vertex_axes(mesh, source, computed);
  const FitElements elements = fit_elements(mesh);
  const FitQuadrature q = fit_quadrature(elements, mesh.positions, fit.samples);
  // rays from each site (shared edge midpoints once)
  const std::vector<double> points = interpolate_vertex_data_at_sites(q, mesh.positions, 3);
  const std::vector<double> normals = interpolate_vertex_data_at_sites(q, axes, 3);  // normalised by the ray code
  std::vector<std::uint64_t> ids(q.sites());
  for (std::size_t s = 0; s < ids.size(); ++s) ids[s] = V + s;
  OcclusionFit out;
  out.quadrature_points = q.size();
  std::vector<float> open;
  {
    std::unique_ptr<VisibilityScene> own;
    if (!given) own = std::make_unique<VisibilityScene>(mesh);
    const VisibilityScene& scene = given ? *given : *own;
    if (adaptive) {
      OcclusionToError r = occlusion_to_error_at_points(scene, points, normals, ids, *adaptive);
      open = std::move(r.open_fraction);
      out.rays = r.total_rays;
    } else {
      AmbientOcclusion r = ambient_occlusion_at_points(scene, points, normals, ids, fixed);
      open = std::move(r.open_fraction);
      out.rays = r.rays;
    }
  }
  const std::vector<double> f(open.begin(), open.end());  // at the sites, as least_squares_fit takes it
  const std::vector<double> point(point_open.begin(), point_open.end());
  LeastSquaresFitOptions solve = fit.solve;
  solve.lower = 0;
  solve.upper = 1;
  out.solve = least_squares_fit(elements, mesh.positions, q, f, point, 1, solve);
  if (fit.measure_error) {
    out.error_fit = relative_l2_error(q, f, out.solve.values, 1);
    out.error_point = relative_l2_error(q, f, point, 1);
  } else {
    out.error_fit = out.error_point = std::numeric_limits<double>::quiet_NaN();
  }
  out.open_fraction.assign(out.solve.values.begin(), out.solve.values.end());
  out.solve.values.clear();
  return out;
}

}  // namespace

OcclusionFit fit_occlusion(const Mesh& mesh, const std::vector<float>& point_open, const AmbientOcclusionOptions& fixed,
                           const OcclusionToErrorOptions* adaptive, const VertexFitOptions& fit, const std::string& source) {
  return fit_against(nullptr, mesh, point_open, fixed, adaptive, fit, source);
}

OcclusionFit fit_occlusion(const VisibilityScene& scene, const Mesh& mesh, const std::vector<float>& point_open,
                           const AmbientOcclusionOptions& fixed, const OcclusionToErrorOptions* adaptive,
                           const VertexFitOptions& fit, const std::string& source) {
  return fit_against(&scene, mesh, point_open, fixed, adaptive, fit, source);
}

}  // namespace shadetool
