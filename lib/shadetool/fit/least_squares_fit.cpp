// least_squares_fit.cpp: see least_squares_fit.h.
#include <shadetool/fit/least_squares_fit.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <cstddef>
#include <memory>
#include <new>
#include <string>
#include <type_traits>


#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/error.h>
#include <shadetool/fit/triangle_quadrature.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/polygon_triangles.h>

namespace shadetool {

namespace {

Vec3d vertex_position(const std::vector<double>& positions, std::uint32_t v) { return get3(positions, v); }

double triangle_area(const std::vector<double>& positions, const std::uint32_t* v) {
  return 0.5 * length(triangle_area_vector(positions.data(), v[0], v[1], v[2]).N);
}

using Lanes4 = double __attribute__((vector_size(32)));
using Mask4 = std::int64_t __attribute__((vector_size(32)));

// area[t] = triangle_area of triangles [0, T) (3 vertex ids each), four at a time in 4-wide lanes:
// the edges e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2 and their squared lengths; N = e_k x (-e_k+2)
// about the apex k (geometry/face_area_vector.h: k = 2 when e0 is longest, 0 for e1, else 1;
// -e_k+2 is its p_k+2 - p_k exactly, so N is its bits); its length as core/vec3.h's length
// computes it (the largest |component| m factored out: m sqrt(|N / m|^2), or m itself when m is
// 0, NaN or Inf; std::fmax's choice where a component is NaN); half of it. The same operations
// per lane as triangle_area: the same bits (tests/fit checks zero, huge, tiny and non-finite
// triangles), without the index reload, the std::fmax calls and the scalar divisions.
__attribute__((target_clones("avx2", "default")))
void triangle_areas(const std::vector<double>& positions, const std::uint32_t* tri_vertex, std::size_t T, double* area) {
  const Mask4 magnitude = {0x7fffffffffffffff, 0x7fffffffffffffff, 0x7fffffffffffffff, 0x7fffffffffffffff};
  const Lanes4 infinity = {HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL};
  const double* const P = positions.data();
  std::size_t t = 0;
  for (; t + 4 <= T; t += 4) {
    Lanes4 p[3][3] = {};  // [corner][coordinate], a triangle per lane
    for (int l = 0; l < 4; ++l)
      for (int c = 0; c < 3; ++c) {
        const double* v = P + 3 * std::size_t(tri_vertex[3 * (t + l) + c]);
        for (int d = 0; d < 3; ++d) p[c][d][l] = v[d];
      }
    Lanes4 e[3][3];  // [edge][coordinate]
    for (int d = 0; d < 3; ++d) {
      e[0][d] = p[1][d] - p[0][d];
      e[1][d] = p[2][d] - p[1][d];
      e[2][d] = p[0][d] - p[2][d];
    }
    const Lanes4 l0 = e[0][0] * e[0][0] + e[0][1] * e[0][1] + e[0][2] * e[0][2];
    const Lanes4 l1 = e[1][0] * e[1][0] + e[1][1] * e[1][1] + e[1][2] * e[1][2];
    const Lanes4 l2 = e[2][0] * e[2][0] + e[2][1] * e[2][1] + e[2][2] * e[2][2];
    const Mask4 apex2 = (l0 >= l1) & (l0 >= l2);            // apex_corner's ties, in its order
    const Mask4 apex0 = ~apex2 & (l1 > l0) & (l1 >= l2);
    Lanes4 a[3], b[3];  // apex 2: (e2, -e1); apex 0: (e0, -e2); apex 1: (e1, -e0)
    for (int d = 0; d < 3; ++d) {
      a[d] = apex2 ? e[2][d] : (apex0 ? e[0][d] : e[1][d]);
      b[d] = -(apex2 ? e[1][d] : (apex0 ? e[2][d] : e[0][d]));
    }
    const Lanes4 x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    const Lanes4 ax = (Lanes4)((Mask4)x & magnitude), ay = (Lanes4)((Mask4)y & magnitude),
                 az = (Lanes4)((Mask4)z & magnitude);
    const Lanes4 m_yz = ((az > ay) | (ay != ay)) ? az : ay;  // std::fmax(ay, az)
    const Lanes4 m = ((m_yz > ax) | (ax != ax)) ? m_yz : ax;  // std::fmax(ax, m_yz)
    const Mask4 scaled = (m > 0) & (m < infinity);          // else m: zero, NaN or Inf, nothing to scale
    const Lanes4 sx = x / m, sy = y / m, sz = z / m;        // divisor checked per lane (scaled)
    const Lanes4 squared = sx * sx + sy * sy + sz * sz;
    Lanes4 root;
    for (int l = 0; l < 4; ++l) root[l] = std::sqrt(squared[l]);
    const Lanes4 half = 0.5 * (scaled ? m * root : m);
    std::memcpy(area + t, &half, sizeof half);
  }
  for (; t < T; ++t) area[t] = triangle_area(positions, tri_vertex + 3 * t);
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

// Quad k's 4 x 4 block of M by 3x3 Gauss-Legendre (`gauss`) on its bilinear map; false when it has
// no mass (zero trace: every area element 0), and then it is no part of the system.
bool quad_mass(const FitElements& e, const std::vector<double>& positions, const std::vector<GaussPoint>& gauss,
               std::size_t k, double m[16]) {
  Vec3d c[4];
  quad_corners(e, positions, k, c);
  std::fill(m, m + 16, 0.0);
  for (const GaussPoint& gu : gauss)
    for (const GaussPoint& gv : gauss) {
      const BilinearPoint b = bilinear_point(c, gu.t, gv.t);
      const double w = gu.weight * gv.weight * b.area_element;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m[4 * i + j] += w * b.phi[i] * b.phi[j];
    }
  return m[0] + m[5] + m[10] + m[15] > 0;
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

// Whether a point with these corners and weights is the midpoint of an edge: exactly two weights
// of 1/2 (the rest 0) on two distinct vertices; its key (lo, hi) is the two vertices, lower first.
bool midpoint_edge(const std::uint32_t* vertex, const double* phi, int corners, std::uint32_t& lo, std::uint32_t& hi) {
  std::uint32_t ends[2];
  int halves = 0;
  for (int j = 0; j < corners; ++j) {
    if (phi[j] == 0) continue;
    if (phi[j] != 0.5 || halves == 2) return false;
    ends[halves++] = vertex[j];
  }
  if (halves != 2 || ends[0] == ends[1]) return false;
  lo = std::min(ends[0], ends[1]);
  hi = std::max(ends[0], ends[1]);
  return true;
}

// q.site and q.site_point (least_squares_fit.h, Sites). A midpoint's key is its edge's two
// vertices, bucketed by the lower vertex (counts and offsets: no map). In point order, a midpoint
// looks for its higher vertex among its bucket's entries so far: found, it joins that entry's site
// (the first point with its key, since the entries are made in point order); not found, it opens a
// new site and makes the entry. A triangle's rule point is a midpoint of the same local edge in
// every triangle, so the rule is asked once; quads' points one by one. When no point is a midpoint
// (the 1-, 6- and 12-point rules, quads' Gauss points) both stay empty: every point its own site.
// V: the vertex count.
void assign_sites(FitQuadrature& q, std::size_t V, FitScratch* spare) {
  const std::size_t S = q.size(), R = q.rule.size(), T = q.tri_area.size();
  q.site.clear();
  q.site_point.clear();
  q.midpoint_corners.clear();
  std::vector<std::array<int, 2>> rule_edge(R, {-1, -1});  // local corners of a midpoint's edge, or -1
  bool rule_midpoints = false;
  for (std::size_t k = 0; k < R; ++k) {
    std::uint32_t lo = 0, hi = 0;
    const std::uint32_t local[3] = {0, 1, 2};
    if (!midpoint_edge(local, q.rule[k].barycentric.data(), 3, lo, hi)) continue;
    rule_edge[k] = {int(lo), int(hi)};
    rule_midpoints = true;
  }
  if (!rule_midpoints && q.quad_weight.empty()) return;  // no point can be a midpoint: every point its own site
  constexpr std::uint64_t kNone = ~std::uint64_t(0);
  // fn(p, key) for every point p in order, key = (lo, hi) of a midpoint, all ones: none, from the
  // point's vertices.
  const std::uint32_t* const tri_vertex = q.triangle_vertices();
  const auto for_each_key = [&](auto&& fn) {
    const auto key_of = [](std::uint32_t a, std::uint32_t b) {
      return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    };
    for (std::size_t j = 0, p = 0; j < T; ++j)
      for (std::size_t k = 0; k < R; ++k, ++p) {
        if (rule_edge[k][0] < 0) {
          fn(p, kNone);
          continue;
        }
        const std::uint32_t a = tri_vertex[3 * j + rule_edge[k][0]], b = tri_vertex[3 * j + rule_edge[k][1]];
        fn(p, a != b ? key_of(a, b) : kNone);  // two distinct vertices: an edge's midpoint (midpoint_edge's rule)
      }
    for (std::size_t m = 0, p = q.triangle_points(); m < q.quad_weight.size(); ++m, ++p) {
      std::uint32_t lo = 0, hi = 0;
      fn(p, midpoint_edge(&q.quad_vertex[4 * m], &q.quad_phi[4 * m], 4, lo, hi) ? key_of(lo, hi) : kNone);
    }
  };
  // The keys are stored by the first pass for the second while they fit in a core's cache (4 MiB:
  // the 10k and 99k tori; reading them back is cheaper than recomputing them), and recomputed by
  // the second pass above that (8 bytes a point: at 1M triangles and 3 points 24 MB that would be
  // written to fresh pages and read back from memory). The same keys either way.
  const bool store_keys = S * sizeof(std::uint64_t) < (std::size_t(4) << 20);
  const std::unique_ptr<std::uint64_t[]> stored(store_keys ? new std::uint64_t[S] : nullptr);  // written before read
  std::vector<std::uint32_t> offset(V + 1, 0);  // counts per lower vertex, then offsets
  std::size_t midpoints = 0;
  for_each_key([&](std::size_t p, std::uint64_t key) {
    if (store_keys) stored[p] = key;
    if (key == kNone) return;
    ++offset[(key >> 32) + 1];
    ++midpoints;
  });
  if (midpoints == 0) return;  // every point its own site
  const bool edges_only = midpoints == S;  // every site an edge's midpoint: midpoint_corners (after the pass)
  for (std::size_t v = 0; v < V; ++v) offset[v + 1] += offset[v];
  std::vector<std::uint32_t> end(offset.begin(), offset.end() - 1);
  // not zero-filled: an entry is written before it is read (below end[lo]); at 1M triangles the
  // fill was two passes over 12 MB each. One block of bytes, the two arrays placed in it, handed
  // to `spare` after (FitScratch).
  const std::size_t entries = offset[V];
  // handed over (below) from 4 MiB: then at least the bytes the caller wants (FitScratch::wanted)
  const std::size_t entry_bytes = 2 * entries * sizeof(std::uint32_t);
  const bool hand_over = spare && entry_bytes >= (std::size_t(4) << 20);
  const std::size_t block_bytes = hand_over ? std::max(entry_bytes, spare->wanted) : entry_bytes;
  std::unique_ptr<std::byte[]> block(new std::byte[block_bytes]);
  advise_huge_pages(block.get(), block_bytes);
  // entry k: its higher vertex at 2k, its site at 2k + 1 (one cache line for both: a point that
  // finds its edge reads the site beside the vertex it compared)
  std::uint32_t* const entry = ::new (static_cast<void*>(block.get())) std::uint32_t[2 * entries];
  reserve_bulk(q.site, S);
  q.site.resize(S);
  // site_point: of its S possible entries only `sites` are written (half of them on a closed mesh
  // under the 3-point rule). Above 4 MiB it is reserved and appended to, so that the unwritten half
  // is never faulted in (6 MB at 1M triangles); below, sized and indexed (the appends cost 13% of
  // the 10k torus's quadrature: bench/fit/results.md, fit11). The same entries either way.
  const bool append_sites = S * sizeof(std::uint32_t) >= (std::size_t(4) << 20);
  if (append_sites)
    reserve_bulk(q.site_point, S);
  else
    q.site_point.resize(S);
  std::size_t sites = 0;
  const auto place = [&](std::size_t p, std::uint64_t key) {
    if (key != kNone) {
      const std::size_t lo = key >> 32;
      const std::uint32_t hi = std::uint32_t(key);
      std::uint32_t k = offset[lo];
      while (k < end[lo] && entry[2 * std::size_t(k)] != hi) ++k;
      if (k < end[lo]) {  // an earlier point of this edge: its site
        q.site[p] = entry[2 * std::size_t(k) + 1];
        return;
      }
      entry[2 * std::size_t(k)] = hi;  // the first point of this edge
      entry[2 * std::size_t(k) + 1] = std::uint32_t(sites);
      ++end[lo];
    }
    q.site[p] = std::uint32_t(sites);
    if (append_sites)
      q.site_point.push_back(std::uint32_t(p));
    else
      q.site_point[sites] = std::uint32_t(p);
    ++sites;
  };
  if (store_keys)
    for (std::size_t p = 0; p < S; ++p) place(p, stored[p]);
  else
    for_each_key(place);
  q.site_point.resize(sites);
  if (edges_only && q.quad_weight.empty()) {  // every point a triangle's midpoint: so every rule point
    q.midpoint_corners.resize(R);
    for (std::size_t k = 0; k < R; ++k)
      q.midpoint_corners[k] = {std::uint8_t(rule_edge[k][0]), std::uint8_t(rule_edge[k][1])};
  }
  // The entries are read no more: handed over when they are worth keeping (4 MiB and more: 1M
  // triangles hold 24 MB; kept alive below that, a block only moves the allocator's later
  // choices, which measured slower on the 10k torus), else freed here as before.
  if (hand_over) {
    spare->bytes = std::move(block);
    spare->size = block_bytes;
  }
}

// M + lambda R as element data (least_squares_fit.h), applied to a block of channels without
// assembling a sparse matrix: each CG step is one pass over the elements, and building the
// matrix (Eigen's setFromTriplets) cost more than the whole solve (bench/fit/results.md).
struct FitOperator {
  const std::uint32_t* tri_node = nullptr;  // 3 per triangle of positive area (the quadrature's)
  const double* tri_area = nullptr;         // 1 per triangle of positive area
  std::size_t triangles = 0;
  std::vector<std::uint32_t> quad_node;  // 4 per quad with mass
  std::vector<double> quad_mass;         // 16 per quad: its 4 x 4 block of M
  std::vector<std::uint32_t> edge_node;  // 4 per regularised edge: a, b, wing 1, wing 2
  std::vector<double> edge_d;            // 4 per edge: d sqrt(lambda (A1 + A2)^2), R_e = (d . c)^2
  std::vector<double> diagonal;          // #nodes: of M + lambda R
  std::vector<double> lumped;            // #nodes: row sums of M (= of M + lambda R: R 1 = 0), the lumped
                                         // mass; empty without quads and R: then 2 diagonal_i (lumped_mass)
  double lumped_mass(std::size_t i) const { return lumped.empty() ? 2 * diagonal[i] : lumped[i]; }
};

// 1/12 rounded: M_t's scale area/12 as one multiplication per triangle in each operator pass (a
// division per triangle held the pass back; the scale then differs from area/12 by at most an
// ulp, M's entries by a relative 2^-52: far inside the solve's tolerance).
constexpr double kTwelfth = 1.0 / 12;

// y = A x for x, y #nodes by W (W = 1 or 4 lanes), and x^T A x per lane summed over the elements
// (CG's p^T A p without a pass over the nodes). Sequential in element order: the same bits for any
// thread count.
// y += M_t x for triangle t: area/12 [[2,1,1],[1,2,1],[1,1,2]] = area/12 (I + 1 1^T), and
// x^T M_t x = area/12 sum_i x_i (x_i + x_0 + x_1 + x_2) into xAx (one of four accumulators: the
// position of t in its round of apply_operator's four quarters).
template <std::size_t W>
inline void add_triangle_product(const FitOperator& A, std::size_t t, const double* x, double* y, double* xAx) {
  const double s = A.tri_area[t] * kTwelfth;  // area/12 to within an ulp: a multiplication, not a division
  if (s == 0) return;
  const std::size_t n0 = A.tri_node[3 * t] * W, n1 = A.tri_node[3 * t + 1] * W, n2 = A.tri_node[3 * t + 2] * W;
  for (std::size_t k = 0; k < W; ++k) {
    const double x0 = x[n0 + k], x1 = x[n1 + k], x2 = x[n2 + k], sum = x0 + x1 + x2;
    const double t0 = x0 + sum, t1 = x1 + sum, t2 = x2 + sum;
    y[n0 + k] += s * t0;
    y[n1 + k] += s * t1;
    y[n2 + k] += s * t2;
    xAx[k] += s * (x0 * t0 + x1 * t1 + x2 * t2);
  }
}

// Storage of CG's vectors (least_squares_fit.h, Precision): T = double, or float on the 8-bit path.
// Every value is loaded into double and every operation and sum is done in double; only the store
// rounds (to T). Loads and stores by memcpy: a float vector may live in the memory of a spent
// std::vector<double> (the rvalue overload), so no float lvalue reads a double object.
using Floats4 = float __attribute__((vector_size(16)));
template <class T>
inline __attribute__((always_inline)) void load4(Lanes4& v, const T* p) {
  if constexpr (std::is_same_v<T, double>) {
    std::memcpy(&v, p, sizeof v);
  } else {
    static_assert(std::is_same_v<T, float>);
    float s[4];
    std::memcpy(s, p, sizeof s);
    v = Lanes4{s[0], s[1], s[2], s[3]};  // exact: every float is a double (element-wise: GCC 12 makes
                                         // one vcvtps2pd of it, and four of __builtin_convertvector)
  }
}
// Stores v (rounded to nearest in T) and leaves in v the value stored, so that later sums use what
// the next pass will read. For T = double: a plain store, v unchanged (the double path's bits).
template <class T>
inline __attribute__((always_inline)) void store4(T* p, Lanes4& v) {
  if constexpr (std::is_same_v<T, double>) {
    std::memcpy(p, &v, sizeof v);
  } else {
    const Floats4 s = __builtin_convertvector(v, Floats4);  // rounded to nearest
    std::memcpy(p, &s, sizeof s);
    v = Lanes4{s[0], s[1], s[2], s[3]};
  }
}
template <class T>
inline double load1(const T* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return double(v);
}
template <class T>
inline void store1(T* p, double v) {
  const T s = T(v);
  std::memcpy(p, &s, sizeof s);
}

// The same for every triangle, 4 lanes per node (3 channels and a zero pad, least_squares_fit's
// layout for 3 channels): one 4-wide operation per node where add_triangle_product<1> does one
// scalar one per lane. Built for AVX2 and for the baseline (target_clones; no FMA): per lane the
// operations of add_triangle_product, in the same order, so the same bits on either and the bits
// of one channel solved alone (XT = double). The triangles are taken from four quarters of the
// list in turn (apply_operator); xAx_out: 4 lanes, the four quarters' accumulators summed
// (0 + 1) + (2 + 3). XT: the storage of x (float on the 8-bit path); y is double (CG's Ap: a
// float y would round at each node update, in the chain of updates, measured slower).
// Subtract: y -= M_t x instead (the true residual b - A x, made in place in b; -(s t) is the bits
// of s t negated, so b - A x has the rounding of the y = A x pass).
template <class XT, bool Subtract>
__attribute__((target_clones("avx2", "default")))
void add_triangle_products_4(const FitOperator& A, const XT* x, double* y, double* xAx_out) {
  const std::size_t T = A.triangles, Q = (T + 3) / 4;
  Lanes4 acc0 = {0, 0, 0, 0}, acc1 = acc0, acc2 = acc0, acc3 = acc0;
  const auto one = [&](std::size_t t, Lanes4& acc) __attribute__((always_inline)) {
    const double scale = A.tri_area[t] * kTwelfth;  // area/12 to within an ulp: a multiplication, not a division
    if (scale == 0) return;
    const double s = Subtract ? -scale : scale;
    const std::size_t n0 = std::size_t(A.tri_node[3 * t]) * 4, n1 = std::size_t(A.tri_node[3 * t + 1]) * 4,
                      n2 = std::size_t(A.tri_node[3 * t + 2]) * 4;
    Lanes4 x0, x1, x2, y0, y1, y2;
    load4(x0, x + n0);
    load4(x1, x + n1);
    load4(x2, x + n2);
    const Lanes4 sum = x0 + x1 + x2;
    const Lanes4 t0 = x0 + sum, t1 = x1 + sum, t2 = x2 + sum;
    load4(y0, y + n0);  // load, add, store one node at a time: nodes may repeat
    y0 += s * t0;
    store4(y + n0, y0);
    load4(y1, y + n1);
    y1 += s * t1;
    store4(y + n1, y1);
    load4(y2, y + n2);
    y2 += s * t2;
    store4(y + n2, y2);
    acc += s * (x0 * t0 + x1 * t1 + x2 * t2);
  };
  for (std::size_t i = 0; i < Q; ++i) {  // t = i, i + Q, i + 2Q, i + 3Q (the last round may hold fewer)
    one(i, acc0);
    if (i + Q < T) one(i + Q, acc1);
    if (i + 2 * Q < T) one(i + 2 * Q, acc2);
    if (i + 3 * Q < T) one(i + 3 * Q, acc3);
  }
  const Lanes4 total = (acc0 + acc1) + (acc2 + acc3);
  std::memcpy(xAx_out, &total, sizeof total);
}

// y = A x (Subtract: y -= A x) and xAx = x^T A x per lane (triangles' four accumulators, then the
// quads', then the edges': the same order for W = 1 and 4). y_zeroed: y is 0 already (CG's
// direction pass clears it). XT: as add_triangle_products_4 (float only with W = 4).
template <std::size_t W, class XT = double, bool Subtract = false>
void apply_operator(const FitOperator& A, const XT* x, double* y, double* xAx, bool y_zeroed) {
  constexpr std::size_t w = W;
  static_assert(W == 4 || (std::is_same_v<XT, double> && !Subtract));
  if (!y_zeroed) std::fill(y, y + A.diagonal.size() * w, 0.0);
  // The triangles taken from four quarters of the list in turn: neighbouring triangles of a mesh
  // share nodes, so in list order each update of y waits for the store of the one before; four
  // far-apart chains overlap (bench/fit/results.md). A fixed order: the same bits on every run.
  const std::size_t T = A.triangles, Q = (T + 3) / 4;
  if constexpr (W == 4) {
    add_triangle_products_4<XT, Subtract>(A, x, y, xAx);
  } else {
    double acc[4][W] = {};
    for (std::size_t i = 0; i < Q; ++i)
      for (std::size_t t = i, a = 0; t < T; t += Q, ++a) add_triangle_product<W>(A, t, x, y, acc[a]);
    for (std::size_t c = 0; c < w; ++c) xAx[c] = (acc[0][c] + acc[1][c]) + (acc[2][c] + acc[3][c]);
  }
  const auto X = [&](std::size_t i) { return load1(x + i); };
  const auto add_y = [&](std::size_t i, double v) {
    if constexpr (Subtract)
      y[i] -= v;
    else
      y[i] += v;
  };
  for (std::size_t k = 0; k < A.quad_mass.size() / 16; ++k) {
    const std::uint32_t* n = &A.quad_node[4 * k];
    const double* m = &A.quad_mass[16 * k];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (std::size_t c = 0; c < w; ++c) add_y(n[i] * w + c, m[4 * i + j] * X(n[j] * w + c));
    for (std::size_t c = 0; c < w; ++c) {  // x^T m x, row by row
      double quad = 0;
      for (int i = 0; i < 4; ++i) {
        double row = 0;
        for (int j = 0; j < 4; ++j) row += m[4 * i + j] * X(n[j] * w + c);
        quad += X(n[i] * w + c) * row;
      }
      xAx[c] += quad;
    }
  }
  for (std::size_t k = 0; k < A.edge_d.size() / 4; ++k) {
    const std::uint32_t* n = &A.edge_node[4 * k];
    const double* d = &A.edge_d[4 * k];
    for (std::size_t c = 0; c < w; ++c) {
      const double dx = d[0] * X(n[0] * w + c) + d[1] * X(n[1] * w + c) + d[2] * X(n[2] * w + c) + d[3] * X(n[3] * w + c);
      for (int i = 0; i < 4; ++i) add_y(n[i] * w + c, d[i] * dx);
      xAx[c] += dx * dx;  // x^T R_e x = (d . x)^2
    }
  }
}

// The elements' M (and lambda R) as FitOperator, M's diagonal (only with lambda > 0: otherwise it
// is A.diagonal), R's edge counts in `fit`. The
// triangles are the quadrature's (those of positive area, in element order).
void build_fit_operator(const FitElements& e, const std::vector<double>& positions, const FitQuadrature& q,
                        double lambda, FitOperator& A, std::vector<double>& mass_diagonal, LeastSquaresFit& fit) {
  const std::size_t N = e.nodes, T = q.tri_area.size();
  reserve_bulk(A.diagonal, N);
  A.diagonal.assign(N, 0.0);
  A.tri_node = q.triangle_nodes();
  A.tri_area = q.tri_area.data();
  A.triangles = T;
  std::vector<RegTriangle> reg;
  if (lambda > 0) reg.reserve(T + 2 * e.quad_face.size());
  // M, triangles: area/12 [[2,1,1],[1,2,1],[1,1,2]].
  for (std::size_t t = 0; t < T; ++t) {
    const std::uint32_t* n = &q.triangle_nodes()[3 * t];
    const double area = q.tri_area[t];
    if (!(area > 0)) continue;
    for (int i = 0; i < 3; ++i) A.diagonal[n[i]] += area / 6;
    const std::uint32_t* v = &q.triangle_vertices()[3 * t];
    if (lambda > 0) reg.push_back({{n[0], n[1], n[2]}, {v[0], v[1], v[2]}});
  }
  // The triangles' row sums of area/12 [[2,1,1],...] are area/3 = 2 (area/6) per corner: twice
  // their diagonal (doubling is exact, so twice the sum is the sum of the doubles).
  // Stored only when there are quads or R (R adds to the diagonal below, not to the row sums); else
  // lumped_mass gives 2 diagonal_i: one array of #nodes and one pass fewer.
  if (!e.quad_face.empty() || lambda > 0) {
    A.lumped.resize(N);
    for (std::size_t i = 0; i < N; ++i) A.lumped[i] = 2 * A.diagonal[i];
  }
  // M, quads: 3x3 Gauss-Legendre on the bilinear map.
  const std::vector<GaussPoint> gauss = gauss_legendre_unit(3);
  for (std::size_t k = 0; k < e.quad_face.size(); ++k) {
    const std::uint32_t* n = &e.quad_node[4 * k];
    const std::uint32_t* v = &e.quad_vertex[4 * k];
    double m[16];
    if (!quad_mass(e, positions, gauss, k, m)) continue;
    A.quad_node.insert(A.quad_node.end(), n, n + 4);
    A.quad_mass.insert(A.quad_mass.end(), m, m + 16);
    for (int i = 0; i < 4; ++i) {
      A.diagonal[n[i]] += m[5 * i];
      A.lumped[n[i]] += m[4 * i] + m[4 * i + 1] + m[4 * i + 2] + m[4 * i + 3];
    }
    if (lambda > 0) {
      reg.push_back({{n[0], n[1], n[2]}, {v[0], v[1], v[2]}});
      reg.push_back({{n[0], n[2], n[3]}, {v[0], v[2], v[3]}});
    }
  }
  if (!(lambda > 0)) return;  // M's diagonal is A's
  mass_diagonal = A.diagonal;

  // R: the interior edges (exactly two triangles of positive area), found by sorting the sides.
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
        const double root = std::sqrt(lambda * weight);
        for (int r = 0; r < 4; ++r) {
          A.edge_node.push_back(nodes[r]);
          A.edge_d.push_back(root * d[r]);
        }
        for (int r = 0; r < 4; ++r) A.diagonal[nodes[r]] += lambda * weight * d[r] * d[r];
        ++fit.regularized_edges;
      } else {
        ++fit.skipped_edges;
      }
    }
    i = j;
  }
}

// The larger of a and b, b when b is NaN (a NaN residual fails the stop's test).
inline double max_keeping_nan(double a, double b) { return a >= b ? a : b; }
// acc = max(acc, |v| scale) per lane (a NaN in |v| scale is kept, so that a NaN residual fails the
// stop's test). By reference: a 32-byte vector is not passed by value (ABI).
inline __attribute__((always_inline)) void lanes4_max_abs(Lanes4& acc, const Lanes4& v, double scale) {
  const Lanes4 a = (v < 0 ? -v : v) * scale;
  acc = acc >= a ? acc : a;
}

// The rounding of one float store of x, per lane: d = exact - stored (exact in double: a double and
// its rounding to float differ by a double, Sterbenz), summed as d^2 into mass and as |d| into max
// (the drift bound of the float path, least_squares_fit.h, Precision; Drift).
struct Drift4 {
  Lanes4 mass = {0, 0, 0, 0}, max = {0, 0, 0, 0};
  void out(double* to) const {  // mass[4], then max[4]
    std::memcpy(to, &mass, sizeof mass);
    std::memcpy(to + 4, &max, sizeof max);
  }
};
inline __attribute__((always_inline)) void add_drift(Drift4& drift, const Lanes4& exact, const Lanes4& stored) {
  const Lanes4 d = exact - stored;
  drift.mass += d * d;
  lanes4_max_abs(drift.max, d, 1.0);
}

// CG's per-iteration vector passes over 4 lanes per node (block_conjugate_gradient<4>), one 4-wide
// operation per node where the scalar loops do four: per lane the same operations in the same
// node order (each lane's sums run over the nodes in turn), so the same bits. AVX2 and baseline
// builds (target_clones; no FMA). T: the vectors' storage (load4/store4: double, or float on the
// 8-bit path; arithmetic and sums in double either way, each sum over the stored values).
// r -= alpha Ap; res2 += r^2; res_mass += r^2 inv_m_i (inv_m non-null); abs_new += r^2 inv_d_i;
// res_max = max |r_i| inv_d_i (res_max_out non-null: the sharp stop's term, fit_error_bound), per
// lane; Ap cleared for the next operator pass (its lines are in cache here: the direction pass
// need not stream Ap). x += alpha p is left to the direction pass (lanes4_direction), which reads
// p anyway, or to lanes4_add_step after the last step.
template <class T>
__attribute__((target_clones("avx2", "default")))
void lanes4_step(const double* inv_d, const double* inv_m, std::size_t N, const double alpha_in[4], double* Ap,
                 T* r, double res2_out[4], double res_mass_out[4], double abs_new_out[4], double* res_max_out) {
  Lanes4 alpha, res2 = {0, 0, 0, 0}, res_mass = {0, 0, 0, 0}, abs_new = {0, 0, 0, 0}, res_max = {0, 0, 0, 0}, Api, ri;
  std::memcpy(&alpha, alpha_in, sizeof alpha);
  for (std::size_t i = 0; i < N; ++i) {
    Lanes4 zero = {0, 0, 0, 0};
    load4(Api, Ap + 4 * i);
    load4(ri, r + 4 * i);
    ri = ri - alpha * Api;
    store4(r + 4 * i, ri);
    store4(Ap + 4 * i, zero);
    res2 += ri * ri;
    if (inv_m) res_mass += ri * ri * inv_m[i];
    abs_new += ri * ri * inv_d[i];
    if (res_max_out) lanes4_max_abs(res_max, ri, inv_d[i]);
  }
  std::memcpy(res2_out, &res2, sizeof res2);
  std::memcpy(res_mass_out, &res_mass, sizeof res_mass);
  std::memcpy(abs_new_out, &abs_new, sizeof abs_new);
  if (res_max_out) std::memcpy(res_max_out, &res_max, sizeof res_max);
}
// x += alpha p (the last step's, when no direction pass follows it).
template <class T>
__attribute__((target_clones("avx2", "default")))
void lanes4_add_step(const T* p, std::size_t N, const double alpha_in[4], T* x, double* drift_out) {
  Lanes4 alpha, pi, xi;
  Drift4 drift;
  std::memcpy(&alpha, alpha_in, sizeof alpha);
  for (std::size_t i = 0; i < N; ++i) {
    load4(pi, p + 4 * i);
    load4(xi, x + 4 * i);
    xi += alpha * pi;
    const Lanes4 exact = xi;
    store4(x + 4 * i, xi);
    if (drift_out) add_drift(drift, exact, xi);  // sum dx^2, max |dx|
  }
  if (drift_out) drift.out(drift_out);
}
// The first residual r = b - Ap (b double: for T = double r may be b itself, b in and r out), with
// sum b^2, sum r^2 and (inv_m non-null) sum r^2 inv_m_i and max |r_i| inv_m_i, per lane.
template <class T>
__attribute__((target_clones("avx2", "default")))
void lanes4_residual(const double* Ap, const double* inv_m, std::size_t N, const double* b, T* r, double rhs2_out[4],
                     double res2_out[4], double res_mass_out[4], double res_max_out[4]) {
  Lanes4 rhs2 = {0, 0, 0, 0}, res2 = {0, 0, 0, 0}, res_mass = {0, 0, 0, 0}, res_max = {0, 0, 0, 0}, bi, Api;
  for (std::size_t i = 0; i < N; ++i) {
    std::memcpy(&bi, b + 4 * i, sizeof bi);
    load4(Api, Ap + 4 * i);
    Lanes4 ri = bi - Api;
    store4(r + 4 * i, ri);
    rhs2 += bi * bi;
    res2 += ri * ri;
    if (inv_m) {
      res_mass += ri * ri * inv_m[i];
      lanes4_max_abs(res_max, ri, inv_m[i]);
    }
  }
  std::memcpy(rhs2_out, &rhs2, sizeof rhs2);
  std::memcpy(res2_out, &res2, sizeof res2);
  std::memcpy(res_mass_out, &res_mass, sizeof res_mass);
  std::memcpy(res_max_out, &res_max, sizeof res_max);
}
// The first direction p = inv_d_i r, with sum r p, per lane.
template <class T>
__attribute__((target_clones("avx2", "default")))
void lanes4_first_direction(const T* r, const double* inv_d, std::size_t N, T* p, double abs_out[4]) {
  Lanes4 abs = {0, 0, 0, 0}, ri;
  for (std::size_t i = 0; i < N; ++i) {
    load4(ri, r + 4 * i);
    Lanes4 pi = ri * inv_d[i];
    store4(p + 4 * i, pi);
    abs += ri * pi;
  }
  std::memcpy(abs_out, &abs, sizeof abs);
}
// x += alpha p (the last step's, deferred: lanes4_step), then p = inv_d_i r + beta p, per lane.
template <class T>
__attribute__((target_clones("avx2", "default")))
void lanes4_direction(const T* r, const double* inv_d, std::size_t N, const double alpha_in[4],
                      const double beta_in[4], T* x, T* p, double* drift_out) {
  Lanes4 alpha, beta, ri, pi, xi;
  Drift4 drift;
  std::memcpy(&alpha, alpha_in, sizeof alpha);
  std::memcpy(&beta, beta_in, sizeof beta);
  for (std::size_t i = 0; i < N; ++i) {
    load4(ri, r + 4 * i);
    load4(pi, p + 4 * i);
    load4(xi, x + 4 * i);
    xi += alpha * pi;
    pi = ri * inv_d[i] + beta * pi;
    const Lanes4 exact = xi;
    store4(x + 4 * i, xi);
    store4(p + 4 * i, pi);
    if (drift_out) add_drift(drift, exact, xi);  // sum dx^2, max |dx|
  }
  if (drift_out) drift.out(drift_out);
}
// sum t^2 and (inv_m non-null) sum t^2 inv_m_i and max |t_i| inv_m_i per lane, t double (the true
// residual's check).
__attribute__((target_clones("avx2", "default")))
void lanes4_norms(const double* t, const double* inv_m, std::size_t N, double res2_out[4], double res_mass_out[4],
                  double res_max_out[4]) {
  Lanes4 res2 = {0, 0, 0, 0}, res_mass = {0, 0, 0, 0}, res_max = {0, 0, 0, 0}, ti;
  for (std::size_t i = 0; i < N; ++i) {
    std::memcpy(&ti, t + 4 * i, sizeof ti);
    res2 += ti * ti;
    if (inv_m) {
      res_mass += ti * ti * inv_m[i];
      lanes4_max_abs(res_max, ti, inv_m[i]);
    }
  }
  std::memcpy(res2_out, &res2, sizeof res2);
  std::memcpy(res_mass_out, &res_mass, sizeof res_mass);
  std::memcpy(res_max_out, &res_max, sizeof res_max);
}

// b_i += sum over the triangles' points of w_k phi_i(x_k) f(x_k) (least_squares_fit.h, b), one
// update per corner of each triangle: with w_k = rule_k.weight area and phi_i(x_k) = the rule's
// barycentric coordinate, corner c of triangle j adds area_j (sum_k g_kc f_k), g_kc =
// rule_k.weight barycentric_kc, over the points k with g_kc != 0 (a point where phi is 0 is not
// read: the old per-point loop's w == 0 skip), in k order. TriangleLoads holds those g_kc.
struct TriangleLoads {
  int count[3] = {};
  int point[3][12] = {};  // the rules have at most 12 points (triangle_quadrature.h)
  double g[3][12] = {};
};
TriangleLoads triangle_loads(const std::vector<QuadraturePoint>& rule) {
  TriangleLoads out;
  for (int c = 0; c < 3; ++c)
    for (std::size_t k = 0; k < rule.size() && k < 12; ++k) {
      const double g = rule[k].weight * rule[k].barycentric[c];
      if (g == 0) continue;
      out.point[c][out.count[c]] = int(k);
      out.g[c][out.count[c]++] = g;
    }
  return out;
}

// The triangle loads of `width` channels into b with L lanes per node (L >= width), scalar.
// inverse_diagonal: 0 off the system (those rows stay 0); null when every node is in the system.
void add_triangle_loads(const FitQuadrature& q, const TriangleLoads& g, const double* f, std::size_t width,
                        std::size_t L, bool per_site, const double* inverse_diagonal, double* b) {
  const std::size_t R = q.rule.size(), T = q.tri_area.size();
  const std::uint32_t* const nodes = q.triangle_nodes();
  for (std::size_t j = 0; j < T; ++j) {
    const double area = q.tri_area[j];
    for (int c = 0; c < 3; ++c) {
      const std::size_t r = nodes[3 * j + c];
      if (inverse_diagonal && inverse_diagonal[r] == 0) continue;
      for (std::size_t k = 0; k < width; ++k) {
        double sum = 0;
        for (int m = 0; m < g.count[c]; ++m) {
          const std::size_t p = j * R + std::size_t(g.point[c][m]);
          sum += g.g[c][m] * f[(per_site ? q.site_of(p) : p) * width + k];
        }
        b[r * L + k] += area * sum;
      }
    }
  }
}

// The same for 3 channels in 4 lanes of b per node (the fourth stays 0): the points' three values
// loaded once per triangle, one 4-wide update per corner; per lane the operations of
// add_triangle_loads in its order, so the bits of one channel alone (AVX2 and baseline builds,
// target_clones; no FMA). R: the rule's size when known at compile time (1, 3), else 0.
template <std::size_t R>
inline __attribute__((always_inline)) void triangle_loads_4_body(const FitQuadrature& q, const TriangleLoads& g,
                                                                 const double* f, bool per_site,
                                                                 const double* inverse_diagonal, double* b) {
  const std::size_t rule = R ? R : q.rule.size(), T = q.tri_area.size();
  const std::uint32_t* const nodes = q.triangle_nodes();
  double dense[3][R ? R : 12] = {};  // g_kc by point (0 where phi is 0): a fixed-size loop for R > 0
  for (int c = 0; c < 3; ++c)
    for (int m = 0; m < g.count[c]; ++m) dense[c][g.point[c][m]] = g.g[c][m];
  for (std::size_t j = 0; j < T; ++j) {
    Lanes4 sum[3] = {};
    for (std::size_t k = 0; k < rule; ++k) {  // in k order: add_triangle_loads' sums
      const std::size_t p = j * rule + k;
      const double* fs = f + 3 * (per_site ? q.site_of(p) : p);
      const Lanes4 fv = {fs[0], fs[1], fs[2], 0};
      for (int c = 0; c < 3; ++c)
        if (dense[c][k] != 0) sum[c] += dense[c][k] * fv;
    }
    const double area = q.tri_area[j];
    for (int c = 0; c < 3; ++c) {
      const std::size_t r = nodes[3 * j + c];
      if (inverse_diagonal && inverse_diagonal[r] == 0) continue;
      Lanes4 br;
      std::memcpy(&br, b + 4 * r, sizeof br);
      br += area * sum[c];
      std::memcpy(b + 4 * r, &br, sizeof br);
    }
  }
}
__attribute__((target_clones("avx2", "default")))
void add_triangle_loads_4(const FitQuadrature& q, const TriangleLoads& g, const double* f, bool per_site,
                          const double* inverse_diagonal, double* b) {
  switch (q.rule.size()) {
    case 1: return triangle_loads_4_body<1>(q, g, f, per_site, inverse_diagonal, b);
    case 3: return triangle_loads_4_body<3>(q, g, f, per_site, inverse_diagonal, b);
    default: return triangle_loads_4_body<0>(q, g, f, per_site, inverse_diagonal, b);  // a size_t, not an enum
  }
}

struct BlockCgOptions {
  double tolerance = 1e-10;   // relative residual per channel
  // > 0: also stop a channel once sum_i r_i^2 / inverse_mass_i <= accuracy_trigger accuracy_bound
  // (least_squares_fit.h, Solver: at the full bound every value is within the accuracy of the exact
  // solution; float storage stops the recursion at a quarter of it and checks the true residual)
  double accuracy_bound = 0;
  double accuracy_trigger = 1;
  // > 0 (with accuracy_bound): the sharp stop (least_squares_fit.h, Solver; lambda = 0, triangles
  // only, inverse_mass the Jacobi diagonal): a channel stops once fit_error_bound(max_i |r_i| / M_ii,
  // sum_i r_i^2 / M_ii, min M_ii) <= sqrt(accuracy_trigger) accuracy (the same margin as the sum's
  // trigger, in the norm). 0: the 2-norm stop, sum_i r_i^2 / M_ii <= accuracy_trigger accuracy_bound.
  double sharp_accuracy = 0;
  double min_mass = 0;  // min M_ii over the system (> 0 with sharp_accuracy)
  const std::vector<double>* inverse_mass = nullptr;  // #nodes: 1 / M_ii (0 off the system)
  int max_iterations = 0;
  std::array<double, 4>* rhs2_out = nullptr;  // non-null (W = 4): sum b^2 per lane
  // Non-null (W = 4, float storage, the sharp stop): the drift of the recursive residual r from the
  // true one t = b - A x bounded as it accrues (least_squares_fit.h, Precision).
  struct Drift* drift = nullptr;
};

// The float path's drift bound, per lane: every float store of r (its rounding dr = exact - stored)
// and of x (dx) moves t - r by dr or A dx, so at the end
//   |D^-1/2 (t - r)|_2 <= sum over the stores (|D^-1/2 dr|_2 or 2 |D^1/2 dx|_2)
//   max_i |t_i - r_i| / M_ii <= sum over the stores (max_i |dr_i| / M_ii or 2 max_i |dx_i|)
// (lambda = 0, triangles: |D^-1/2 A D^-1/2|_2 <= 2, Wathen, and the rows of A are positive and sum
// to 2 M_ii). r's roundings from the stored r's own sums, which the stop computes anyway: rounding
// to nearest float, |dr_i| <= u |r_i| + 2^-150 (u = 2^-24; the absolute term for a subnormal r), so
// |D^-1/2 dr|_2 <= u sqrt(sum r_i^2 / M_ii) + 2^-150 sqrt(#nodes max 1 / M_ii) and max_i |dr_i| / M_ii
// <= u max_i |r_i| / M_ii + 2^-150 max 1 / M_ii. x's measured in the passes that store x (sum dx^2,
// max |dx|), |D^1/2 dx|_2 <= sqrt(max M_ii) |dx|_2. res_mass, res_max: the last recursive r's sums
// (out).
struct Drift {
  double max_mass = 0, max_inverse_mass = 0;  // max M_ii and max 1 / M_ii over the system (in)
  std::size_t nodes = 0;                      // (in)
  std::array<double, 4> norm{}, max{}, res_mass{}, res_max{};
  void add_r(const std::array<double, 4>& mass, const std::array<double, 4>& largest) {  // a store of r
    constexpr double u = 0x1p-24, tiny = 0x1p-150;
    for (int k = 0; k < 4; ++k) {
      norm[k] += u * std::sqrt(mass[k]) + tiny * std::sqrt(double(nodes) * max_inverse_mass);
      max[k] += u * largest[k] + tiny * max_inverse_mass;
    }
  }
  void add_x(const double sums[8]) {  // a store of x: a pass's Drift4 (sum dx^2 [4], max |dx| [4])
    for (int k = 0; k < 4; ++k) {
      norm[k] += 2 * std::sqrt(max_mass * sums[k]);
      max[k] += 2 * sums[4 + k];
    }
  }
};

// Memory for CG's work vectors: `count` arrays of n values of T, carved from already-touched
// memory (a spent f: least_squares_fit's rvalue overload; `spent_doubles` doubles) while it lasts,
// in the order asked, the rest in one allocation (not value-initialised: each is written before it
// is read).
template <class T>
struct WorkVectors {
  std::unique_ptr<T[]> own;
  std::array<T*, 4> at{};
  WorkVectors(double* spent, std::size_t spent_doubles, std::size_t n, std::size_t count) {
    const std::size_t room = spent && n > 0 ? spent_doubles * sizeof(double) / (n * sizeof(T)) : 0;  // divisor checked
    const std::size_t in_spent = std::min(count, room);
    own.reset(count > in_spent ? new T[(count - in_spent) * n] : nullptr);
    for (std::size_t i = 0; i < count; ++i)  // T values in a double array: read and written by memcpy only
      at[i] = i < in_spent ? reinterpret_cast<T*>(spent) + i * n : own.get() + (i - in_spent) * n;
  }
};

// Jacobi-preconditioned conjugate gradient (Hestenes & Stiefel; the loop of Eigen's
// ConjugateGradient) on W channels at once (W = 1 or 3): one operator pass per step serves all
// channels, each with its own step lengths and its own stop. b: #nodes by W (double); r: the
// residual (T = double: may be b itself, b in and r out: one array fewer to fault in). x: #nodes
// by W, the first guess in, the solution out; rows in off_system stay 0. p, Ap: work vectors. T:
// the vectors' storage (float only with W = 4; least_squares_fit.h, Precision). Counts into fit
// (iterations: operator passes, the most over channels; residual: the largest relative residual
// of the recursion; converged).
template <std::size_t W, class T>
void block_conjugate_gradient(const FitOperator& A, const std::vector<double>& inverse_diagonal,
                              const std::vector<std::uint32_t>& off_system, const double* b, T* r,
                              const BlockCgOptions& o, T* x, T* p, double* Ap, LeastSquaresFit& fit) {
  static_assert(W == 4 || std::is_same_v<T, double>);
  using Channels = std::array<double, W>;
  const std::size_t N = inverse_diagonal.size(), n = N * W;
  const double* const inv_d = inverse_diagonal.data();
  const double* const inv_m = o.inverse_mass ? o.inverse_mass->data() : nullptr;
  // out = A in, and in^T A in per channel (summed over the elements; rows off the system: in is 0
  // there, and out is set to 0)
  const auto apply = [&](const T* in, double* out, double* inAin, bool out_zeroed) {
    apply_operator<W, T>(A, in, out, inAin, out_zeroed);
    for (std::uint32_t i : off_system)
      for (std::size_t k = 0; k < W; ++k) out[i * W + k] = 0;
  };
  Channels rhs2{}, res2{}, res_mass{}, res_max{}, threshold{}, abs_new{}, abs_old{}, pAp{}, alpha{}, beta{};
  std::array<bool, W> active{};
  const bool bounded = o.accuracy_bound > 0 && inv_m;
  const bool mass_is_jacobi = inv_m == inv_d;  // lambda = 0: r^T D^-1 r is both the stop's sum and CG's r^T z
  const bool sharp = bounded && mass_is_jacobi && o.sharp_accuracy > 0 && o.min_mass > 0;
  const double stop_at = o.accuracy_trigger * o.accuracy_bound;
  const double sharp_stop_at = std::sqrt(o.accuracy_trigger) * o.sharp_accuracy;
  const auto accurate = [&](std::size_t k) {
    if (!bounded) return false;
    return sharp ? fit_error_bound(res_max[k], res_mass[k], o.min_mass) <= sharp_stop_at : res_mass[k] <= stop_at;
  };
  apply(x, Ap, pAp.data(), false);  // pAp unused here
  if constexpr (W == 4) {
    lanes4_residual(Ap, bounded ? inv_m : nullptr, N, b, r, rhs2.data(), res2.data(), res_mass.data(), res_max.data());
    if (o.drift) o.drift->add_r(res_mass, res_max);  // inv_m = inv_d (the sharp stop)
    if (o.rhs2_out) *o.rhs2_out = rhs2;
  } else {
    for (std::size_t i = 0, node = 0; i < n; i += W, ++node)
      for (std::size_t k = 0; k < W; ++k) {
        const double bi = b[i + k];
        r[i + k] = bi - Ap[i + k];
        rhs2[k] += bi * bi;
        res2[k] += r[i + k] * r[i + k];
        if (bounded) {
          res_mass[k] += r[i + k] * r[i + k] * inv_m[node];
          res_max[k] = max_keeping_nan(res_max[k], std::fabs(r[i + k]) * inv_m[node]);
        }
      }
  }
  std::size_t running = 0;
  for (std::size_t k = 0; k < W; ++k) {
    threshold[k] = std::max(o.tolerance * o.tolerance * rhs2[k], std::numeric_limits<double>::min());
    active[k] = false;
    if (rhs2[k] == 0) {  // b = 0: the solution is 0
      for (std::size_t i = k; i < n; i += W) store1(x + i, 0.0);
      res2[k] = 0;
    } else if (!(res2[k] < threshold[k] || accurate(k))) {
      active[k] = true;
      ++running;
    }
  }
  if constexpr (W == 4) {
    lanes4_first_direction(r, inv_d, N, p, abs_new.data());
  } else {
    for (std::size_t i = 0, node = 0; i < n; i += W, ++node)
      for (std::size_t k = 0; k < W; ++k) {
        p[i + k] = r[i + k] * inv_d[node];
        abs_new[k] += r[i + k] * p[i + k];
      }
  }
  int iterations = 0;
  bool x_behind = false;  // 4 lanes: the last step's x += alpha p not yet made (lanes4_step)
  while (running > 0 && iterations < o.max_iterations) {
    apply(p, Ap, pAp.data(), iterations > 0);  // p^T A p summed over the elements; Ap cleared by the step (4 lanes) or the direction pass
    ++iterations;
    for (std::size_t k = 0; k < W; ++k)  // divisor checked (pAp <= 0: p = 0, a breakdown: the channel stops)
      alpha[k] = active[k] && pAp[k] > 0 ? abs_new[k] / pAp[k] : 0;
    res2.fill(0.0);
    res_mass.fill(0.0);
    res_max.fill(0.0);
    abs_old = abs_new;
    abs_new.fill(0.0);
    if constexpr (W == 4) {  // z = D^-1 r, not stored; x += alpha p in the direction pass (or below)
      lanes4_step(inv_d, bounded && !mass_is_jacobi ? inv_m : nullptr, N, alpha.data(), Ap, r, res2.data(),
                  res_mass.data(), abs_new.data(), sharp ? res_max.data() : nullptr);
      if (o.drift) o.drift->add_r(abs_new, res_max);  // sum r_i^2 / M_ii (abs_new: inv_d = inv_m)
      x_behind = true;
    } else {
      for (std::size_t i = 0, node = 0; i < n; i += W, ++node)  // z = D^-1 r, not stored
        for (std::size_t k = 0; k < W; ++k) {
          x[i + k] += alpha[k] * p[i + k];
          const double ri = r[i + k] - alpha[k] * Ap[i + k];
          r[i + k] = ri;
          res2[k] += ri * ri;
          if (bounded && !mass_is_jacobi) res_mass[k] += ri * ri * inv_m[node];
          abs_new[k] += ri * ri * inv_d[node];  // r^T z for the next step (unused if this one stops)
          if (sharp) res_max[k] = max_keeping_nan(res_max[k], std::fabs(ri) * inv_d[node]);
        }
    }
    if (bounded && mass_is_jacobi) res_mass = abs_new;  // sum r_i^2 inv_m_i with inv_m = inv_d: the same sum
    for (std::size_t k = 0; k < W; ++k)
      if (active[k] && (res2[k] < threshold[k] || accurate(k) || !(pAp[k] > 0))) {
        active[k] = false;
        --running;
      }
    if (running == 0) break;
    for (std::size_t k = 0; k < W; ++k)  // divisor checked; a stopped channel's p no longer matters (alpha 0)
      beta[k] = active[k] && abs_old[k] > 0 ? abs_new[k] / abs_old[k] : 0;
    if constexpr (W == 4) {
      double sums[8];
      lanes4_direction(r, inv_d, N, alpha.data(), beta.data(), x, p, o.drift ? sums : nullptr);
      if (o.drift) o.drift->add_x(sums);
      x_behind = false;
    } else {
      for (std::size_t i = 0, node = 0; i < n; i += W, ++node)
        for (std::size_t k = 0; k < W; ++k) {
          p[i + k] = r[i + k] * inv_d[node] + beta[k] * p[i + k];
          Ap[i + k] = 0;  // for the next operator pass
        }
    }
  }
  if constexpr (W == 4)
    if (x_behind) {
      double sums[8];
      lanes4_add_step(p, N, alpha.data(), x, o.drift ? sums : nullptr);
      if (o.drift) o.drift->add_x(sums);
    }
  if constexpr (W == 4)
    if (o.drift)
      for (std::size_t k = 0; k < 4; ++k) {
        o.drift->res_mass[k] = res_mass[k];
        o.drift->res_max[k] = res_max[k];
      }
  fit.iterations = std::max(fit.iterations, iterations);
  for (std::size_t k = 0; k < W; ++k) {
    const double relative = rhs2[k] > 0 ? std::sqrt(res2[k] / rhs2[k]) : 0.0;  // divisor checked
    fit.residual = std::max(fit.residual, relative);
    fit.converged = fit.converged && (res2[k] < threshold[k] || accurate(k));
  }
}

// b and x #nodes by `width` lanes, double (cg_lanes: 4 for 3 channels, the fourth b = 0 and so
// x = 0, a channel solved at once); widths other than 1 and 4: one channel at a time. b:
// overwritten (the residual). p and Ap in `spent` (spent_doubles already-touched doubles) while
// it lasts (WorkVectors).
void block_conjugate_gradient(const FitOperator& A, const std::vector<double>& inverse_diagonal,
                              const std::vector<std::uint32_t>& off_system, double* b, std::size_t width,
                              const BlockCgOptions& o, double* x, double* spent, std::size_t spent_doubles,
                              LeastSquaresFit& fit) {
  const std::size_t N = inverse_diagonal.size(), W = width == 1 || width == 4 ? width : 1;
  WorkVectors<double> work(spent, spent_doubles, N * W, 2);  // p, Ap
  if (width == 1) return block_conjugate_gradient<1>(A, inverse_diagonal, off_system, b, b, o, x, work.at[0], work.at[1], fit);
  if (width == 4) return block_conjugate_gradient<4>(A, inverse_diagonal, off_system, b, b, o, x, work.at[0], work.at[1], fit);
  std::vector<double> bk(N), xk(N);
  for (std::size_t k = 0; k < width; ++k) {
    for (std::size_t i = 0; i < N; ++i) {
      bk[i] = b[i * width + k];
      xk[i] = x[i * width + k];
    }
    block_conjugate_gradient<1>(A, inverse_diagonal, off_system, bk.data(), bk.data(), o, xk.data(), work.at[0],
                                work.at[1], fit);
    for (std::size_t i = 0; i < N; ++i) x[i * width + k] = xk[i];
  }
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
  std::size_t triangles = 0, quads = 0;  // to size the arrays once
  bool every_face_a_triangle = true;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const std::size_t size = mesh.face_size(f);
    const bool quad = size == 4 && !quad_is_concave(mesh.positions.data(), mesh.corner_vertex.data() + mesh.face_start[f]);
    quads += quad;
    triangles += size >= 3 && !quad ? size - 2 : 0;
    every_face_a_triangle = every_face_a_triangle && size == 3;
  }
  e.triangles = triangles;
  if (every_face_a_triangle && !own_nodes) {  // the loop's arrays would be the corners and 0..T-1: views
    e.mesh_corner_vertex = mesh.corner_vertex.data();
    return e;
  }
  reserve_bulk(e.tri_vertex, 3 * triangles);
  if (own_nodes) reserve_bulk(e.tri_node, 3 * triangles);  // else empty: the nodes are the vertices
  reserve_bulk(e.tri_face, triangles);
  e.quad_vertex.reserve(4 * quads);
  e.quad_node.reserve(4 * quads);
  e.quad_face.reserve(quads);
  std::vector<std::uint32_t> split;  // one face's triangles as corner positions, reused
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const std::size_t size = mesh.face_size(f), c0 = mesh.face_start[f];
    if (size < 3) {
      ++e.skipped_faces;
      continue;
    }
    // A convex quad by its bilinear map; a concave one (geometry/polygon_triangles.h
    // quad_is_concave: the map folds) as two triangles, below.
    if (size == 4 && !quad_is_concave(mesh.positions.data(), mesh.corner_vertex.data() + c0)) {
      for (std::size_t j = 0; j < 4; ++j) {
        e.quad_vertex.push_back(mesh.corner_vertex[c0 + j]);
        e.quad_node.push_back(node_of(c0 + j));
      }
      e.quad_face.push_back(std::uint32_t(f));
      continue;
    }
    // As render draws it: geometry/polygon_triangles.h (inside the outline; a triangle, or a
    // convex polygon: the fan from corner 0; a concave quad through its reflex corner).
    split.clear();
    polygon_triangles(mesh.positions.data(), mesh.corner_vertex.data() + c0, std::uint32_t(size), split);
    for (std::size_t t = 0; t + 2 < split.size(); t += 3) {
      for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t c = c0 + split[t + k];
        e.tri_vertex.push_back(mesh.corner_vertex[c]);
        if (own_nodes) e.tri_node.push_back(corner_node[c]);
      }
      e.tri_face.push_back(std::uint32_t(f));
    }
  }
  return e;
}

FitQuadrature fit_quadrature(const FitElements& e, const std::vector<double>& positions, int samples,
                             FitScratch* spare) {
  if (!triangle_quadrature_supported(samples))
    throw Error("fit_quadrature: " + std::to_string(samples) + " points per triangle is not a rule (1, 3, 6 or 12)");
  FitQuadrature q;
  q.samples = samples;
  q.rule = triangle_quadrature(samples);
  const std::size_t T = e.triangles;
  q.element_triangles = T;
  // The areas in place, then the triangles of positive area kept (all of them, the common case: copies).
  reserve_bulk(q.tri_area, T);
  q.tri_area.resize(T);
  triangle_areas(positions, e.triangle_vertices(), T, q.tri_area.data());
  std::size_t kept = 0;
  for (std::size_t t = 0; t < T; ++t) kept += q.tri_area[t] > 0;  // no area, no part of the integral
  if (kept == T) {  // views of the elements' arrays (header)
    q.elements_vertex = e.triangle_vertices();
    q.elements_node = e.triangle_nodes();
    q.elements_face = e.mesh_corner_vertex ? nullptr : e.tri_face.data();
  } else {
    const bool own_nodes = !e.tri_node.empty();  // else q's stays empty too: the vertices
    q.tri_node.resize(own_nodes ? 3 * kept : 0);
    q.tri_vertex.resize(3 * kept);
    q.tri_face.resize(kept);
    for (std::size_t t = 0, j = 0; t < T; ++t) {
      if (!(q.tri_area[t] > 0)) continue;
      for (int i = 0; i < 3; ++i) {
        if (own_nodes) q.tri_node[3 * j + i] = e.tri_node[3 * t + i];
        q.tri_vertex[3 * j + i] = e.triangle_vertices()[3 * t + i];
      }
      q.tri_area[j] = q.tri_area[t];  // j <= t: in place
      q.tri_face[j++] = e.triangle_face(t);
    }
    q.tri_area.resize(kept);
  }
  const int g = quad_gauss_points(samples);
  const std::vector<GaussPoint> gauss = gauss_legendre_unit(g);
  for (std::size_t k = 0; k < e.quad_face.size(); ++k) {
    Vec3d c[4];
    quad_corners(e, positions, k, c);
    for (const GaussPoint& gu : gauss)
      for (const GaussPoint& gv : gauss) {
        const BilinearPoint b = bilinear_point(c, gu.t, gv.t);
        if (!(b.area_element > 0)) continue;
        for (int j = 0; j < 4; ++j) {
          q.quad_node.push_back(e.quad_node[4 * k + j]);
          q.quad_vertex.push_back(e.quad_vertex[4 * k + j]);
          q.quad_phi.push_back(b.phi[j]);
        }
        q.quad_weight.push_back(gu.weight * gv.weight * b.area_element);
        q.quad_face.push_back(e.quad_face[k]);
      }
  }
  assign_sites(q, positions.size() / 3, spare);
  return q;
}

FitPoint FitQuadrature::point(std::size_t p) const {
  FitPoint out;
  const std::size_t R = rule.size();
  if (p < triangle_points()) {
    const std::size_t j = p / R, k = p - j * R;  // divisor: R >= 1 when there are triangle points
    for (int i = 0; i < 3; ++i) {
      out.node[i] = triangle_nodes()[3 * j + i];
      out.vertex[i] = triangle_vertices()[3 * j + i];
      out.phi[i] = rule[k].barycentric[i];
    }
    out.corners = 3;
    out.weight = rule[k].weight * tri_area[j];
    out.face = triangle_face(j);
  } else {
    const std::size_t m = p - triangle_points();
    for (int i = 0; i < 4; ++i) {
      out.node[i] = quad_node[4 * m + i];
      out.vertex[i] = quad_vertex[4 * m + i];
      out.phi[i] = quad_phi[4 * m + i];
    }
    out.corners = 4;
    out.weight = quad_weight[m];
    out.face = quad_face[m];
  }
  return out;
}

std::vector<double> interpolate_vertex_data_at_sites(const FitQuadrature& q, const std::vector<double>& data,
                                                     std::size_t width) {
  std::vector<double> out(q.sites() * width);
  for (std::size_t i = 0; i < q.sites(); ++i) interpolate_vertex_data_at_site(q, i, data.data(), width, &out[i * width]);
  return out;
}

std::vector<double> site_values_at_points(const FitQuadrature& q, const std::vector<double>& values, std::size_t width) {
  if (q.site.empty()) return values;  // every point its own site, numbered in point order
  std::vector<double> out(q.size() * width);
  for (std::size_t s = 0; s < q.size(); ++s)
    for (std::size_t k = 0; k < width; ++k) out[s * width + k] = values[q.site[s] * width + k];
  return out;
}

namespace {
// sum phi_j data[index_j] at every point (#points by width); index: the point's vertices or nodes.
std::vector<double> interpolate_at_points(const FitQuadrature& q, const std::vector<double>& data, std::size_t width,
                                          bool by_node) {
  std::vector<double> out(q.size() * width, 0.0);
  q.for_each_point([&](std::size_t p, const std::uint32_t* node, const std::uint32_t* vertex, const double* phi,
                       int corners, double) {
    for (int j = 0; j < corners; ++j) {
      if (phi[j] == 0) continue;
      const std::size_t i = by_node ? node[j] : vertex[j];
      for (std::size_t k = 0; k < width; ++k) out[p * width + k] += phi[j] * data[i * width + k];
    }
  });
  return out;
}
}  // namespace

std::vector<double> interpolate_vertex_data(const FitQuadrature& q, const std::vector<double>& data, std::size_t width) {
  return interpolate_at_points(q, data, width, false);
}

std::vector<double> interpolate_node_values(const FitQuadrature& q, const std::vector<double>& values, std::size_t width) {
  return interpolate_at_points(q, values, width, true);
}

std::vector<std::uint32_t> fit_fallback_nodes(const FitElements& e, const std::vector<double>& positions,
                                              const FitQuadrature& q) {
  // least_squares_fit's own rule: a node is in the system when its M_ii > 0.
  FitOperator A;
  std::vector<double> mass_diagonal;
  LeastSquaresFit counts;
  build_fit_operator(e, positions, q, 0.0, A, mass_diagonal, counts);
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < e.nodes; ++i)
    if (!(A.diagonal[i] > 0)) out.push_back(std::uint32_t(i));
  return out;
}

LeastSquaresFit least_squares_fit(const FitElements& e, const std::vector<double>& positions, const FitQuadrature& q,
                                  const std::vector<double>& f, const std::vector<double>& point_values,
                                  std::size_t width, const LeastSquaresFitOptions& options) {
  const bool f_sized = f.size() == q.size() * width || f.size() == q.sites() * width;  // per point or per site
  if (!f_sized || point_values.size() != e.nodes * width)
    throw Error("least_squares_fit: " + std::to_string(f.size()) + " signal values for " + std::to_string(q.size()) +
                " points and " + std::to_string(point_values.size()) + " point values for " + std::to_string(e.nodes) +
                " nodes (width " + std::to_string(width) + ")");
  return least_squares_fit(
      e, positions, q, f,
      [&](const std::vector<std::uint32_t>& nodes) {
        std::vector<double> at(nodes.size() * width);
        for (std::size_t i = 0; i < nodes.size(); ++i)
          for (std::size_t k = 0; k < width; ++k) at[i * width + k] = point_values[nodes[i] * width + k];
        return at;
      },
      width, options);
}

namespace {
// The float path's recursion stops at 0.8 of the accuracy bound (about 0.9 of it in the residual's
// norm): the rest is room for the drift between the recursive residual and the true one, which
// the check after the solve measures (least_squares_fit.h, Precision; on the tori of
// bench/fit/results.md the two differed by at most 5% of the sum at the stop).
constexpr double kFloatTrigger = 0.8;

// FloatAboveCache: float vectors once the double path's per-iteration working set (x, r, p, Ap at
// 32 bytes a node each, the triangles' nodes and areas at 20 bytes each) exceeds this: below it
// the vectors stay in cache, the passes are bound by their operations and the float conversions
// and the true residual's check cost more than the halved traffic saves (bench/fit/results.md,
// fit11: the 99k torus, 6.4 MB of vectors, solved 10-20% slower in float; the 1M torus, 64 MB,
// 4-8% faster). A server core's last-level cache.
constexpr std::size_t kFloatVectorsAbove = std::size_t(32) << 20;

// The float path's check (solve_float_vectors, when the drift bound does not prove every channel):
// t = b - A x in double (x's float values exactly, in place in b), each channel proven by the stop
// on t, or finished in double (correction: e, #nodes by 4).
template <class FirstGuess>
void check_and_finish(const FitOperator& A, const std::vector<double>& inverse_diagonal,
                      const std::vector<std::uint32_t>& off_system, double* b, const float* x,
                      const BlockCgOptions& options, const FirstGuess& first_guess, const std::array<double, 4>& rhs2,
                      bool sharp, std::unique_ptr<double[]>& correction, LeastSquaresFit& fit) {
  const std::size_t N = inverse_diagonal.size(), n = 4 * N;
  // The check: t = b - A x in double (x's float values exactly), sum t^2 and sum t^2 / M_ii per lane.
  double unused[4], t2[4], t_mass[4], t_max[4];
  apply_operator<4, float, true>(A, x, b, unused, true);
  for (std::uint32_t i : off_system)
    for (std::size_t k = 0; k < 4; ++k) b[4 * std::size_t(i) + k] = 0;
  lanes4_norms(b, options.inverse_mass->data(), N, t2, t_mass, t_max);
  std::array<bool, 4> proven{};
  bool all = true;
  double residual_proven = 0, t_relative_rest = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const double relative = rhs2[k] > 0 ? std::sqrt(t2[k] / rhs2[k]) : 0.0;  // divisor checked
    const double threshold = std::max(options.tolerance * options.tolerance * rhs2[k], std::numeric_limits<double>::min());
    const bool within = sharp ? fit_error_bound(t_max[k], t_mass[k], options.min_mass) <= options.sharp_accuracy
                              : t_mass[k] <= options.accuracy_bound;
    proven[k] = within || t2[k] < threshold;  // b = 0: t = 0, proven
    all = all && proven[k];
    if (proven[k])
      residual_proven = std::max(residual_proven, relative);
    else
      t_relative_rest = std::max(t_relative_rest, relative);
  }
  fit.residual = std::max(residual_proven, t_relative_rest);
  fit.converged = all;
  const int left = options.max_iterations - fit.iterations;
  if (!all && left > 0) {
    fit.double_finish = true;
    for (std::size_t k = 0; k < 4; ++k)
      if (proven[k])
        for (std::size_t i = 0; i < N; ++i) b[4 * i + k] = 0;  // nothing left to solve: e = 0
    correction.reset(new double[n]);
    first_guess(b, correction.get());
    BlockCgOptions rest = options;
    rest.max_iterations = left;
    rest.rhs2_out = nullptr;
    LeastSquaresFit counts;
    block_conjugate_gradient(A, inverse_diagonal, off_system, b, 4, rest, correction.get(), nullptr, 0, counts);
    fit.iterations += counts.iterations;
    fit.residual = std::max(residual_proven, counts.residual * t_relative_rest);  // counts' residual: relative to |t|
    fit.converged = counts.converged;
  }
}

// The 8-bit path's solve (least_squares_fit.h, Precision): x, r and p stored in float, Ap and b in
// double (Ap, p, r, x in that order in the spent f while it lasts; x in the caller's x_given when
// non-null: the quadrature's scratch); every sum in double. The
// recursion stops at kFloatTrigger of the accuracy bound; then the true residual t = b - A x of
// the float x is computed in double, in place in b (read no more), and a channel is proven when
// sum t_i^2 / M_ii is within the bound (or |t| within the tolerance of |b|). A channel that is not
// (the recursion drifted, or the bound lies below what float x can resolve) is finished in double:
// CG on A e = t from e's lumped-mass guess, c = x + e. Writes fit.values (#nodes by 3, the rows in
// the system; values_in_spent non-null: called first, it makes fit.values the spent f's vector)
// and fit's counts (residual: the true one, relative to |b|).
template <class FirstGuess>
void solve_float_vectors(const FitOperator& A, const std::vector<double>& inverse_diagonal,
                         const std::vector<std::uint32_t>& off_system, double* b, float* x_given,
                         const BlockCgOptions& options, const FirstGuess& first_guess, double* spent,
                         std::size_t spent_size, const std::function<void()>& values_in_spent,
                         LeastSquaresFit& fit) {
  const std::size_t N = inverse_diagonal.size(), n = 4 * N;
  // Ap (double, n) first in the spent f, then p, r and x (float; x: x_given when non-null) in
  // what is left of it
  const WorkVectors<double> wide(spent, spent_size, n, 1);
  const bool Ap_in_spent = spent && spent_size >= n;
  const WorkVectors<float> v(Ap_in_spent ? spent + n : nullptr, Ap_in_spent ? spent_size - n : 0, n, x_given ? 2 : 3);
  double* const Ap = wide.at[0];
  float* const p = v.at[0];
  float* const r = v.at[1];
  float* const x = x_given ? x_given : v.at[2];
  first_guess(b, x);
  BlockCgOptions cg = options;
  cg.accuracy_trigger = kFloatTrigger;
  std::array<double, 4> rhs2{};
  cg.rhs2_out = &rhs2;
  fit.float_vectors = true;
  const bool sharp = options.sharp_accuracy > 0 && options.min_mass > 0 && options.inverse_mass == &inverse_diagonal;
  Drift drift;  // the sharp stop: the drift bounded as it accrues (Drift)
  if (sharp) {
    drift.nodes = N;
    for (std::size_t i = 0; i < N; ++i) drift.max_mass = std::max(drift.max_mass, A.diagonal[i]);
    drift.max_inverse_mass = 1 / options.min_mass;  // divisor checked: sharp needs min_mass > 0
    cg.drift = &drift;
  }
  block_conjugate_gradient<4, float>(A, inverse_diagonal, off_system, b, r, cg, x, p, Ap, fit);
  // Proven without the check when the recursion's residual and the drift bound meet the sharp stop
  // for every channel: |D^-1/2 t| <= |D^-1/2 r| + norm, max |t_i| / M_ii <= max |r_i| / M_ii + max.
  bool drift_proven = sharp;
  for (std::size_t k = 0; k < 4 && drift_proven; ++k) {
    const double norm = std::sqrt(drift.res_mass[k]) + drift.norm[k];
    drift_proven = rhs2[k] == 0 ||
                   fit_error_bound(drift.res_max[k] + drift.max[k], norm * norm, options.min_mass) <= options.sharp_accuracy;
  }
  if (drift_proven) {
    fit.drift_bounded = true;
    fit.converged = true;
  }
  std::unique_ptr<double[]> correction;  // e, #nodes by 4, when a channel is finished in double
  if (!drift_proven) check_and_finish(A, inverse_diagonal, off_system, b, x, options, first_guess, rhs2, sharp, correction, fit);
  // fit.values into the spent f (values_in_spent non-null): its first 24 bytes a node are Ap's
  // (double, placed first), dead now; x is never there (after Ap, p and r, or in the scratch)
  if (values_in_spent) values_in_spent();
  for (std::size_t i = 0; i < N; ++i)  // c = x + e in double (the float values exactly, e's rounding 2^-53)
    for (std::size_t k = 0; k < 3; ++k)
      fit.values[3 * i + k] = load1(x + 4 * i + k) + (correction ? correction[4 * i + k] : 0.0);
}

// least_squares_fit; spent: f's own vector when the caller handed it over (the rvalue overload): its
// memory, already touched, holds CG's p and Ap once b is assembled (f is not read after that).
LeastSquaresFit fit_with(const FitElements& e, const std::vector<double>& positions, const FitQuadrature& q,
                         const std::vector<double>& f, const PointValuesAt& point_values_at, std::size_t width,
                         const LeastSquaresFitOptions& options, std::vector<double>* spent) {
  const std::size_t N = e.nodes, S = q.size();
  const bool per_site = f.size() != S * width && f.size() == q.sites() * width;  // f at the sites
  if (f.size() != S * width && !per_site)
    throw Error("least_squares_fit: " + std::to_string(f.size()) + " signal values for " + std::to_string(S) +
                " points (width " + std::to_string(width) + ")");
  if (!(options.regularization >= 0) || !std::isfinite(options.regularization))
    throw Error("least_squares_fit: the regularization weight must be finite and >= 0");
  LeastSquaresFit fit;
  FitOperator A;
  std::vector<double> mass_diagonal;
  if (q.element_triangles != e.triangles)
    throw Error("least_squares_fit: the quadrature is not of these elements (made for " +
                std::to_string(q.element_triangles) + " triangles, given " + std::to_string(e.triangles) + ")");
  build_fit_operator(e, positions, q, options.regularization, A, mass_diagonal, fit);

  // The system over the nodes with mass; the others keep their point value.
  // Jacobi preconditioner and 1 / M_ii (the same with lambda = 0); 0 off the system
  const bool regularized = options.regularization > 0;
  std::vector<double> inverse_diagonal, inverse_mass(regularized ? N : 0, 0.0);
  reserve_bulk(inverse_diagonal, N);
  inverse_diagonal.assign(N, 0.0);
  std::vector<std::uint32_t> off_system;
  double min_mass = std::numeric_limits<double>::infinity();  // over the nodes of the system
  for (std::size_t i = 0; i < N; ++i) {
    if (A.diagonal[i] > 0) {
      inverse_diagonal[i] = 1 / A.diagonal[i];  // divisor checked
      if (regularized && mass_diagonal[i] > 0) inverse_mass[i] = 1 / mass_diagonal[i];  // divisor checked
      min_mass = std::min(min_mass, regularized ? mass_diagonal[i] : A.diagonal[i]);
    } else {
      off_system.push_back(std::uint32_t(i));
      ++fit.fallback_nodes;
    }
  }
  // fit.values in the spent f's memory (3 channels: written after the solve from the padded x,
  // while CG's vectors there are dead), so that the output faults in no fresh page (12 MB at 1M);
  // else a vector of its own (zero-filled: the fallback nodes' rows are written after).
  const bool values_in_spent = spent && width == 3 && off_system.size() < N && spent->size() >= N * width;
  const auto take_spent_for_values = [&] {  // after the solve; the vector keeps its capacity
    fit.values = std::move(*spent);
    fit.values.resize(N * width);
  };
  if (!values_in_spent) fit.values.assign(N * width, 0.0);
  if (off_system.size() < N) {
    // b with L lanes per node: 3 channels padded to 4 (the fourth b = 0, so its solution is 0 and
    // it stops at once), for add_triangle_products_4; otherwise the channels. b for every channel in
    // one pass over the points, in double (Precision: b is the check's reference).
    const std::size_t L = width == 3 ? 4 : width;
    // b (and the float path's x: 4 bytes a lane) in the caller's spent memory when it holds them
    // (LeastSquaresFitOptions::scratch), else allocated; zero-filled either way
    std::unique_ptr<std::byte[]> held;
    std::size_t held_size = 0;
    if (options.scratch && options.scratch->size >= N * L * sizeof(double)) {
      held = std::move(options.scratch->bytes);
      held_size = options.scratch->size;
      options.scratch->size = 0;
    } else {
      if (options.scratch) {  // too small to use: back to the allocator before b is allocated
        options.scratch->bytes.reset();
        options.scratch->size = 0;
      }
      held.reset(new std::byte[N * L * sizeof(double)]);
      held_size = N * L * sizeof(double);
      advise_huge_pages(held.get(), held_size);
    }
    double* const b = ::new (static_cast<void*>(held.get())) double[N * L];
    std::fill(b, b + N * L, 0.0);
    float* const x_in_held =  // the float path's x after b, when there is room
        held_size >= N * L * (sizeof(double) + sizeof(float))
            ? ::new (static_cast<void*>(held.get() + N * L * sizeof(double))) float[N * L]
            : nullptr;
    const TriangleLoads loads = triangle_loads(q.rule);
    const double* const in_system = off_system.empty() ? nullptr : inverse_diagonal.data();
    if (L == 4)
      add_triangle_loads_4(q, loads, f.data(), per_site, in_system, b);
    else
      add_triangle_loads(q, loads, f.data(), width, L, per_site, in_system, b);
    for (std::size_t m = 0, s = q.triangle_points(); m < q.quad_weight.size(); ++m, ++s) {  // the quads' points
      const double* fs = &f[(per_site ? q.site_of(s) : s) * width];
      for (int j = 0; j < 4; ++j) {
        const std::size_t r = q.quad_node[4 * m + j];
        const double w = q.quad_weight[m] * q.quad_phi[4 * m + j];
        if (w == 0 || inverse_diagonal[r] == 0) continue;
        for (std::size_t k = 0; k < width; ++k) b[r * L + k] += w * fs[k];
      }
    }
    // The first guess: the lumped-mass projection c0_i = b_i / sum_j M_ij (the L2 projection with M
    // replaced by its row-sum diagonal; exact for a constant f). It needs only b, not the point
    // values, so the result does not depend on whether the caller computed them. 0 off the system.
    // x: #nodes by L, of T (float: the division's result rounded once).
    const auto first_guess = [&](const double* rhs, auto* x) {
      for (std::size_t i = 0; i < N; ++i) {  // all L lanes (a pad lane: b = 0, so 0), one vector division
        const double m = A.lumped_mass(i);
        const bool mass = inverse_diagonal[i] != 0 && m > 0;  // off the system (no mass): 0 during CG
        if (L == 4) {  // one 4-wide division and store (store4: rounded for float), per lane b_i / m
          Lanes4 v;
          std::memcpy(&v, rhs + 4 * i, sizeof v);
          Lanes4 c = mass ? v / m : Lanes4{0, 0, 0, 0};  // divisor checked
          store4(x + 4 * i, c);
        } else {
          for (std::size_t k = 0; k < L; ++k) store1(x + i * L + k, mass ? rhs[i * L + k] / m : 0.0);  // divisor checked
        }
      }
    };
    BlockCgOptions cg;
    cg.tolerance = options.tolerance;
    // accuracy a: stop at sum r_i^2 / M_ii <= (a mu)^2 min M_ii (header, Solver); mu = 1/2 with
    // triangles only, 1/4 with quads (Wathen's lower eigenvalue bounds of diag(M)^-1 M)
    const double mu = e.quad_face.empty() ? 0.5 : 0.25;
    if (options.accuracy > 0 && min_mass > 0 && std::isfinite(min_mass)) {
      cg.accuracy_bound = options.accuracy * mu * options.accuracy * mu * min_mass;
      cg.inverse_mass = regularized ? &inverse_mass : &inverse_diagonal;
      if (!regularized && e.quad_face.empty()) {  // D^-1 A = D^-1 M, its spectrum in [1/2, 2] (Wathen)
        cg.sharp_accuracy = options.accuracy;
        cg.min_mass = min_mass;
      }
    }
    cg.max_iterations = options.max_iterations > 0 ? options.max_iterations : int(2 * (N - off_system.size()));
    // b is assembled: f is read no more, and its memory (spent) holds work vectors
    double* const spent_data = spent ? spent->data() : nullptr;
    const std::size_t spent_size = spent ? spent->size() : 0;
    bool float_vectors = false;
    const bool bounded = L == 4 && cg.accuracy_bound > 0;  // 3 channels in 4 lanes, an accuracy
    switch (options.vectors) {
      case FitVectorStorage::Double: break;
      case FitVectorStorage::Float: float_vectors = bounded; break;
      case FitVectorStorage::FloatAboveCache:
        float_vectors = bounded && 4 * 32 * N + 20 * A.triangles > kFloatVectorsAbove;
        break;
    }
    if (float_vectors) {
      solve_float_vectors(A, inverse_diagonal, off_system, b, x_in_held, cg, first_guess, spent_data, spent_size,
                          values_in_spent ? std::function<void()>(take_spent_for_values) : nullptr, fit);
    } else {
      // the solution padded to L lanes (not value-initialised: the first guess writes it whole), or
      // fit.values itself
      const std::unique_ptr<double[]> padded(L != width ? new double[N * L] : nullptr);
      double* const x = L != width ? padded.get() : fit.values.data();
      first_guess(b, x);
      block_conjugate_gradient(A, inverse_diagonal, off_system, b, L, cg, x, spent_data, spent_size, fit);
      if (values_in_spent) take_spent_for_values();  // p and Ap there are dead; x is padded's
      if (L != width)
        for (std::size_t i = 0; i < N; ++i)
          for (std::size_t k = 0; k < width; ++k) fit.values[i * width + k] = x[i * L + k];
    }
  }
  if (!off_system.empty()) {  // the nodes outside the system keep their point values
    const std::vector<double> at = point_values_at(off_system);
    if (at.size() != off_system.size() * width)
      throw Error("least_squares_fit: " + std::to_string(at.size()) + " point values for " +
                  std::to_string(off_system.size()) + " fallback nodes (width " + std::to_string(width) + ")");
    for (std::size_t j = 0; j < off_system.size(); ++j)
      for (std::size_t k = 0; k < width; ++k) fit.values[off_system[j] * width + k] = at[j * width + k];
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

}  // namespace

LeastSquaresFit least_squares_fit(const FitElements& e, const std::vector<double>& positions, const FitQuadrature& q,
                                  const std::vector<double>& f, const PointValuesAt& point_values_at,
                                  std::size_t width, const LeastSquaresFitOptions& options) {
  return fit_with(e, positions, q, f, point_values_at, width, options, nullptr);
}

LeastSquaresFit least_squares_fit(const FitElements& e, const std::vector<double>& positions, const FitQuadrature& q,
                                  std::vector<double>&& f, const PointValuesAt& point_values_at, std::size_t width,
                                  const LeastSquaresFitOptions& options) {
  std::vector<double> spent = std::move(f);  // ours now: CG's scratch after the loads
  return fit_with(e, positions, q, spent, point_values_at, width, options, &spent);
}

double relative_l2_error(const FitQuadrature& q, const std::vector<double>& f, const std::vector<double>& node_values,
                         std::size_t width) {
  const bool per_site = f.size() != q.size() * width && f.size() == q.sites() * width;  // f at the sites
  double num = 0, den = 0;
  q.for_each_point([&](std::size_t s, const std::uint32_t* node, const std::uint32_t*, const double* phi, int corners,
                       double weight) {
    const double* fs = &f[(per_site ? q.site_of(s) : s) * width];
    for (std::size_t k = 0; k < width; ++k) {
      double g = 0;
      for (int j = 0; j < corners; ++j) g += phi[j] * node_values[node[j] * width + k];
      const double d = g - fs[k];
      num += weight * d * d;
      den += weight * fs[k] * fs[k];
    }
  });
  if (!(den > 0)) return num > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  return std::sqrt(num / den);  // divisor checked
}

}  // namespace shadetool
