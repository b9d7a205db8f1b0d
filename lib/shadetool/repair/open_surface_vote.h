// open_surface_vote.h: which way an open component should face, by the generalised winding number
// of the component itself (Jacobson et al. 2013).
//
// Why the winding number and not rays: an open surface has no inside, but it wraps around a
// region (a hemisphere around its centre, a cloth around what it was draped on), and the winding
// number says which: at the surface, the principal value w (the mean of the two sides) is
// positive when the surface bends around the region behind it, i.e. when it faces away from that
// region, and negative when it faces into it. It is deterministic (no ray directions to choose, no
// rays grazing edges or slipping through cracks between unwelded faces), tolerant of holes and
// non-manifold pieces by construction, and cheap with the hierarchy of Barill et al. 2018
// (O(log F) per sample). Rays (libigl's orient_outward_ao, Borodin et al. 2004) count how often
// each side is seen from outside; on a surface with a clear wrapped region both agree, and where
// they do not (a flat sheet, a symmetric terrain) neither has evidence.
//
// Inputs:  mesh     positions #V by 3, faces #F
//          winding  face_reverse #F (the consistent winding)
//          faces    the component's faces
// Output:  OpenSurfaceVote with
//   vote        sum over sampled faces of area * w at the face's centroid (own face left out,
//               i.e. the principal value), with the consistent winding
//   magnitude   sum of area * |w|;  area  sum of sampled areas;  samples  faces sampled
//   decided     |vote| >= 1/2 magnitude (faces voting for the winner outweigh the others 3:1)
//               and magnitude >= 1e-3 area (mean |w| well above the hierarchy's error)
//   invert      decided and vote < 0: reverse the whole component
// Samples: every face when the component has at most 2048, else 2048 spread evenly through the
// face list. Zero-area faces carry no weight. Precision: double.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/consistent_winding.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct OpenSurfaceVote {
  double vote = 0, magnitude = 0, area = 0;
  std::size_t samples = 0;
  bool decided = false;
  bool invert = false;
};

OpenSurfaceVote open_surface_vote(const Mesh& mesh, const ConsistentWinding& winding,
                                  const std::vector<std::uint32_t>& faces);

}  // namespace shadetool
#pragma GCC visibility pop
