// normals_test_util.h: error measures shared by the normals tests.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/mesh.h"
#include "support/analytic_meshes.h"

namespace shadetool::testing {

struct AngularError {
  double mean_deg = 0, max_deg = 0;
  std::size_t non_finite = 0;
};

// Angle between each computed normal (#V by 3) and the exact one, in degrees.
inline AngularError angular_error(const std::vector<double>& normals, const std::vector<Vec3d>& exact) {
  AngularError e;
  for (std::size_t v = 0; v < exact.size(); ++v) {
    const Vec3d n = get3(normals, v);
    if (!is_finite(n)) { ++e.non_finite; continue; }
    const double a = angle_degrees(n, exact[v]);
    e.mean_deg += a;
    e.max_deg = std::max(e.max_deg, a);
  }
  e.mean_deg /= double(exact.size());
  return e;
}

}  // namespace shadetool::testing
