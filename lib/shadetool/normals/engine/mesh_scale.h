// mesh_scale.h: one exact power-of-two scale per mesh, so that no product the normals kernels form
// (squared lengths ~ x^2, area vectors and their squares ~ x^2 .. x^4, Max's l0 l1 l2 ~ x^6 and
// its weights ~ x^-2) over- or underflows, whatever the size of the mesh (internal to lib/normals).
//
// Inputs:  mesh     positions #V by 3, faces (a view: core/mesh_view.h)
//          storage  holds the scaled positions when they are needed (left empty otherwise: no
//                   allocation)
// Output:  in_kernel_range returns `mesh` itself when its sampled largest |coordinate| m lies in
//          [2^-kKernelRangeExponent, 2^kKernelRangeExponent) (every ordinary mesh: no copy, no
//          pass over the positions), else a view of the same faces over `storage`, filled with the
//          mesh's positions times 2^-e, e = ilogb(m) (clamped to [-1000, 1000]), so its sampled
//          largest coordinate lies in [1, 2). Faces are never copied.
// Why the result is bitwise scale-invariant: multiplying by a power of two is exact while results
// stay normal, so a mesh scaled by 2^k gives the same scaled copy bit for bit as the mesh itself,
// and every later operation is identical. Inside the range the kernels' arithmetic (and their
// range thresholds: 1e+-125 on squared edges, 1e+-250 on N . N, 1e+-280 on sums, the normal range
// of l0 l1 l2) commutes with the power of two for any face whose edges are longer than ~2^-130 of
// the mesh's largest coordinate (l0 l1 l2 >= 2^-1022 at x = 2^-32 2^-130), so the unscaled
// computation gives the bits the scaled one would.
// The trigger and the scale both come from m = sampled_max_coordinate: max |coordinate| over
// kRangeSample vertices spread evenly over the mesh (all vertices when #V <= kRangeSample): ~1000
// loads instead of a pass over 3 #V doubles, which is not negligible beside the kernels (figures:
// bench/normals/results/notes.md). m scales exactly with
// the mesh (its ilogb moves by k), so a 2^k-scaled mesh is copied to the same bits as the mesh
// itself, whatever its unsampled vertices hold. A mesh whose unsampled vertices lie far (2^32 and
// more) beyond its sampled ones is computed as far as the kernels' range allows (out-of-range faces
// are degenerate, as before this rule; never NaN).
// Non-finite coordinates are ignored by the maximum and stay NaN or Inf in the copy (the faces
// using them are degenerate, as unscaled). Scaling down can round a coordinate below 2^-1022 of the
// largest into a subnormal: such a vertex is at relative distance 2^-1022 from others anyway.
// Precision: double; the multiplications are exact (for normal results).
#pragma once

#include <cstddef>
#include <vector>

#include <shadetool/core/mesh_view.h>

namespace shadetool::normals_detail {

// Meshes whose sampled largest |coordinate| lies in [2^-32, 2^32) run unscaled.
constexpr int kKernelRangeExponent = 32;
constexpr std::size_t kRangeSample = 1024;

// Largest finite |coordinate| among up to kRangeSample vertices spread evenly (vertex i V / n);
// 0 when none is finite and nonzero.
double sampled_max_coordinate(const MeshView& mesh);

// The power of two 2^-e, e = ilogb(peak) clamped to [-1000, 1000], that brings a positive finite
// peak into [1, 2); 1 for a peak that is zero or not finite. The one rule for choosing a scale, used
// for positions here and for the float path's contributions (corner_contributions.h).
double power_of_two_scale(double peak);

// `mesh`, or its faces over its positions scaled into the kernels' range in `storage` (see above).
MeshView in_kernel_range(const MeshView& mesh, std::vector<double>& storage);

}  // namespace shadetool::normals_detail
