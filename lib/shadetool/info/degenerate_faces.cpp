// degenerate_faces.cpp: see degenerate_faces.h.
#include <shadetool/info/degenerate_faces.h>

#include <cstdint>
#include <vector>

#include <shadetool/geometry/degenerate_face.h>

namespace shadetool::info {

DegenerateFaces degenerate_faces(const Mesh& mesh) {
  DegenerateFaces d;
  std::vector<std::uint32_t> scratch;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    switch (face_degenerate_kind(mesh, f, scratch)) {
      case DegenerateKind::None: break;
      case DegenerateKind::RepeatedIndex: ++d.repeated_index; ++d.total; break;
      case DegenerateKind::TooFewCorners:  // no area at all
      case DegenerateKind::ZeroArea: ++d.zero_area; ++d.total; break;
      case DegenerateKind::NonFinite: ++d.nonfinite; break;
    }
  }
  return d;
}

}  // namespace shadetool::info
