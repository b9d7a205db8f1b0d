// affine_maps.h: the elementary affine maps the transform flags name, and their composition.
//
// Inputs/Outputs (every map is an Affine3d, p -> A p + t, A 3 by 3 row-major, t 3 by 1):
//   scale_map(s)                    A = diag(sx, sy, sz), t = 0
//   rotation_map(degrees, axis)     A = R (Rodrigues' formula, right-handed: counter-clockwise
//                                   seen from the tip of `axis` looking towards the origin), t = 0
//   translation_map(d)              A = I, t = d
//   affine_from_row_major(values)   12 values: the rows of [A | t] (3 by 4); 16 values: the rows of
//                                   a 4 by 4 homogeneous matrix whose last row must be 0 0 0 1
//   compose_in_order(maps)          maps[0] acts first: M = maps[n-1] o ... o maps[1] o maps[0]
//
// Rotation: R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T with k = axis / |axis| (Rodrigues
// 1840; e.g. Murray, Li & Sastry, "A Mathematical Introduction to Robotic Manipulation", 1994, ch. 2).
// The angle is in degrees at this interface (radians only inside) and reduced exactly to
// [-45, 45] degrees plus a multiple of 90 before sin/cos, so multiples of 90 degrees give exact
// 0 and +-1 entries (a quarter turn of an integer grid stays an integer grid).
//
// Precision: double throughout; composition is exact matrix products in double (no inversion).
//
// Degenerate input, refused with shadetool::Error `SOURCE: what is wrong` (SOURCE names the flag
// or file the numbers came from): a non-finite number anywhere, a rotation axis of zero length,
// a wrong count of matrix values, and a 4 by 4 matrix whose last row is not exactly 0 0 0 1 (a
// projective map: it does not map normals by any 3 by 3 matrix, so no normal transform exists).
#pragma once

#include <string>
#include <vector>

#include <shadetool/core/affine.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

Affine3d scale_map(const Vec3d& s, const std::string& source = "--scale");
Affine3d rotation_map(double degrees, const Vec3d& axis, const std::string& source = "--rotate");
Affine3d translation_map(const Vec3d& d, const std::string& source = "--translate");
Affine3d affine_from_row_major(const std::vector<double>& values, const std::string& source = "--matrix");
Affine3d compose_in_order(const std::vector<Affine3d>& maps);

// sin and cos of an angle in degrees, exact at multiples of 90 degrees (see above).
void sin_cos_degrees(double degrees, double& sin_out, double& cos_out);

}  // namespace shadetool
#pragma GCC visibility pop
