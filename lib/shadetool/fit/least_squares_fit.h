// least_squares_fit.h: the vertex values whose Gouraud interpolation is closest, in L2 over the
// surface, to a signal f known at quadrature points (Kavan, Bargteil & Sloan, "Least Squares
// Vertex Baking", EGSR 2011).
//
// Objective, per channel:   E(c) = integral over S of (sum_i c_i phi_i(x) - f(x))^2 dA + lambda R(c)
// phi_i are the hat functions Gouraud interpolation uses (render/render_mesh.h): barycentric on
// triangles and on the triangles of polygons with 5 or more corners and of concave quads
// (geometry/polygon_triangles.h: inside the outline, as render draws them; a convex polygon: the
// fan from corner 0; a concave quad, quad_is_concave, through its reflex corner); on convex quads the
// bilinear weights (1-u)(1-v), u(1-v), uv, (1-u)v of corners 0..3 (the map P(u, v) of
// render/inverse_bilinear.h; render blends a planar quad exactly so, a non-planar one on its fan).
// Its minimum solves the normal equations
//     (M + lambda R) c = b,   M_ij = integral phi_i phi_j dA,   b_i = integral phi_i f dA.
//   M   triangles: area/12 [[2,1,1],[1,2,1],[1,1,2]] (exact); quads: 3x3 Gauss-Legendre on the unit
//       square with dA = |P_u x P_v| du dv (exact for planar quads: the integrand has degree <= 3
//       in u and in v).
//   b   the quadrature `q` (fit_quadrature: triangle_quadrature.h's rule with `samples` points per
//       triangle; quads n x n Gauss-Legendre, n = 1, 2, 3 for samples 1, 3, 6 or 12), f given at
//       its points.
//   R   the paper's edge-based regulariser (its section on regularisation; the form below is the
//       one of NVIDIA's optix_prime_baking sample, adapted from P.-P. Sloan's code): for every edge
//       shared by exactly two triangles T1, T2 (of the splits above; convex quads on their 0-2
//       diagonal), the two triangles unfolded into one plane about the edge,
//           R(c) = sum_edges (A1 + A2)^2 |grad g|T1 - grad g|T2|^2,   g = sum_i c_i phi_i,
//       zero exactly when g is one linear function across the edge: it penalises kinks, not
//       slopes, so a linear signal is still reproduced exactly. (A1 + A2)^2 |grad|^2 has the units of
//       f^2 times area, as the data term: lambda is dimensionless and does not change with scale.
//       Edges with a zero-length side or a zero-height triangle are left out (counted).
// Nodes are what carries a value: corner_node maps each corner to its node (the vertex, or a
// corner group split at a crease or seam: then no edge joins the two sides, M and R never couple
// them, and the fitted values keep the discontinuity).
//
// Solver: Jacobi-preconditioned conjugate gradient on M + lambda R (symmetric positive definite
// when every node touches a face of positive area), matrix-free: A is kept as its elements (area/12
// per triangle, a 4 x 4 block per quad, a vector d per regularised edge) and applied by one pass
// over them per step, so no sparse matrix is assembled; all channels in one block (one pass serves
// them all; each channel has its own step lengths and stop). Three channels are held in 4-wide
// lanes per node (a fourth of b = 0, solved at once), so that the operator and the vector passes
// do one 4-wide operation per node (AVX2 where the CPU has it, target_clones, no FMA): per lane the
// scalar operations in the scalar order, so each channel's values are the bits of that channel
// solved alone (tests/fit checks). Stopped per channel when
// |A c - b| <= tolerance |b| (default 1e-10), from the lumped-mass projection as the first guess:
// c0_i = b_i / sum_j M_ij, the L2 projection with M replaced by the diagonal of its row sums
// (mass lumping; Zienkiewicz & Taylor, The Finite Element Method, vol. 1, the lumped mass matrix;
// R's rows sum to 0, so the row sums of M + lambda R are M's). It is exact for a constant f, needs
// only b, and so does not depend on the point values (bench/fit/results.md: CG iterations against
// the point values as the first guess). With
// accuracy a > 0 (8-bit outputs: kEightBitFitAccuracy, a quarter of a step) a channel also stops
// once every value is provably within a of the exact solution. With e = c - c*, r = A c - b = A e,
// D = diag(M) and mu a lower bound of the eigenvalues of D^-1 M (Wathen, "Realistic eigenvalue
// bounds for the Galerkin mass matrix", IMA J. Numer. Anal. 7, 1987: they lie in [1/2, 2] for
// linear triangles of any shape and in [1/4, 9/4] for bilinear rectangles; distorted quads stay
// near it, tests/fit checks jittered ones; so mu = 1/2 without quads, 1/4 with), and R positive
// semi-definite:  mu |D^1/2 e|^2 <= e^T M e <= e^T A e = e^T r <= |D^1/2 e| |D^-1/2 r|,  so
//     |e|_inf <= |e|_2 <= |D^1/2 e|_2 / sqrt(min D) <= |D^-1/2 r|_2 / (mu sqrt(min D)),
// and CG stops at sum_i r_i^2 / M_ii <= (a mu)^2 min_i M_ii (the 2-norm stop).
// Sharp stop (lambda = 0 and triangles only, the common case; fit_error_bound): then A = M and the
// spectrum of B = D^-1/2 M D^-1/2 lies in [1/2, 2] (Wathen: each element's D_t^-1 M_t has the
// eigenvalues 1/2, 1/2, 2, and x^T M x / x^T D x is a ratio of sums of the elements' terms), so the
// eigenvalues 1/l of B^-1 lie in [1/2, 2] and those of E = B^-1 - (5/4) I in [-3/4, 3/4]: |E|_2 <=
// 3/4. With s = D^-1/2 r, e = D^-1/2 B^-1 s = D^-1/2 ((5/4) s + E s), and |(E s)_i| <= |E s|_2 <=
// (3/4) |s|_2, so for every node i
//     |e_i| <= (5/4) |r_i| / M_ii + (3/4) |D^-1/2 r|_2 / sqrt(M_ii)
//           <= (5/4) max_i |r_i| / M_ii + (3/4) sqrt(sum_i r_i^2 / M_ii / min_i M_ii),
// and CG stops when that is <= a. It is never above the 2-norm bound 2 |D^-1/2 r|_2 / sqrt(min D)
// (max_i |r_i| / M_ii <= |D^-1/2 r|_2 / sqrt(min D)), and below it by up to 8/3 where the residual
// is spread over many nodes (the 2-norm term dominates: 3/4 against 2): on the 1M torus one CG
// iteration fewer (bench/fit/results.md, fit13). With quads (no proven upper eigenvalue bound for a
// distorted quad) or lambda > 0 (D^-1 A's upper bound unknown) the 2-norm stop stays. The 8-bit bytes
// written then differ from the exact solution's only where that value lies within a of a rounding
// boundary (bench/fit/results.md: on the 10k torus 8 CG iterations instead of 17 under the studio
// scene, 3 instead of 13 under the window). Nodes
// that touch no face of positive area (isolated vertices, only degenerate faces) keep their point
// value (fallback_nodes) and are left out of the system.
// Clamping: after the solve, every value outside [lower, upper] is set to the bound and counted
// (an unconstrained L2 fit overshoots near a sharp edge of f: a highlight, a shadow boundary).
//
// Sums: b adds, per triangle corner, area sum_k (w_k phi_k) f_k over the rule's points (one update
// per corner); CG's p^T A p is summed over the elements as p^T A p = sum_t area_t/12 sum_i p_i
// (p_i + p_0 + p_1 + p_2) (+ quads' p^T m p, + edges' (d . p)^2) in the operator's pass, in four
// accumulators (no pass over the nodes). Both are the same sums as the per-point and per-node
// ones in another order: the colours move by rounding only, far inside the stop's accuracy
// (bench/fit/results.md: over data/ and the corpus against the per-point sums).
// Precision: b is assembled in double, sequentially in element order, and the solve is single
// threaded, so the result is the same bits for any thread count. CG's vectors are double, except
// on the 8-bit path (accuracy a > 0, 3 channels; options.vectors Float, or FloatAboveCache, the
// default, on meshes whose vectors do not stay in cache): there x, r and p are stored in float (16
// bytes a node for 4 lanes instead of 32; Ap stays double: the operator's scatter adds into it
// node by node, and a float store there lengthens every update's chain, measured slower), every
// value loaded into double, every operation, sum and dot product done in double, only the store
// rounded (relative 2^-24, about 6e-8: a float x is within 6e-8 |c| of the double one, some 16000
// times inside a = 1/1020 for c in [0, 1]). Sums stay in double because the stop's
// sum_i r_i^2 / M_ii adds #nodes terms: in float its rounding would grow with the count. What
// float storage breaks is the proof above, which needs the true residual b - A c: the recursive
// residual r (r -= alpha Ap, stored in float; x rounded at each step) drifts from it by rounding of
// order 2^-24 |A| |x| summed over the steps. So the float recursion stops at 0.8 of the bound.
// With the sharp stop the drift is then bounded from the roundings themselves: each float store of
// r (exact value minus stored value dr) moves t - r by dr, each store of x (dx) by A dx, and nothing
// else does (x0 is what it is, and t0 = b - A x0 is what the first residual rounds), so t - r is
// the sum of those moves and
//     |D^-1/2 (t - r)|_2 <= sum (|D^-1/2 dr|_2 or 2 sqrt(max M_ii) |dx|_2)   (|D^-1/2 A D^-1/2|_2 <= 2)
//     max_i |t_i - r_i| / M_ii <= sum (max |dr_i| / M_ii or 2 max |dx_i|)   (A >= 0, rows sum to 2 M_ii)
// r's terms from the stored r's own sums (|dr_i| <= 2^-24 |r_i| + 2^-150: rounding to nearest,
// a subnormal's absolute error), x's measured exactly (a double and its float rounding differ by a
// double) in the passes that store x: no pass of their own. When
// fit_error_bound of r's sums plus these is within a for every channel, the channel is proven
// without t (LeastSquaresFit::drift_bounded; on the 1M torus the bound is a few % of a: values of
// size 1 round by 6e-8). Otherwise (quads, lambda > 0, large values) the true residual t = b - A c
// of the float c is computed in double (one operator pass, in place in b, which is read no more)
// and tested against the full bound: the proof holds for t as computed, whatever the drift. Either
// way the doubles' own roundings (t's, A p's: about 2^-53 of |b|) are ignored as the double path
// ignores its own. A channel whose t is not within the bound (the drift took more
// than the margin, or the bound asks for more than a float c can resolve:
// |D^-1/2 A (c - fl(c))| grows as sqrt(#nodes) while the bound does not) is finished in double: CG
// on A e = t from e's lumped-mass guess, c + e (LeastSquaresFit::double_finish). The float c
// itself is as good as a double one: Wathen's bound keeps the condition number of the
// Jacobi-preconditioned M within 4 for any mesh, so rounding the vectors perturbs c by about 1e-7
// of |c|; the sqrt(#nodes) is the 2-norm bound's, not the solution's. The double path (HDR,
// accuracy 0, other widths, FitVectorStorage::Double) is unchanged: its bits are those of the
// release before the float path.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/fit/triangle_quadrature.h>
#include <shadetool/fit/vertex_fit.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// The faces as interpolation elements. Inputs: mesh (faces), corner_node (#C node ids; empty:
// the corner's vertex), nodes (#nodes; ignored when corner_node is empty: #V).
// tri_node is empty when the nodes are the vertices (no corner_node): triangle_nodes() is then
// the triangles' vertices (one array fewer to fill and fault in; likewise in FitQuadrature).
// When every face is a triangle and the nodes are the vertices (the common case), the triangles are
// the mesh's faces in order and nothing is copied: tri_vertex and tri_face stay empty,
// triangle_vertices() is the mesh's own corner_vertex (mesh_corner_vertex: the mesh must outlive the
// elements and stay unchanged) and triangle t is face t. Read the triangles through the accessors.
struct FitElements {
  std::size_t nodes = 0;
  std::size_t triangles = 0;                                     // the faces' triangles
  std::vector<std::uint32_t> tri_vertex, tri_node, tri_face;     // 3 (or 0), 3 (or 0), 1 (or 0) per triangle
  std::vector<std::uint32_t> quad_vertex, quad_node, quad_face;  // 4, 4, 1 per quad
  std::size_t skipped_faces = 0;                                 // fewer than 3 corners
  const std::uint32_t* mesh_corner_vertex = nullptr;             // the mesh's corner_vertex, or null
  const std::uint32_t* triangle_vertices() const { return mesh_corner_vertex ? mesh_corner_vertex : tri_vertex.data(); }
  const std::uint32_t* triangle_nodes() const { return tri_node.empty() ? triangle_vertices() : tri_node.data(); }
  std::uint32_t triangle_face(std::size_t t) const { return mesh_corner_vertex ? std::uint32_t(t) : tri_face[t]; }
};
FitElements fit_elements(const Mesh& mesh, const std::vector<std::uint32_t>& corner_node = {}, std::size_t nodes = 0);

// The quadrature points: triangles' first, then quads', in element order. Per point up to 4
// (node, phi) pairs, its weight w_k dA (units of `positions`, squared), its face, and its element's
// vertices and their weights (to interpolate per-vertex data: positions, normals); point(p) gives
// them, for_each_point visits them in order.
// Storage: a triangle's points are its rule's (`rule`: barycentric phi and weight fraction) on its
// corners, so only the triangles of positive area are stored (nodes, vertices, area, face: 36 bytes
// each, whatever the rule), point j * R + k being point k of the j-th of them (R = rule.size()).
// Quads' points (bilinear weights, area element) are stored one by one after them.
// Sites: where the signal is evaluated. A point at the midpoint of an edge (the 3-point rule's) is
// the same place, with the same interpolated per-vertex data, in both triangles of the edge (those
// that share its two vertices), so the two points share one site; every other point is its own
// site. Sites are numbered in the order of their first point; `site` and `site_point` are empty
// when every point is its own site (site p is point p).
// When every triangle has positive area (the common case) the triangles are the elements' and q
// copies none of them: tri_node, tri_vertex and tri_face stay empty and q reads the elements'
// arrays (elements_vertex, elements_node; their faces elements_face, or the identity when null):
// the elements (and the mesh they view) must outlive q. Read them through the accessors.
struct FitPoint {
  std::uint32_t node[4] = {}, vertex[4] = {};
  double phi[4] = {};  // unused: 0
  int corners = 0;     // 3 (triangle) or 4 (quad)
  double weight = 0;
  std::uint32_t face = 0;
};
struct FitQuadrature {
  int samples = 3;
  std::vector<QuadraturePoint> rule;        // the triangle rule (fit/triangle_quadrature.h)
  std::size_t element_triangles = 0;        // the elements' triangle count (those of no area included)
  std::vector<std::uint32_t> tri_node;      // 3 per triangle of positive area, or empty: the vertices
  std::vector<std::uint32_t> tri_vertex;    // 3 per triangle of positive area (or empty: the elements')
  std::vector<double> tri_area;             // 1 per triangle of positive area
  std::vector<std::uint32_t> tri_face;      // 1 per triangle of positive area (or empty: the elements')
  const std::uint32_t* elements_vertex = nullptr;  // every triangle kept: the elements' (else null)
  const std::uint32_t* elements_node = nullptr;
  const std::uint32_t* elements_face = nullptr;    // null with elements_vertex: triangle j is face j
  std::vector<std::uint32_t> quad_node;     // 4 per quad point
  std::vector<std::uint32_t> quad_vertex;   // 4 per quad point
  std::vector<double> quad_phi;             // 4 per quad point
  std::vector<double> quad_weight;          // 1 per quad point
  std::vector<std::uint32_t> quad_face;     // 1 per quad point
  std::vector<std::uint32_t> site;          // 1 per point, or empty (site p is point p)
  std::vector<std::uint32_t> site_point;    // 1 per site: its first point, or empty (identity)
  // When every point is an edge's midpoint (the 3-point rule on triangles only): per rule point,
  // the two local corners of weight 1/2 (site_edge_vertices reads a site's edge through them and
  // site_point: no array of 2 vertices a site, 12 MB of fresh pages at 1M triangles); else empty.
  std::vector<std::array<std::uint8_t, 2>> midpoint_corners;

  std::size_t triangle_points() const { return tri_area.size() * rule.size(); }
  const std::uint32_t* triangle_vertices() const { return elements_vertex ? elements_vertex : tri_vertex.data(); }
  const std::uint32_t* triangle_nodes() const {
    return elements_vertex ? elements_node : (tri_node.empty() ? tri_vertex.data() : tri_node.data());
  }
  std::uint32_t triangle_face(std::size_t j) const {
    return elements_vertex ? (elements_face ? elements_face[j] : std::uint32_t(j)) : tri_face[j];
  }
  std::size_t size() const { return triangle_points() + quad_weight.size(); }
  std::size_t sites() const { return site_point.empty() ? size() : site_point.size(); }
  std::size_t site_of(std::size_t p) const { return site.empty() ? p : site[p]; }
  std::size_t first_point(std::size_t i) const { return site_point.empty() ? i : site_point[i]; }
  FitPoint point(std::size_t p) const;

  // fn(p, node, vertex, phi, corners, weight) for every point p in order (node, vertex, phi:
  // `corners` entries; weight w_k dA). Inline: the solve's and the error's loops call it.
  template <class Fn>
  void for_each_point(Fn&& fn) const {
    const std::size_t R = rule.size(), T = tri_area.size();
    const std::uint32_t* const tri_nodes = triangle_nodes();
    const std::uint32_t* const tri_vertex = triangle_vertices();
    std::size_t p = 0;
    for (std::size_t j = 0; j < T; ++j)
      for (std::size_t k = 0; k < R; ++k, ++p)
        fn(p, &tri_nodes[3 * j], &tri_vertex[3 * j], rule[k].barycentric.data(), 3, rule[k].weight * tri_area[j]);
    for (std::size_t m = 0; m < quad_weight.size(); ++m, ++p)
      fn(p, &quad_node[4 * m], &quad_vertex[4 * m], &quad_phi[4 * m], 4, quad_weight[m]);
  }
};
// Memory one step of a fit has written and no longer needs, handed to the next step so that the
// next step's arrays land on pages already faulted in (at 1M triangles every fresh MB costs about
// 0.37 ms CPU in the kernel's page clearing and faults: bench/fit/results.md, fit10 and fit11).
// Untyped bytes (not value-initialised): each user places its own arrays in them (placement new).
// fit_quadrature leaves its site search's bucket entries here (8 bytes a midpoint: 24 MB at 1M
// triangles and 3 points) when they take 4 MiB or more (none for rules without midpoints);
// least_squares_fit places b (and the float path's x) in them when they are large enough
// (LeastSquaresFitOptions::scratch), and frees them otherwise.
// wanted (in, set by the caller before fit_quadrature): the bytes the next step would place in
// them (fit_scratch_bytes); when the entries are handed over the block is made at least that large.
// The entries take 8 bytes x 3T = 48V - 96 on a closed genus-0 triangle mesh (T = 2V - 4), 96
// bytes short of b and the float x (48 a node): without it the 1M-triangle sphere's x took fresh
// pages. Bytes past the entries are untouched until used (no page is faulted in for them).
struct FitScratch {
  std::unique_ptr<std::byte[]> bytes;
  std::size_t size = 0;    // bytes
  std::size_t wanted = 0;  // bytes (in)
};
// What least_squares_fit places in a FitScratch for `nodes` nodes and `width` channels: b (double,
// 3 channels in 4 lanes) and, for 3 channels, the float path's x (4 bytes a lane).
inline std::size_t fit_scratch_bytes(std::size_t nodes, std::size_t width) {
  return width == 3 ? nodes * 4 * (sizeof(double) + sizeof(float)) : nodes * width * sizeof(double);
}

// positions: #V by 3 (the space the area is measured in: world, for lighting). samples: 1, 3, 6, 12
// (Error otherwise). spare: non-null, receives the site search's spent memory (FitScratch).
FitQuadrature fit_quadrature(const FitElements& elements, const std::vector<double>& positions, int samples,
                             FitScratch* spare = nullptr);

// Per-vertex data (#V by width) at the quadrature points (#points by width): sum phi_k data[vertex_k].
std::vector<double> interpolate_vertex_data(const FitQuadrature& q, const std::vector<double>& vertex_data,
                                            std::size_t width);
// The same at one site i: out[0..width) = sum phi_k data[vertex_k] at its first point (inline: the
// shading loops call it per site).
inline void interpolate_vertex_data_at_site(const FitQuadrature& q, std::size_t i, const double* vertex_data,
                                            std::size_t width, double* out) {
  const std::size_t p = q.first_point(i), R = q.rule.size();
  const std::uint32_t* vertex;
  const double* phi;
  int corners;
  if (p < q.triangle_points()) {
    const std::size_t j = R == 1 ? p : p / R;  // divisor: R >= 1 when there are triangle points
    vertex = &q.triangle_vertices()[3 * j];
    phi = q.rule[p - j * R].barycentric.data();
    corners = 3;
  } else {
    const std::size_t m = p - q.triangle_points();
    vertex = &q.quad_vertex[4 * m];
    phi = &q.quad_phi[4 * m];
    corners = 4;
  }
  for (std::size_t k = 0; k < width; ++k) out[k] = 0;
  for (int j = 0; j < corners; ++j) {
    if (phi[j] == 0) continue;
    const std::size_t v = vertex[j];
    for (std::size_t k = 0; k < width; ++k) out[k] += phi[j] * vertex_data[v * width + k];
  }
}
// The edge of site i when every site is an edge's midpoint (!q.midpoint_corners.empty()): its two
// vertices, lower first, from its first point's triangle (a site's data is then 0.5 d_lo + 0.5 d_hi,
// the bits of interpolate_vertex_data_at_site: two products of 1/2 added, in either order).
inline void site_edge_vertices(const FitQuadrature& q, std::size_t i, std::uint32_t& lo, std::uint32_t& hi) {
  const std::size_t p = q.first_point(i), R = q.midpoint_corners.size();
  const std::size_t j = R == 3 ? p / 3 : p / R;  // divisor: R >= 1 (the rule's points); 3 spelled out: no division
  const std::array<std::uint8_t, 2>& c = q.midpoint_corners[p - j * R];
  const std::uint32_t* const v = &q.triangle_vertices()[3 * j];
  lo = std::min(v[c[0]], v[c[1]]);
  hi = std::max(v[c[0]], v[c[1]]);
}
// The same at the sites (#sites by width), and values at the sites copied to their points.
std::vector<double> interpolate_vertex_data_at_sites(const FitQuadrature& q, const std::vector<double>& vertex_data,
                                                     std::size_t width);
std::vector<double> site_values_at_points(const FitQuadrature& q, const std::vector<double>& site_values,
                                          std::size_t width);
// Per-node values (#nodes by width) interpolated at the quadrature points, as Gouraud shows them.
std::vector<double> interpolate_node_values(const FitQuadrature& q, const std::vector<double>& node_values,
                                            std::size_t width);

// How CG stores its vectors x, r and p (Ap, which the operator's scatter accumulates, is double
// either way; header, Precision).
enum class FitVectorStorage {
  Double,           // always double: the HDR path's, and the bits of each channel solved alone
  Float,            // float when the solve has an accuracy (8-bit output) and 3 channels; else double
  FloatAboveCache,  // Float once the double vectors would not stay in cache (above 32 MiB: at 1M
                    // triangles, not at 100k), where halving their bytes pays; else double
};

struct LeastSquaresFitOptions {
  double regularization = 0;  // lambda (dimensionless; 0: the plain least-squares solution, the
                             // least error; bench/fit/results.md: R costs 5x the solve's time)
  double tolerance = 1e-10;      // relative residual |A c - b| / |b| at which CG stops
  double accuracy = 0;           // > 0: also stop once every value is within this of the exact one
  int max_iterations = 0;        // 0: 2 * #nodes (Eigen's default)
  double lower = 0;                                        // clamp after the solve
  double upper = std::numeric_limits<double>::infinity();
  FitVectorStorage vectors = FitVectorStorage::FloatAboveCache;
  // Spent memory the solve may use for b (and x): taken (the pointee is empty after); its
  // placement changes no value. Null: allocated.
  FitScratch* scratch = nullptr;
};

// The sharp stop's bound on max_i |c_i - c*_i| (Solver above; lambda = 0, triangles only) from the
// residual r = A c - b: res_max = max_i |r_i| / M_ii, res_mass = sum_i r_i^2 / M_ii, min_mass =
// min_i M_ii over the system. Infinity when min_mass is not > 0 (no bound).
inline double fit_error_bound(double res_max, double res_mass, double min_mass) {
  return min_mass > 0 ? 1.25 * res_max + 0.75 * std::sqrt(res_mass / min_mass)  // divisor checked
                      : std::numeric_limits<double>::infinity();
}

// A quarter of an 8-bit step: the accuracy an 8-bit output needs of the solve (see Solver above).
constexpr double kEightBitFitAccuracy = 1.0 / 1020;

// What a caller of a fit chooses (`--fit`, `--fit-samples`, `--fit-regularization`).
struct VertexFitOptions {
  VertexFit method = VertexFit::Point;
  int samples = 3;  // quadrature points per triangle (fit/triangle_quadrature.h)
  LeastSquaresFitOptions solve;
  // The fitted and point-sampled errors (relative_l2_error, two passes over the points) are
  // measured only when asked for (the CLI: --stats or --json); false: both reported as NaN.
  bool measure_error = true;
};

struct LeastSquaresFit {
  std::vector<double> values;       // #nodes by width
  std::size_t clamped = 0;          // values set to lower or upper
  std::size_t fallback_nodes = 0;   // nodes on no face of positive area: their point value
  std::size_t regularized_edges = 0;
  std::size_t skipped_edges = 0;    // interior edges left out of R (degenerate butterfly)
  int iterations = 0;               // CG iterations, the most over the channels (with a double
                                    // finish: the float solve's and the finish's together)
  double residual = 0;              // relative residual reached, the largest over the channels
  bool converged = true;
  bool float_vectors = false;       // CG's vectors were stored in float (Precision)
  bool double_finish = false;       // ... and a channel's true residual was above the bound: finished in double
  bool drift_bounded = false;       // ... and every channel proven by the recursion's residual and the drift
                                    // bound (Precision), without the true residual's operator pass
};

// The nodes that touch no face of positive area (no triangle of q, no quad with mass): they are no
// part of the system and keep their point value (LeastSquaresFit::fallback_nodes counts them).
// Ascending node ids: the list least_squares_fit hands its PointValuesAt (built by the same
// operator, so the same rule).
std::vector<std::uint32_t> fit_fallback_nodes(const FitElements& elements, const std::vector<double>& positions,
                                              const FitQuadrature& q);

// f: #points by width, the signal at q's points, or #sites by width, its value at each site (one
// value for all the points of a site; the two are the same when every point is its own site). point_values: #nodes by width, read only at the
// fallback nodes (fit_fallback_nodes: the others may hold anything). Error for mismatched sizes.
LeastSquaresFit least_squares_fit(const FitElements& elements, const std::vector<double>& positions,
                                  const FitQuadrature& q, const std::vector<double>& f,
                                  const std::vector<double>& point_values, std::size_t width,
                                  const LeastSquaresFitOptions& options = {});

// The same, for a caller that has no point values at every node: point_values_at(nodes) is called
// once, after the solve and only when some node is outside the system, with the ascending fallback
// nodes (fit_fallback_nodes), and returns their values, #nodes by width (Error otherwise).
using PointValuesAt = std::function<std::vector<double>(const std::vector<std::uint32_t>& nodes)>;
LeastSquaresFit least_squares_fit(const FitElements& elements, const std::vector<double>& positions,
                                  const FitQuadrature& q, const std::vector<double>& f,
                                  const PointValuesAt& point_values_at, std::size_t width,
                                  const LeastSquaresFitOptions& options = {});

// The same, f handed over (moved in; empty after): once b is assembled f is read no more, and its
// memory, already touched, holds CG's work vectors (p and Ap: 2 #nodes x 4 doubles for 3 channels,
// p alone when f is smaller; on the float path Ap, p and r, as many as fit), so the solve does not
// fault in fresh pages for them (at 1M triangles and 3 points, 32 of the bake's ~170 MB of fresh
// pages; bench/fit/results.md, fit10), and for 3 channels the result's values take f's vector
// after the solve (its capacity kept: f's). For a caller that has no further use for f
// (bake-lighting without --stats). The same bits.
LeastSquaresFit least_squares_fit(const FitElements& elements, const std::vector<double>& positions,
                                  const FitQuadrature& q, std::vector<double>&& f,
                                  const PointValuesAt& point_values_at, std::size_t width,
                                  const LeastSquaresFitOptions& options = {});

// The relative L2 distance between the interpolated node values and f (per point or per site, as
// least_squares_fit takes it), by the quadrature q:
//   sqrt( sum_k w_k |g(x_k) - f_k|^2 / sum_k w_k |f_k|^2 )   (0 when f is zero everywhere and g is).
double relative_l2_error(const FitQuadrature& q, const std::vector<double>& f,
                         const std::vector<double>& node_values, std::size_t width);

}  // namespace shadetool
#pragma GCC visibility pop
