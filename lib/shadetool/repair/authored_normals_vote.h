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
//   agreeing, disagreeing   faces whose input winding agrees (e_f > 0) or disagrees (e_f < 0) with
//              their input normals, e_f = authored_face_evidence(mesh, f) (the input winding, not
//              the consistent one); faces with e_f = 0 or not finite (no valid normal, zero area)
//              are neither
//   agreeing_weight, disagreeing_weight  the sums of |e_f| over those faces
// winding_agrees(vote, consistent): the input's winding and its normals make the same statement:
// the component's input winding is already consistent (no face reversed by step 1) and decided
// with invert = false (agreeing faces outweigh the others 2:1). Repair keeps such a component as
// it is, before any geometric evidence is asked (repair_mesh.h: what repair trusts, in order).
// thin_closed_component: |V| <= 1e-3 * A * L (V the signed volume, A the area, L the bounding box
// diagonal): a shell thinner than about 0.3% of its size (a sphere has |V| / (A L) = 0.096), whose
// volume sign says less than its authored normals. Precision: double.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/consistent_winding.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct AuthoredNormalsVote {
  double vote = 0, magnitude = 0;
  bool decided = false, invert = false;
  std::size_t agreeing = 0, disagreeing = 0;
  double agreeing_weight = 0, disagreeing_weight = 0;
};

// e_f = N_f . m_f for face f as the input winds it (N_f its area vector, m_f the sum of its
// corners' unit input normals): > 0 the winding agrees with the authored normals, < 0 it
// disagrees, 0 (or not finite) no evidence. 0 when the mesh has no normals.
double authored_face_evidence(const Mesh& mesh, std::size_t f);

bool winding_agrees(const AuthoredNormalsVote& vote, bool input_consistent);

// Whether the mesh carries normals a vote can use.
bool has_authored_normals(const Mesh& mesh);

AuthoredNormalsVote authored_normals_vote(const Mesh& mesh, const ConsistentWinding& winding,
                                          const std::vector<std::uint32_t>& faces);

bool thin_closed_component(const Mesh& mesh, const std::vector<std::uint32_t>& faces, double volume);

}  // namespace shadetool
#pragma GCC visibility pop
