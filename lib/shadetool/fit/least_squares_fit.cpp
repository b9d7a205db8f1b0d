// least_squares_fit.cpp: see least_squares_fit.h.
#include <shadetool/fit/least_squares_fit.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <shadetool/core/error.h>
#include <shadetool/fit/triangle_quadrature.h>
#include <shadetool/geometry/face_area_vector.h>

namespace shadetool {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

Vec3d vertex_position(const std::vector<double>& positions, std::uint32_t v) { return get3(positions, v); }

double triangle_area(const std::vector<double>& positions, const std::uint32_t* v) {
  return 0.5 * length(triangle_area_vector(positions.data(), v[0], v[1], v[2]).N);
}

// The bilinear map of quad q0..q3 at (u, v): its corner weights and area element |P_u x P_v|.
struct BilinearPoint {
  double phi[4];
  double area_element;
};
BilinearPoint bilinear_point(const Vec3d q[4], double u, double v) {
  BilinearPoint b{{(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v}, 0};
  const Vec3d pu = (q[1] - q[0]) * (1 - v) + (q[2] - q[3]) * v;
  const Vec3d pv = (q[3] - q[0]) * (1 - u) + (q[2] - q[1]) * u;
  b.area_element = length(cross(pu, pv));
  return b;
}

int quad_gauss_points(int samples) { return samples == 1 ? 1 : (samples == 3 ? 2 : 3); }

void quad_corners(const FitElements& e, const std::vector<double>& positions, std::size_t k, Vec3d q[4]) {
  for (int j = 0; j < 4; ++j) q[j] = vertex_position(positions, e.quad_vertex[4 * k + j]);
}

// One triangle of the regulariser's edge map: its nodes, vertices and area.
struct RegTriangle {
  std::uint32_t node[3];
  std::uint32_t vertex[3];
};

// The squared kink of g across edge (a, b) between wings w1 and w2, unfolded about the edge
// (least_squares_fit.h, R): with t the unit edge direction, wing w at (x, +-y) in the plane,
// grad g . t is the same on both sides, and grad g . s = (c_w - c_a - x (c_b - c_a) / L) / y, so
// R_e = (A1 + A2)^2 (d . c)^2 with d over (a, b, w1, w2). False for a degenerate butterfly.
bool edge_kink(const Vec3d& pa, const Vec3d& pb, const Vec3d& pw1, const Vec3d& pw2, double d[4], double& weight) {
  const Vec3d e = pb - pa;
  const double L = length(e);
  if (!(L > 0) || !std::isfinite(L)) return false;
  const Vec3d t = e * (1.0 / L);  // divisor checked
  const double x1 = dot(pw1 - pa, t), x2 = dot(pw2 - pa, t);
  const double y1 = length((pw1 - pa) - t * x1), y2 = length((pw2 - pa) - t * x2);
  if (!(y1 > 0) || !(y2 > 0)) return false;
  // side 1: g_s = (c_w1 - c_a - x1 (c_b - c_a)/L) / y1; side 2 (wing at -y2): the same with -y2.
  const double s1 = 1.0 / y1, s2 = -1.0 / y2;  // divisors checked above
  d[0] = (x1 / L - 1) * s1 - (x2 / L - 1) * s2;
  d[1] = (-x1 / L) * s1 - (-x2 / L) * s2;
  d[2] = s1;
  d[3] = -s2;
  const double area_sum = 0.5 * L * (y1 + y2);
  weight = area_sum * area_sum;
  return true;
}

}  // namespace

FitElements fit_elements(const Mesh& mesh, const std::vector<std::uint32_t>& corner_node, std::size_t nodes) {
  FitElements e;
  const bool own_nodes = !corner_node.empty();
  if (own_nodes && corner_node.size() != mesh.num_corners())
    throw Error("fit_elements: corner_node has " + std::to_string(corner_node.size()) + " entries for " +
                std::to_string(mesh.num_corners()) + " corners");
  e.nodes = own_nodes ? nodes : mesh.num_vertices();
  const auto node_of = [&](std::size_t c) { return own_nodes ? corner_node[c] : mesh.corner_vertex[c]; };
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const std::size_t size = mesh.face_size(f), c0 = mesh.face_start[f];
    if (size < 3) {
      ++e.skipped_faces;
      continue;
    }
    if (size == 4) {
      for (std::size_t j = 0; j < 4; ++j) {
        e.quad_vertex.push_back(mesh.corner_vertex[c0 + j]);
        e.quad_node.push_back(node_of(c0 + j));
      }
      e.quad_face.push_back(std::uint32_t(f));
      continue;
    }
    for (std::size_t i = 1; i + 1 < size; ++i) {  // fan from corner 0, as render draws it
      for (std::size_t c : {c0, c0 + i, c0 + i + 1}) {
        e.tri_vertex.push_back(mesh.corner_vertex[c]);
        e.tri_node.push_back(node_of(c));
      }
      e.tri_face.push_back(std::uint32_t(f));
    }
  }
  return e;
}

FitQuadrature fit_quadrature(const FitElements& e, const std::vector<double>& positions, int samples) {
  if (!triangle_quadrature_supported(samples))
    throw Error("fit_quadrature: " + std::to_string(samples) + " points per triangle is not a rule (1, 3, 6 or 12)");
  FitQuadrature q;
  q.samples = samples;
  const auto push = [&q](const std::uint32_t* nodes, const std::uint32_t* vertices, const double* phi, int n,
                         double weight, std::uint32_t face) {
    for (int j = 0; j < 4; ++j) {
      q.node.push_back(nodes[j < n ? j : 0]);
      q.vertex.push_back(vertices[j < n ? j : 0]);
      q.phi.push_back(j < n ? phi[j] : 0.0);
    }
    q.weight.push_back(weight);
    q.face.push_back(face);
  };
  const std::vector<QuadraturePoint> rule = triangle_quadrature(samples);
  const std::size_t T = e.tri_face.size();
  const int g = quad_gauss_points(samples);
  const std::size_t most = T * rule.size() + e.quad_face.size() * std::size_t(g * g);
  q.node.reserve(4 * most);
  q.vertex.reserve(4 * most);
  q.phi.reserve(4 * most);
  q.weight.reserve(most);
  q.face.reserve(most);
  for (std::size_t t = 0; t < T; ++t) {
    const double area = triangle_area(positions, &e.tri_vertex[3 * t]);
    if (!(area > 0)) continue;  // no area, no part of the integral
    for (const QuadraturePoint& p : rule)
      push(&e.tri_node[3 * t], &e.tri_vertex[3 * t], p.barycentric.data(), 3, p.weight * area, e.tri_face[t]);
  }
  const std::vector<GaussPoint> gauss = gauss_legendre_unit(quad_gauss_points(samples));
  for (std::size_t k = 0; k < e.quad_face.size(); ++k) {
    Vec3d c[4];
    quad_corners(e, positions, k, c);
    for (const GaussPoint& gu : gauss)
      for (const GaussPoint& gv : gauss) {
        const BilinearPoint b = bilinear_point(c, gu.t, gv.t);
        if (!(b.area_element > 0)) continue;
        push(&e.quad_node[4 * k], &e.quad_vertex[4 * k], b.phi, 4, gu.weight * gv.weight * b.area_element, e.quad_face[k]);
      }
  }
  return q;
}

std::vector<double> interpolate_vertex_data(const FitQuadrature& q, const std::vector<double>& data, std::size_t width) {
  std::vector<double> out(q.size() * width, 0.0);
  for (std::size_t s = 0; s < q.size(); ++s)
    for (int j = 0; j < 4; ++j) {
      const double phi = q.phi[4 * s + j];
      if (phi == 0) continue;
      const std::size_t v = q.vertex[4 * s + j];
      for (std::size_t k = 0; k < width; ++k) out[s * width + k] += phi * data[v * width + k];
    }
  return out;
}

std::vector<double> interpolate_node_values(const FitQuadrature& q, const std::vector<double>& values, std::size_t width) {
  std::vector<double> out(q.size() * width, 0.0);
  for (std::size_t s = 0; s < q.size(); ++s)
    for (int j = 0; j < 4; ++j) {
      const double phi = q.phi[4 * s + j];
      if (phi == 0) continue;
      const std::size_t n = q.node[4 * s + j];
      for (std::size_t k = 0; k < width; ++k) out[s * width + k] += phi * values[n * width + k];
    }
  return out;
}

LeastSquaresFit least_squares_fit(const FitElements& e, const std::vector<double>& positions, const FitQuadrature& q,
                                  const std::vector<double>& f, const std::vector<double>& point_values,
                                  std::size_t width, const LeastSquaresFitOptions& options) {
  const std::size_t N = e.nodes, S = q.size();
  if (f.size() != S * width || point_values.size() != N * width)
    throw Error("least_squares_fit: " + std::to_string(f.size()) + " signal values for " + std::to_string(S) +
                " points and " + std::to_string(point_values.size()) + " point values for " + std::to_string(N) +
                " nodes (width " + std::to_string(width) + ")");
  if (!(options.regularization >= 0) || !std::isfinite(options.regularization))
    throw Error("least_squares_fit: the regularization weight must be finite and >= 0");
  LeastSquaresFit fit;
  std::vector<Triplet> triplets;
  triplets.reserve(9 * e.tri_face.size() + 16 * e.quad_face.size() +
                   (options.regularization > 0 ? 16 * 3 * (e.tri_face.size() + 2 * e.quad_face.size()) / 2 : 0));
  std::vector<double> diagonal(N, 0.0), mass_diagonal(N, 0.0);  // of M + lambda R, of M
  const auto add = [&](std::uint32_t i, std::uint32_t j, double v) {
    triplets.emplace_back(int(i), int(j), v);
    if (i == j) diagonal[i] += v;
  };
  const auto add_mass = [&](std::uint32_t i, std::uint32_t j, double v) {
    add(i, j, v);
    if (i == j) mass_diagonal[i] += v;
  };

  // M, triangles: area/12 [[2,1,1],[1,2,1],[1,1,2]].
  const std::size_t T = e.tri_face.size();
  std::vector<RegTriangle> reg;
  reg.reserve(T + 2 * e.quad_face.size());
  for (std::size_t t = 0; t < T; ++t) {
    const std::uint32_t* n = &e.tri_node[3 * t];
    const double area = triangle_area(positions, &e.tri_vertex[3 * t]);
    if (!(area > 0)) continue;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add_mass(n[i], n[j], area / 12 * (i == j ? 2 : 1));
    if (options.regularization > 0)
      reg.push_back({{n[0], n[1], n[2]}, {e.tri_vertex[3 * t], e.tri_vertex[3 * t + 1], e.tri_vertex[3 * t + 2]}});
  }
  // M, quads: 3x3 Gauss-Legendre on the bilinear map.
  const std::vector<GaussPoint> gauss = gauss_legendre_unit(3);
  for (std::size_t k = 0; k < e.quad_face.size(); ++k) {
    const std::uint32_t* n = &e.quad_node[4 * k];
    const std::uint32_t* v = &e.quad_vertex[4 * k];
    Vec3d c[4];
    quad_corners(e, positions, k, c);
    double m[4][4] = {};
    for (const GaussPoint& gu : gauss)
      for (const GaussPoint& gv : gauss) {
        const BilinearPoint b = bilinear_point(c, gu.t, gv.t);
        const double w = gu.weight * gv.weight * b.area_element;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) m[i][j] += w * b.phi[i] * b.phi[j];
      }
    if (!(m[0][0] + m[1][1] + m[2][2] + m[3][3] > 0)) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) add_mass(n[i], n[j], m[i][j]);
    if (options.regularization > 0) {
      reg.push_back({{n[0], n[1], n[2]}, {v[0], v[1], v[2]}});
      reg.push_back({{n[0], n[2], n[3]}, {v[0], v[2], v[3]}});
    }
  }

  // R: the interior edges (exactly two triangles of positive area), found by sorting the sides.
  if (options.regularization > 0) {
    struct Side {
      std::uint64_t key;  // (min node, max node)
      std::uint32_t triangle;
      std::uint8_t opposite;  // local index of the wing
    };
    std::vector<Side> sides;
    sides.reserve(3 * reg.size());
    for (std::size_t t = 0; t < reg.size(); ++t) {
      if (!(triangle_area(positions, reg[t].vertex) > 0)) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = reg[t].node[(k + 1) % 3], b = reg[t].node[(k + 2) % 3];
        sides.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), std::uint32_t(t), std::uint8_t(k)});
      }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
      return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
    });
    for (std::size_t i = 0; i < sides.size();) {
      std::size_t j = i;
      while (j < sides.size() && sides[j].key == sides[i].key) ++j;
      if (j - i == 2) {
        const RegTriangle& t1 = reg[sides[i].triangle];
        const RegTriangle& t2 = reg[sides[i + 1].triangle];
        const int k1 = sides[i].opposite, k2 = sides[i + 1].opposite;
        const std::uint32_t a = t1.node[(k1 + 1) % 3], b = t1.node[(k1 + 2) % 3];
        const std::uint32_t va = t1.vertex[(k1 + 1) % 3], vb = t1.vertex[(k1 + 2) % 3];
        const std::uint32_t nodes[4] = {a, b, t1.node[k1], t2.node[k2]};
        double d[4], weight = 0;
        if (edge_kink(get3(positions, va), get3(positions, vb), get3(positions, t1.vertex[k1]),
                      get3(positions, t2.vertex[k2]), d, weight)) {
          const double s = options.regularization * weight;
          for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) add(nodes[r], nodes[c], s * d[r] * d[c]);
          ++fit.regularized_edges;
        } else {
          ++fit.skipped_edges;
        }
      }
      i = j;
    }
  }

  // The system over the nodes with mass; the others keep their point value.
  std::vector<int> index(N, -1);
  int n_active = 0;
  for (std::size_t i = 0; i < N; ++i) {
    if (diagonal[i] > 0) index[i] = n_active++;
    else ++fit.fallback_nodes;
  }
  fit.values = point_values;
  if (n_active > 0) {
    std::vector<Triplet> mapped;
    mapped.reserve(triplets.size());
    for (const Triplet& t : triplets) {
      const int r = index[std::size_t(t.row())], c = index[std::size_t(t.col())];
      if (r >= 0 && c >= 0) mapped.emplace_back(r, c, t.value());
    }
    triplets.clear();
    triplets.shrink_to_fit();
    SparseMatrix A(n_active, n_active);
    A.setFromTriplets(mapped.begin(), mapped.end());
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(options.tolerance);
    if (options.max_iterations > 0) cg.setMaxIterations(options.max_iterations);
    cg.compute(A);
    double min_mass = std::numeric_limits<double>::infinity();  // over the active nodes
    for (std::size_t i = 0; i < N; ++i)
      if (index[i] >= 0) min_mass = std::min(min_mass, mass_diagonal[i]);
    // b for every channel in one pass over the points (each entry summed in point order, as one
    // pass per channel would).
    std::vector<double> b_all(std::size_t(n_active) * width, 0.0);
    for (std::size_t s = 0; s < S; ++s)
      for (int j = 0; j < 4; ++j) {
        const int r = index[q.node[4 * s + j]];
        if (r < 0) continue;
        const double w = q.weight[s] * q.phi[4 * s + j];
        for (std::size_t k = 0; k < width; ++k) b_all[std::size_t(r) * width + k] += w * f[s * width + k];
      }
    for (std::size_t k = 0; k < width; ++k) {
      Eigen::VectorXd b(n_active), x0(n_active);
      for (int r = 0; r < n_active; ++r) b[r] = b_all[std::size_t(r) * width + k];
      for (std::size_t i = 0; i < N; ++i)
        if (index[i] >= 0) x0[index[i]] = point_values[i * width + k];
      // accuracy: |A c - b|_2 <= accuracy min M_ii / 4 bounds every value's error (header, Solver).
      const double b_norm = b.norm();
      double tolerance = options.tolerance;
      if (options.accuracy > 0 && b_norm > 0 && min_mass > 0 && std::isfinite(min_mass))
        tolerance = std::max(tolerance, options.accuracy * min_mass / 4 / b_norm);  // divisor checked
      cg.setTolerance(tolerance);
      const Eigen::VectorXd x = cg.solveWithGuess(b, x0);
      fit.iterations = std::max(fit.iterations, int(cg.iterations()));
      fit.residual = std::max(fit.residual, double(cg.error()));
      fit.converged = fit.converged && cg.info() == Eigen::Success;
      for (std::size_t i = 0; i < N; ++i)
        if (index[i] >= 0) fit.values[i * width + k] = x[index[i]];
    }
  }
  for (double& v : fit.values) {
    if (v < options.lower) {
      v = options.lower;
      ++fit.clamped;
    } else if (v > options.upper) {
      v = options.upper;
      ++fit.clamped;
    }
  }
  return fit;
}

double relative_l2_error(const FitQuadrature& q, const std::vector<double>& f, const std::vector<double>& node_values,
                         std::size_t width) {
  const std::vector<double> g = interpolate_node_values(q, node_values, width);
  double num = 0, den = 0;
  for (std::size_t s = 0; s < q.size(); ++s)
    for (std::size_t k = 0; k < width; ++k) {
      const double d = g[s * width + k] - f[s * width + k];
      num += q.weight[s] * d * d;
      den += q.weight[s] * f[s * width + k] * f[s * width + k];
    }
  if (!(den > 0)) return num > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return std::sqrt(num / den);  // divisor checked
}

}  // namespace shadetool
