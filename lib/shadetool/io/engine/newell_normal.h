// newell_normal.h (engine, not installed): the unit normal of one polygon of a Mesh, for the
// readers and writers that must supply a normal the file lacks (OBJ corners without vn, STL
// facets of fan triangles with no area), from the geometry module's one area vector.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <shadetool/core/mesh.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/scaled_length.h>

namespace shadetool::io {

// The unit normal of face f: its area vector (geometry/face_area_vector.h: two shortest edges for
// a triangle, Newell for a polygon) normalised by the one safe rule (geometry/scaled_length.h),
// or (0,0,0) when the face has no area by the one degenerate rule (geometry/degenerate_face.h's
// face_area_kind: fewer than 3 corners, NaN/Inf, or |N| <= 64 eps times its bound), as the normals
// module decides it: a sliver's area vector is rounding noise, not a direction.
inline Vec3d newell_normal(const Mesh& mesh, std::size_t f) {
  if (face_area_kind(mesh, f) != DegenerateKind::None) return {0, 0, 0};
  Vec3d n{0, 0, 0};
  if (!normalise_checked(face_area_vector(mesh, f), n)) return {0, 0, 0};
  return n;
}

}  // namespace shadetool::io
