// transform_normals.cpp: see transform_normals.h.
#include <shadetool/transform/transform_normals.h>

#include <cmath>

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/geometry/scaled_length.h>

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

namespace {

// The one safe-length rule (geometry/scaled_length.h): |x|^2 inside [kSquaresFrom, kSquaresTo]
// means x is finite, non-zero, and its squared length neither overflowed nor lost precision to
// underflow: 1/sqrt(|x|^2) is then accurate to an ulp or two. (One reciprocal and three products
// instead of three divisions: this loop is the whole cost of `transform` on a mesh with normals.)

bool zero_or_not_finite(const Vec3d& v) { return !is_finite(v) || (v.x == 0 && v.y == 0 && v.z == 0); }

// Unit vector along B v for the General path, in the rare case where |B v|^2 left that range:
// v is scaled by a power of two (exact) so that its largest component is in [0.5, 1), B v is
// recomputed and normalised with the overflow-safe length(). A zero result keeps v.
Vec3d normalized_image_careful(const Mat3d& B, const Vec3d& v) {
  int e = 0;
  std::frexp(std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))), &e);
  return normalized_or(B * Vec3d{std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)}, v);
}

}  // namespace

std::size_t transform_normals(std::vector<double>& normals, const NormalMap& map) {
  if (map.untouched) return 0;
  double* data = normals.data();
  const Mat3d B = map.B;
  const bool normalize = map.normalize;
  return engine::count_over_ranges(normals.size() / 3, [&](std::size_t begin, std::size_t end) {
    std::size_t left = 0;
    for (std::size_t i = begin; i < end; ++i) {
      double* p = data + 3 * i;
      const Vec3d v{p[0], p[1], p[2]};
      Vec3d w = B * v;
      // One test covers the common case: a NaN/Inf or zero v makes |.|^2 fall outside the range.
      const double s = normalize ? dot(w, w) : dot(v, v);
      if (s >= kSquaresFrom && s <= kSquaresTo) {
        if (normalize) w = w * (1.0 / std::sqrt(s));  // s checked on the line above
      } else if (zero_or_not_finite(v)) {
        ++left;  // left exactly as read
        continue;
      } else if (normalize) {
        w = normalized_image_careful(B, v);
      }  // else: an orthogonal B keeps v's (tiny or huge, finite) length; w = B v as computed
      p[0] = w.x;
      p[1] = w.y;
      p[2] = w.z;
    }
    return left;
  });
}

}  // namespace shadetool
