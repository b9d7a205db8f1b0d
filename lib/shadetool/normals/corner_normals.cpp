// corner_normals.cpp: see corner_normals.h.
//
// Steps: (1) unit face normals (crease test, degenerate faces; face_normals.h, vectorised for
// triangles); (2) the fan of every vertex as flat arrays (VertexFans: offsets + one record per
// corner {corner, face, next vertex, previous vertex}, in ascending corner order), built in two
// passes in face order (count, fill), the first also adding up each vertex's unit face normals for
// SmoothCone: a vertex whose faces are all valid and whose normals' sum shows them all within half
// the crease angle of their mean cannot be split by a crease;
// (3) in parallel over vertices, reading each fan as one sequential run: a cone vertex whose fan
// is one closed ring (closed_smooth_ring) is one group at once; any other vertex links the two
// corners across each smooth manifold edge of its fan (link_small_fan: every pair of edge ends
// compared, no sort, for fans of up to kSmallFan corners; link_large_fan: ends sorted by far
// vertex, for poles and cone apexes; union-find over the vertex's corners, no allocation per
// vertex), CreaseTest deciding only where SmoothCone could not, and numbers its groups by first
// corner; (4) prefix sum of group counts gives each vertex's rows in the pool, and one pass in
// corner order gives every corner its row (corner_index); (5) the corners'
// weighted contributions (corner_contributions.h) are summed into their rows by the same
// deterministic parallel scatter as vertex_normals (accumulate_by_vertex.h), so a group's sum adds
// its corners in ascending corner order: with no crease in the way the result is vertex_normals'
// bit for bit; (6) rows normalised in parallel, fallbacks for the rare rows that cannot be.
// Precision: contributions in double, rounded once to T, sums in T (double or float, as
// vertex_normals; corner_contributions.h); the crease test compares angles in double:
// interior_angle(|n1 x n2|, n1 . n2) > crease_angle (interior_angle.h), decided from n1 . n2 alone
// away from the threshold (CreaseTest: the same verdicts, see there).
// Same results, bit for bit, as the crease path before issue 31 (grouping by sorted edge ends and
// an angle per edge end; tests/support/corner_normals_reference.h keeps it as the reference of
// tests/normals/corner_normals_bitwise.cpp); figures in bench/normals/results/notes.md.
#include <shadetool/normals/corner_normals.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include <tbb/parallel_invoke.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/error.h>

#include <shadetool/geometry/interior_angle.h>
#include <shadetool/geometry/union_find.h>
#include <shadetool/normals/engine/accumulate_by_vertex.h>
#include <shadetool/normals/engine/corner_contributions.h>
#include <shadetool/normals/engine/crease_paths.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/engine/mesh_scale.h>
#include <shadetool/normals/engine/normalise_sums.h>
#include <shadetool/normals/engine/smooth_cone.h>
#include <shadetool/normals/engine/vertex_slots.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/core/engine/usable_threads.h>
#include <shadetool/normals/vertex_fallback.h>

namespace shadetool {
namespace {

using namespace normals_detail;
using namespace engine;

// What the fan grouping reads of a corner: its face, and the vertices after and before it in the
// face; in a degenerate face (whose edges are creases) both are the corner's own vertex, which no
// edge end of the fan leads to.
constexpr std::uint32_t kNoLink = 0xffffffffu;  // link_small_fan: a corner linked to none
struct FanCorner {
  std::uint32_t corner, face, next, prev;
};

// Whether face f has a unit normal in fn (#F by 3, face_normals.h: zero for a degenerate face).
inline bool has_normal(const double* fn, std::uint32_t f) {
  const double* n = fn + 3 * std::size_t(f);
  return !(n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0);
}

// The fans of all vertices as flat arrays, built in face order (two passes over the corners:
// count, fill): fan[offset[v] .. offset[v+1]) are the FanCorners of vertex v in ascending corner
// order. The grouping then reads each vertex's fan as one sequential run instead of fetching every
// corner's face from anywhere in the face arrays.
// cone_smooth[v]: every face at v is valid and within half the crease angle of their mean normal
// (SmoothCone), so no crease can split v: its edges are tested for topology only.
// Scratch in BulkVectors (core/bulk_reserve.h: unzeroed, huge pages): every entry is written.
constexpr std::uint32_t kFanPadding = 8;  // records after the last fan: ring tests load 8 whatever the fan size
struct VertexFans {
  std::vector<std::uint32_t> offset;
  BulkVector<FanCorner> fan;
  std::vector<std::uint8_t> cone_smooth;
};

// Face order of the corners of face f: [begin, end), triangles by arithmetic.
struct FaceCorners {
  std::uint32_t begin, end;
};
inline FaceCorners face_corners(const MeshView& mesh, bool triangles, std::size_t f) {
  if (triangles) return {std::uint32_t(3 * f), std::uint32_t(3 * f + 3)};
  return {mesh.face_begin(f), mesh.face_end(f)};
}

// The crease test: the edge between unit face normals na, nb is smooth when
// interior_angle(|na x nb|, na . nb) <= crease_angle (geometry/interior_angle.h), as it always was.
// Fast path: most edges are far from the threshold, and their verdict follows from d = na . nb
// alone: with |na|, |nb| within 1e-6 of 1 (double normals: ~1e-16; float-rounded ones: ~1e-7),
// cos(phi) for the true angle phi between them lies within 4e-7 of the computed d, and the
// computed interior angle within 1e-14 of phi. So d > cos(crease_angle) + kBand gives phi, and
// the computed angle, below crease_angle (smooth), d < cos(crease_angle) - kBand above it
// (crease); only inside the band is the angle computed, by the same expression as before. The
// verdicts are therefore exactly those of the angle comparison (tests/normals/
// corner_normals_bitwise.cpp checks edges at exactly the threshold). cos is monotonic only on
// [0, pi]: crease_angle < 0 or NaN makes every edge a crease (no angle is <= it), crease_angle
// >= pi every edge smooth (interior_angle never exceeds kPi).
struct CreaseTest {
  static constexpr double kBand = 1e-5;
  double angle, above, below;  // smooth when d > above; crease when d < below

  explicit CreaseTest(double crease_angle) : angle(crease_angle) {
    const double inf = std::numeric_limits<double>::infinity();
    if (!(crease_angle >= 0.0)) {
      above = below = inf;  // every edge a crease
    } else if (crease_angle >= kPi) {
      above = below = -inf;  // every edge smooth
    } else {
      const double c = std::cos(crease_angle);
      above = c + kBand;
      below = c - kBand;
    }
  }
  SHADETOOL_INLINE bool smooth(const Vec3d& na, const Vec3d& nb) const {
    const double d = dot(na, nb);
    if (d > above) return true;
    if (d < below) return false;
    const Vec3d x = cross(na, nb);
    // unit vectors: |na x nb| <= 1, no scaling needed before squaring
    return interior_angle(std::sqrt(dot(x, x)), d) <= angle;
  }
};

// SmoothCone (engine/smooth_cone.h) decides, per vertex, that no crease can split it.

// Vertex fans (VertexFans) in two passes in face order, each touching one 16-byte record per
// vertex (FanBuild) at every corner: (a) count the corners of each vertex and add up its faces'
// unit normals (as float; NaN for a degenerate face) for SmoothCone; a prefix sum turns the counts
// into the first slot of each run, and SmoothCone decides each vertex; (b) fill each vertex's run
// with its FanCorners. Neither pass branches on the data.
VertexFans vertex_fans(const MeshView& mesh, const double* fn, const SmoothCone& cone) {
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces();
  const std::uint32_t* cv = mesh.corner_vertex;
  const bool triangles = mesh.all_triangles();
  struct alignas(16) FanBuild {
    float x, y, z;    // (a) sum of the faces' unit normals, NaN after a degenerate face
    std::uint32_t n;  // (a) corners counted; (b) next free slot of the run
  };
  BulkVector<FanBuild> build(V);
  std::fill(build.begin(), build.end(), FanBuild{0.0f, 0.0f, 0.0f, 0});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t f = 0; f < F; ++f) {
    const FaceCorners fc = face_corners(mesh, triangles, f);
    const double* n = fn + 3 * f;
    const bool valid = has_normal(fn, std::uint32_t(f));
    const float x = valid ? float(n[0]) : nan, y = float(n[1]), z = float(n[2]);
    for (std::uint32_t c = fc.begin; c < fc.end; ++c) {
      FanBuild& b = build[cv[c]];
      b = {b.x + x, b.y + y, b.z + z, b.n + 1};
    }
  }
  VertexFans vf;
  vf.offset.resize(V + 1);
  vf.cone_smooth.resize(V);
  std::uint32_t slots = 0;
  for (std::size_t v = 0; v < V; ++v) {
    const FanBuild b = build[v];
    vf.offset[v] = slots;
    vf.cone_smooth[v] = b.n != 0 && cone.passes(b.n, b.x, b.y, b.z);
    slots += b.n;
    build[v].n = vf.offset[v];
  }
  vf.offset[V] = slots;
  vf.fan.resize(mesh.num_corners() + kFanPadding);
  for (std::size_t k = 0; k < kFanPadding; ++k) vf.fan[mesh.num_corners() + k] = {0, 0, 0, 0};
  for (std::size_t f = 0; f < F; ++f) {
    const FaceCorners fc = face_corners(mesh, triangles, f);
    const bool valid = has_normal(fn, std::uint32_t(f));
    for (std::uint32_t c = fc.begin; c < fc.end; ++c) {
      const std::uint32_t v = cv[c];
      const std::uint32_t next = valid ? cv[c + 1 < fc.end ? c + 1 : fc.begin] : v;
      const std::uint32_t prev = valid ? cv[c > fc.begin ? c - 1 : fc.end - 1] : v;
      vf.fan[build[v].n++] = {c, std::uint32_t(f), next, prev};
    }
  }
  return vf;
}

constexpr std::size_t kPrefetchVertices = 16;

// Per-range scratch for the vertex fans (grown to the largest fan seen, never shrunk).
constexpr std::uint32_t kSmallFan = 32;
struct FanScratch {
  std::vector<std::uint64_t> ends;
  std::vector<std::uint32_t> parent_, number_;
  std::uint32_t* parent(std::uint32_t d) {
    if (parent_.size() < d) parent_.resize(d);
    for (std::uint32_t i = 0; i < d; ++i) parent_[i] = i;
    return parent_.data();
  }
  std::uint32_t* number(std::uint32_t d) {
    if (number_.size() < d) number_.resize(d);
    std::fill(number_.begin(), number_.begin() + d, ~0u);
    return number_.data();
  }
};

// Whether the fan of vertex v is one closed ring of smooth manifold edges through all its d
// corners (d <= kRingFan). Every corner i needs exactly one corner j arriving from the vertex it
// leaves to (prev[j] == next[i], next[i] != v); when each of these matches is a single corner and
// together they cover all d corners, the successor map i -> j is a permutation, so every far vertex
// is left once and reached once: every edge of the fan is manifold and links exactly the two
// corners link_small_fan would link. Then the ring is one group when the permutation is one cycle
// (walked from corner 0) and each of its links is smooth. Any other fan returns false (the caller
// links it edge by edge). The matches are found all at once (SSE2: four 4-lane compares), not
// searched corner by corner: link_small_fan's pairwise scan cost ~60 ns per vertex.
constexpr std::uint32_t kRingFan = 16;

// One vertex id per corner of a fan (its next or its previous vertex), kRingFan lanes, lanes >= d
// set to v (which no edge end of the fan leads to); equal(w): bit j set where lane j is w, all lanes
// compared at once (SSE2: four 4-lane compares), no search.
struct FanLanes {
  alignas(16) std::uint32_t lanes[kRingFan];
  FanLanes(std::uint32_t v, const FanCorner* fan, std::uint32_t d, std::uint32_t FanCorner::*end) {
    for (std::uint32_t k = 0; k < kRingFan; ++k) lanes[k] = k < d ? fan[k].*end : v;
  }
  std::uint32_t equal(std::uint32_t w) const {
#if defined(__SSE2__)
    const __m128i x = _mm_set1_epi32(int(w));
    std::uint32_t m = 0;
    for (std::uint32_t q = 0; q < kRingFan / 4; ++q) {
      const __m128i l = _mm_load_si128(reinterpret_cast<const __m128i*>(lanes + 4 * q));
      m |= std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(l, x)))) << (4 * q);
    }
    return m;
#else
    std::uint32_t m = 0;
    for (std::uint32_t q = 0; q < kRingFan; ++q) m |= std::uint32_t(lanes[q] == w) << q;
    return m;
#endif
  }
};

template <class Smooth>
bool closed_smooth_ring(std::uint32_t v, const FanCorner* fan, std::uint32_t d, const Smooth& smooth) {
  if (d > kRingFan) return false;
  const FanLanes prv(v, fan, d, &FanCorner::prev);
  std::uint32_t succ[kRingFan];
  std::uint32_t covered = 0;
  bool single = true;
  for (std::uint32_t i = 0; i < d; ++i) {
    const std::uint32_t w = fan[i].next;
    const std::uint32_t m = prv.equal(w);
    single &= (w != v) & (m != 0) & ((m & (m - 1)) == 0);
    covered |= m;
    succ[i] = std::uint32_t(__builtin_ctz(m | (1u << 31)));
  }
  if (!single || covered != (1u << d) - 1) return false;
  std::uint32_t k = 0;
  for (std::uint32_t step = 1; step <= d; ++step) {
    const std::uint32_t j = succ[k];
    if (!smooth(fan[k].face, fan[j].face) || (j == 0) != (step == d)) return false;
    k = j;
  }
  return true;
}

// closed_smooth_ring for a triangle fan of 1..8 corners with every face valid and no smoothing
// groups (so every link is smooth: two corners of v in different valid triangles), without a
// branch on the data: 8 lanes whatever d, each corner's successor (the first corner arriving from
// the vertex it leaves to) found by two 4-lane compares, and the cycle by walking the successor
// map 8 steps and asking that the first return to corner 0 be step d. Such a walk visits all d
// corners once, so the successor map is a permutation of them; then no far vertex is left twice
// (two corners leaving to w would have the same successor) nor reached twice (the successor is
// the first arriving corner, and every corner is some corner's successor): every link is a
// manifold edge, and the d links join all corners in one group, as link_small_fan would.
constexpr std::uint32_t kRing8 = 8;
inline bool closed_triangle_ring8(std::uint32_t v, const FanCorner* fan, std::uint32_t d) {
#if defined(__SSE2__)
  const __m128i vv = _mm_set1_epi32(int(v)), count = _mm_set1_epi32(int(d));
  const __m128i* r = reinterpret_cast<const __m128i*>(fan);  // {corner, face, next, prev}
  alignas(16) std::uint32_t nxt[kRing8];
  __m128i prev[2];
  for (int q = 0; q < 2; ++q) {
    const __m128i hi01 = _mm_unpackhi_epi32(_mm_loadu_si128(r + 4 * q), _mm_loadu_si128(r + 4 * q + 1));
    const __m128i hi23 = _mm_unpackhi_epi32(_mm_loadu_si128(r + 4 * q + 2), _mm_loadu_si128(r + 4 * q + 3));
    const __m128i index = _mm_add_epi32(_mm_set1_epi32(4 * q), _mm_setr_epi32(0, 1, 2, 3));
    const __m128i in_fan = _mm_cmplt_epi32(index, count);
    prev[q] = _mm_or_si128(_mm_and_si128(in_fan, _mm_unpackhi_epi64(hi01, hi23)), _mm_andnot_si128(in_fan, vv));
    _mm_store_si128(reinterpret_cast<__m128i*>(nxt + 4 * q), _mm_unpacklo_epi64(hi01, hi23));
  }
  std::uint32_t succ[kRing8];
  bool linked = true;  // every corner leaves to a far vertex that some corner arrives from
  for (std::uint32_t i = 0; i < kRing8; ++i) {
    const std::uint32_t w = nxt[i];
    const __m128i x = _mm_set1_epi32(int(w));
    const std::uint32_t m = std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(prev[0], x)))) |
                            std::uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(prev[1], x)))) << 4;
    linked &= (i >= d) | ((w != v) & (m != 0));
    succ[i] = std::uint32_t(__builtin_ctz(m | 0x100u)) & (kRing8 - 1);
  }
  std::uint32_t k = 0, returns = 0;  // bit s: the walk is at corner 0 after s steps
  for (std::uint32_t step = 1; step <= kRing8; ++step) {
    k = succ[k];
    returns |= std::uint32_t(k == 0) << step;
  }
  return linked & (std::uint32_t(__builtin_ctz(returns | 0x200u)) == d);
#else
  return closed_smooth_ring(v, fan, d, [](std::uint32_t, std::uint32_t) { return true; });
#endif
}

// The end of link_small_fan and link_fan16: to[i] is the corner that corner i's leaving edge links
// to (kNoLink: none), links how many are linked. When all d are, to is a permutation (each far
// vertex is left and reached once), and one cycle through all d corners is one group: true. Else
// the links unite their corners in parent: false.
inline bool one_ring_or_unite(const std::uint32_t* to, std::uint32_t d, std::uint32_t links, std::uint32_t* parent) {
  if (links == d) {
    std::uint32_t k = 0, steps = 0;
    do {
      k = to[k];
      ++steps;
    } while (k != 0 && steps <= d);
    if (steps == d) return true;
  }
  for (std::uint32_t i = 0; i < d; ++i)
    if (to[i] != kNoLink) union_find_unite(parent, i, to[i]);
  return false;
}

// Linking the corners of vertex v (corners[0 .. d), ascending; local index i) across its smooth
// manifold edges: edge {v, w} joins corners i and j when exactly two edge ends at v lead to w, one
// leaving v (corner i, next vertex w) and one arriving (corner j, previous vertex w), both in valid
// faces, and smooth(face i, face j). Corners of degenerate faces have no ends (their edges are
// creases). parent: d roots on entry (union_find.h; union by lower index).
// Small fans: every pair compared (d^2 <= 1024 comparisons, no sort, no allocation).
// Returns true when the fan is one closed ring of smooth edges through every corner (the common
// case: one group, the caller skips the union-find); else links the corners in parent.
template <class Smooth>
bool link_small_fan(std::uint32_t v, const FanCorner* fan, std::uint32_t d, const Smooth& smooth, std::uint32_t* parent) {
  std::uint32_t nxt[kSmallFan], prv[kSmallFan], to[kSmallFan];
  for (std::uint32_t i = 0; i < d; ++i) {
    nxt[i] = fan[i].next;
    prv[i] = fan[i].prev;
  }
  std::uint32_t links = 0;
  for (std::uint32_t i = 0; i < d; ++i) {
    to[i] = kNoLink;
    const std::uint32_t w = nxt[i];
    if (w == v) continue;  // no edge end (a degenerate face, or a face that repeats v)
    std::uint32_t leaving = 0, arriving = 0, j = 0;
    for (std::uint32_t k = 0; k < d; ++k) {
      leaving += nxt[k] == w;
      if (prv[k] == w) { ++arriving; j = k; }
    }
    if (leaving == 1 && arriving == 1 && smooth(fan[i].face, fan[j].face)) {
      to[i] = j;
      ++links;
    }
  }
  return one_ring_or_unite(to, d, links, parent);
}

// Whether mask m has exactly one bit set.
inline bool one_bit(std::uint32_t m) { return m != 0 && (m & (m - 1)) == 0; }

// link_small_fan for fans of up to kRingFan corners, the same links and result: each corner's
// leaving and arriving ends at w counted by FanLanes masks instead of a scan over the fan.
template <class Smooth>
bool link_fan16(std::uint32_t v, const FanCorner* fan, std::uint32_t d, const Smooth& smooth, std::uint32_t* parent) {
  const FanLanes nxt(v, fan, d, &FanCorner::next), prv(v, fan, d, &FanCorner::prev);
  std::uint32_t to[kRingFan];
  std::uint32_t links = 0;
  for (std::uint32_t i = 0; i < d; ++i) {
    to[i] = kNoLink;
    const std::uint32_t w = fan[i].next;
    if (w == v) continue;  // no edge end (a degenerate face, or a face that repeats v)
    const std::uint32_t leaving = nxt.equal(w), arriving = prv.equal(w);
    // exactly one lane each (no popcount: without -mpopcnt it is a libgcc call, 6% of a CAD run)
    if (!one_bit(leaving) || !one_bit(arriving)) continue;
    const std::uint32_t j = std::uint32_t(__builtin_ctz(arriving));
    if (smooth(fan[i].face, fan[j].face)) {
      to[i] = j;
      ++links;
    }
  }
  return one_ring_or_unite(to, d, links, parent);
}

// Large fans (a pole, a cone apex): the edge ends as one 64-bit key each: far vertex (high 32
// bits), local corner index, and whether the edge leaves v (bit 0); sorting the keys sorts by far
// vertex, then corner. The same links as link_small_fan.
template <class Smooth>
void link_large_fan(std::uint32_t v, const FanCorner* fan, std::uint32_t d, const Smooth& smooth, std::uint32_t* parent,
                    std::vector<std::uint64_t>& ends) {
  auto end_key = [](std::uint32_t far, std::uint32_t local, bool out) {
    return (std::uint64_t(far) << 32) | (std::uint64_t(local) << 1) | std::uint64_t(out);
  };
  ends.clear();
  for (std::uint32_t i = 0; i < d; ++i) {
    const std::uint32_t n = fan[i].next, p = fan[i].prev;  // both v in a degenerate face: no ends
    if (n != v) ends.push_back(end_key(n, i, true));
    if (p != v) ends.push_back(end_key(p, i, false));
  }
  std::sort(ends.begin(), ends.end());
  for (std::size_t i = 0; i < ends.size();) {
    std::size_t j = i + 1;
    while (j < ends.size() && (ends[j] >> 32) == (ends[i] >> 32)) ++j;
    // exactly two ends, one leaving v and one arriving
    if (j - i == 2 && (ends[i] & 1) != (ends[i + 1] & 1)) {
      const auto la = std::uint32_t(ends[i] & 0xffffffffu) >> 1, lb = std::uint32_t(ends[i + 1] & 0xffffffffu) >> 1;
      if (smooth(fan[la].face, fan[lb].face)) union_find_unite(parent, la, lb);
    }
    i = j;
  }
}

// Sums of the corners contributions into rows: row target[c] < rows for every corner, added in
// ascending corner order by the deterministic parallel scatter (accumulate_by_vertex.h). The sums
// are in `normals` (3 rows values) for T = double, else in float_sum. The chunk plan is made
// beside the (serial) zeroing of the arrays. Returns the number of degenerate faces.
template <class T, Weighting W>
std::size_t sum_rows(const MeshView& mesh, const std::uint32_t* target, std::size_t rows, std::vector<double>& normals,
                     std::vector<float>& float_sum) {
  ChunkPlan plan;
  tbb::parallel_invoke(
      [&] {
        reserve_bulk(normals, 3 * rows);
        normals.assign(3 * rows, 0.0);
        if constexpr (!std::is_same_v<T, double>) float_sum.assign(3 * rows, 0.0f);
      },
      [&] { plan = plan_chunks<true>(mesh, target, rows); });
  T* sum;
  if constexpr (std::is_same_v<T, double>) sum = normals.data();
  else sum = float_sum.data();
  const bool triangles = mesh.all_triangles();
  // float Area/Max: one power of two for the whole mesh (corner_contributions.h); a row whose float
  // sum still overflows cannot be normalised and takes the caller's fallback (a valid unit normal, counted).
  const double scale = contribution_scale<T, W>(mesh);
  return accumulate_by_target<true, T>(mesh, plan, target,
      [&](std::size_t f_begin, std::size_t f_end, auto&& sink) {
        return triangles ? triangle_contributions<T, W>(mesh, f_begin, f_end, sink, scale)
                         : polygon_contributions<T, W>(mesh, f_begin, f_end, sink, scale);
      }, sum);
}

template <class T, Weighting W>
GroupNormals group_normals(const MeshView& mesh, const std::vector<std::uint32_t>& corner_group, std::size_t num_groups) {
  GroupNormals out;
  // Corners in no group go to one extra row, dropped afterwards.
  bool any_outside = false;
  for (std::uint32_t g : corner_group) any_outside = any_outside || g == kNoGroup;
  std::vector<std::uint32_t> mapped;
  const std::uint32_t* target = corner_group.data();
  if (any_outside) {
    mapped = corner_group;
    for (std::uint32_t& g : mapped)
      if (g == kNoGroup) g = std::uint32_t(num_groups);
    target = mapped.data();
  }
  const std::size_t rows = num_groups + (any_outside ? 1 : 0);
  std::vector<float> float_sum;
  out.degenerate_faces = sum_rows<T, W>(mesh, target, rows, out.normals, float_sum);
  const T* sum;
  if constexpr (std::is_same_v<T, double>) sum = out.normals.data();
  else sum = float_sum.data();
  out.normals.resize(3 * num_groups);
  for (std::size_t g = 0; g < num_groups; ++g) {
    double* o = &out.normals[3 * g];
    if (!normalise_sum(double(sum[3 * g]), double(sum[3 * g + 1]), double(sum[3 * g + 2]), o)) {
      o[0] = o[1] = o[2] = 0.0;
      out.failed.push_back(std::uint32_t(g));
    }
  }
  return out;
}

// The general path. base (optional): #V + 1, vertex v's rows are base[v] .. base[v + 1].
// counted: only vertices < counted are grouped and their rows normalised; every later vertex is
// one row (the sum of its corners, not normalised) and fallback_corners counts none of its
// corners. The one-thread path runs this on the faces around its hard vertices, numbered first,
// and keeps only their rows: a vertex's groups and its rows' sums read nothing of other vertices,
// and its rows come before any later vertex's, so they are what compute on all vertices gives
// (the other vertices of such a sub-mesh have open fans: grouping them was most of its cost).
template <class T, Weighting W>
CornerNormals compute(const MeshView& mesh, double crease_angle, Precision precision, const std::uint32_t* face_group,
                      std::vector<std::uint32_t>* base_out = nullptr, std::size_t counted = ~std::size_t(0)) {
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners();
  // (1) face normals: zero for degenerate faces.
  BulkVector<double> fn(3 * mesh.num_faces());  // every entry written
  face_normals(mesh, precision, fn.data());
  auto face_valid = [&](std::uint32_t f) { return has_normal(fn.data(), f); };
  // (2) the vertex fans, and which vertices no crease can split.
  const VertexFans vf = vertex_fans(mesh, fn.data(), SmoothCone(crease_angle));

  // (3) groups per vertex, numbered within the vertex (0 .. groups[v]). The corners of a vertex
  // that is one ring (one group, by far the most) are not written here: corner_index starts at 0
  // and (4) adds each vertex's first pool row in one pass in corner order.
  CornerNormals out;
  reserve_bulk(out.corner_index, C);  // huge pages for the fresh array (core/bulk_reserve.h)
  out.corner_index.resize(C);
  const std::size_t grouped = std::min(V, counted);
  std::vector<std::uint32_t> groups(V, 1);  // vertices >= grouped: one row each (see above)
  std::vector<std::uint8_t> has_degenerate_group(V, 0);
  const CreaseTest crease(crease_angle);
  // Whether the two faces of a manifold edge join: not the same face, the same smoothing group
  // (not 0: flat), and no crease between their normals.
  auto same_group = [&](std::uint32_t fa, std::uint32_t fb) {
    return fa != fb && (!face_group || (face_group[fa] == face_group[fb] && face_group[fa] != 0));
  };
  auto smooth = [&](std::uint32_t fa, std::uint32_t fb) __attribute__((always_inline)) {
    auto normal = [&](std::uint32_t f) { return Vec3d{fn[3 * std::size_t(f)], fn[3 * std::size_t(f) + 1], fn[3 * std::size_t(f) + 2]}; };
    return same_group(fa, fb) && crease.smooth(normal(fa), normal(fb));
  };
  const bool plain_triangles = mesh.all_triangles() && !face_group;
  parallel_ranges(grouped, [&](std::size_t v_begin, std::size_t v_end) {
    FanScratch scratch;  // reused across the range's vertices
    for (std::size_t v = v_begin; v < v_end; ++v) {
      const std::uint32_t begin = vf.offset[v], d = vf.offset[v + 1] - begin;
      if (d == 0) { groups[v] = 0; continue; }
      // A vertex that is not inside its smooth cone reads the normals of its faces and writes its
      // corners' groups, anywhere in those arrays: fetch them kPrefetchVertices ahead (measured:
      // without it the grouping of a CAD mesh, most of whose vertices lie on creases, took 1.3x
      // as long; bench/normals/results/notes.md).
      if (v + kPrefetchVertices < v_end && !vf.cone_smooth[v + kPrefetchVertices])
        for (std::uint32_t i = vf.offset[v + kPrefetchVertices], e = vf.offset[v + kPrefetchVertices + 1]; i < e; ++i) {
          __builtin_prefetch(fn.data() + 3 * std::size_t(vf.fan[i].face));
          __builtin_prefetch(out.corner_index.data() + vf.fan[i].corner, 1);
        }
      const FanCorner* fan = vf.fan.data() + begin;
      // A vertex inside its smooth cone has only valid faces and no crease: its edges join by
      // topology (and smoothing group) alone, with the same verdicts as `smooth` (SmoothCone).
      const bool cone = vf.cone_smooth[v];
      if (cone && (plain_triangles && d <= kRing8 ? closed_triangle_ring8(std::uint32_t(v), fan, d)
                                                  : closed_smooth_ring(std::uint32_t(v), fan, d, same_group))) {
        groups[v] = 1;
        continue;
      }
      std::uint32_t* parent = scratch.parent(d);
      if (d <= kSmallFan) {
        const bool ring = d <= kRingFan ? (cone ? link_fan16(std::uint32_t(v), fan, d, same_group, parent)
                                                : link_fan16(std::uint32_t(v), fan, d, smooth, parent))
                                        : (cone ? link_small_fan(std::uint32_t(v), fan, d, same_group, parent)
                                                : link_small_fan(std::uint32_t(v), fan, d, smooth, parent));
        if (ring) {  // one group, no degenerate face
          groups[v] = 1;
          continue;
        }
      } else if (cone) {
        link_large_fan(std::uint32_t(v), fan, d, same_group, parent, scratch.ends);
      } else {
        link_large_fan(std::uint32_t(v), fan, d, smooth, parent, scratch.ends);
      }
      // Number groups by first corner; degenerate-face corners share the vertex's only group
      // when it has one, else get a group of their own (numbered last).
      std::uint32_t* number = scratch.number(d);
      std::uint32_t g = 0;
      bool any_degenerate = false;
      for (std::uint32_t i = 0; i < d; ++i) {
        if (!cone && !face_valid(fan[i].face)) { any_degenerate = true; continue; }
        const std::uint32_t r = union_find_root(parent, i);
        if (number[r] == ~0u) number[r] = g++;
        out.corner_index[fan[i].corner] = number[r];
      }
      if (any_degenerate) {
        std::uint32_t dg = 0;
        if (g != 1) { dg = g++; has_degenerate_group[v] = 1; }
        for (std::uint32_t i = 0; i < d; ++i)
          if (!face_valid(fan[i].face)) out.corner_index[fan[i].corner] = dg;
      }
      groups[v] = g;
    }
  });

  // (4) pool rows: vertex v owns rows base[v] .. base[v] + groups[v].
  std::vector<std::uint32_t> base(V + 1, 0);
  for (std::size_t v = 0; v < V; ++v) base[v + 1] = base[v] + groups[v];
  const std::size_t N = base[V];
  parallel_ranges(C, [&](std::size_t b, std::size_t e) {
    for (std::size_t c = b; c < e; ++c) out.corner_index[c] += base[mesh.corner_vertex[c]];
  });

  // (5) sums: in the output array itself in double, else in a float accumulator.
  std::vector<float> float_sum;
  out.degenerate_faces = sum_rows<T, W>(mesh, out.corner_index.data(), N, out.normals, float_sum);
  T* sum;
  if constexpr (std::is_same_v<T, double>) sum = out.normals.data();
  else sum = float_sum.data();
  // A group made only of degenerate corners takes the vertex's smooth sum: all its valid
  // contributions, i.e. the sum of its other groups.
  parallel_ranges(V, [&](std::size_t v_begin, std::size_t v_end) {
    for (std::size_t v = v_begin; v < v_end; ++v) {
      if (!has_degenerate_group[v]) continue;
      const std::size_t dg = base[v + 1] - 1;
      for (std::size_t r = base[v]; r < dg; ++r)
        for (int k = 0; k < 3; ++k) sum[3 * dg + k] += sum[3 * r + k];
    }
  });

  // (6) normalise rows; a row that cannot be normalised takes the normal of the first valid face
  // among its corners, else of the vertex, else (0, 0, 1) (kFallbackNormal).
  std::vector<std::size_t> fallback_corners(grouped, 0);
  parallel_ranges(grouped, [&](std::size_t v_begin, std::size_t v_end) {
    for (std::size_t v = v_begin; v < v_end; ++v) {
      for (std::uint32_t r = base[v]; r < base[v + 1]; ++r) {
        double* o = &out.normals[3 * std::size_t(r)];
        if (normalise_sum(double(sum[3 * std::size_t(r)]), double(sum[3 * std::size_t(r) + 1]),
                          double(sum[3 * std::size_t(r) + 2]), o))
          continue;
        std::uint32_t in_group = ~0u, any = ~0u;
        std::size_t corners_in_row = 0;
        for (std::uint32_t i = vf.offset[v]; i < vf.offset[v + 1]; ++i) {
          const std::uint32_t c = vf.fan[i].corner, f = vf.fan[i].face;
          const bool mine = out.corner_index[c] == r;
          corners_in_row += mine;
          if (face_valid(f)) {
            if (any == ~0u) any = f;
            if (mine && in_group == ~0u) in_group = f;
          }
        }
        const std::uint32_t f = in_group != ~0u ? in_group : any;
        for (int k = 0; k < 3; ++k) o[k] = f != ~0u ? fn[3 * std::size_t(f) + k] : kFallbackNormal[k];
        fallback_corners[v] += corners_in_row;
      }
    }
  });
  for (std::size_t v = 0; v < grouped; ++v) out.fallback_corners += fallback_corners[v];
  if (base_out) base_out->swap(base);
  return out;
}

// The one-thread path (triangle meshes without smoothing groups, Angle or Uniform weighting):
// the same results as compute, bit for bit, with no vertex-major gathering for the vertices that
// are one smooth group (most vertices of a smooth mesh). Steps:
// (1) add_faces_to_slots (engine/vertex_slots.h): one pass in face order gives every vertex its
//     contribution sum S (ascending corner order: compute's group sum), the sum U of its unit face
//     normals, its corner count d and up to kSlotPairs (next, prev) pairs;
// (2) in vertex order, a vertex is easy when every face at it was taken by the vector pass (valid:
//     U is not NaN), SmoothCone passes on U (no crease can split it), d <= kSlotPairs and its pairs form one closed
//     ring (one_smooth_ring; smooth_rings8, the same verdicts for 8 vertices at once, where the CPU
//     has AVX2), and S normalises: compute would find exactly one group for it, whose
//     row is S normalised (the same sum, the same normalise_sum). Every other vertex with corners is
//     hard. Each vertex with corners takes one provisional row, in vertex order;
// (3) the faces with a hard corner, in ascending order, are a sub-mesh (its vertices renumbered,
//     the hard ones first in ascending order) that compute groups: every face of a hard vertex is
//     in it, in the same order, so the vertex's fan, groups, group sums and fallbacks are those of
//     compute on the whole mesh (nothing else is read: Angle and Uniform contributions have no
//     per-mesh scale, corner_contributions.h);
// (4) each hard vertex's rows replace its provisional row (the pool widened where it has several
//     groups), and one pass in corner order writes corner_index.
// Returns false (out untouched) where SmoothCone cannot pass any vertex (crease angles below ~0.6
// degrees, negative or NaN) or the corner count reaches 2^31, and, when `choose`, on meshes of fewer
// than kOneThreadMinFaces faces, where the probe
// (worth_one_thread_path) predicts too many hard vertices or more than kHardShare of the vertices
// turn out hard after (2): compute alone is faster there (bench/normals/results/notes.md, fifth
// round). Whichever path runs, the results are the same bits.
constexpr std::uint32_t kHardBit = 0x80000000u;
constexpr double kHardShare = 0.5;
// Below this many faces the general path is as fast or faster (its arrays stay in cache; measured
// on the irregular sphere and the faceted icosahedron: 0.9x at 20k faces, 1.1-1.15x at 60-80k).
constexpr std::size_t kOneThreadMinFaces = 50000;

// Whether the one-thread path is likely to pay: kProbeWindows windows of kProbeFaces faces or
// F / kProbeShare, whichever is more, spread over the mesh, each copied out as a small mesh of its
// own (vertices renumbered through a hash table: no array of #V is touched) and put through pass 1
// (add_faces_to_slots); then each of its vertices is classified: hard for certain when a face at it
// was not taken by the vector pass, it has more than kSlotPairs corners, or it fails SmoothCone
// (adding faces cannot make the spread d - |U| smaller: it is a minimum over directions of a sum of
// non-negative terms; the test's margins grow with d); easy when its corners seen form one closed ring; else not counted (its fan
// may continue outside the window). Worth it when the hard share among the counted vertices is at
// most kProbeHardShare (measured: bench/normals/results/notes.md, fifth round; the window size:
// seventh round, the same verdicts at F / 512), or when too few
// vertices could be counted to tell; the probe stops after a window where enough vertices were
// counted and the hard share already exceeds twice that. The estimate leans towards hard (a window cuts fans open, and
// only closed ones count as easy); it only chooses between two paths that give the same bits.
constexpr std::size_t kProbeWindows = 8, kProbeFaces = 256, kProbeShare = 4096, kProbeMinCounted = 32;
constexpr double kProbeHardShare = 0.05;

template <class T>
bool worth_one_thread_path(const MeshView& mesh, const SmoothCone& cone) {
  const std::size_t F = mesh.num_faces();
  const std::size_t window = std::max(kProbeFaces, F / kProbeShare);
  if (F < 2 * kProbeWindows * window) return true;
  std::size_t table = 1;
  while (table < 6 * window) table <<= 1;  // load <= 1/2
  std::vector<std::uint32_t> key(table), id(table), local_cv(3 * window);
  std::vector<double> local_positions;
  local_positions.reserve(9 * window);
  BulkVector<VertexSlot<T>> slots(3 * window + 1);
  std::size_t hard = 0, easy = 0;
  for (std::size_t k = 0; k < kProbeWindows; ++k) {
    const std::size_t f_begin = (2 * k + 1) * F / (2 * kProbeWindows);
    std::fill(key.begin(), key.end(), ~0u);
    local_positions.clear();
    std::uint32_t n = 0;
    for (std::size_t i = 0; i < 3 * window; ++i) {
      const std::uint32_t v = mesh.corner_vertex[3 * f_begin + i];
      std::size_t h = (std::size_t(v) * 0x9E3779B1u) & (table - 1);
      while (key[h] != ~0u && key[h] != v) h = (h + 1) & (table - 1);
      if (key[h] == ~0u) {
        key[h] = v;
        id[h] = n++;
        local_positions.insert(local_positions.end(), mesh.positions + 3 * std::size_t(v), mesh.positions + 3 * std::size_t(v) + 3);
      }
      local_cv[i] = id[h];
    }
    const MeshView part = MeshView::triangles(local_positions.data(), n, local_cv.data(), window);
    clear_vertex_slots(slots.data(), std::size_t(n) + 1);
    add_faces_to_slots<T, Weighting::Angle>(part, 0, window, slots.data());
    for (std::uint32_t v = 0; v < n; ++v) {
      const VertexSlot<T>& sl = slots[v];
      if (sl.d > kSlotPairs || !cone.passes(sl.d, sl.u[0], sl.u[1], sl.u[2])) ++hard;
      else if (one_smooth_ring(v, sl)) ++easy;
    }
    // Clearly not worth it (twice the limit): stop here (a CAD part stops after its first window).
    if (hard + easy >= kProbeMinCounted && double(hard) > 2.0 * kProbeHardShare * double(hard + easy)) return false;
  }
  return hard + easy < kProbeMinCounted || double(hard) <= kProbeHardShare * double(hard + easy);
}

template <class T, Weighting W>
bool compute_one_thread(const MeshView& mesh, double crease_angle, Precision precision, bool choose, CornerNormals& out) {
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners(), F = mesh.num_faces();
  const SmoothCone cone(crease_angle);
  if (!cone.usable || C >= kHardBit) return false;
  if (choose && (F < kOneThreadMinFaces || !worth_one_thread_path<T>(mesh, cone))) return false;
  const std::uint32_t* cv = mesh.corner_vertex;
  // (1)
  BulkVector<VertexSlot<T>> slots(V + 1);  // +1: padding read by one_smooth_ring
  clear_vertex_slots(slots.data(), V + 1);
  const std::size_t degenerate = add_faces_to_slots<T, W>(mesh, 0, F, slots.data());
  // (2) row[v]: provisional row of an easy vertex; kHardBit | h for the h-th hard vertex.
  BulkVector<std::uint32_t> row(V);
  std::vector<std::uint32_t> hard, hard_row;
  // The pool becomes out.normals: room for the hard vertices' extra rows reserved (address space;
  // a pool that needs more grows once, in (4)).
  std::vector<double> pool;
  reserve_bulk(pool, 3 * (V + V / 16 + 16));
  pool.resize(3 * V);
  std::vector<std::uint64_t> hard_bit((V + 63) / 64, 0);  // the gather in (3) reads this, not row
  std::uint32_t used = 0;
  // The ring test, 8 vertices at a time where the CPU has AVX2 (smooth_rings8, the same verdicts),
  // computed for a block of 8 when the first of its vertices needs it (most vertices of a CAD part
  // fail the cone first, so most of its blocks are never computed).
#if defined(SHADETOOL_SLOT_RING_LANES)
  const bool lanes = slot_ring_lanes_available();
  std::uint32_t block = 0, block_of = ~0u;
#endif
  auto ring = [&](std::uint32_t v, const VertexSlot<T>& sl) {
#if defined(SHADETOOL_SLOT_RING_LANES)
    const std::uint32_t b = v & ~7u;
    if (lanes && std::size_t(b) + 8 <= V) {
      if (block_of != b) {
        block = smooth_rings8(b, &slots[b]);
        block_of = b;
      }
      return ((block >> (v & 7u)) & 1u) != 0;
    }
#endif
    return one_smooth_ring(v, sl);
  };
  for (std::uint32_t v = 0; v < V; ++v) {
    const VertexSlot<T>& sl = slots[v];
    row[v] = used;
    if (sl.d == 0) continue;  // no corner: no row
    double* o = &pool[3 * std::size_t(used)];
    const bool easy = sl.d <= kSlotPairs && cone.passes(sl.d, sl.u[0], sl.u[1], sl.u[2]) && ring(v, sl) &&
                      normalise_sum(double(sl.s[0]), double(sl.s[1]), double(sl.s[2]), o);
    if (!easy) {
      row[v] = kHardBit | std::uint32_t(hard.size());
      hard.push_back(v);
      hard_row.push_back(used);
      hard_bit[v >> 6] |= std::uint64_t(1) << (v & 63);
    }
    ++used;
  }
  if (choose && double(hard.size()) > kHardShare * double(used)) return false;
  slots = BulkVector<VertexSlot<T>>();
  // (3) the sub-mesh of the faces around hard vertices, computed by the general path.
  const std::uint32_t H = std::uint32_t(hard.size());
  std::vector<std::uint32_t> sub_faces, sub_cv, sub_base;
  CornerNormals sub;
  if (H) {
    std::vector<std::uint32_t> local(V, ~0u), sub_vertex(hard);
    for (std::uint32_t h = 0; h < H; ++h) local[hard[h]] = h;
    for (std::size_t f = 0; f < F; ++f) {
      const std::uint32_t* c = cv + 3 * f;
      auto is_hard = [&](std::uint32_t v) { return (hard_bit[v >> 6] >> (v & 63)) & 1u; };
      if (!(is_hard(c[0]) | is_hard(c[1]) | is_hard(c[2]))) continue;
      sub_faces.push_back(std::uint32_t(f));
      for (int k = 0; k < 3; ++k) {
        std::uint32_t& l = local[c[k]];
        if (l == ~0u) {
          l = std::uint32_t(sub_vertex.size());
          sub_vertex.push_back(c[k]);
        }
        sub_cv.push_back(l);
      }
    }
    std::vector<double> sub_positions(3 * sub_vertex.size());
    for (std::size_t l = 0; l < sub_vertex.size(); ++l)
      for (int k = 0; k < 3; ++k) sub_positions[3 * l + k] = mesh.positions[3 * std::size_t(sub_vertex[l]) + k];
    const MeshView sub_mesh =
        MeshView::triangles(sub_positions.data(), sub_vertex.size(), sub_cv.data(), sub_faces.size());
    sub = compute<T, W>(sub_mesh, crease_angle, precision, nullptr, &sub_base, H);
  }
  // (4) rows: hard vertex h's groups at final row first[h] (its provisional row shifted by the extra
  // rows of the hard vertices before it), easy rows shifted likewise.
  std::size_t extra = 0;
  for (std::uint32_t h = 0; h < H; ++h) extra += sub_base[h + 1] - sub_base[h] - 1;  // >= 1 group each
  const std::size_t N = used + extra;
  std::vector<std::uint32_t> delta(H);  // final row - sub-mesh row, mod 2^32
  // In place, from the last hard vertex back: the easy rows after hard vertex h move up by the
  // extra rows of hard vertices 0 .. h, and h's groups take its provisional row and the gap.
  pool.resize(3 * N);
  std::size_t shift = extra, end = used;  // provisional rows (hard_row[h], end) are easy
  for (std::uint32_t h = H; h-- > 0;) {
    const std::size_t r = hard_row[h], g = sub_base[h + 1] - sub_base[h];
    if (shift != 0 && end > r + 1)
      std::memmove(&pool[3 * (r + 1 + shift)], &pool[3 * (r + 1)], 3 * (end - r - 1) * sizeof(double));
    shift -= g - 1;
    std::copy_n(&sub.normals[3 * std::size_t(sub_base[h])], 3 * g, &pool[3 * (r + shift)]);
    delta[h] = std::uint32_t(r + shift) - sub_base[h];
    end = r;
  }
  out.normals.swap(pool);
  if (extra != 0) {
    shift = 0;
    for (std::uint32_t v = 0; v < V; ++v) {
      const std::uint32_t r = row[v];
      if (r & kHardBit) shift += sub_base[(r & ~kHardBit) + 1] - sub_base[r & ~kHardBit] - 1;
      else row[v] = std::uint32_t(r + shift);
    }
  }
  reserve_bulk(out.corner_index, C);
  out.corner_index.resize(C);
  std::uint32_t* ci = out.corner_index.data();
  std::size_t p = 0, next_sub = sub_faces.empty() ? F : sub_faces[0];
  for (std::size_t f = 0; f < F; ++f) {
    const std::size_t c = 3 * f;
    if (f != next_sub) {
      ci[c] = row[cv[c]]; ci[c + 1] = row[cv[c + 1]]; ci[c + 2] = row[cv[c + 2]];
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t r = row[cv[c + k]];
      ci[c + k] = (r & kHardBit) ? sub.corner_index[3 * p + k] + delta[r & ~kHardBit] : r;
    }
    ++p;
    next_sub = p < sub_faces.size() ? sub_faces[p] : F;
  }
  out.fallback_corners = sub.fallback_corners;
  out.degenerate_faces = degenerate;
  return true;
}

}  // namespace

GroupNormals corner_group_normals(const Mesh& mesh, const std::vector<std::uint32_t>& corner_group,
                                  std::size_t num_groups, Weighting weighting, Precision precision) {
  if (corner_group.size() != mesh.num_corners())
    throw Error("corner_group_normals: the group array's size differs from the corner count");
  if (num_groups >= kNoGroup) throw Error("corner_group_normals: too many groups");
  for (std::uint32_t g : corner_group)
    if (g != kNoGroup && g >= num_groups) throw Error("corner_group_normals: a corner's group is out of range");
  std::vector<double> storage;  // exactly scaled positions for a mesh outside the kernels' range (engine/mesh_scale.h)
  const MeshView in_range = in_kernel_range(mesh, storage);
  return dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    return group_normals<T, W>(in_range, corner_group, num_groups);
  });
}

namespace {

CornerNormals corner_normals_in_groups(const MeshView& mesh, double crease_angle, Weighting weighting,
                                       Precision precision, const std::uint32_t* face_group,
                                       normals_detail::CreasePath path = normals_detail::CreasePath::Auto) {
  using normals_detail::CreasePath;
  std::vector<double> storage;  // exactly scaled positions for a mesh outside the kernels' range (engine/mesh_scale.h)
  const MeshView in_range = in_kernel_range(mesh, storage);
  return dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    if constexpr (W == Weighting::Angle || W == Weighting::Uniform) {
      const bool one_thread = path == CreasePath::OneThread || (path == CreasePath::Auto && usable_threads() == 1);
      if (one_thread && !face_group && in_range.all_triangles()) {
        CornerNormals out;
        if (compute_one_thread<T, W>(in_range, crease_angle, precision, path == CreasePath::Auto, out)) return out;
      }
    }
    return compute<T, W>(in_range, crease_angle, precision, face_group);
  });
}

}  // namespace

namespace normals_detail {

CornerNormals corner_normals_by(const MeshView& mesh, double crease_angle, Weighting weighting, Precision precision,
                                CreasePath path) {
  return corner_normals_in_groups(mesh, crease_angle, weighting, precision, nullptr, path);
}

}  // namespace normals_detail

CornerNormals corner_normals(const MeshView& mesh, double crease_angle, Weighting weighting, Precision precision) {
  return corner_normals_in_groups(mesh, crease_angle, weighting, precision, nullptr);
}

CornerNormals corner_normals(const Mesh& mesh, double crease_angle, const std::vector<std::uint32_t>& face_group,
                             Weighting weighting, Precision precision) {
  if (face_group.size() != mesh.num_faces())
    throw Error("corner_normals: the smoothing group array's size differs from the face count");
  return corner_normals_in_groups(MeshView(mesh), crease_angle, weighting, precision, face_group.data());
}

// A Mesh is computed through its view: one code path.
CornerNormals corner_normals(const Mesh& mesh, double crease_angle, Weighting weighting, Precision precision) {
  return corner_normals(MeshView(mesh), crease_angle, weighting, precision);
}

}  // namespace shadetool
