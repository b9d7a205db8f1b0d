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

double sampled_max_coordinate(const MeshView& mesh) {
  const std::size_t V = mesh.num_vertices();
  const double* P = mesh.positions;
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

MeshView in_kernel_range(const MeshView& mesh, std::vector<double>& storage) {
  const double sampled = sampled_max_coordinate(mesh);
  if (!(sampled > 0.0)) return mesh;  // no finite nonzero coordinate: nothing to scale
  const int e = std::ilogb(sampled);
  if (e >= -kKernelRangeExponent && e < kKernelRangeExponent) return mesh;
  const double scale = power_of_two_scale(sampled);  // the trigger's own maximum: one rule, no second pass
  const std::size_t n = 3 * mesh.num_vertices();
  storage.resize(n);
  for (std::size_t i = 0; i < n; ++i) storage[i] = mesh.positions[i] * scale;  // exact
  MeshView scaled = mesh;
  scaled.positions = storage.data();
  return scaled;
}

}  // namespace shadetool::normals_detail
