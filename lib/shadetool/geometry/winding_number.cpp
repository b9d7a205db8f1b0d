// winding_number.cpp: solid angles and the fast winding-number hierarchy (see the header).
#include <shadetool/geometry/winding_number.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shadetool {

namespace {
constexpr double kFourPi = 12.566370614359172953850573533118;
constexpr std::uint32_t kLeafSize = 8;
}  // namespace

double triangle_solid_angle(const Vec3d& pa, const Vec3d& pb, const Vec3d& pc, const Vec3d& q) {
  const Vec3d a = pa - q, b = pb - q, c = pc - q;
  const double det = dot(a, cross(b, c));
  if (det == 0.0) return 0.0;  // in the plane: principal value (see the header)
  const double la = length(a), lb = length(b), lc = length(c);
  const double denom = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
  return 2.0 * std::atan2(det, denom);
}

WindingNumberTree winding_number_tree(const Mesh& mesh, const std::vector<std::uint32_t>& faces,
                                      const std::vector<std::uint8_t>& face_reverse) {
  WindingNumberTree t;
  // Origin: centre of the bounding box of the faces' corners.
  Vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::uint32_t f : faces)
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      const Vec3d p = mesh.position(mesh.corner_vertex[c]);
      for (int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], p[i]); hi[i] = std::max(hi[i], p[i]); }
    }
  if (lo.x <= hi.x) t.origin = lo * 0.5 + hi * 0.5;

  for (std::uint32_t f : faces) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    if (e - b < 3) continue;
    const bool rev = !face_reverse.empty() && face_reverse[f];
    const Vec3d p0 = mesh.position(mesh.corner_vertex[b]) - t.origin;
    for (std::uint32_t i = b + 1; i + 1 < e; ++i) {
      const Vec3d p1 = mesh.position(mesh.corner_vertex[i]) - t.origin;
      const Vec3d p2 = mesh.position(mesh.corner_vertex[i + 1]) - t.origin;
      t.corners.push_back(p0);
      t.corners.push_back(rev ? p2 : p1);
      t.corners.push_back(rev ? p1 : p2);
      t.triangle_face.push_back(f);
    }
  }
  const std::uint32_t T = std::uint32_t(t.triangle_face.size());
  if (T == 0) return t;

  // Build over a permutation, then reorder the triangles into leaf order.
  std::vector<std::uint32_t> order(T);
  std::iota(order.begin(), order.end(), 0u);
  std::vector<Vec3d> centroid(T);
  std::vector<Vec3d> area_vector(T);
  std::vector<double> area(T);
  for (std::uint32_t i = 0; i < T; ++i) {
    const Vec3d &a = t.corners[3 * i], &b = t.corners[3 * i + 1], &c = t.corners[3 * i + 2];
    centroid[i] = (a + b + c) * (1.0 / 3.0);
    area_vector[i] = cross(b - a, c - a) * 0.5;
    area[i] = length(area_vector[i]);
  }

  struct Task { std::uint32_t node, first, count; };
  std::vector<Task> stack{{0, 0, T}};
  t.nodes.emplace_back();
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    WindingNumberTree::Node node;
    node.first = task.first;
    node.count = task.count;
    double total_area = 0;
    Vec3d weighted{}, plain{}, clo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, chi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::uint32_t k = task.first; k < task.first + task.count; ++k) {
      const std::uint32_t i = order[k];
      node.area_vector += area_vector[i];
      total_area += area[i];
      weighted += centroid[i] * area[i];
      plain += centroid[i];
      for (int d = 0; d < 3; ++d) { clo[d] = std::min(clo[d], centroid[i][d]); chi[d] = std::max(chi[d], centroid[i][d]); }
    }
    // Area-weighted centre; the plain mean when every triangle has zero area.
    node.center = total_area > 0 ? weighted * (1.0 / total_area) : plain * (1.0 / double(task.count));
    for (std::uint32_t k = task.first; k < task.first + task.count; ++k) {
      const std::uint32_t i = order[k];
      for (int j = 0; j < 3; ++j) node.radius = std::max(node.radius, length(t.corners[3 * i + j] - node.center));
      const Vec3d offset = centroid[i] - node.center;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) node.moment[3 * r + c] += area_vector[i][r] * offset[c];
    }
    if (task.count > kLeafSize) {
      const Vec3d extent = chi - clo;
      const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
      const std::uint32_t half = task.count / 2;
      std::nth_element(order.begin() + task.first, order.begin() + task.first + half, order.begin() + task.first + task.count,
                       [&](std::uint32_t x, std::uint32_t y) { return centroid[x][axis] < centroid[y][axis]; });
      node.left = std::uint32_t(t.nodes.size());
      node.right = node.left + 1;
      t.nodes.emplace_back();
      t.nodes.emplace_back();
      stack.push_back({node.left, task.first, half});
      stack.push_back({node.right, task.first + half, task.count - half});
    }
    t.nodes[task.node] = node;
  }

  std::vector<Vec3d> corners(3 * std::size_t(T));
  std::vector<std::uint32_t> triangle_face(T);
  for (std::uint32_t k = 0; k < T; ++k) {
    for (int j = 0; j < 3; ++j) corners[3 * k + j] = t.corners[3 * order[k] + j];
    triangle_face[k] = t.triangle_face[order[k]];
  }
  t.corners.swap(corners);
  t.triangle_face.swap(triangle_face);
  return t;
}

double winding_number(const WindingNumberTree& tree, const Vec3d& q_mesh, std::uint32_t skip_face, double beta) {
  if (tree.nodes.empty()) return 0.0;
  const Vec3d q = q_mesh - tree.origin;
  double omega = 0;
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const WindingNumberTree::Node& n = tree.nodes[stack[--top]];
    const Vec3d d = n.center - q;
    const double dist = length(d);
    if (dist > beta * n.radius) {
      // Far field (dist > beta * radius >= 0, so dist > 0): dipole plus gradient term.
      const double inv3 = 1.0 / (dist * dist * dist), inv5 = inv3 / (dist * dist);
      const double* M = n.moment;
      const double trace = M[0] + M[4] + M[8];
      const double dMd = d.x * (M[0] * d.x + M[1] * d.y + M[2] * d.z) + d.y * (M[3] * d.x + M[4] * d.y + M[5] * d.z) +
                         d.z * (M[6] * d.x + M[7] * d.y + M[8] * d.z);
      omega += dot(n.area_vector, d) * inv3 + trace * inv3 - 3.0 * dMd * inv5;
      continue;
    }
    if (n.left == 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
        if (tree.triangle_face[k] == skip_face) continue;
        omega += triangle_solid_angle(tree.corners[3 * k], tree.corners[3 * k + 1], tree.corners[3 * k + 2], q);
      }
      continue;
    }
    stack[top++] = n.left;
    stack[top++] = n.right;
  }
  return omega / kFourPi;
}

}  // namespace shadetool
