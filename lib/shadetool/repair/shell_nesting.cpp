// shell_nesting.cpp: nesting depth of closed shells by winding numbers (see the header).
#include <shadetool/repair/shell_nesting.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <shadetool/geometry/winding_number.h>

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

  // Candidate containers of A: shells whose box contains A's box, so also A's box centre. A
  // uniform grid over all boxes (about S cells) lists each box in the cells it overlaps; boxes
  // over more than 64 cells (a room around many parts) go to one list every shell checks.
  Box all;
  for (const Box& b : box) { all.add(b.lo); all.add(b.hi); }
  const int G = std::max(1, int(std::ceil(std::cbrt(double(S)))));
  auto cell_of = [&](const Vec3d& p, int axis) {
    const double extent = all.hi[axis] - all.lo[axis];
    const double t = extent > 0 ? (p[axis] - all.lo[axis]) / extent : 0.0;  // divisor checked
    return std::min(G - 1, std::max(0, int(t * G)));
  };
  std::vector<std::vector<std::uint32_t>> cell(std::size_t(G) * G * G);
  std::vector<std::uint32_t> large;
  for (std::uint32_t b = 0; b < S; ++b) {
    int lo[3], hi[3];
    long cells = 1;
    for (int i = 0; i < 3; ++i) {
      lo[i] = cell_of(box[b].lo, i);
      hi[i] = cell_of(box[b].hi, i);
      cells *= hi[i] - lo[i] + 1;
    }
    if (cells > 64) { large.push_back(b); continue; }
    for (int x = lo[0]; x <= hi[0]; ++x)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int z = lo[2]; z <= hi[2]; ++z) cell[(std::size_t(x) * G + y) * G + z].push_back(b);
  }

  std::vector<std::unique_ptr<WindingNumberTree>> tree(S);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> contained;  // (inner, outer) shell positions
  auto test = [&](std::size_t a, std::size_t bi) {
    if (a == bi || !box[a].inside(box[bi])) return;
    const std::uint32_t kb = shells[bi];
    if (!tree[bi]) {
      std::vector<std::uint32_t> faces(groups.faces.begin() + groups.start[kb], groups.faces.begin() + groups.start[kb + 1]);
      tree[bi] = std::make_unique<WindingNumberTree>(winding_number_tree(mesh, faces, winding.face_reverse));
    }
    const double sign = shell_invert[kb] ? -1.0 : 1.0;
    for (const Vec3d& p : samples[a])
      if (!(sign * winding_number(*tree[bi], p) > 0.5)) return;
    contained.emplace_back(std::uint32_t(a), std::uint32_t(bi));
  };
  for (std::size_t a = 0; a < S; ++a) {
    const Vec3d centre = box[a].lo * 0.5 + box[a].hi * 0.5;
    for (std::uint32_t bi : cell[(std::size_t(cell_of(centre, 0)) * G + cell_of(centre, 1)) * G + cell_of(centre, 2)]) test(a, bi);
    for (std::uint32_t bi : large) test(a, bi);
  }
  // Two shells each "inside" the other are the same surface twice (a duplicated object): their
  // samples sit on each other, where w is 1/2 up to rounding. Neither is nested.
  std::sort(contained.begin(), contained.end());
  for (auto [a, bi] : contained)
    if (!std::binary_search(contained.begin(), contained.end(), std::make_pair(bi, a))) ++depth[shells[a]];
  return depth;
}

}  // namespace shadetool
