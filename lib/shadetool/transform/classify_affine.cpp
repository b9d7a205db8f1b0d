// classify_affine.cpp: see classify_affine.h.
#include <shadetool/transform/classify_affine.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <shadetool/core/error.h>

namespace shadetool {

namespace {

double max_abs_entry(const Mat3d& A) {
  double m = 0;
  for (const auto& row : A.m)
    for (double e : row) m = std::max(m, std::fabs(e));
  return m;
}

double frobenius_squared(const Mat3d& A) {
  double s = 0;
  for (const auto& row : A.m)
    for (double e : row) s += e * e;
  return s;
}

// max |(Q^T Q - I)_ij|: how far the columns of Q are from orthonormal (infinity if Q^T Q
// overflowed: callers pass matrices with entries of order 1, this is a safety net).
double orthogonality_defect(const Mat3d& Q) {
  const Mat3d G = transpose(Q) * Q;
  double d = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double e = std::fabs(G.m[i][j] - (i == j ? 1.0 : 0.0));
      if (!std::isfinite(e)) return std::numeric_limits<double>::infinity();
      d = std::max(d, e);
    }
  return d;
}

bool is_identity(const Mat3d& A) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!(std::fabs(A.m[i][j] - (i == j ? 1.0 : 0.0)) <= kIdentityTolerance)) return false;
  return true;
}

}  // namespace

Mat3d scaled_to_unit(const Mat3d& A, int& exponent) {
  exponent = 0;
  const double m = max_abs_entry(A);
  if (!(m > 0) || !std::isfinite(m)) return A;
  std::frexp(m, &exponent);  // m = f 2^exponent, f in [0.5, 1)
  Mat3d S = A;
  for (auto& row : S.m)
    for (auto& e : row) e = std::ldexp(e, -exponent);
  return S;
}

AffineClass classify_affine(const Affine3d& M) {
  for (const auto& row : M.A.m)
    for (double e : row)
      if (!std::isfinite(e)) throw Error("transform: the matrix has a NaN or infinite entry");
  if (!is_finite(M.t)) throw Error("transform: the translation has a NaN or infinite component");

  AffineClass c;
  c.det = determinant(M.A);  // may overflow for huge A; only its sign and the scaled value are used below
  int k = 0;
  const Mat3d S = scaled_to_unit(M.A, k);
  const double det_s = determinant(S);  // det(A) = det_s 2^(3k)
  c.mirror = det_s < 0;
  const double f2 = frobenius_squared(S);
  const double mean_sq = f2 / 3.0;  // (||S||_F / sqrt 3)^2, >= 1/12 unless S = 0
  c.relative_det = mean_sq > 0 ? std::fabs(det_s) / (mean_sq * std::sqrt(mean_sq)) : 0.0;
  if (!std::isfinite(c.det)) c.det = std::ldexp(det_s, 3 * k);  // inf only through overflow: report the best we have

  if (is_identity(M.A)) {
    c.path = (M.t.x == 0 && M.t.y == 0 && M.t.z == 0) ? TransformPath::Identity : TransformPath::Translation;
    return c;
  }
  if (!(c.relative_det >= kSingularTolerance)) {
    c.path = TransformPath::Singular;
    return c;
  }
  // An orthogonal A has its largest entry in [1/sqrt 3, 1], i.e. frexp exponent k = 0 or 1.
  if ((k == 0 || k == 1) && orthogonality_defect(M.A) <= kOrthogonalTolerance) {
    c.path = TransformPath::Rotation;
    return c;
  }
  // Uniform scale: s^2 = ||A||_F^2 / 3 = mean_sq * 4^k, and Q = A / s = S / sqrt(mean_sq).
  const double s_unit = std::sqrt(mean_sq);  // > 0: S != 0 here (a zero A is singular above)
  Mat3d Q = S;
  for (auto& row : Q.m)
    for (auto& e : row) e /= s_unit;
  if (orthogonality_defect(Q) <= kOrthogonalTolerance) {
    c.path = TransformPath::UniformScale;
    c.uniform_scale = std::ldexp(s_unit, k);
    return c;
  }
  c.path = TransformPath::General;
  return c;
}

const char* path_name(TransformPath path) {
  switch (path) {
    case TransformPath::Identity: return "identity";
    case TransformPath::Translation: return "translation";
    case TransformPath::Rotation: return "rotation";
    case TransformPath::UniformScale: return "uniform-scale";
    case TransformPath::General: return "general";
    case TransformPath::Singular: return "singular";
  }
  return "unknown";
}

}  // namespace shadetool
