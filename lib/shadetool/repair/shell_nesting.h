// shell_nesting.h: how many other closed shells contain each closed shell (nesting depth).
//
// Inputs:  mesh       positions #V by 3, faces #F
//          winding    face_component, face_reverse (the consistent winding)
//          groups     faces_by_component(winding)
//          shells     the component indices to consider (closed, orientable, with a signed volume)
//          shell_invert  #K flags: 1 when component k must be reversed as a whole for its volume
//                     to be positive (every considered shell is evaluated outward-facing)
// Output:  #K depths (0 for components not in `shells`): the number of other shells B that
//          contain shell A. Shells at odd depth bound a cavity (the inner shell of a hollow
//          ball) and face into it: that is containment parity, as CGAL's
//          orient_to_bound_a_volume does.
//
// Method: B contains A when A's bounding box lies in B's and B's winding number (outward-facing,
// so 1 inside) exceeds 1/2 at every one of up to 64 sample points on A (centroids of faces
// spread evenly through A's face list). Requiring every sample keeps shells that merely
// intersect (a character's head sphere pushed into its body) from being called nested. A's
// points lie on A, not on B, unless the shells touch; then the answer is whichever side rounding
// puts them, and two shells found inside each other (the same surface twice) count as not
// nested. Winding numbers use WindingNumberTree (built only for shells that are candidates).
// Candidates come from a uniform grid of about K cells over the shells' boxes (a container's box
// holds the centre of the inner shell's box; boxes spanning more than 64 cells are checked by
// every shell), so K small separate shells cost O(K), not O(K^2), box tests, plus O(log F) per
// sample actually evaluated.
#pragma once

#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/consistent_winding.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::vector<std::uint32_t> shell_nesting_depth(const Mesh& mesh, const ConsistentWinding& winding,
                                               const ComponentFaces& groups, const std::vector<std::uint32_t>& shells,
                                               const std::vector<std::uint8_t>& shell_invert);

}  // namespace shadetool
#pragma GCC visibility pop
