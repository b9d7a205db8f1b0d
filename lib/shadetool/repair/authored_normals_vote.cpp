// authored_normals_vote.cpp: orientation evidence from the input's normals (see the header).
#include <shadetool/repair/authored_normals_vote.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/face_area_vector.h>

namespace shadetool {

namespace {

// The input normal at corner c of face f, unit, or zero where there is none valid.
Vec3d input_normal(const Mesh& mesh, std::size_t f, std::uint32_t c) {
  Vec3d n{0, 0, 0};
  if (mesh.has_corner_normals()) {
    const std::uint32_t i = mesh.corner_normal_index[c];
    if (std::size_t(i) * 3 + 2 < mesh.corner_normals.size()) n = get3(mesh.corner_normals, i);
  } else if (mesh.has_vertex_normals()) {
    n = get3(mesh.vertex_normals, mesh.corner_vertex[c]);
  } else if (mesh.has_face_normals()) {
    n = get3(mesh.face_normals, f);
  }
  return normalized_or(n, Vec3d{0, 0, 0});
}

}  // namespace

bool has_authored_normals(const Mesh& mesh) {
  return mesh.has_corner_normals() || mesh.has_vertex_normals() || mesh.has_face_normals();
}

double authored_face_evidence(const Mesh& mesh, std::size_t f) {
  if (!has_authored_normals(mesh)) return 0;
  Vec3d m{0, 0, 0};
  for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) m += input_normal(mesh, f, c);
  return dot(face_area_vector(mesh, f), m);
}

bool winding_agrees(const AuthoredNormalsVote& vote, bool input_consistent) {
  return input_consistent && vote.decided && !vote.invert && vote.agreeing > 0;
}

AuthoredNormalsVote authored_normals_vote(const Mesh& mesh, const ConsistentWinding& winding,
                                          const std::vector<std::uint32_t>& faces) {
  AuthoredNormalsVote v;
  if (!has_authored_normals(mesh)) return v;
  for (std::uint32_t f : faces) {
    double e = authored_face_evidence(mesh, f);
    if (!std::isfinite(e)) continue;
    if (e > 0) { ++v.agreeing; v.agreeing_weight += e; }
    if (e < 0) { ++v.disagreeing; v.disagreeing_weight -= e; }
    if (winding.face_reverse[f]) e = -e;
    v.vote += e;
    v.magnitude += std::abs(e);
  }
  v.decided = v.magnitude > 0 && 3 * std::abs(v.vote) >= v.magnitude;
  v.invert = v.decided && v.vote < 0;
  return v;
}

bool thin_closed_component(const Mesh& mesh, const std::vector<std::uint32_t>& faces, double volume) {
  double area = 0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec3d lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  for (std::uint32_t f : faces) {
    area += 0.5 * length(face_area_vector(mesh, f));
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      const Vec3d p = mesh.position(mesh.corner_vertex[c]);
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], p[i]);
        hi[i] = std::max(hi[i], p[i]);
      }
    }
  }
  const double extent = length(hi - lo);
  return std::abs(volume) <= 1e-3 * area * extent;
}

}  // namespace shadetool
