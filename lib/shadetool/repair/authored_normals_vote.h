// authored_normals_vote.h: which way a component should face, by the normals the input came with.
//
// Geometry cannot orient every component: a closed sheet of near-zero volume (a leaf or a sign
// modelled as a closed thin shell, both sides welded at the rim) has a volume whose sign is
// rounding noise, and a flat open sheet wraps nothing. Where the input carries valid normals, the
// artist's intent is evidence: each face votes with its area vector (under the consistent winding)
// against the mean of the input normals at its corners.
//
// Inputs:  mesh     positions #V by 3, faces #F, and normals: corner normals (OBJ `vn`) if present,
//                   else vertex normals, else face normals; none: no vote
//          winding  face_reverse #F (the consistent winding)
//          faces    the component's faces
// Output:  AuthoredNormalsVote with
//   vote       sum over faces of N_f . m_f, N_f the face's area vector as consistently wound (geometry/face_area_vector.h),
//              m_f the sum of its corners' unit input normals (non-finite or zero ones skipped)
//   magnitude  sum of |N_f . m_f|
//   decided    magnitude > 0 and |vote| >= magnitude / 3 (faces agreeing outweigh the others 2:1)
//   invert     decided and vote < 0
// thin_closed_component: |V| <= 1e-3 * A * L (V the signed volume, A the area, L the bounding box
// diagonal): a shell thinner than about 0.3% of its size (a sphere has |V| / (A L) = 0.096), whose
// volume sign says less than its authored normals. Precision: double.
#pragma once

#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/consistent_winding.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct AuthoredNormalsVote {
  double vote = 0, magnitude = 0;
  bool decided = false, invert = false;
};

// Whether the mesh carries normals a vote can use.
bool has_authored_normals(const Mesh& mesh);

AuthoredNormalsVote authored_normals_vote(const Mesh& mesh, const ConsistentWinding& winding,
                                          const std::vector<std::uint32_t>& faces);

bool thin_closed_component(const Mesh& mesh, const std::vector<std::uint32_t>& faces, double volume);

}  // namespace shadetool
#pragma GCC visibility pop
