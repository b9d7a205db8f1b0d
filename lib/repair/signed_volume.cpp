// signed_volume.cpp: component volumes relative to their centroids (see the header).
#include "repair/signed_volume.h"

#include <cmath>
#include <cstdint>

namespace shadetool {

ComponentVolumes component_signed_volumes(const Mesh& mesh, const ConsistentWinding& winding) {
  const std::size_t K = winding.num_components, F = mesh.num_faces();
  ComponentVolumes out;
  out.centroid.assign(K, Vec3d{});
  out.volume.assign(K, 0.0);
  out.magnitude.assign(K, 0.0);

  // Centroid: reference vertex (first corner of the seed face) plus the mean offset from it.
  std::vector<Vec3d> reference(K), offset_sum(K);
  std::vector<double> corners(K, 0.0);
  for (std::size_t k = 0; k < K; ++k) {
    const std::uint32_t seed = winding.component_seed[k];
    if (mesh.face_size(seed) > 0) reference[k] = mesh.position(mesh.corner_vertex[mesh.face_start[seed]]);
  }
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t k = winding.face_component[f];
    if (k == ConsistentWinding::kNoComponent) continue;
    const Vec3d r = reference[k];
    Vec3d s{};
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) s += mesh.position(mesh.corner_vertex[c]) - r;
    offset_sum[k] += s;
    corners[k] += double(mesh.face_size(f));
  }
  for (std::size_t k = 0; k < K; ++k)
    out.centroid[k] = corners[k] > 0 ? reference[k] + offset_sum[k] * (1.0 / corners[k]) : reference[k];

  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t k = winding.face_component[f];
    if (k == ConsistentWinding::kNoComponent) continue;
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    if (e - b < 3) continue;
    const Vec3d c = out.centroid[k];
    const Vec3d p0 = mesh.position(mesh.corner_vertex[b]) - c;
    double sum = 0, abs_sum = 0;
    Vec3d pi = mesh.position(mesh.corner_vertex[b + 1]) - c;
    for (std::uint32_t i = b + 2; i < e; ++i) {
      const Vec3d pj = mesh.position(mesh.corner_vertex[i]) - c;
      const double det = dot(p0, cross(pi, pj));
      sum += det;
      abs_sum += std::abs(det);
      pi = pj;
    }
    out.volume[k] += winding.face_reverse[f] ? -sum : sum;
    out.magnitude[k] += abs_sum;
  }
  for (std::size_t k = 0; k < K; ++k) {
    out.volume[k] /= 6.0;
    out.magnitude[k] /= 6.0;
  }
  return out;
}

}  // namespace shadetool
