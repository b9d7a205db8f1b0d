// degenerate_faces.cpp
#include <shadetool/info/degenerate_faces.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shadetool::info {

namespace {

bool has_repeated_index(const Mesh& mesh, std::uint32_t b, std::uint32_t e, std::vector<std::uint32_t>& scratch) {
  if (e - b <= 8) {
    for (std::uint32_t i = b; i < e; ++i)
      for (std::uint32_t j = i + 1; j < e; ++j)
        if (mesh.corner_vertex[i] == mesh.corner_vertex[j]) return true;
    return false;
  }
  scratch.assign(mesh.corner_vertex.begin() + b, mesh.corner_vertex.begin() + e);
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

}  // namespace

FaceDegeneracy face_degeneracy(const Mesh& mesh, std::size_t f, std::vector<std::uint32_t>& scratch) {
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  if (has_repeated_index(mesh, b, e, scratch)) return FaceDegeneracy::RepeatedIndex;
  const Vec3d p0 = mesh.position(mesh.corner_vertex[b]);
  Vec3d area{0, 0, 0};
  bool finite = std::isfinite(p0.x) && std::isfinite(p0.y) && std::isfinite(p0.z);
  for (std::uint32_t c = b + 1; c + 1 < e; ++c) {
    const Vec3d p1 = mesh.position(mesh.corner_vertex[c]) - p0;
    const Vec3d p2 = mesh.position(mesh.corner_vertex[c + 1]) - p0;
    area += cross(p1, p2);
  }
  finite = finite && std::isfinite(area.x) && std::isfinite(area.y) && std::isfinite(area.z);
  if (!finite) return FaceDegeneracy::NonFinite;
  if (area.x == 0 && area.y == 0 && area.z == 0) return FaceDegeneracy::ZeroArea;
  return FaceDegeneracy::None;
}

DegenerateFaces degenerate_faces(const Mesh& mesh) {
  DegenerateFaces d;
  std::vector<std::uint32_t> scratch;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    switch (face_degeneracy(mesh, f, scratch)) {
      case FaceDegeneracy::None: break;
      case FaceDegeneracy::RepeatedIndex: ++d.repeated_index; ++d.total; break;
      case FaceDegeneracy::NonFinite: ++d.nonfinite; break;
      case FaceDegeneracy::ZeroArea: ++d.zero_area; ++d.total; break;
    }
  }
  return d;
}

}  // namespace shadetool::info
