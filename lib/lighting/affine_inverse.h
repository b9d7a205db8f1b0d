// affine_inverse.h: the inverse of an affine map x -> A x + t, and whether a map is the identity.
//
// Inputs:  M  affine map (3x3 A, translation t), double
// Output:  M^-1 = (A^-1, -A^-1 t), with A^-1 = cof(A)^T / det(A) (Cramer's rule; cofactor from
//          core/affine.h, no pivoting needed for 3x3). Relative error about cond(A) * 2^-53.
// Degenerate input: det(A) zero or not finite -> returns false and leaves `inverse` untouched;
//          the one division is by a determinant checked on the line before.
//
// Kept inside lighting/ (core/affine.h is shared and only extended additively by its owner).
#pragma once

#include <cmath>

#include <shadetool/core/affine.h>

namespace shadetool {

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
