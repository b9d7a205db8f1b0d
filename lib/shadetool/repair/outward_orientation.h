// outward_orientation.h: which components to reverse as a whole so that each faces outward.
//
// Inputs:  mesh        positions #V by 3, faces #F
//          winding     the consistent winding (face_component, face_reverse, K components)
//          boundaries  component_boundaries(...): component_closed #K
// Output:  OutwardOrientation with
//   component_invert #K  1 = reverse the component relative to the consistent winding
//   component_basis  #K  what decided it, in the order it is asked (what repair trusts):
//     WindingAndNormals  the input's winding is consistent and its authored normals agree with it
//                  (authored_normals_vote.h, winding_agrees): the author said twice which side
//                  is out; kept, and no geometric evidence is asked (a room or a sky box faces
//                  in; an open terrain faces up whatever its winding number says)
//     AuthoredNormals  the input's normals decide: (a) the part's input winding is inconsistent,
//                  so the majority of its agreeing evidence decides (2:1); or (b) geometry has
//                  no evidence (below): a closed component too thin for its volume's sign to mean
//                  anything (thin_closed_component) or with no volume, an open one with an
//                  undecided vote
//     Volume       closed, orientable: the signed volume (signed_volume.h) made positive
//     NestedShell  as Volume, then reversed because an odd number of other closed shells contain
//                  it (shell_nesting.h): the inner shell of a hollow ball faces its cavity. Never
//                  applied to a WindingAndNormals or AuthoredNormals component.
//     SurfaceVote  open, orientable: the winding-number vote (open_surface_vote.h) was decisive
//     Majority     no evidence (non-orientable; closed with no volume; open with an undecided
//                  vote; no normals or undecided ones): the winding most of the component's input
//                  faces already had is kept (ties keep the seed face's), so nothing is reversed
//                  that the input did not get wrong by a majority
//   nested_shells        components with basis NestedShell
//   majority_components  components with basis Majority
//   normals_components   components with basis AuthoredNormals
//   agreeing_components  components with basis WindingAndNormals
//   geometry_overruled   WindingAndNormals components that geometry would have reversed (a
//                        negative volume, odd nesting depth, or a decisive vote against)
//   faces_agreeing, faces_disagreeing  over all components: faces whose input winding agrees or
//                        disagrees with their authored normals (authored_face_evidence)
//
// Every decision depends on the geometry, the input normals and the consistent winding only, never
// on the input winding of a single face, except Majority and WindingAndNormals, which a repaired
// mesh satisfies with zero reversals: repairing a repaired mesh changes nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/component_boundaries.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/repair/signed_volume.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class OrientationBasis : std::uint8_t { WindingAndNormals, AuthoredNormals, Volume, NestedShell, SurfaceVote, Majority };

struct OutwardOrientation {
  std::vector<std::uint8_t> component_invert;
  std::vector<OrientationBasis> component_basis;
  std::size_t nested_shells = 0;
  std::size_t majority_components = 0;
  std::size_t normals_components = 0;  // basis AuthoredNormals
  std::size_t agreeing_components = 0;  // basis WindingAndNormals
  std::size_t geometry_overruled = 0;
  std::size_t faces_agreeing = 0, faces_disagreeing = 0;
};

OutwardOrientation outward_orientation(const Mesh& mesh, const ConsistentWinding& winding,
                                       const ComponentBoundaries& boundaries);
// The same, with the volumes already computed (component_signed_volumes(mesh, winding)).
OutwardOrientation outward_orientation(const Mesh& mesh, const ConsistentWinding& winding,
                                       const ComponentBoundaries& boundaries, const ComponentVolumes& volumes);

}  // namespace shadetool
#pragma GCC visibility pop
