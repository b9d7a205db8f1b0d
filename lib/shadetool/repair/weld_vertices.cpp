// weld_vertices.cpp: grid-hash vertex welding (see the header).
#include <shadetool/repair/weld_vertices.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <shadetool/core/error.h>

namespace shadetool {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();
constexpr double kCellsPerAxis = double(1u << 21) - 2;

// Open addressing, linear probing: packed cell -> first kept vertex in the cell.
struct CellHash {
  std::vector<std::uint64_t> key;
  std::vector<std::uint32_t> head;
  std::uint64_t mask = 0;
  explicit CellHash(std::size_t n) {
    std::size_t cap = 16;
    while (cap < 2 * n) cap *= 2;
    key.assign(cap, kEmpty);
    head.assign(cap, kNone);
    mask = cap - 1;
  }
  static std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
    x ^= x >> 30; x *= 0xbf58476d1ce4e5b9ULL; x ^= x >> 27; x *= 0x94d049bb133111ebULL; return x ^ (x >> 31);
  }
  std::size_t slot(std::uint64_t k) const {
    std::size_t i = mix(k) & mask;
    while (key[i] != kEmpty && key[i] != k) i = (i + 1) & mask;
    return i;
  }
};

}  // namespace

WeldResult weld_vertices(Mesh& mesh, double eps) {
  if (!(eps >= 0) || !std::isfinite(eps)) fail("weld_vertices", 0, "weld distance must be finite and >= 0");
  const std::size_t V = mesh.num_vertices();
  WeldResult out;
  out.old_to_new.resize(V);
  if (V == 0) return out;

  Vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t v = 0; v < V; ++v) {
    const Vec3d p = mesh.position(v);
    if (!is_finite(p)) continue;
    for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], p[i]); hi[i] = std::max(hi[i], p[i]); }
  }
  const double extent = lo.x <= hi.x ? std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) : 0.0;
  double h = std::max(eps, extent / kCellsPerAxis);
  if (!(h > 0) || !std::isfinite(h)) h = 1.0;  // all points equal (or none finite): one cell

  std::vector<std::uint32_t> rep(V, kNone), next_in_cell(V, kNone);
  CellHash cells(V);
  auto cell_of = [&](const Vec3d& p, std::int64_t c[3]) {
    for (int i = 0; i < 3; ++i) c[i] = std::int64_t(std::floor((p[i] - lo[i]) / h));  // h > 0 checked
  };
  auto pack = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (std::uint64_t(x) << 42) | (std::uint64_t(y) << 21) | std::uint64_t(z);
  };
  const int reach = eps > 0 ? 1 : 0;  // eps = 0: exact duplicates share a cell

  std::size_t kept = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const Vec3d p = mesh.position(v);
    if (!is_finite(p)) { rep[v] = std::uint32_t(v); out.old_to_new[v] = std::uint32_t(kept++); continue; }
    std::int64_t c[3];
    cell_of(p, c);
    std::uint32_t best = kNone;
    double best_d = HUGE_VAL;
    for (int dx = -reach; dx <= reach; ++dx)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dz = -reach; dz <= reach; ++dz) {
          const std::int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
          if (x < 0 || y < 0 || z < 0) continue;
          const std::size_t s = cells.slot(pack(x, y, z));
          if (cells.key[s] == kEmpty) continue;
          for (std::uint32_t r = cells.head[s]; r != kNone; r = next_in_cell[r]) {
            // length, not its square: squares of distances below 1e-154 underflow to 0
            const double d = length(mesh.position(r) - p);
            if (d <= eps && (d < best_d || (d == best_d && r < best))) { best = r; best_d = d; }
          }
        }
    if (best != kNone) {
      rep[v] = best;
      out.old_to_new[v] = out.old_to_new[best];
      continue;
    }
    rep[v] = std::uint32_t(v);
    out.old_to_new[v] = std::uint32_t(kept++);
    const std::size_t s = cells.slot(pack(c[0], c[1], c[2]));
    cells.key[s] = pack(c[0], c[1], c[2]);
    next_in_cell[v] = cells.head[s];
    cells.head[s] = std::uint32_t(v);
  }

  out.removed = V - kept;
  if (out.removed == 0) return out;
  // Positions and every per-vertex array (normals, colours, quality, properties: Mesh's
  // for_each_vertex_array): a merged vertex keeps its representative's values. An array of the
  // wrong length (a caller's) is left as it is, for the writer's note.
  auto compact = [&](auto& a, std::size_t width) {
    if (a.size() != width * V) return;
    for (std::size_t v = 0; v < V; ++v) {
      if (rep[v] != v) continue;
      const std::size_t n = out.old_to_new[v];
      for (std::size_t i = 0; i < width; ++i) a[width * n + i] = a[width * v + i];
    }
    a.resize(width * kept);
  };
  compact(mesh.positions, 3);
  mesh.for_each_vertex_array(compact);
  for (auto& v : mesh.corner_vertex) v = v < V ? out.old_to_new[v] : v;
  return out;
}

}  // namespace shadetool
