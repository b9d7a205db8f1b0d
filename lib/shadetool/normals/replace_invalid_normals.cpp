// replace_invalid_normals.cpp: see replace_invalid_normals.h.
#include <shadetool/normals/replace_invalid_normals.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/fallback_normal.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {

bool invalid(const double* n) {
  const bool finite = std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]);
  return !finite || (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0);
}

bool any_invalid(const std::vector<double>& a) {
  for (std::size_t i = 0; i + 3 <= a.size(); i += 3)
    if (invalid(&a[i])) return true;
  return false;
}

void put(double* slot, const double* n) {
  if (invalid(n)) n = kFallbackNormal;  // a degenerate face's (0, 0, 0), a failed group's
  for (int k = 0; k < 3; ++k) slot[k] = n[k];
}

}  // namespace

InvalidNormalsReplaced replace_invalid_normals(Mesh& mesh, Weighting weighting) {
  InvalidNormalsReplaced out;
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces(), C = mesh.num_corners();
  const bool bad_vertex = mesh.has_vertex_normals() && any_invalid(mesh.vertex_normals);
  const bool bad_corner = mesh.has_corner_normals() && any_invalid(mesh.corner_normals);
  const bool bad_face = mesh.has_face_normals() && any_invalid(mesh.face_normals);
  if (!bad_vertex && !bad_corner && !bad_face) return out;

  std::vector<double> smooth;  // vertex normals from the faces, when some row needs them
  if (bad_vertex || bad_corner) smooth = vertex_normals(mesh, weighting, Precision::Double).normals;
  if (bad_vertex)
    for (std::size_t v = 0; v < V && 3 * v + 2 < mesh.vertex_normals.size(); ++v)
      if (invalid(&mesh.vertex_normals[3 * v])) {
        put(&mesh.vertex_normals[3 * v], &smooth[3 * v]);
        ++out.vertex;
      }
  if (bad_corner) {
    const std::size_t N = mesh.corner_normals.size() / 3;
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> group(C), first_corner(N, kNone);
    for (std::size_t c = 0; c < C; ++c) {
      const std::uint32_t i = c < mesh.corner_normal_index.size() ? mesh.corner_normal_index[c] : kNoGroup;
      group[c] = i < N ? i : kNoGroup;
      if (i < N && first_corner[i] == kNone) first_corner[i] = std::uint32_t(c);
    }
    const GroupNormals reference = corner_group_normals(mesh, group, N, weighting, Precision::Double);
    for (std::size_t i = 0; i < N; ++i) {
      double* slot = &mesh.corner_normals[3 * i];
      if (!invalid(slot)) continue;
      const double* n = kFallbackNormal;  // unreferenced entry
      if (first_corner[i] != kNone) {
        n = &reference.normals[3 * i];  // (0, 0, 0) for a failed group: the vertex's normal
        const std::uint32_t v = mesh.corner_vertex[first_corner[i]];
        if (invalid(n) && v < V) n = &smooth[3 * std::size_t(v)];
      }
      put(slot, n);
      ++out.corner;
    }
  }
  if (bad_face) {
    const std::vector<double> flat = face_normals(mesh, Precision::Double);
    for (std::size_t f = 0; f < F && 3 * f + 2 < mesh.face_normals.size(); ++f)
      if (invalid(&mesh.face_normals[3 * f])) {
        put(&mesh.face_normals[3 * f], &flat[3 * f]);
        ++out.face;
      }
  }
  return out;
}

std::string invalid_normals_note(const InvalidNormalsReplaced& r) {
  if (r.total() == 0) return {};
  std::string kinds;
  auto add = [&](std::size_t n, const char* kind) {
    if (n == 0) return;
    if (!kinds.empty()) kinds += ", ";
    kinds += std::to_string(n) + " " + kind;
  };
  add(r.vertex, "vertex");
  add(r.corner, "corner");
  add(r.face, "face");
  return std::to_string(r.total()) + (r.total() == 1 ? " input normal had" : " input normals had") +
         " no direction (zero, NaN or Inf): replaced by the computed " + (r.total() == 1 ? "one" : "ones") + " (" + kinds + ")";
}

}  // namespace shadetool
