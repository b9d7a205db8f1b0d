// look_at.cpp: see look_at.h.
#include <shadetool/lighting/look_at.h>

namespace shadetool {

bool look_at(const Vec3d& eye, const Vec3d& target, const Vec3d& up, Affine3d& view) {
  const Vec3d zero{0, 0, 0};
  const Vec3d f = normalized_or(target - eye, zero);
  if (f == zero) return false;  // eye == target: no view direction
  const Vec3d s = normalized_or(cross(f, up), zero);
  if (s == zero) return false;  // up parallel to the view direction (or zero)
  const Vec3d u = cross(s, f);  // unit: s and f are orthonormal
  Affine3d V;
  for (int c = 0; c < 3; ++c) {
    V.A.m[0][c] = s[c];
    V.A.m[1][c] = u[c];
    V.A.m[2][c] = -f[c];
  }
  V.t = -(V.A * eye);
  view = V;
  return true;
}

}  // namespace shadetool
