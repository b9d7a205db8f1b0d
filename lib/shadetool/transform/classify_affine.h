// classify_affine.h: which path a transform needs, decided from A alone (the 3 by 3 part of
// p -> A p + t), so that no more work is done on a mesh than the map requires.
//
// Input:  M  an Affine3d (A 3 by 3, t 3 by 1), finite entries (Error otherwise)
// Output: AffineClass
//   path:
//     Identity      A = I (within kIdentityTolerance) and t = 0 exactly: nothing changes
//     Translation   A = I (within kIdentityTolerance), t != 0: positions move, normals and faces
//                   are untouched (their bytes stay equal)
//     Rotation      A orthogonal: ||A^T A - I||max <= kOrthogonalTolerance. Normals n' = A n,
//                   not renormalised (A keeps lengths to within the tolerance)
//     UniformScale  A = s Q with s > 0, Q orthogonal (same tolerance on Q = A / s, s^2 =
//                   ||A||_F^2 / 3): normals n' = Q n, i.e. rotated only
//     General       anything else that is not singular: n' = sign(det A) cof(A) n, normalised
//     Singular      relative_det < kSingularTolerance (see below): normals have no reliable
//                   transform; transform_mesh refuses unless normals are dropped or recomputed
//   mirror         det(A) < 0: faces must be re-wound (an orthogonal A with det -1 is a
//                  Rotation with mirror = true: a rotation composed with a reflection)
//   det            det(A)
//   relative_det   |det A| / (||A||_F / sqrt 3)^3, in [0, 1] (by the AM-GM inequality on the
//                  singular values: s1 s2 s3 <= ((s1^2 + s2^2 + s3^2) / 3)^(3/2)); 1 exactly when
//                  A is a uniform scale times an orthogonal matrix, 0 when A is singular.
//                  Independent of the scale of A: it measures |det| relative to A's size.
//
// Tolerances (why these numbers):
//   kIdentityTolerance = 4 eps (eps = 2^-52): treating such an A as I moves a point by at most
//     3 * 4 eps |p|, the size of the rounding error of computing A p itself.
//   kOrthogonalTolerance = 1e-12: a normal mapped by such an A (or Q) keeps unit length to within
//     1.5e-12 (|A n|^2 = 1 + n^T E n, |n^T E n| <= 3 * 1e-12), far below what float output can
//     show (6e-8) and below the 1e-7 promised; composed rotations stay well inside it (each
//     product adds a few eps).
//   kSingularTolerance = 1e-9: the entries of a composed A carry rounding of about eps ||A||; the
//     transformed normals then move by up to about eps / relative_det radians, which at 1e-9 is
//     2e-7 rad (1.3e-5 degrees), the resolution of a float normal. Below it the normals (and for
//     relative_det near eps even the sign of det, i.e. whether the map mirrors) are not reliable.
//
// Precision: double. A is first scaled by a power of two (exact) so that its largest entry lies
// in [0.5, 1): det and the norms neither overflow nor underflow for any finite A (e.g. 1e200).
#pragma once

#include <shadetool/core/affine.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class TransformPath { Identity, Translation, Rotation, UniformScale, General, Singular };

struct AffineClass {
  TransformPath path = TransformPath::Identity;
  bool mirror = false;
  double det = 1;
  double relative_det = 1;
  double uniform_scale = 1;  // s for UniformScale (1 for Identity/Translation/Rotation)
};

constexpr double kIdentityTolerance = 4 * 2.220446049250313e-16;
constexpr double kOrthogonalTolerance = 1e-12;
constexpr double kSingularTolerance = 1e-9;

AffineClass classify_affine(const Affine3d& M);

// "identity", "translation", "rotation", "uniform-scale", "general", "singular".
const char* path_name(TransformPath path);

// A scaled by 2^-k so that max |a_ij| lies in [0.5, 1) (exact: only the exponent changes);
// returns k via `exponent`. The zero matrix is returned unchanged with exponent 0.
Mat3d scaled_to_unit(const Mat3d& A, int& exponent);

}  // namespace shadetool
#pragma GCC visibility pop
