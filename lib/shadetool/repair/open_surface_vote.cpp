// open_surface_vote.cpp: winding-number vote for an open component (see the header).
#include <shadetool/repair/open_surface_vote.h>

#include <algorithm>
#include <cmath>

#include <shadetool/geometry/winding_number.h>

namespace shadetool {

namespace {
constexpr std::size_t kMaxSamples = 2048;
}  // namespace

OpenSurfaceVote open_surface_vote(const Mesh& mesh, const ConsistentWinding& winding,
                                  const std::vector<std::uint32_t>& faces) {
  OpenSurfaceVote out;
  // One face cannot wrap anything: its own face is left out of its sample, so w = 0 exactly.
  // Returning early spares a tree per face of a triangle soup.
  if (faces.size() < 2) return out;
  const WindingNumberTree tree = winding_number_tree(mesh, faces, winding.face_reverse);
  const std::size_t n = faces.size(), m = std::min(n, kMaxSamples);
  for (std::size_t j = 0; j < m; ++j) {
    const std::uint32_t f = faces[j * n / m];
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    if (e - b < 3) continue;
    // Area (Newell, fan from corner 0) and centroid, relative to corner 0.
    const Vec3d p0 = mesh.position(mesh.corner_vertex[b]);
    Vec3d twice_area{}, offset{};
    Vec3d pi = mesh.position(mesh.corner_vertex[b + 1]) - p0;
    offset += pi;
    for (std::uint32_t i = b + 2; i < e; ++i) {
      const Vec3d pj = mesh.position(mesh.corner_vertex[i]) - p0;
      twice_area += cross(pi, pj);
      offset += pj;
      pi = pj;
    }
    const double area = 0.5 * length(twice_area);
    if (!(area > 0) || !std::isfinite(area)) continue;
    const Vec3d q = p0 + offset * (1.0 / double(e - b));
    const double w = winding_number(tree, q, f);
    out.vote += area * w;
    out.magnitude += area * std::abs(w);
    out.area += area;
    ++out.samples;
  }
  out.decided = out.magnitude > 0 && std::abs(out.vote) >= 0.5 * out.magnitude && out.magnitude >= 1e-3 * out.area;
  out.invert = out.decided && out.vote < 0;
  return out;
}

}  // namespace shadetool
