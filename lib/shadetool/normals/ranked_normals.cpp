// ranked_normals.cpp: see ranked_normals.h.
#include <shadetool/normals/ranked_normals.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_fallback.h>

namespace shadetool {

double ranked_weight_base(int strength) {
  if (strength < 1 || strength > 100) throw Error("weighted normals: the strength must be in [1, 100]");
  if (strength == 100) return 32767.0;
  if (strength == 1) return 1.0 / 32767.0;
  const double w = strength / 50.0;
  return (w - 1) * 25 > 1 ? (w - 1) * 25 : w;
}

namespace {

// Angle between the corner's edges to its neighbours, in [0, pi]; 0 for a zero-length edge.
double corner_angle(const Vec3d& p, const Vec3d& prev, const Vec3d& next) {
  const Vec3d a = next - p, b = prev - p, x = cross(a, b);
  return std::atan2(std::sqrt(dot(x, x)), dot(a, b));
}

}  // namespace

CornerNormals ranked_normals(const Mesh& mesh, const RankedWeightingOptions& options) {
  const double w = ranked_weight_base(options.strength);
  if (!(options.threshold >= 0)) throw Error("weighted normals: the threshold must be >= 0");
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces(), C = mesh.num_corners();
  CornerNormals out;
  // Items: vertices, or (keep sharp) the smooth groups of corner_normals.
  std::size_t items = V;
  if (options.crease_angle >= 0) {
    CornerNormals groups = corner_normals(mesh, options.crease_angle);
    out.corner_index = std::move(groups.corner_index);
    items = groups.normals.size() / 3;
  } else {
    out.corner_index = mesh.corner_vertex;
  }
  const std::vector<double> fn = face_normals(mesh, Precision::Double);
  // Each corner's value.
  std::vector<double> value(C, 0.0);
  std::vector<std::uint32_t> face_of(C);
  for (std::size_t f = 0; f < F; ++f) {
    const bool valid = !(fn[3 * f] == 0 && fn[3 * f + 1] == 0 && fn[3 * f + 2] == 0);
    if (!valid) ++out.degenerate_faces;
    const double area = 0.5 * length(face_area_vector(mesh, f));
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    for (std::uint32_t c = b; c < e; ++c) {
      face_of[c] = std::uint32_t(f);
      if (!valid) { value[c] = -1; continue; }  // contributes nothing
      const Vec3d p = mesh.position(mesh.corner_vertex[c]);
      const Vec3d prev = mesh.position(mesh.corner_vertex[c > b ? c - 1 : e - 1]);
      const Vec3d next = mesh.position(mesh.corner_vertex[c + 1 < e ? c + 1 : b]);
      switch (options.mode) {
        case RankedWeighting::FaceArea: value[c] = area; break;
        case RankedWeighting::CornerAngle: value[c] = corner_angle(p, prev, next); break;
        case RankedWeighting::FaceAreaAngle: value[c] = area * corner_angle(p, prev, next); break;
      }
    }
  }
  std::vector<std::uint32_t> order(C);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return value[a] > value[b]; });
  struct Item {
    double current = 0;  // the value that last set the rank
    int rank = 0;
    Vec3d sum{0, 0, 0};
  };
  std::vector<Item> item(items);
  for (std::uint32_t c : order) {
    if (value[c] < 0) continue;
    Item& it = item[out.corner_index[c]];
    if (it.current == 0) it.current = value[c];
    if (std::fabs(it.current - value[c]) > options.threshold) {
      ++it.rank;
      it.current = value[c];
    }
    it.sum = it.sum + get3(fn, face_of[c]) * (value[c] / std::pow(w, it.rank));  // w > 0
  }
  out.normals.assign(3 * items, 0.0);
  std::vector<std::uint32_t> first_face(items, ~0u);
  for (std::size_t c = 0; c < C; ++c)
    if (value[c] >= 0 && first_face[out.corner_index[c]] == ~0u) first_face[out.corner_index[c]] = face_of[c];
  std::vector<std::uint8_t> fell_back(items, 0);
  for (std::size_t i = 0; i < items; ++i) {
    const Vec3d n = normalized_or(item[i].sum, Vec3d{0, 0, 0});
    if (n.x == 0 && n.y == 0 && n.z == 0) {
      fell_back[i] = 1;
      const Vec3d f = first_face[i] != ~0u ? get3(fn, first_face[i]) : Vec3d{kFallbackNormal[0], kFallbackNormal[1], kFallbackNormal[2]};
      set3(out.normals, i, f);
    } else {
      set3(out.normals, i, n);
    }
  }
  for (std::size_t c = 0; c < C; ++c) out.fallback_corners += fell_back[out.corner_index[c]];
  return out;
}

}  // namespace shadetool
