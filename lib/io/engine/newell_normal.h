// newell_normal.h (engine, not installed): the unit normal of one polygon of a Mesh, for the
// readers and writers that must supply a normal the file lacks (OBJ corners without vn, STL
// facets of fan triangles with no area). The geometry module's face area vector is the library's
// one home for this formula; io keeps this copy until io may depend on it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <shadetool/core/mesh.h>

namespace shadetool::io {

// The unit normal of face f by Newell's sum over its corners (any polygon), or (0,0,0) when the
// sum vanishes or is not finite (a face with no area). Sum in double; scaled by its largest
// component before the length is taken, so the squares neither overflow nor underflow.
inline Vec3d newell_normal(const Mesh& mesh, std::size_t f) {
  Vec3d n{0, 0, 0};
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  for (std::uint32_t c = b; c < e; ++c) {
    const Vec3d p = mesh.position(mesh.corner_vertex[c]);
    const Vec3d q = mesh.position(mesh.corner_vertex[c + 1 < e ? c + 1 : b]);
    n.x += (p.y - q.y) * (p.z + q.z);
    n.y += (p.z - q.z) * (p.x + q.x);
    n.z += (p.x - q.x) * (p.y + q.y);
  }
  const double m = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
  if (!(m > 0) || !std::isfinite(m)) return {0, 0, 0};
  n = n * (1.0 / m);  // divisor checked
  const double len = length(n);  // in [1, sqrt(3)]
  return n * (1.0 / len);
}


}  // namespace shadetool::io
