// fix_normals.cpp: check stored normals against the repaired faces (see the header).
#include <shadetool/repair/fix_normals.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {

enum class Verdict { Valid, NaN, Inf, Zero, Flipped };

// `reference` may be zero: then no flipped test (nothing to compare with).
Verdict judge(const Vec3d& stored, const Vec3d& reference) {
  if (std::isnan(stored.x) || std::isnan(stored.y) || std::isnan(stored.z)) return Verdict::NaN;
  if (!is_finite(stored)) return Verdict::Inf;
  if (stored.x == 0 && stored.y == 0 && stored.z == 0) return Verdict::Zero;
  if (dot(stored, reference) < 0) return Verdict::Flipped;
  return Verdict::Valid;
}

// Replaces the 3 doubles at `slot` when the verdict says so; counts it if any bit changed.
bool replace(double* slot, Verdict verdict, const Vec3d& replacement, NormalsFix& fix) {
  if (verdict == Verdict::Valid) return false;
  const double r[3] = {replacement.x, replacement.y, replacement.z};
  if (std::memcmp(slot, r, sizeof r) == 0) return false;
  std::memcpy(slot, r, sizeof r);
  switch (verdict) {
    case Verdict::NaN: ++fix.nan; break;
    case Verdict::Inf: ++fix.inf; break;
    case Verdict::Zero: ++fix.zero; break;
    case Verdict::Flipped: ++fix.flipped; break;
    case Verdict::Valid: break;
  }
  return true;
}

}  // namespace

NormalsFix fix_normals(Mesh& mesh, Weighting weighting) {
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces(), C = mesh.num_corners();
  if (mesh.has_vertex_normals() && mesh.vertex_normals.size() != 3 * V)
    fail("fix_normals", 0, "vertex normal array size differs from 3 x the vertex count");
  if (mesh.has_corner_normals() && mesh.corner_normal_index.size() != C)
    fail("fix_normals", 0, "corner normal index array size differs from the corner count");
  if (mesh.has_face_normals() && mesh.face_normals.size() != 3 * F)
    fail("fix_normals", 0, "face normal array size differs from 3 x the face count");

  NormalsFix fix;
  // Face normals ((0,0,0) for a degenerate face) only when stored normals are to be checked.
  const bool check_stored = mesh.has_vertex_normals() || mesh.has_face_normals();
  const std::vector<double> face_n = check_stored ? face_normals(mesh, Precision::Double) : std::vector<double>{};
  VertexNormals recomputed = vertex_normals(mesh, weighting, Precision::Double);

  if (!mesh.has_vertex_normals() && !mesh.has_corner_normals()) {
    mesh.vertex_normals = std::move(recomputed.normals);
    fix.missing = V;
    fix.vertex = V;
  } else if (mesh.has_vertex_normals()) {
    // A vertex is comparable when it has a face with a valid normal.
    std::vector<std::uint8_t> has_face(V, 0);
    for (std::size_t f = 0; f < F; ++f) {
      const Vec3d n = get3(face_n, f);
      if (n.x == 0 && n.y == 0 && n.z == 0) continue;
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
        if (mesh.corner_vertex[c] < V) has_face[mesh.corner_vertex[c]] = 1;
    }
    for (std::size_t v = 0; v < V; ++v) {
      const Vec3d r = get3(recomputed.normals, v);
      const Verdict verdict = judge(get3(mesh.vertex_normals, v), has_face[v] ? r : Vec3d{});
      fix.vertex += replace(&mesh.vertex_normals[3 * v], verdict, r, fix);
    }
  }

  if (mesh.has_corner_normals()) {
    const std::size_t N = mesh.corner_normals.size() / 3;
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    // Reference: each pool entry's normal from the corners that reference it (the normals
    // library's corner_group_normals); entries with no corner or no valid face have none.
    std::vector<std::uint32_t> group(C);
    std::vector<std::uint32_t> first_corner(N, kNone);
    for (std::size_t c = 0; c < C; ++c) {
      const std::uint32_t i = mesh.corner_normal_index[c];
      group[c] = i < N ? i : kNoGroup;
      if (i < N && first_corner[i] == kNone) first_corner[i] = std::uint32_t(c);
    }
    const GroupNormals reference = corner_group_normals(mesh, group, N, weighting, Precision::Double);
    std::vector<std::uint8_t> has_reference(N, 1);
    for (std::uint32_t i : reference.failed) has_reference[i] = 0;
    for (std::size_t i = 0; i < N; ++i) {
      if (first_corner[i] == kNone) continue;  // unreferenced: left alone
      const Vec3d ref = get3(reference.normals, i);  // (0, 0, 0) when failed: no flipped test
      const Verdict verdict = judge(get3(mesh.corner_normals, i), ref);
      const std::uint32_t v = mesh.corner_vertex[first_corner[i]];
      const Vec3d fallback = v < V ? get3(recomputed.normals, v) : Vec3d{0, 0, 1};
      fix.corner += replace(&mesh.corner_normals[3 * i], verdict, has_reference[i] ? ref : fallback, fix);
    }
  }

  if (mesh.has_face_normals()) {
    for (std::size_t f = 0; f < F; ++f) {
      const Vec3d n = get3(face_n, f);
      fix.face += replace(&mesh.face_normals[3 * f], judge(get3(mesh.face_normals, f), n), n, fix);
    }
  }
  return fix;
}

}  // namespace shadetool
