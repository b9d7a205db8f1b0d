// mesh_scale.cpp: see mesh_scale.h.
#include <shadetool/normals/engine/mesh_scale.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadetool::normals_detail {

namespace {

inline void track(double& peak, const double* p) {
  for (int k = 0; k < 3; ++k) {
    const double a = std::fabs(p[k]);
    if (a <= std::numeric_limits<double>::max()) peak = std::max(peak, a);  // skips NaN and Inf
  }
}

}  // namespace

double sampled_max_coordinate(const Mesh& mesh) {
  const std::size_t V = mesh.num_vertices();
  const double* P = mesh.positions.data();
  double peak = 0.0;
  if (V <= kRangeSample) {
    for (std::size_t v = 0; v < V; ++v) track(peak, P + 3 * v);
  } else {
    for (std::size_t i = 0; i < kRangeSample; ++i) track(peak, P + 3 * (i * V / kRangeSample));
  }
  return peak;
}

double power_of_two_scale(double peak) {
  if (!(peak > 0.0) || !std::isfinite(peak)) return 1.0;
  const int e = std::max(-1000, std::min(1000, std::ilogb(peak)));
  return std::ldexp(1.0, -e);
}

const Mesh& in_kernel_range(const Mesh& mesh, std::optional<Mesh>& storage) {
  const double sampled = sampled_max_coordinate(mesh);
  if (!(sampled > 0.0)) return mesh;  // no finite nonzero coordinate: nothing to scale
  const int e = std::ilogb(sampled);
  if (e >= -kKernelRangeExponent && e < kKernelRangeExponent) return mesh;
  const double scale = power_of_two_scale(sampled);  // the trigger's own maximum: one rule, no second pass
  Mesh& copy = storage.emplace();
  copy.positions.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) copy.positions[i] = mesh.positions[i] * scale;  // exact
  copy.face_start = mesh.face_start;
  copy.corner_vertex = mesh.corner_vertex;
  return copy;
}

}  // namespace shadetool::normals_detail
