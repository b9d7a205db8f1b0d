// invalid_normals.cpp: see invalid_normals.h.
#include <shadetool/normals/invalid_normals.h>

#include <cmath>

namespace shadetool {

std::size_t count_invalid_normals(const std::vector<double>& normals) {
  std::size_t bad = 0;
  for (std::size_t i = 0; i + 3 <= normals.size(); i += 3) {
    const double x = normals[i], y = normals[i + 1], z = normals[i + 2];
    const bool finite = std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
    if (!finite || (x == 0.0 && y == 0.0 && z == 0.0)) ++bad;
  }
  return bad;
}

}  // namespace shadetool
