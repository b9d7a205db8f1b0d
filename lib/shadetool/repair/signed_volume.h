// signed_volume.h: signed volume enclosed by each component, with the winding it will have after
// the consistent-winding reversals; optionally the degenerate faces, found in the same pass.
//
// Inputs:  mesh        positions #V by 3, faces #F (polygons are fan-triangulated from corner 0)
//          winding     face_component #F, face_reverse #F, component_seed, num_components K
//          degenerate  null, or filled as degenerate_faces(mesh) would fill it (same kinds and
//                      counts): the pass reads every face's positions anyway, and a triangle's
//                      edge cross product serves both tests
// Outputs: ComponentVolumes with
//   reference #K  r: the first vertex of the component's seed face
//   centroid  #K  mean of the component's corner positions
//   volume    #K  V = 1/6 sum over fan triangles (p0, pi, pi+1) of det(p0 - r, pi - r, pi+1 - r),
//                 negated for reversed faces; positive when a closed component's faces wind
//                 counter-clockwise seen from outside (divergence theorem). Computed as
//                 (p0 - r) . ((pi - p0) x (pi+1 - p0)), the same determinant.
//   magnitude #K  the same sum of |det| / 6: the scale the volume is compared with
//
// Precision: double throughout. Every tetrahedron is spanned from a vertex r of the component
// itself (not the origin), so the terms scale with the component's size and not its distance from
// the origin: a unit sphere placed at 1e6 loses ~1e-10 of its volume, where volumes spanned from
// the origin would cancel at ~1e12 and lose everything. (An earlier version spanned them from the
// centroid, which needs a second pass; for a closed component the volume does not depend on the
// apex, and a vertex of the component bounds the terms as well.) Only closed components have a
// volume that does not depend on r; the caller decides. Degenerate faces contribute (near) zero.
// Threads: meshes of 32768+ faces with at most 4096 components are summed in two fixed halves
// (TBB), added in order: the result depends on F and K, never on the number of threads.
#pragma once

#include <cmath>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/repair/degenerate_faces.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct ComponentVolumes {
  std::vector<Vec3d> reference;
  std::vector<Vec3d> centroid;
  std::vector<double> volume;
  std::vector<double> magnitude;
};

ComponentVolumes component_signed_volumes(const Mesh& mesh, const ConsistentWinding& winding,
                                          DegenerateFaces* degenerate = nullptr);

// Whether a volume is too small relative to its magnitude to have a sign: a closed surface that
// encloses nothing (two coincident faces wound oppositely, a flat double-sided sheet).
inline bool volume_has_sign(double volume, double magnitude) {
  return std::abs(volume) > 1e-6 * magnitude;
}

}  // namespace shadetool
#pragma GCC visibility pop
