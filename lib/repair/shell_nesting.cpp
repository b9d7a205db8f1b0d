// shell_nesting.cpp: nesting depth of closed shells by winding numbers (see the header).
#include "repair/shell_nesting.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "repair/winding_number.h"

namespace shadetool {

namespace {

constexpr std::size_t kSamplesPerShell = 64;

struct Box {
  Vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec3d& p) {
    for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], p[i]); hi[i] = std::max(hi[i], p[i]); }
  }
  bool inside(const Box& o) const {
    return lo.x >= o.lo.x && lo.y >= o.lo.y && lo.z >= o.lo.z && hi.x <= o.hi.x && hi.y <= o.hi.y && hi.z <= o.hi.z;
  }
};

Vec3d face_centroid(const Mesh& mesh, std::uint32_t f) {
  Vec3d s{};
  const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
  const Vec3d p0 = mesh.position(mesh.corner_vertex[b]);
  for (std::uint32_t c = b; c < e; ++c) s += mesh.position(mesh.corner_vertex[c]) - p0;
  return p0 + s * (1.0 / double(e - b));  // e > b: faces in a component have corners
}

}  // namespace

std::vector<std::uint32_t> shell_nesting_depth(const Mesh& mesh, const ConsistentWinding& winding,
                                               const ComponentFaces& groups, const std::vector<std::uint32_t>& shells,
                                               const std::vector<std::uint8_t>& shell_invert) {
  const std::size_t K = winding.num_components, S = shells.size();
  std::vector<std::uint32_t> depth(K, 0);
  if (S < 2) return depth;

  std::vector<Box> box(S);
  std::vector<std::vector<Vec3d>> samples(S);
  for (std::size_t s = 0; s < S; ++s) {
    const std::uint32_t k = shells[s];
    const std::uint32_t b = groups.start[k], n = groups.start[k + 1] - b;
    for (std::uint32_t i = b; i < b + n; ++i) {
      const std::uint32_t f = groups.faces[i];
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) box[s].add(mesh.position(mesh.corner_vertex[c]));
    }
    const std::size_t m = std::min<std::size_t>(n, kSamplesPerShell);
    for (std::size_t j = 0; j < m; ++j) samples[s].push_back(face_centroid(mesh, groups.faces[b + j * n / m]));
  }

  std::vector<std::unique_ptr<WindingNumberTree>> tree(S);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> contained;  // (inner, outer) shell positions
  for (std::size_t a = 0; a < S; ++a) {
    for (std::size_t bi = 0; bi < S; ++bi) {
      if (a == bi || !box[a].inside(box[bi])) continue;
      const std::uint32_t kb = shells[bi];
      if (!tree[bi]) {
        std::vector<std::uint32_t> faces(groups.faces.begin() + groups.start[kb], groups.faces.begin() + groups.start[kb + 1]);
        tree[bi] = std::make_unique<WindingNumberTree>(winding_number_tree(mesh, faces, winding.face_reverse));
      }
      const double sign = shell_invert[kb] ? -1.0 : 1.0;
      bool inside = true;
      for (const Vec3d& p : samples[a])
        if (!(sign * winding_number(*tree[bi], p) > 0.5)) { inside = false; break; }
      if (inside) contained.emplace_back(std::uint32_t(a), std::uint32_t(bi));
    }
  }
  // Two shells each "inside" the other are the same surface twice (a duplicated object): their
  // samples sit on each other, where w is 1/2 up to rounding. Neither is nested.
  std::sort(contained.begin(), contained.end());
  for (auto [a, bi] : contained)
    if (!std::binary_search(contained.begin(), contained.end(), std::make_pair(bi, a))) ++depth[shells[a]];
  return depth;
}

}  // namespace shadetool
