// affine_maps.cpp: see affine_maps.h.
#include <shadetool/core/math_constants.h>
#include <shadetool/transform/affine_maps.h>

#include <cmath>
#include <sstream>

#include <shadetool/core/error.h>

namespace shadetool {

namespace {


void require_finite(const Vec3d& v, const std::string& source, const char* what) {
  if (!is_finite(v)) fail(source, 0, std::string(what) + " must be finite numbers");
}

std::string shortest(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

}  // namespace

void sin_cos_degrees(double degrees, double& sin_out, double& cos_out) {
  // remainder() is exact: r in [-180, 180]. q = nearest multiple of 90; r - 90 q is exact by
  // Sterbenz' lemma (r and 90 q are within a factor 2 of each other whenever q != 0).
  const double r = std::remainder(degrees, 360.0);
  const double q = std::nearbyint(r / 90.0);
  const double x = (r - 90.0 * q) * (kPi / 180.0);  // |x| <= pi/4
  const double s = std::sin(x), c = std::cos(x);
  switch (static_cast<int>(q)) {
    case 0: sin_out = s; cos_out = c; break;
    case 1: sin_out = c; cos_out = -s; break;
    case -1: sin_out = -c; cos_out = s; break;
    default: sin_out = -s; cos_out = -c; break;  // q = +-2: half a turn
  }
  sin_out += 0.0;  // turn -0 into +0, so no "-0" reaches an output file
  cos_out += 0.0;
}

Affine3d scale_map(const Vec3d& s, const std::string& source) {
  require_finite(s, source, "scale factors");
  Affine3d M;
  M.A = Mat3d::diagonal(s.x, s.y, s.z);
  return M;
}

Affine3d rotation_map(double degrees, const Vec3d& axis, const std::string& source) {
  if (!std::isfinite(degrees)) fail(source, 0, "the angle must be a finite number of degrees");
  require_finite(axis, source, "the axis components");
  const double axis_length = length(axis);
  if (!(axis_length > 0)) fail(source, 0, "the rotation axis has zero length");
  const Vec3d k{axis.x / axis_length, axis.y / axis_length, axis.z / axis_length};  // checked above

  double s, c;
  sin_cos_degrees(degrees, s, c);
  // versine 1 - cos: 2 sin^2(a/2) near a = 0, where 1 - c would cancel; elsewhere 1 - c is exact
  // enough (c <= cos 45 degrees in magnitude after the reduction, no cancellation).
  const double r = std::remainder(degrees, 360.0);
  double v;
  if (std::fabs(r) <= 45.0) {
    const double h = std::sin(r * (kPi / 360.0));
    v = 2.0 * h * h;
  } else {
    v = 1.0 - c;
  }

  // R = c I + s [k]x + v k k^T   (Rodrigues)
  Affine3d M;
  auto& R = M.A.m;
  R[0][0] = c + v * k.x * k.x;
  R[1][1] = c + v * k.y * k.y;
  R[2][2] = c + v * k.z * k.z;
  R[0][1] = v * k.x * k.y - s * k.z;
  R[1][0] = v * k.x * k.y + s * k.z;
  R[0][2] = v * k.x * k.z + s * k.y;
  R[2][0] = v * k.x * k.z - s * k.y;
  R[1][2] = v * k.y * k.z - s * k.x;
  R[2][1] = v * k.y * k.z + s * k.x;
  for (auto& row : R)
    for (auto& e : row) e += 0.0;  // no -0 entries
  return M;
}

Affine3d translation_map(const Vec3d& d, const std::string& source) {
  require_finite(d, source, "translation components");
  Affine3d M;
  M.t = d;
  return M;
}

Affine3d affine_from_row_major(const std::vector<double>& values, const std::string& source) {
  if (values.size() != 12 && values.size() != 16)
    fail(source, 0, "expected 12 or 16 numbers (a 3x4 or 4x4 matrix, row-major), got " + std::to_string(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      fail(source, 0, "matrix entry " + std::to_string(i + 1) + " (row " + std::to_string(i / 4 + 1) + ", column " +
                          std::to_string(i % 4 + 1) + ") is not a finite number");
  if (values.size() == 16) {
    const double* w = &values[12];
    if (!(w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 1))
      fail(source, 0, "the last row of a 4x4 matrix must be 0 0 0 1, got " + shortest(w[0]) + " " + shortest(w[1]) + " " +
                          shortest(w[2]) + " " + shortest(w[3]) +
                          ": a projective map has no affine normal transform (divide by w yourself if it is a "
                          "uniform homogeneous scale)");
  }
  Affine3d M;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) M.A.m[r][c] = values[4 * r + c];
    M.t[r] = values[4 * r + 3];
  }
  return M;
}

Affine3d compose_in_order(const std::vector<Affine3d>& maps) {
  Affine3d M;
  for (const auto& m : maps) M = compose(m, M);
  return M;
}

}  // namespace shadetool
