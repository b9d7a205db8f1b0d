// flat_patches.cpp: see flat_patches.h.
#include <shadetool/normals/flat_patches.h>

#include <cmath>

#include <algorithm>

#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/union_find.h>
#include <shadetool/normals/face_normals.h>

namespace shadetool {

namespace {

bool coplanar(const Vec3d& a, const Vec3d& b) {
  const Vec3d x = cross(a, b);
  return std::sqrt(dot(x, x)) <= kDegenerateTolerance && dot(a, b) > 0;
}

// The normal of each face's planar patch: faces joined across shared edges when coplanar, the
// patch's normal the normalised sum of its faces' area vectors (one vector for the whole patch).
std::vector<double> patch_normals(const Mesh& mesh, const std::vector<double>& fn) {
  const std::size_t F = mesh.num_faces();
  struct Edge { std::uint32_t a, b, f; };
  std::vector<Edge> edges;
  edges.reserve(mesh.num_corners());
  for (std::size_t f = 0; f < F; ++f) {
    if (fn[3 * f] == 0 && fn[3 * f + 1] == 0 && fn[3 * f + 2] == 0) continue;
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    for (std::uint32_t c = b; c < e; ++c) {
      const std::uint32_t u = mesh.corner_vertex[c], v = mesh.corner_vertex[c + 1 < e ? c + 1 : b];
      edges.push_back({std::min(u, v), std::max(u, v), std::uint32_t(f)});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  UnionFind patches(F);
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (edges[i].a == edges[i + 1].a && edges[i].b == edges[i + 1].b && coplanar(get3(fn, edges[i].f), get3(fn, edges[i + 1].f)))
      patches.unite(edges[i].f, edges[i + 1].f);
  std::vector<double> sum(3 * F, 0.0), out(3 * F, 0.0);
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t r = patches.find(std::uint32_t(f));
    set3(sum, r, get3(sum, r) + face_area_vector(mesh, f));
  }
  for (std::size_t f = 0; f < F; ++f) set3(out, f, normalized_or(get3(sum, patches.find(std::uint32_t(f))), get3(fn, f)));
  return out;
}

}  // namespace

std::size_t snap_flat_patches(const Mesh& mesh, std::vector<double>& normals, const std::vector<std::uint32_t>* corner_index) {
  const std::size_t R = normals.size() / 3;
  const std::vector<double> fn = face_normals(mesh, Precision::Double);
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> first(R, kNone);  // first valid face of each row
  std::vector<std::uint8_t> planar(R, 1);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Vec3d n = get3(fn, f);
    if (n.x == 0 && n.y == 0 && n.z == 0) continue;  // degenerate
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      const std::uint32_t r = corner_index ? (*corner_index)[c] : mesh.corner_vertex[c];
      if (r >= R || !planar[r]) continue;
      if (first[r] == kNone) { first[r] = std::uint32_t(f); continue; }
      planar[r] = coplanar(n, get3(fn, first[r]));
    }
  }
  const std::vector<double> pn = patch_normals(mesh, fn);
  std::size_t replaced = 0;
  for (std::size_t r = 0; r < R; ++r) {
    if (first[r] == kNone || !planar[r]) continue;
    const Vec3d n0 = get3(pn, first[r]);
    if (get3(normals, r) != n0) ++replaced;
    set3(normals, r, n0);
  }
  return replaced;
}

}  // namespace shadetool
