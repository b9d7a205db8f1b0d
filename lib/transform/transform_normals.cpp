// transform_normals.cpp: see transform_normals.h.
#include "transform/transform_normals.h"

#include <cmath>

#include "core/error.h"
#include "core/mesh.h"

namespace shadetool {

NormalMap normal_map(const Affine3d& M, const AffineClass& c) {
  NormalMap map;
  switch (c.path) {
    case TransformPath::Identity:
    case TransformPath::Translation:
      return map;
    case TransformPath::Rotation:
      map.untouched = false;
      map.B = M.A;
      return map;
    case TransformPath::UniformScale: {
      // Q = A / s with s = ||A||_F / sqrt 3, computed on the exactly scaled S = A 2^-k.
      int k = 0;
      Mat3d Q = scaled_to_unit(M.A, k);
      double f2 = 0;
      for (const auto& row : Q.m)
        for (double e : row) f2 += e * e;
      const double s_unit = std::sqrt(f2 / 3.0);  // > 0: a zero A is Singular, not UniformScale
      for (auto& row : Q.m)
        for (auto& e : row) e /= s_unit;
      map.untouched = false;
      map.B = Q;
      return map;
    }
    case TransformPath::General: {
      int k = 0;
      map.untouched = false;
      map.normalize = true;
      map.B = signed_cofactor(scaled_to_unit(M.A, k));
      return map;
    }
    case TransformPath::Singular:
      break;
  }
  throw Error("transform: a singular map has no normal transform (drop or recompute the normals)");
}

std::size_t transform_normals(std::vector<double>& normals, const NormalMap& map) {
  if (map.untouched) return 0;
  std::size_t left = 0;
  const std::size_t n = normals.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d v = get3(normals, i);
    if (!is_finite(v) || (v.x == 0 && v.y == 0 && v.z == 0)) {
      ++left;
      continue;
    }
    Vec3d w = map.B * v;
    if (map.normalize) {
      if (!is_finite(w)) {  // overflow for |v| near DBL_MAX: scale v by a power of two (exact) and retry
        int e = 0;
        std::frexp(std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))), &e);
        w = map.B * Vec3d{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
      }
      w = normalized_or(w, v);  // |w| > 0 for finite v != 0 and regular B; the fallback keeps v
    }
    set3(normals, i, w);
  }
  return left;
}

}  // namespace shadetool
