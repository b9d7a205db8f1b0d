// flat_patches.h: a vertex (or smooth group) all of whose faces lie in one plane gets exactly that
// plane's normal, not a weighted sum of nearly equal normals rounded to a slightly different
// vector (the failure users report in trimesh's smooth_shade and manifold's CalculateNormals:
// flat parts of a model that shade with faint seams).
//
// Inputs:  mesh          positions, faces
//          normals       #R by 3 pool to correct in place: vertex normals (R = #V, corner_index
//                        null) or corner normals with corner_index (#C, row of each corner)
// Output:  normals       rows whose valid faces are coplanar replaced by the normal of the planar
//                        patch of the first such face: faces joined across shared edges when
//                        coplanar, the patch's normal the normalised sum of its faces' area vectors
//                        (geometry/face_area_vector.h), one vector for the whole patch, so every
//                        vertex of a flat part gets the same bits; for an axis-aligned plane
//                        exactly (0, 0, +-1) and so on
//          returns       rows replaced
// Coplanar: every face's unit normal n_f against the first one's n_0: |n_f x n_0| <=
// kDegenerateTolerance (64 eps, the degenerate rule's, geometry/degenerate_face.h) and
// n_f . n_0 > 0. Faces sharing a vertex with parallel normals lie in one plane through it.
// Degenerate faces are ignored; a row with no valid face is left as it is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::size_t snap_flat_patches(const Mesh& mesh, std::vector<double>& normals,
                              const std::vector<std::uint32_t>* corner_index);

}  // namespace shadetool
#pragma GCC visibility pop
