// signed_volume.cpp: component volumes from a vertex of each component, in one pass over the
// faces that can also classify degenerate faces (see the header).
#include <shadetool/core/engine/parallel.h>
#include <shadetool/repair/signed_volume.h>

#include <cmath>
#include <cstdint>

#include <tbb/parallel_for.h>

#include <shadetool/core/bulk_reserve.h>

namespace shadetool {

ComponentVolumes component_signed_volumes(const Mesh& mesh, const ConsistentWinding& winding, DegenerateFaces* degenerate) {
  const std::size_t K = winding.num_components, F = mesh.num_faces();
  constexpr std::uint32_t kNone = ConsistentWinding::kNoComponent;
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const std::uint32_t* fs = mesh.face_start.data();
  const double* P = mesh.positions.data();
  const bool triangles = mesh.all_triangles();
  auto position = [P](std::uint32_t v) { return Vec3d{P[3 * v], P[3 * v + 1], P[3 * v + 2]}; };

  ComponentVolumes out;
  out.reference.assign(K, Vec3d{});
  out.centroid.assign(K, Vec3d{});
  out.volume.assign(K, 0.0);
  out.magnitude.assign(K, 0.0);
  for (std::size_t k = 0; k < K; ++k) {
    const std::uint32_t seed = winding.component_seed[k];
    if (mesh.face_size(seed) > 0) out.reference[k] = position(cv[fs[seed]]);
  }
  if (degenerate) {
    reserve_bulk(degenerate->kind, F);
    degenerate->kind.resize(F);
  }

  // One part of the faces, summed into its own per-component arrays. Sums of the current run of
  // faces of one component are kept in registers (no store-to-load chain through the arrays) and
  // flushed when the component changes.
  struct Sums {
    std::vector<double> volume, magnitude, corners;
    std::vector<Vec3d> offsets;
  };
  const std::uint32_t* component = winding.face_component.data();
  const std::uint8_t* reverse = winding.face_reverse.data();
  DegenerateKind* kind = degenerate ? degenerate->kind.data() : nullptr;
  auto sum_part = [&](std::size_t f0, std::size_t f1, Sums& sums) {
    sums.volume.assign(K, 0.0);
    sums.magnitude.assign(K, 0.0);
    sums.corners.assign(K, 0.0);
    sums.offsets.assign(K, Vec3d{});
    std::uint32_t run = kNone;
    Vec3d r{}, run_offsets{};
    double run_volume = 0, run_magnitude = 0, run_corners = 0;
    auto flush = [&]() {
      if (run == kNone) return;
      sums.volume[run] += run_volume;
      sums.magnitude[run] += run_magnitude;
      sums.offsets[run] += run_offsets;
      sums.corners[run] += run_corners;
      run_volume = run_magnitude = run_corners = 0;
      run_offsets = Vec3d{};
    };
    for (std::size_t f = f0; f < f1; ++f) {
      const std::uint32_t k = component[f];
      if (k == kNone) {  // no winding, or a duplicate: only classified
        if (kind) kind[f] = degenerate_kind(mesh, f);
        continue;
      }
      if (k != run) {
        flush();
        run = k;
        r = out.reference[k];
      }
      const std::uint32_t b = triangles ? std::uint32_t(3 * f) : fs[f], e = triangles ? b + 3 : fs[f + 1];
      double det_sum = 0, abs_sum = 0;
      Vec3d offsets{};
      if (triangles) {
        const Vec3d p0 = position(cv[b]), p1 = position(cv[b + 1]), p2 = position(cv[b + 2]);
        const Vec3d e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
        // The rule's sufficient test on this cross product (no choice of the shortest edges,
        // whose branches mispredict on randomly flipped faces); the rule itself only when it fails.
        if (kind) kind[f] = triangle_surely_valid(n, e1, e2) ? DegenerateKind::None : degenerate_kind(mesh, f);
        const Vec3d q0 = p0 - r;
        det_sum = dot(q0, n);  // det(p0 - r, p1 - r, p2 - r)
        abs_sum = std::abs(det_sum);
        offsets = q0 + (p1 - r) + (p2 - r);
      } else {
        if (kind) kind[f] = degenerate_kind(mesh, f);
        if (e == b) continue;  // an empty face: no corners, no volume
        const Vec3d p0 = position(cv[b]), q0 = p0 - r;
        offsets = q0;
        if (e - b >= 2) offsets += position(cv[b + 1]) - r;
        for (std::uint32_t i = b + 2; i < e; ++i) {  // fan triangles (p0, p_i-1, p_i)
          offsets += position(cv[i]) - r;
          const double det = dot(q0, cross(position(cv[i - 1]) - p0, position(cv[i]) - p0));
          det_sum += det;
          abs_sum += std::abs(det);
        }
      }
      run_volume += (1.0 - 2.0 * double(reverse[f])) * det_sum;  // a sign, without a branch on random flips
      run_magnitude += abs_sum;
      run_offsets += offsets;
      run_corners += double(e - b);
    }
    flush();
  };

  // Two fixed halves of the faces, in parallel, when the mesh is large and has few components
  // (each half keeps K sums); the halves are added in order, so the result does not depend on
  // the number of threads (only on F and K).
  const std::size_t parts = F >= engine::kSerialBelow && K <= 4096 ? 2 : 1;
  std::vector<Sums> part(parts);
  if (parts == 1) sum_part(0, F, part[0]);
  else tbb::parallel_for(std::size_t(0), parts, [&](std::size_t i) { sum_part(F * i / parts, F * (i + 1) / parts, part[i]); });
  std::vector<Vec3d> offset_sum(K);
  std::vector<double> corners(K, 0.0);
  for (const Sums& sums : part)
    for (std::size_t k = 0; k < K; ++k) {
      out.volume[k] += sums.volume[k];
      out.magnitude[k] += sums.magnitude[k];
      offset_sum[k] += sums.offsets[k];
      corners[k] += sums.corners[k];
    }
  for (std::size_t k = 0; k < K; ++k) {
    out.volume[k] /= 6.0;
    out.magnitude[k] /= 6.0;
    out.centroid[k] = corners[k] > 0 ? out.reference[k] + offset_sum[k] * (1.0 / corners[k]) : out.reference[k];
  }
  if (degenerate) count_degenerate_kinds(*degenerate);
  return out;
}

}  // namespace shadetool
