// affine.h: 3x3 matrices and affine maps x -> A x + t, composed and applied in double.
//
// Normals transform by the cofactor matrix cof(A) = det(A) A^-T (the inverse transpose up to the
// positive or negative scale det(A)): t.n = 0 must survive the map, so n' = A^-T n (Turkowski,
// "Properties of Surface-Normal Transformations", Graphics Gems, 1990; Physically Based Rendering,
// 3rd ed., section 2.8.3 "Normals"). The cofactor needs no division, so it
// stays defined and accurate when A is badly conditioned. When det(A) < 0 (a mirror) cof(A) n
// points to the other side of the mapped surface: outward normals are sign(det A) cof(A) n, and a
// mesh's winding must be reversed to keep faces oriented (transform/ does that).
#pragma once

#include <array>
#include <cmath>
#include <type_traits>

#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Row-major 3x3: m[r][c].
struct Mat3d {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

  static Mat3d identity() { return {}; }
  static Mat3d diagonal(double a, double b, double c) {
    Mat3d r;
    r.m = {{{a, 0, 0}, {0, b, 0}, {0, 0, c}}};
    return r;
  }
  Vec3d row(int r) const { return {m[r][0], m[r][1], m[r][2]}; }
  Vec3d col(int c) const { return {m[0][c], m[1][c], m[2][c]}; }
};

inline Mat3d operator*(const Mat3d& a, const Mat3d& b) {
  Mat3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
  return r;
}
inline Vec3d operator*(const Mat3d& a, const Vec3d& v) { return {dot(a.row(0), v), dot(a.row(1), v), dot(a.row(2), v)}; }

inline Mat3d transpose(const Mat3d& a) {
  Mat3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

inline double determinant(const Mat3d& a) { return dot(a.row(0), cross(a.row(1), a.row(2))); }

// cof(A): entry (i,j) is (-1)^(i+j) times the minor of A without row i and column j.
// Built from A's columns c0, c1, c2: A^T cof(A) = det(A) I says column j of cof(A) is orthogonal
// to every column of A but c_j, so column j = c_(j+1) x c_(j+2) (indices mod 3). Exact products,
// no division: defined for singular A too (where it is the adjugate's transpose).
inline Mat3d cofactor(const Mat3d& a) {
  const Vec3d c0 = a.col(0), c1 = a.col(1), c2 = a.col(2);
  const Vec3d r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
  Mat3d r;
  for (int i = 0; i < 3; ++i) {
    r.m[i][0] = r0[i];
    r.m[i][1] = r1[i];
    r.m[i][2] = r2[i];
  }
  return r;
}

// An affine map p -> A p + t.
struct Affine3d {
  Mat3d A = Mat3d::identity();
  Vec3d t{0, 0, 0};
};

// (second o first): apply `first`, then `second`.
inline Affine3d compose(const Affine3d& second, const Affine3d& first) {
  return {second.A * first.A, second.A * first.t + second.t};
}

inline Vec3d transform_point(const Affine3d& M, const Vec3d& p) { return M.A * p + M.t; }
inline Vec3d transform_vector(const Affine3d& M, const Vec3d& v) { return M.A * v; }

// Normal transform, unnormalised: sign(det A) cof(A) n, so outward stays outward also for mirrors
// (whose faces are re-wound). Pass cof = cofactor(M.A) and its sign once per mesh.
inline Normal3d transform_normal(const Mat3d& signed_cofactor, const Normal3d& n) {
  return Normal3d(signed_cofactor * static_cast<const Vec3d&>(n));
}
// A normal is not a point or a direction: mapping it by A is the mistake these make impossible.
// (Templates, so that a braced {x, y, z} still means a point, not an ambiguity.)
template <class N, std::enable_if_t<std::is_same_v<N, Normal3d>, int> = 0>
Vec3d transform_point(const Affine3d& M, const N& n) = delete;
template <class N, std::enable_if_t<std::is_same_v<N, Normal3d>, int> = 0>
Vec3d transform_vector(const Affine3d& M, const N& n) = delete;
inline Mat3d signed_cofactor(const Mat3d& A) {
  Mat3d c = cofactor(A);
  if (determinant(A) < 0)
    for (auto& row : c.m)
      for (auto& x : row) x = -x;
  return c;
}

// The inverse of x -> A x + t: M^-1 = (A^-1, -A^-1 t), with A^-1 = cof(A)^T / det(A) (Cramer's
// rule; no pivoting needed for 3x3). Relative error about cond(A) * 2^-53.
// Degenerate input: det(A) zero or not finite -> returns false and leaves `inverse` untouched;
// the one division is by a determinant checked on the line before.
inline bool invert_affine(const Affine3d& M, Affine3d& inverse) {
  const double det = determinant(M.A);
  if (!(det != 0.0) || !std::isfinite(det)) return false;
  const Mat3d cof_t = transpose(cofactor(M.A));
  Affine3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.A.m[i][j] = cof_t.m[i][j] / det;  // det checked above
  r.t = -(r.A * M.t);
  inverse = r;
  return true;
}

// Exactly the identity map (bitwise 1s and 0s): then applying it can be skipped without changing
// a single bit of the result.
inline bool is_identity(const Affine3d& M) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (M.A.m[i][j] != (i == j ? 1.0 : 0.0)) return false;
  return M.t.x == 0.0 && M.t.y == 0.0 && M.t.z == 0.0;
}

}  // namespace shadetool
#pragma GCC visibility pop
