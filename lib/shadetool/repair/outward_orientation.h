// outward_orientation.h: which components to reverse as a whole so that each faces outward.
//
// Inputs:  mesh        positions #V by 3, faces #F
//          winding     the consistent winding (face_component, face_reverse, K components)
//          boundaries  component_boundaries(...): component_closed #K
// Output:  OutwardOrientation with
//   component_invert #K  1 = reverse the component relative to the consistent winding
//   component_basis  #K  what decided it:
//     Volume       closed, orientable: the signed volume (signed_volume.h) made positive
//     NestedShell  as Volume, then reversed because an odd number of other closed shells contain
//                  it (shell_nesting.h): the inner shell of a hollow ball faces its cavity
//     SurfaceVote  open, orientable: the winding-number vote (open_surface_vote.h) was decisive
//     AuthoredNormals  the input's normals (authored_normals_vote.h) were decisive where geometry
//                  is not: a closed component too thin for its volume's sign to mean anything
//                  (thin_closed_component) or with no volume, or an open one with an undecided vote
//     Majority     no geometric evidence (non-orientable; closed with no volume; open with an
//                  undecided vote): the winding most of the component's input faces already had
//                  is kept (ties keep the seed face's), so nothing is reversed that the input
//                  did not get wrong by a majority
//   nested_shells        components with basis NestedShell
//   majority_components  components with basis Majority
//
// Every decision depends on the geometry, the input normals and the consistent winding only, never
// on the input winding of a single face, except Majority, which a repaired mesh satisfies with zero reversals:
// repairing a repaired mesh changes nothing.
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

enum class OrientationBasis : std::uint8_t { Volume, NestedShell, SurfaceVote, AuthoredNormals, Majority };

struct OutwardOrientation {
  std::vector<std::uint8_t> component_invert;
  std::vector<OrientationBasis> component_basis;
  std::size_t nested_shells = 0;
  std::size_t majority_components = 0;
  std::size_t normals_components = 0;  // basis AuthoredNormals
};

OutwardOrientation outward_orientation(const Mesh& mesh, const ConsistentWinding& winding,
                                       const ComponentBoundaries& boundaries);
// The same, with the volumes already computed (component_signed_volumes(mesh, winding)).
OutwardOrientation outward_orientation(const Mesh& mesh, const ConsistentWinding& winding,
                                       const ComponentBoundaries& boundaries, const ComponentVolumes& volumes);

}  // namespace shadetool
#pragma GCC visibility pop
