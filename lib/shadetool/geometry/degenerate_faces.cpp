// degenerate_faces.cpp: every face classified by the one rule, and counted (see the header).
#include <shadetool/geometry/degenerate_faces.h>

#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadetool {

DegenerateFaces degenerate_faces(const Mesh& mesh) {
  const std::size_t F = mesh.num_faces();
  DegenerateFaces d;
  d.kind.assign(F, DegenerateKind::None);
  // Faces are independent: split over threads (results do not depend on their number).
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, F, 1 << 14), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<std::uint32_t> scratch;
    for (std::size_t f = r.begin(); f < r.end(); ++f) d.kind[f] = face_degenerate_kind(mesh, f, scratch);
  });
  count_degenerate_kinds(d);
  return d;
}

void count_degenerate_kinds(DegenerateFaces& d) {
  d.too_few_corners = d.repeated_index = d.zero_area = d.non_finite = 0;
  for (DegenerateKind k : d.kind) {
    switch (k) {
      case DegenerateKind::None: break;
      case DegenerateKind::TooFewCorners: ++d.too_few_corners; break;
      case DegenerateKind::RepeatedIndex: ++d.repeated_index; break;
      case DegenerateKind::ZeroArea: ++d.zero_area; break;
      case DegenerateKind::NonFinite: ++d.non_finite; break;
    }
  }
}

}  // namespace shadetool
