// two_sided_faces.h: faces that are the back of an earlier face: the same vertices (indices, not
// positions) in the reverse cyclic order. An exporter writes a two-sided surface this way
// (Blender 2.71's chair_model.obj: every triangle twice, once per winding); summed into one vertex
// normal, the two sides cancel to rounding noise.
//
// Inputs:  mesh   faces #F of any size (positions are not read)
// Output:  TwoSidedFaces with
//   front_of  #F  for a back face, the earlier face it is the back of; kNotBack otherwise. Each
//                 front has at most one back: a third copy of the same triangle with the back's
//                 winding is the back of no one (it is a plain duplicate, for repair to report).
//   backs         how many faces have a front
// A face with fewer than 3 corners is never a front or a back. Faces that are the same in the
// same order are duplicates, not backs.
// Method: faces bucketed by their smallest vertex index (counts, offsets, data: two passes), and
// each face compared with the earlier faces of its bucket only; a bucket holds the faces around
// one vertex whose other corners all have larger indices, a handful on any real mesh: O(C).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct TwoSidedFaces {
  static constexpr std::uint32_t kNotBack = 0xffffffffu;
  std::vector<std::uint32_t> front_of;
  std::size_t backs = 0;
};

TwoSidedFaces two_sided_faces(const Mesh& mesh);

// The mesh with the back faces left out: the positions and the other faces, in order, nothing
// else (no attributes): what normals are computed from when a surface is two-sided.
Mesh front_faces(const Mesh& mesh, const TwoSidedFaces& two_sided);

}  // namespace shadetool
#pragma GCC visibility pop
