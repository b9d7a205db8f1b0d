// transform_normals.h: the matrix that maps normals under p -> A p + t, and its application to a
// flat array of normals (vertex normals, the corner-normal pool or face normals alike).
//
// Formula: a tangent t of the surface maps to A t; a normal n must stay orthogonal to every
// mapped tangent: (A t) . n' = t . (A^T n') = 0 for all t with t . n = 0, so A^T n' is parallel
// to n and n' is parallel to A^-T n (the "inverse transpose" rule: t^T A^T (A^T)^-1 n = 0;
// Turkowski, "Properties of Surface-Normal Transformations", Graphics Gems, 1990; Pharr, Jakob
// and Humphreys, Physically Based Rendering, 3rd ed., section 2.8.3 "Normals"). We use the cofactor matrix cof(A) = det(A) A^-T instead:
// the same direction up to the factor det(A), computed from 2x2 minors with no division, so it is
// defined and accurate however badly A is conditioned. The factor's sign flips the normal when
// det(A) < 0; outward normals are sign(det A) cof(A) n, and transform_mesh re-winds the faces of
// such a mirror so that they agree (reverse_winding.h).
//
// Inputs:  M, c        the map and classify_affine(M) (c.path must not be Singular: Error)
// Output:  NormalMap   B (3 by 3) and whether B n must be normalised:
//   Identity, Translation  untouched (B = I, nothing is done: bytes stay equal)
//   Rotation               B = A, no normalisation (A orthogonal: lengths kept to 1.5e-12)
//   UniformScale           B = A / s (orthogonal), no normalisation; sign(det) cof(sQ) = s^2 Q
//   General                B = sign(det S) cof(S), S = A 2^-k (exact scaling so that the
//                          cofactor's entries are O(1): no overflow for huge or tiny A); B n is
//                          normalised (cof(A) = 4^k cof(S): same direction)
//
// transform_normals(normals #N by 3, map): in place, double precision. A zero normal (the
// normals library's "no normal" value) and a non-finite one are left exactly as they are and
// counted in the return value; B n is never divided by an unchecked length (a finite non-zero n
// maps to a non-zero B n because B is non-singular here).
#pragma once

#include <cstddef>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/transform/classify_affine.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct NormalMap {
  Mat3d B = Mat3d::identity();
  bool untouched = true;   // Identity / Translation: do nothing
  bool normalize = false;  // General path only
};

NormalMap normal_map(const Affine3d& M, const AffineClass& c);

// Returns the number of normals left as they were because they were zero or not finite.
std::size_t transform_normals(std::vector<double>& normals, const NormalMap& map);

}  // namespace shadetool
#pragma GCC visibility pop
