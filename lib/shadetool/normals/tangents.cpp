// tangents.cpp: see tangents.h. The steps are numbered as there; each is a function named after
// what it does. Arithmetic is float in the reference's order (tangents.h, Precision).
#include <shadetool/normals/tangents.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <numeric>

#include <shadetool/core/error.h>
#include <shadetool/core/shading_normals.h>
#include <shadetool/geometry/polygon_triangles.h>
#include <shadetool/normals/engine/tangent_corner_terms.h>

namespace shadetool {
namespace {

struct F3 {
  float x = 0, y = 0, z = 0;
};
F3 operator+(F3 a, F3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
F3 operator-(F3 a, F3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
F3 scale(float s, F3 v) { return {s * v.x, s * v.y, s * v.z}; }
float dot(F3 a, F3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float length(F3 v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
bool operator==(F3 a, F3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
// The reference's zero test: |x| > FLT_MIN.
bool not_zero(float x) { return std::fabs(x) > FLT_MIN; }
bool not_zero(F3 v) { return not_zero(v.x) || not_zero(v.y) || not_zero(v.z); }
// Called where not_zero(v) holds (as the reference); a length that still underflows leaves v as it
// is (the reference would divide by zero there).
F3 normalize(F3 v) {
  const float len = length(v);
  return len > 0.0f ? scale(1.0f / len, v) : v;  // divisor checked
}

// Triangle flags, as the reference's.
constexpr std::uint8_t kDegenerate = 1, kQuadOneDegenerate = 2, kGroupWithAny = 4, kOrientPreserving = 8;
// Corner k of the triangle is in a group (step 6): bit kGrouped << k.
constexpr std::uint8_t kGrouped = 16, kGroupedAny = 16 | 32 | 64;

// The algorithm's view of the mesh: float copies of the values corners refer to (positions,
// normals, texture coordinates: each converted once), and per corner the index of each.
struct Corners {
  std::vector<F3> positions, normals, texcoords;  // texcoords: z = 1, unused
  const std::uint32_t *vertex = nullptr, *normal = nullptr, *texcoord = nullptr;  // #C each
  std::size_t num_corners = 0;
  F3 position(std::uint32_t c) const { return positions[vertex[c]]; }
  F3 normal_of(std::uint32_t c) const { return normals[normal[c]]; }
  F3 texcoord_of(std::uint32_t c) const { return texcoords[texcoord[c]]; }
};

struct Triangles {
  std::size_t count = 0;              // triangles
  // Triangle t is face t, with corners 3 t + k (every face a taken triangle, none moved): corner
  // and face are then left empty and corner_of, face_of give those numbers.
  bool identity = false;
  std::vector<std::uint32_t> corner;  // 3 per triangle: the global corner (the output slot)
  std::vector<std::uint32_t> index;   // 3 per triangle: the welded vertex (step 2's dense number)
  std::vector<std::uint32_t> face;    // the mesh face it came from
  std::vector<std::uint8_t> flag;
  std::uint32_t corner_of(std::size_t slot) const { return identity ? std::uint32_t(slot) : corner[slot]; }
  std::uint32_t face_of(std::size_t t) const { return identity ? std::uint32_t(t) : face[t]; }
  std::size_t good = 0;               // triangles [0, good) are healthy, in order; the rest degenerate
  // Per corner slot 3 t + k of a healthy triangle: the triangle across its edge k (corner k to
  // k + 1), -1 where none.
  std::vector<std::int32_t> neighbour;
};

struct TriInfo {
  F3 os, ot;  // unit derivatives (or zero)
  float mag_s = 0, mag_t = 0;
};

// Scratch arrays are plain heap blocks (new T[n]: members without initialisers stay unwritten),
// never advised as huge pages: a fresh huge page costs its first toucher either next to nothing or
// far more than the 512 small pages it replaces, depending on whether the hypervisor still backs
// that memory, so a call's time depended on the machine's history (bench/normals/results/
// tangents_steps.md, "Bimodality"). Small pages cost the same every time.
using TriInfos = std::unique_ptr<TriInfo[]>;  // per healthy triangle

struct Group {
  std::uint32_t representative;  // the welded vertex
  bool orient;
  std::uint32_t offset, count;  // its corners: members[offset, offset + count), slots 3 t + k (corner k of triangle t)
};

struct TSpace {
  F3 os{1, 0, 0}, ot{0, 1, 0};
  float mag_s = 1, mag_t = 1;
  bool orient = false;
};

// Step 1: triangles of the faces the algorithm takes (every corner textured, 3+ corners), with
// their corners' welded vertices (`welded`: step 2's, per corner). `welded` null: every face is a
// taken triangle, so triangle t is face t with corners 3 t + k (tris.identity), and step 2 wrote
// tris.index (#C) itself.
void make_triangles(const Mesh& mesh, const Corners& in, const std::vector<std::uint8_t>& taken,
                    const std::uint32_t* welded, Triangles& tris) {
  if (!welded) {
    tris.identity = true;
    tris.count = mesh.num_faces();
    tris.flag.assign(tris.count, 0);
    return;
  }
  std::size_t count = 0;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) count += taken[f] ? mesh.face_size(f) - 2 : 0;
  tris.corner.reserve(3 * count);
  tris.index.reserve(3 * count);
  tris.face.reserve(count);
  auto add = [&](std::uint32_t f, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    tris.corner.push_back(a), tris.corner.push_back(b), tris.corner.push_back(c);
    tris.index.push_back(welded[a]), tris.index.push_back(welded[b]), tris.index.push_back(welded[c]);
    tris.face.push_back(f);
  };
  std::vector<std::uint32_t> split;  // a 5+-gon's triangles as corner positions, reused
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (!taken[f]) continue;
    const std::uint32_t b = mesh.face_start[f], n = mesh.face_start[f + 1] - b;
    const auto fu = std::uint32_t(f);
    if (n == 3) {
      add(fu, b, b + 1, b + 2);
    } else if (n == 4) {
      // The shorter diagonal in texture space; tied: in space; still tied: 0-2.
      auto dist2 = [](F3 a, F3 c) { const F3 d = c - a; return d.x * d.x + d.y * d.y + d.z * d.z; };
      const float t02 = dist2(in.texcoord_of(b), in.texcoord_of(b + 2)), t13 = dist2(in.texcoord_of(b + 1), in.texcoord_of(b + 3));
      bool diagonal_02;
      if (t02 < t13) diagonal_02 = true;
      else if (t13 < t02) diagonal_02 = false;
      else diagonal_02 = !(dist2(in.position(b + 1), in.position(b + 3)) < dist2(in.position(b), in.position(b + 2)));
      if (diagonal_02) { add(fu, b, b + 1, b + 2); add(fu, b, b + 2, b + 3); }
      else { add(fu, b, b + 1, b + 3); add(fu, b + 1, b + 2, b + 3); }
    } else {
      // Not in the reference: geometry/polygon_triangles.h, inside the outline, as render draws
      // the polygon and the glTF writer writes it (a convex polygon: the fan from corner 0).
      split.clear();
      polygon_triangles(mesh.positions.data(), mesh.corner_vertex.data() + b, n, split);
      for (std::size_t t = 0; t + 2 < split.size(); t += 3) add(fu, b + split[t], b + split[t + 1], b + split[t + 2]);
    }
  }
  tris.count = tris.face.size();
  tris.flag.assign(tris.count, 0);
}

// Step 2: welded vertex of every corner taken: corners with the same (position, normal, texture
// coordinate) as float == are one vertex (-0 equals +0; a value with a NaN equals nothing),
// numbered densely in the order of their first corners. From the mesh's own indices: each position
// value gets a canonical vertex (the first vertex with that value, by an open-addressing table over
// the vertices, not the corners); the corners, in order, look for their values among the welded
// vertices already found at their canonical vertex (a short list; one with more than kLinear
// welded vertices moves them to a table keyed by all eight values); a corner with the same vertex,
// normal and texture-coordinate indices as its vertex's latest corner takes that one's directly.
struct WeldedVertex {
  F3 p, n;
  float u = 0, v = 0;
};
bool same_values(const WeldedVertex& a, const WeldedVertex& b) {  // float ==: -0 == +0, NaN never
  return (a.p.x == b.p.x) & (a.p.y == b.p.y) & (a.p.z == b.p.z) & (a.n.x == b.n.x) & (a.n.y == b.n.y) &
         (a.n.z == b.n.z) & (a.u == b.u) & (a.v == b.v);  // no short cut: one branch, not eight
}
bool has_nan(const WeldedVertex& a) { return !same_values(a, a); }
std::uint32_t float_bits(float x) {
  x += 0.0f;  // -0 + 0 = +0
  std::uint32_t b;
  std::memcpy(&b, &x, 4);
  return b;
}
std::uint64_t hash_floats(const float* x, int n) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < n; ++i) {
    h = (h ^ float_bits(x[i])) * 0xff51afd7ed558ccdull;
    h ^= h >> 32;
  }
  return h;
}

// The first vertex with each vertex's position (itself when the position has a NaN).
std::vector<std::uint32_t> canonical_positions(const std::vector<F3>& positions) {
  const std::size_t V = positions.size();
  std::vector<std::uint32_t> first(V);
  std::size_t cap = 16;
  while (cap < 2 * V) cap *= 2;
  std::vector<std::uint32_t> table(cap, ~0u);
  // The table is larger than the caches and its slots random: the slot of the vertex kAhead
  // places ahead is hashed and prefetched meanwhile.
  constexpr std::size_t kAhead = 8;
  auto slot_of = [&](std::size_t v) {
    const float x[3] = {positions[v].x, positions[v].y, positions[v].z};
    return hash_floats(x, 3) & (cap - 1);
  };
  std::size_t ahead[kAhead];
  for (std::size_t v = 0; v < kAhead && v < V; ++v) ahead[v] = slot_of(v);
  for (std::size_t v = 0; v < V; ++v) {
    const F3 p = positions[v];
    const std::size_t first_slot = ahead[v % kAhead];
    if (v + kAhead < V) {
      ahead[v % kAhead] = slot_of(v + kAhead);
      __builtin_prefetch(&table[ahead[v % kAhead]]);
    }
    first[v] = std::uint32_t(v);
    if (!(p == p)) continue;  // a NaN
    for (std::size_t slot = first_slot;; slot = (slot + 1) & (cap - 1)) {
      if (table[slot] == ~0u) { table[slot] = std::uint32_t(v); break; }
      if (positions[table[slot]] == p) { first[v] = table[slot]; break; }
    }
  }
  return first;
}

// The welded vertices' values (#U), returned; id (#C): the welded vertex of each corner taken,
// written (left unwritten elsewhere).
std::vector<WeldedVertex> weld(const Mesh& mesh, const Corners& in, const std::vector<std::uint8_t>& taken,
                               bool every_face_taken, std::uint32_t* id) {
  const std::size_t V = in.positions.size(), F = mesh.num_faces();
  const std::vector<std::uint32_t> first = canonical_positions(in.positions);
  struct {
    std::uint32_t* id;
    std::vector<WeldedVertex> vertex;
  } w{id, {}};
  w.vertex.reserve(V + V / 4);
  constexpr std::uint32_t kLinear = 16, kNone = ~0u;
  std::vector<std::uint32_t> head(V, kNone);   // canonical vertex -> its latest welded vertex
  std::vector<std::uint32_t> count(V, 0);      // how many welded vertices it has
  std::vector<std::uint32_t> next;             // welded vertex -> the previous one at its position
  next.reserve(V + V / 4);
  // The table for positions with more than kLinear welded vertices: (all values) -> welded vertex.
  std::vector<std::uint32_t> table;
  auto table_slot = [&](const WeldedVertex& x) {
    const float k[8] = {x.p.x, x.p.y, x.p.z, x.n.x, x.n.y, x.n.z, x.u, x.v};
    std::size_t slot = hash_floats(k, 8) & (table.size() - 1);
    while (table[slot] != kNone && !same_values(w.vertex[table[slot]], x)) slot = (slot + 1) & (table.size() - 1);
    return slot;
  };
  auto grow_table = [&](std::size_t at_least) {
    std::size_t cap = 1024;
    while (cap < 2 * at_least) cap *= 2;
    table.assign(cap, kNone);
    std::size_t in_table = 0;
    for (std::size_t b = 0; b < V; ++b)
      if (count[b] > kLinear)
        for (std::uint32_t k = head[b]; k != kNone; k = next[k]) table[table_slot(w.vertex[k])] = k, ++in_table;
    return in_table;
  };
  std::size_t in_table = 0;
  const F3 *positions = in.positions.data(), *normals = in.normals.data(), *texcoords = in.texcoords.data();
  // Per vertex, the indices (normal, texture coordinate) of its latest corner and that corner's
  // welded vertex: a corner with the same three indices has the same values, so the same welded
  // vertex, found without reading or comparing them (most corners of an indexed mesh). Values with
  // a NaN equal nothing, not even themselves: never recorded.
  struct Recent {
    std::uint32_t normal, texcoord, welded;
  };
  std::vector<Recent> recent(V, Recent{kNone, kNone, kNone});
  // Corner c's welded vertex when it is its vertex's latest corner's (true), else false.
  auto weld_as_recent = [&](std::uint32_t c) {
    const Recent& r = recent[in.vertex[c]];
    if (r.welded == kNone || r.normal != in.normal[c] || r.texcoord != in.texcoord[c]) return false;
    w.id[c] = r.welded;
    return true;
  };
  // The other corners: their values looked for, a new welded vertex when none has them.
  auto weld_by_value = [&](std::uint32_t c) {
    Recent& r = recent[in.vertex[c]];
    const F3 t = texcoords[in.texcoord[c]];
    const WeldedVertex x{positions[in.vertex[c]], normals[in.normal[c]], t.x, t.y};
    const std::uint32_t b = first[in.vertex[c]];
    std::uint32_t k = kNone;
    if (count[b] <= kLinear) {
      k = head[b];
      while (k != kNone && !same_values(w.vertex[k], x)) k = next[k];
    } else if (!has_nan(x)) {
      k = table[table_slot(x)];
    }
    if (k == kNone) {  // a new welded vertex
      k = std::uint32_t(w.vertex.size());
      w.vertex.push_back(x);
      next.push_back(head[b]);
      head[b] = k;
      if (++count[b] == kLinear + 1) in_table = grow_table(in_table + kLinear + 1);  // this position's move in
      else if (count[b] > kLinear && !has_nan(x)) {
        if (2 * (++in_table) > table.size()) in_table = grow_table(in_table);
        else table[table_slot(x)] = k;
      }
    }
    w.id[c] = k;
    if (!has_nan(x)) r = {in.normal[c], in.texcoord[c], k};
  };
  // Corners in face order; when every face is taken that is 0 .. #C - 1 (faces' corners are
  // consecutive), one flat loop.
  if (every_face_taken) {
    for (std::uint32_t c = mesh.face_start.front(); c < mesh.face_start.back(); ++c)
      if (!weld_as_recent(c)) weld_by_value(c);
  } else {
    for (std::size_t f = 0; f < F; ++f)
      if (taken[f])
        for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
          if (!weld_as_recent(c)) weld_by_value(c);
  }
  return std::move(w.vertex);
}

float texture_area(const std::vector<WeldedVertex>& wv, const std::uint32_t* idx) {
  const WeldedVertex &t1 = wv[idx[0]], &t2 = wv[idx[1]], &t3 = wv[idx[2]];
  const float a = (t2.u - t1.u) * (t3.v - t1.v) - (t2.v - t1.v) * (t3.u - t1.u);
  return a < 0 ? -a : a;
}

// Step 4's inputs for one healthy triangle (corners w1, w2, w3): its derivatives before
// normalisation (eq. 18, 19) and twice its signed texture area, written to column i of `in` (the
// rows of normals_detail::tangent_triangle_derivatives, which makes them unit and computes the
// magnitudes); its flags: orientation, and assumed to group with any (cleared when both
// magnitudes are not zero).
void triangle_derivative_inputs(const WeldedVertex& w1, const WeldedVertex& w2, const WeldedVertex& w3,
                                std::uint8_t& flag, float* in, std::size_t i) {
  constexpr std::size_t B = normals_detail::kTangentCornerBlock;
  const F3 v1 = w1.p, v2 = w2.p, v3 = w3.p;
  const float t21x = w2.u - w1.u, t21y = w2.v - w1.v, t31x = w3.u - w1.u, t31y = w3.v - w1.v;
  const F3 d1 = v2 - v1, d2 = v3 - v1;
  const float signed_area2 = t21x * t31y - t21y * t31x;
  const F3 os = scale(t31y, d1) - scale(t21y, d2);   // eq. 18
  const F3 ot = scale(-t31x, d1) + scale(t21x, d2);  // eq. 19
  flag |= kGroupWithAny;
  if (signed_area2 > 0) flag |= kOrientPreserving;
  const float values[7] = {os.x, os.y, os.z, ot.x, ot.y, ot.z, signed_area2};
  for (int row = 0; row < 7; ++row) in[row * B + i] = values[row];
}

// Steps 3 and 4 in one pass over the triangles (each reads its three corners once): a degenerate
// triangle (two equal positions) is marked, every other one gets its derivatives (info, #T, written
// whole: zero for a degenerate triangle), a block of triangles at a time. Then, when there are degenerate triangles, a quad with exactly one of them is marked and
// the degenerate ones are moved after the healthy ones (which keep their order, their info with
// them); last, a quad whose two healthy triangles disagree in orientation takes the larger one's
// (or the healthy one's when the other groups with any).
void degenerate_and_derivatives(const Mesh& mesh, const std::vector<WeldedVertex>& wv, Triangles& tris, TriInfos& info) {
  const std::size_t T = tris.count;
  std::size_t degenerate = 0;
  // Blocks of B triangles: inputs gathered, then made unit (tangent_triangle_derivatives, lane-wise),
  // then stored; a degenerate triangle's column is zero (its outputs zero, as its info was).
  constexpr std::size_t B = normals_detail::kTangentCornerBlock;
  float in[7 * B], out[8 * B];
  for (std::size_t t0 = 0; t0 < T; t0 += B) {
    const std::size_t n = std::min(B, T - t0);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t t = t0 + i;
      const std::uint32_t* idx = &tris.index[3 * t];
      const WeldedVertex &w1 = wv[idx[0]], &w2 = wv[idx[1]], &w3 = wv[idx[2]];
      if (w1.p == w2.p || w1.p == w3.p || w2.p == w3.p) {
        tris.flag[t] |= kDegenerate, ++degenerate;
        for (int row = 0; row < 7; ++row) in[row * B + i] = 0.0f;
        continue;
      }
      triangle_derivative_inputs(w1, w2, w3, tris.flag[t], in, i);
    }
    normals_detail::tangent_triangle_derivatives(n, in, out);
    for (std::size_t i = 0; i < n; ++i) {
      TriInfo& r = info[t0 + i];
      r.os = {out[i], out[B + i], out[2 * B + i]};
      r.ot = {out[3 * B + i], out[4 * B + i], out[5 * B + i]};
      r.mag_s = out[6 * B + i], r.mag_t = out[7 * B + i];
      std::uint8_t& flag = tris.flag[t0 + i];
      if (!(flag & kDegenerate) && not_zero(r.mag_s) && not_zero(r.mag_t)) flag &= std::uint8_t(~kGroupWithAny);
    }
  }
  tris.good = T - degenerate;
  if (degenerate > 0) {
    for (std::size_t t = 0; t + 1 < T;) {
      if (tris.face_of(t) == tris.face_of(t + 1) && mesh.face_size(tris.face_of(t)) == 4) {
        if (((tris.flag[t] ^ tris.flag[t + 1]) & kDegenerate) != 0) {
          tris.flag[t] |= kQuadOneDegenerate;
          tris.flag[t + 1] |= kQuadOneDegenerate;
        }
        t += 2;
      } else {
        ++t;
      }
    }
    std::vector<std::size_t> order;
    order.reserve(T);
    for (std::size_t t = 0; t < T; ++t)
      if (!(tris.flag[t] & kDegenerate)) order.push_back(t);
    for (std::size_t t = 0; t < T; ++t)
      if (tris.flag[t] & kDegenerate) order.push_back(t);
    Triangles sorted;  // corners and faces listed (not identity: triangles move)
    sorted.count = T;
    sorted.good = tris.good;
    TriInfos sorted_info(new TriInfo[T]);
    for (std::size_t t : order) {
      for (int k = 0; k < 3; ++k) {
        sorted.corner.push_back(tris.corner_of(3 * t + k));
        sorted.index.push_back(tris.index[3 * t + k]);
      }
      sorted_info[sorted.face.size()] = info[t];
      sorted.face.push_back(tris.face_of(t));
      sorted.flag.push_back(tris.flag[t]);
    }
    tris = std::move(sorted);
    info = std::move(sorted_info);
  }
  // Quads split in two: none when every triangle is its own face (tris.identity).
  const std::size_t good = tris.identity ? 0 : tris.good;
  for (std::size_t t = 0; t + 1 < good;) {
    if (tris.face_of(t) == tris.face_of(t + 1) && mesh.face_size(tris.face_of(t)) == 4) {
      if (((tris.flag[t] ^ tris.flag[t + 1]) & kOrientPreserving) != 0) {
        const bool first = (tris.flag[t + 1] & kGroupWithAny) != 0 ||
                           texture_area(wv, &tris.index[3 * t]) >= texture_area(wv, &tris.index[3 * (t + 1)]);
        const std::size_t t0 = first ? t : t + 1, t1 = first ? t + 1 : t;
        tris.flag[t1] = std::uint8_t((tris.flag[t1] & ~kOrientPreserving) | (tris.flag[t0] & kOrientPreserving));
      }
      t += 2;
    } else {
      ++t;
    }
  }
}

// Step 5: neighbours across welded edges used in opposite directions; edges in (lower vertex,
// higher vertex, triangle) order, the first unpaired match wins. The order: a counting sort by the
// lower vertex (stable: triangles stay ascending), then each vertex's few edges sorted by
// (higher vertex, corner slot), the slot's order being the triangle's.
void find_neighbours(Triangles& tris, std::size_t num_welded) {
  struct Edge { std::uint32_t hi, slot; };  // slot 3 t + k: edge k of triangle t
  const std::size_t S = 3 * tris.good;
  const std::uint32_t* index = tris.index.data();
  auto other_end = [index](std::size_t j) { return index[j % 3 < 2 ? j + 1 : j - 2]; };
  std::vector<std::uint32_t> start(num_welded + 1, 0);
  for (std::size_t j = 0; j < S; ++j) ++start[std::min(index[j], other_end(j)) + 1];
  for (std::size_t v = 0; v < num_welded; ++v) start[v + 1] += start[v];
  const std::unique_ptr<Edge[]> edges(new Edge[S]);  // filled in full below: not zeroed first
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t j = 0; j < S; ++j) {
      const std::uint32_t a = index[j], b = other_end(j);
      edges[next[std::min(a, b)]++] = {std::max(a, b), std::uint32_t(j)};
    }
  }
  tris.neighbour.assign(S, -1);
  std::int32_t* neighbour = tris.neighbour.data();
  for (std::size_t v = 0; v < num_welded; ++v) {
    Edge* e = edges.get() + start[v];
    const std::size_t n = start[v + 1] - start[v];
    auto before = [](const Edge& a, const Edge& b) { return a.hi != b.hi ? a.hi < b.hi : a.slot < b.slot; };
    if (n > 16) {
      std::sort(e, e + n, before);
    } else {
      for (std::size_t i = 1; i < n; ++i) {  // insertion sort: most vertices have few edges
        const Edge x = e[i];
        std::size_t k = i;
        for (; k > 0 && before(x, e[k - 1]); --k) e[k] = e[k - 1];
        e[k] = x;
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (neighbour[e[i].slot] != -1) continue;
      const bool from_v = index[e[i].slot] == v;  // its direction: from v, or to v
      for (std::size_t j = i + 1; j < n && e[j].hi == e[i].hi; ++j)
        if ((index[e[j].slot] == v) != from_v && neighbour[e[j].slot] == -1) {
          neighbour[e[i].slot] = std::int32_t(e[j].slot / 3);
          neighbour[e[j].slot] = std::int32_t(e[i].slot / 3);
          break;
        }
    }
  }
}

int corner_at(const std::uint32_t* idx, std::uint32_t vertex) {
  // idx[0] == vertex ? 0 : idx[1] == vertex ? 1 : 2, without branches (which corner is random).
  return (1 - int(idx[0] == vertex)) * (2 - int(idx[1] == vertex));
}

// Step 6: groups of triangles around each welded vertex (the reference's four rules), depth first
// through neighbours, left (the edge leaving the vertex) before right.
void build_groups(Triangles& tris, std::vector<Group>& groups, std::vector<std::uint32_t>& members) {
  const std::size_t T = tris.good;
  const std::int32_t* neighbour = tris.neighbour.data();
  members.resize(3 * T);  // a corner is in one group at most
  std::size_t count = 0;
  std::vector<std::int32_t> stack(64);
  std::size_t top = 0;
  auto push = [&](std::int32_t t) {
    if (top == stack.size()) stack.resize(2 * top);
    stack[top++] = t;
  };
  for (std::size_t f = 0; f < T; ++f)
    for (int i = 0; i < 3; ++i) {
      if (tris.flag[f] & (kGroupWithAny | (kGrouped << i))) continue;
      Group group{tris.index[3 * f + i], (tris.flag[f] & kOrientPreserving) != 0, std::uint32_t(count), 0};
      members[count++] = std::uint32_t(3 * f + i);
      tris.flag[f] |= std::uint8_t(kGrouped << i);
      top = 0;
      push(neighbour[3 * f + (i > 0 ? i - 1 : 2)]);
      push(neighbour[3 * f + i]);
      while (top > 0) {
        const std::int32_t t = stack[--top];
        if (t < 0) continue;
        const int k = corner_at(&tris.index[3 * std::size_t(t)], group.representative);
        std::uint8_t& flag = tris.flag[t];
        if (flag & (kGrouped << k)) continue;  // this group's already, or another's
        // The first group to reach a group-with-any triangle sets its orientation (the
        // reference's one order dependency).
        if ((flag & kGroupWithAny) && !(flag & kGroupedAny))
          flag = std::uint8_t((flag & ~kOrientPreserving) | (group.orient ? kOrientPreserving : 0));
        if (((flag & kOrientPreserving) != 0) != group.orient) continue;
        members[count++] = std::uint32_t(3 * t + k);
        flag |= std::uint8_t(kGrouped << k);
        push(neighbour[3 * std::size_t(t) + (k > 0 ? k - 1 : 2)]);
        push(neighbour[3 * std::size_t(t) + k]);
      }
      group.count = std::uint32_t(count - group.offset);
      groups.push_back(group);
    }
  members.resize(count);
}

// Step 7a: per group member (a corner of a healthy triangle), the terms of its group's frame (the
// reference's evaluation, in its arithmetic): the triangle's derivatives projected onto the
// corner's normal (ps, pt) and the corner's angle in the normal's plane, in blocks through the
// vector pass (engine/tangent_corner_terms.h; its arc cosine gives the reference's float(acos(double))).
struct CornerTerm {
  F3 ps, pt;
  float angle;
  float mag_s, mag_t;  // the triangle's (TriInfo), beside the rest
};

// slots: n corner slots (3 t + k: corner k of triangle t); terms: n, written.
void corner_terms(const std::vector<WeldedVertex>& wv, const Triangles& tris, const TriInfos& info,
                  const std::uint32_t* slots, std::size_t n, CornerTerm* terms) {
  using normals_detail::kTangentCornerBlock;
  constexpr std::size_t B = kTangentCornerBlock;
  float in[15 * B], out[7 * B];
  for (std::size_t begin = 0; begin < n; begin += B) {
    const std::size_t count = std::min(B, n - begin);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t t = slots[begin + i] / 3, k = slots[begin + i] % 3;
      const std::uint32_t* idx = &tris.index[3 * t];
      const WeldedVertex& w = wv[idx[k]];
      const F3 e1 = wv[idx[k > 0 ? k - 1 : 2]].p - w.p, e2 = wv[idx[k < 2 ? k + 1 : 0]].p - w.p;
      const TriInfo& ti = info[t];
      const float v[15] = {w.n.x, w.n.y, w.n.z, ti.os.x, ti.os.y, ti.os.z, ti.ot.x, ti.ot.y, ti.ot.z,
                           e1.x, e1.y, e1.z, e2.x, e2.y, e2.z};
      for (int r = 0; r < 15; ++r) in[r * B + i] = v[r];
    }
    normals_detail::tangent_corner_terms(count, in, out);
    for (std::size_t i = 0; i < count; ++i) {
      CornerTerm& c = terms[begin + i];
      c.ps = {out[i], out[B + i], out[2 * B + i]};
      c.pt = {out[3 * B + i], out[4 * B + i], out[5 * B + i]};
      c.angle = out[6 * B + i];
      const TriInfo& ti = info[slots[begin + i] / 3];
      c.mag_s = ti.mag_s;
      c.mag_t = ti.mag_t;
    }
  }
}

// A group's member as group_frames reads it: its slot (3 t + k: corner k of triangle t), its
// triangle's face and whether that groups with any, and its corner's term.
struct Member {
  std::uint32_t slot, face;
  bool any;
  const CornerTerm* term;
};

// The frame of one sub-group: its members' projected derivatives weighted by their corners'
// angles. `sub`: the n members' positions in `m`, in ascending triangle order (the order of the
// sums); null: all of m[0, n).
TSpace evaluate_frame(const Member* m, const std::uint32_t* sub, std::size_t n) {
  TSpace res;
  res.os = {0, 0, 0};
  res.ot = {0, 0, 0};
  res.mag_s = res.mag_t = 0;
  float angle_sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Member& x = m[sub ? sub[i] : i];
    if (x.any) continue;
    const float angle = x.term->angle;
    res.os = res.os + scale(angle, x.term->ps);
    res.ot = res.ot + scale(angle, x.term->pt);
    res.mag_s += angle * x.term->mag_s;
    res.mag_t += angle * x.term->mag_t;
    angle_sum += angle;
  }
  if (not_zero(res.os)) res.os = normalize(res.os);
  if (not_zero(res.ot)) res.ot = normalize(res.ot);
  if (angle_sum > 0) {
    res.mag_s /= angle_sum;  // divisor checked
    res.mag_t /= angle_sum;
  }
  return res;
}

// Whether two members of a group are in each other's sub-group: the reference's angular
// threshold, 180 degrees (cos(float(pi)) rounded to float is exactly -1), or one of them groups with
// any, or both come from one face.
bool joins(const Member& a, const Member& b) {
  const float threshold_cos = -1.0f;
  return a.any || b.any || a.face == b.face ||
         (dot(a.term->ps, b.term->ps) > threshold_cos && dot(a.term->pt, b.term->pt) > threshold_cos);
}

// Whether every pair of a group's n members joins (none antiparallel), so that every member's
// sub-group is the whole group: one frame (the common case). Sure without the pairs when the
// projected derivatives of the members that do not group with any all lie within 60 degrees
// (dot > 0.5) of the first one's: any two of them are then within 120 degrees, their dot below
// -0.5 never near the threshold -1 whatever the float rounding; else every pair is tested.
bool whole_group(const Member* m, std::uint32_t n) {
  bool whole = true;
  std::uint32_t a = 0;
  while (a < n && m[a].any) ++a;
  for (std::uint32_t j = a + 1; j < n && whole; ++j)
    whole = m[j].any || (dot(m[a].term->ps, m[j].term->ps) > 0.5f && dot(m[a].term->pt, m[j].term->pt) > 0.5f);
  if (whole) return true;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (!joins(m[i], m[j])) return false;
  return true;
}

// Two frames meeting at one corner (the triangles of a quad): their mean, or the first when equal.
TSpace average(const TSpace& a, const TSpace& b) {
  if (a.mag_s == b.mag_s && a.mag_t == b.mag_t && a.os == b.os && a.ot == b.ot) return a;
  TSpace r = a;
  r.mag_s = 0.5f * (a.mag_s + b.mag_s);
  r.mag_t = 0.5f * (a.mag_t + b.mag_t);
  r.os = a.os + b.os;
  r.ot = a.ot + b.ot;
  if (not_zero(r.os)) r.os = normalize(r.os);
  if (not_zero(r.ot)) r.ot = normalize(r.ot);
  return r;
}

// The frames reached per corner, by index: each distinct frame stored once (about one per group),
// every corner the index of its own (~0u: none reached it; the reference's default then).
struct CornerFrames {
  std::vector<TSpace> frames;
  std::vector<std::uint32_t> of;  // #C

  // Corner c receives frames[f] from a group of orientation `orient`: its own when it had none,
  // else the mean with the one it has (the two triangles of a quad), in the later group's orientation.
  void receive(std::uint32_t c, std::uint32_t f, bool orient) {
    if (of[c] == ~0u) {
      of[c] = f;  // frames[f].orient is its group's
      return;
    }
    TSpace r = average(frames[of[c]], frames[f]);
    r.orient = orient;
    frames.push_back(r);
    of[c] = std::uint32_t(frames.size() - 1);
  }
};

// Step 7: sub-groups and their frames, written to each member's corner. A group's members are
// taken in ascending triangle order (slots ascend with triangles: one corner per triangle at a
// vertex), the order of the reference's sums.
// The terms are computed for batches of consecutive groups (their members are consecutive), about
// kBatch corners at a time, so that they stay in cache between the two.
void group_frames(const std::vector<WeldedVertex>& wv, const Triangles& tris, const TriInfos& info,
                  const std::vector<Group>& groups, const std::vector<std::uint32_t>& members,
                  CornerFrames& out) {
  constexpr std::size_t kBatch = 512;
  std::vector<CornerTerm> terms;
  std::size_t batch_begin = 0, batch_end = 0;  // members whose terms are in `terms`
  std::vector<Member> m;
  std::vector<std::uint32_t> sub;
  // This group's distinct sub-groups: members in one flat buffer (offsets); their frames are
  // out.frames[base, base + count).
  std::vector<std::uint32_t> sub_members, sub_offset;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Group& group = groups[g];
    const std::uint32_t n = group.count;
    if (group.offset + n > batch_end) {
      std::size_t h = g + 1;
      while (h < groups.size() && groups[h].offset + groups[h].count - group.offset <= kBatch) ++h;
      batch_begin = group.offset;
      batch_end = groups[h - 1].offset + groups[h - 1].count;
      terms.resize(batch_end - batch_begin);
      corner_terms(wv, tris, info, &members[batch_begin], batch_end - batch_begin, terms.data());
    }
    m.resize(n);
    const std::uint32_t* slots = &members[group.offset];
    auto member = [&](std::uint32_t j) {
      const std::uint32_t t = slots[j] / 3;
      return Member{slots[j], tris.face_of(t), (tris.flag[t] & kGroupWithAny) != 0, &terms[group.offset + j - batch_begin]};
    };
    if (n > 16) {
      for (std::uint32_t j = 0; j < n; ++j) m[j] = member(j);
      std::sort(m.begin(), m.end(), [](const Member& a, const Member& b) { return a.slot < b.slot; });
    } else {
      // Most groups are small: each member goes straight to its rank (slots are distinct), counted
      // without branches.
      for (std::uint32_t j = 0; j < n; ++j) {
        std::uint32_t rank = 0;
        for (std::uint32_t i = 0; i < n; ++i) rank += slots[i] < slots[j];
        m[rank] = member(j);
      }
    }
    if (whole_group(m.data(), n)) {
      out.frames.push_back(evaluate_frame(m.data(), nullptr, n));
      out.frames.back().orient = group.orient;
      const auto frame = std::uint32_t(out.frames.size() - 1);
      for (std::uint32_t i = 0; i < n; ++i) out.receive(tris.corner_of(m[i].slot), frame, group.orient);
      continue;
    }
    sub_members.clear();
    sub_offset.assign(1, 0);
    const std::size_t base = out.frames.size();
    for (std::uint32_t d = 0; d < n; ++d) {
      // Members in the order the group reached them (a corner that several triangles of a polygon
      // share averages their frames in that order).
      std::uint32_t i = 0;
      while (m[i].slot != members[group.offset + d]) ++i;
      sub.clear();
      for (std::uint32_t j = 0; j < n; ++j)
        if (j == i || joins(m[i], m[j])) sub.push_back(j);  // ascending, as m
      std::size_t l = 0;
      const std::size_t known = sub_offset.size() - 1;
      while (l < known && !(sub_offset[l + 1] - sub_offset[l] == sub.size() &&
                            std::equal(sub.begin(), sub.end(), sub_members.begin() + sub_offset[l])))
        ++l;
      if (l == known) {
        sub_members.insert(sub_members.end(), sub.begin(), sub.end());
        sub_offset.push_back(std::uint32_t(sub_members.size()));
        out.frames.push_back(evaluate_frame(m.data(), sub.data(), sub.size()));
        out.frames.back().orient = group.orient;
      }
      out.receive(tris.corner_of(m[i].slot), std::uint32_t(base + l), group.orient);
    }
  }
}

// One welded vertex's triangle i (ascending), for frames_by_vertex: its slot, the welded
// vertices after (n) and before (p) the vertex, the triangles (local numbers) across the edges
// vertex -> n (out) and p -> vertex (in), -1 where none; its orientation; grouped yet.
struct LocalTriangle {
  std::uint32_t slot, n, p;
  std::int32_t out, in;
  bool orient, grouped;
};

// find_neighbours' rule at one vertex: each edge {v, w}'s edges in triangle order, each unpaired
// one paired with the first later unpaired one in the opposite direction.
void pair_edges_in_order(LocalTriangle* x, std::uint32_t k) {
  for (std::uint32_t i = 0; i < k; ++i) {
    LocalTriangle& a = x[i];
    if (a.out < 0)
      for (std::uint32_t j = i + 1; j < k; ++j)
        if (x[j].p == a.n && x[j].in < 0) {
          a.out = std::int32_t(j), x[j].in = std::int32_t(i);
          break;
        }
    if (a.in < 0)
      for (std::uint32_t j = i + 1; j < k; ++j)
        if (x[j].n == a.p && x[j].out < 0) {
          a.in = std::int32_t(j), x[j].out = std::int32_t(i);
          break;
        }
  }
}

// The common case of build_groups' search at one vertex: every triangle of one orientation and
// linked into one ring or one fan. The search from triangle 0 then goes along the out links to the
// end (or back to 0), then along the in links from 0: that order written to `members`, true.
// False (nothing meant) otherwise.
bool one_group_walk(const LocalTriangle* x, std::uint32_t k, std::uint32_t* members) {
  bool same = true;
  for (std::uint32_t i = 1; i < k; ++i) same &= x[i].orient == x[0].orient;
  if (!same) return false;
  std::uint32_t n = 0;
  members[n++] = x[0].slot;
  std::int32_t j = x[0].out;
  for (; j > 0 && n < k; j = x[j].out) members[n++] = x[j].slot;
  if (j < 0)
    for (j = x[0].in; j >= 0 && n < k; j = x[j].in) members[n++] = x[j].slot;
  return n == k;
}

// Step 7 for the groups frames_by_vertex finds as one walk (every triangle at a vertex, of one
// orientation, in one ring or fan) of up to kRows members: their members are the vertex's corner
// slots in ascending order, the order of the sums, so they need no sorting. kTangentLanes such
// vertices at a time, one per lane (member j of lane g in column j * kTangentLanes + g), go through
// the vector pass for their corner terms (from the vertex's own values) and then for their frames
// (tangent_lane_frames: evaluate_frame's sums). A lane not surely whole is checked member by
// member (whole_group, evaluate_frame); a group that is not whole is handed back to group_frames
// (`others`), with its members in the walk's order.
class OneGroupFrames {
 public:
  static constexpr std::size_t kRows = normals_detail::kTangentCornerBlock / normals_detail::kTangentLanes;

  OneGroupFrames(const std::vector<WeldedVertex>& wv, const Triangles& tris, const TriInfos& info,
                 CornerFrames& out)
      : wv_(wv), tris_(tris), info_(info), out_(out) {}

  // Vertex v's k corners (x, ascending slots), walk: the same slots in the order the search
  // reached them. k <= kRows.
  void add(std::uint32_t v, const LocalTriangle* x, std::uint32_t k, const std::uint32_t* walk,
           std::vector<Group>& others, std::vector<std::uint32_t>& other_members) {
    const std::size_t g = lanes_;
    const WeldedVertex& w = wv_[v];
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::size_t c = i * L + g;
      const TriInfo& ti = info_[x[i].slot / 3];
      const F3 e1 = wv_[x[i].p].p - w.p, e2 = wv_[x[i].n].p - w.p;
      const float values[15] = {w.n.x, w.n.y, w.n.z, ti.os.x, ti.os.y, ti.os.z, ti.ot.x, ti.ot.y, ti.ot.z,
                                e1.x, e1.y, e1.z, e2.x, e2.y, e2.z};
      for (int row = 0; row < 15; ++row) in_[row * B + c] = values[row];
      mags_[c] = ti.mag_s;
      mags_[B + c] = ti.mag_t;
      slot_[c] = x[i].slot;
      walk_[c] = walk[i];
    }
    lane_[g] = {v, k, x[0].orient};
    count_[g] = int(k);
    rows_ = std::max<std::size_t>(rows_, k);
    if (++lanes_ == L) finish(others, other_members);
  }

  void finish(std::vector<Group>& others, std::vector<std::uint32_t>& other_members) {
    if (lanes_ == 0) return;
    for (std::size_t g = lanes_; g < L; ++g) count_[g] = 0;
    // Columns past a lane's members: zero inputs (finite, quick), results unused.
    for (std::size_t g = 0; g < L; ++g)
      for (std::size_t j = std::size_t(count_[g]); j < rows_; ++j)
        for (int row = 0; row < 15; ++row) in_[row * B + j * L + g] = 0.0f;
    normals_detail::tangent_corner_terms(rows_ * L, in_, terms_);
    normals_detail::tangent_lane_frames(rows_, count_, terms_, mags_, frames_);
    for (std::size_t g = 0; g < lanes_; ++g) {
      const Lane& lane = lane_[g];
      TSpace frame;
      frame.os = {frames_[g], frames_[L + g], frames_[2 * L + g]};
      frame.ot = {frames_[3 * L + g], frames_[4 * L + g], frames_[5 * L + g]};
      frame.mag_s = frames_[6 * L + g];
      frame.mag_t = frames_[7 * L + g];
      if (frames_[8 * L + g] == 0.0f && !whole_lane(g)) {
        others.push_back(Group{lane.vertex, lane.orient, std::uint32_t(other_members.size()), lane.count});
        for (std::size_t j = 0; j < lane.count; ++j) other_members.push_back(walk_[j * L + g]);
        continue;
      }
      frame.orient = lane.orient;
      out_.frames.push_back(frame);
      const auto f = std::uint32_t(out_.frames.size() - 1);
      for (std::size_t j = 0; j < lane.count; ++j) out_.receive(tris_.corner_of(slot_[j * L + g]), f, lane.orient);
    }
    lanes_ = rows_ = 0;
  }

 private:
  static constexpr std::size_t B = normals_detail::kTangentCornerBlock, L = normals_detail::kTangentLanes;
  struct Lane {
    std::uint32_t vertex, count;
    bool orient;
  };

  // whole_group on lane g's members (the lane pass's first test failed: every pair tested).
  bool whole_lane(std::size_t g) const {
    const Lane& lane = lane_[g];
    Member m[kRows];
    CornerTerm term[kRows];
    for (std::size_t j = 0; j < lane.count; ++j) {
      const std::size_t c = j * L + g;
      term[j] = {{terms_[c], terms_[B + c], terms_[2 * B + c]},
                 {terms_[3 * B + c], terms_[4 * B + c], terms_[5 * B + c]},
                 terms_[6 * B + c], mags_[c], mags_[B + c]};
      m[j] = {slot_[c], tris_.face_of(slot_[c] / 3), false, &term[j]};
    }
    return whole_group(m, lane.count);
  }

  const std::vector<WeldedVertex>& wv_;
  const Triangles& tris_;
  const TriInfos& info_;
  CornerFrames& out_;
  float in_[15 * B], terms_[7 * B], mags_[2 * B], frames_[9 * L];
  std::uint32_t slot_[B], walk_[B];
  Lane lane_[L];
  int count_[L];
  std::size_t lanes_ = 0, rows_ = 0;
};

// Steps 5, 6 and 7 vertex by vertex, for a mesh with no triangle that groups with any (the only
// link between two vertices' groups: the first group to reach such a triangle sets its
// orientation). The groups at welded vertex v depend on v's triangles alone: a neighbour across an
// edge {v, w} shares v, and find_neighbours pairs the edges of {v, w} among themselves in triangle
// order; so each vertex's corners (a counting sort of the corner slots by welded vertex, ascending)
// are paired and searched here as find_neighbours and build_groups would, in local arrays. Same
// groups, members in the same order, taken vertex by vertex instead of by first corner, which
// changes no frame (a corner only receives frames from its own vertex's groups, and those keep
// their order). A vertex whose triangles form one group gets its frame at once (OneGroupFrames);
// the other groups are returned (groups, members) for group_frames.
void frames_by_vertex(const std::vector<WeldedVertex>& wv, const Triangles& tris, const TriInfos& info,
                      std::vector<Group>& groups, std::vector<std::uint32_t>& members, CornerFrames& out) {
  const std::size_t S = 3 * tris.good, num_welded = wv.size();
  const std::uint32_t* index = tris.index.data();
  std::vector<std::uint32_t> start(num_welded + 1, 0);
  for (std::size_t j = 0; j < S; ++j) ++start[index[j] + 1];
  for (std::size_t v = 0; v < num_welded; ++v) start[v + 1] += start[v];
  const std::unique_ptr<std::uint32_t[]> slots(new std::uint32_t[S]);  // filled in full below
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t j = 0; j < S; ++j) slots[next[index[j]]++] = std::uint32_t(j);
  }
  const std::unique_ptr<OneGroupFrames> one_group(new OneGroupFrames(wv, tris, info, out));
  std::vector<LocalTriangle> local(64);
  std::vector<std::uint32_t> walk(64);
  std::vector<std::int32_t> stack(2 * local.size() + 2);  // a search pushes 2 + 2 per member
  for (std::size_t v = 0; v < num_welded; ++v) {
    const std::uint32_t b = start[v], k = start[v + 1] - b;
    if (k == 0) continue;  // a vertex of degenerate triangles only
    if (k > local.size()) local.resize(2 * k), walk.resize(2 * k), stack.resize(4 * k + 2);
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::uint32_t s = slots[b + i], t = s / 3, c = s % 3;
      local[i] = {s, index[3 * t + (c < 2 ? c + 1 : 0)], index[3 * t + (c > 0 ? c - 1 : 2)], -1, -1,
                  (tris.flag[t] & kOrientPreserving) != 0, false};
    }
    pair_edges_in_order(local.data(), k);
    if (k <= OneGroupFrames::kRows && one_group_walk(local.data(), k, walk.data())) {
      one_group->add(std::uint32_t(v), local.data(), k, walk.data(), groups, members);
      continue;
    }
    // build_groups' search, through the local neighbours.
    for (std::uint32_t i = 0; i < k; ++i) {
      if (local[i].grouped) continue;
      Group group{std::uint32_t(v), local[i].orient, std::uint32_t(members.size()), 0};
      members.push_back(local[i].slot);
      local[i].grouped = true;
      std::size_t top = 0;
      stack[top++] = local[i].in;
      stack[top++] = local[i].out;
      while (top > 0) {
        const std::int32_t j = stack[--top];
        if (j < 0) continue;
        LocalTriangle& x = local[std::size_t(j)];
        if (x.grouped || x.orient != group.orient) continue;
        members.push_back(x.slot);
        x.grouped = true;
        stack[top++] = x.in;
        stack[top++] = x.out;
      }
      group.count = std::uint32_t(members.size() - group.offset);
      groups.push_back(group);
    }
  }
  one_group->finish(groups, members);
}

// Step 8: frames for the corners of degenerate triangles.
void degenerate_frames(const Mesh& mesh, const Corners& in, std::size_t num_welded, const Triangles& tris,
                       std::vector<std::uint32_t>& out) {
  const std::size_t T = tris.count, good = tris.good;
  if (good == T) return;  // no degenerate triangle (nor, then, a quad with one)
  std::vector<std::uint32_t> first(num_welded, ~0u);  // welded vertex -> first healthy corner slot
  for (std::size_t j = 3 * good; j-- > 0;) first[tris.index[j]] = std::uint32_t(j);
  for (std::size_t t = good; t < T; ++t) {
    if (tris.flag[t] & kQuadOneDegenerate) continue;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t j = first[tris.index[3 * t + i]];
      if (j != ~0u) out[tris.corner_of(3 * t + i)] = out[tris.corner_of(j)];
    }
  }
  for (std::size_t t = 0; t < good; ++t) {
    if (!(tris.flag[t] & kQuadOneDegenerate)) continue;
    const std::uint32_t b = mesh.face_start[tris.face_of(t)];
    unsigned present = 0;
    for (int i = 0; i < 3; ++i) present |= 1u << (tris.corner_of(3 * t + i) - b);
    std::uint32_t missing = 0;
    while (present & (1u << missing)) ++missing;
    const F3 dst = in.position(b + missing);
    for (int i = 0; i < 3; ++i)
      if (in.position(tris.corner_of(3 * t + i)) == dst) {
        out[b + missing] = out[tris.corner_of(3 * t + i)];
        break;
      }
  }
}

}  // namespace

Vec3d perpendicular_unit(const Vec3d& n) {
  if (!is_finite(n) || std::fabs(dot(n, n) - 1.0) > 1e-3) return {1.0, 0.0, 0.0};
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);  // divisor checked: |sign + n.z| >= 1
  const double b = n.x * n.y * a;
  return {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

TangentFrames mikktspace_tangents(const Mesh& mesh) {
  if (!mesh.has_texcoords()) throw Error("tangents: the mesh has no texture coordinates");
  // The normals that shade the corners (core/shading_normals.h: corner, else vertex, else face).
  const ShadingNormals shading = shading_normals(mesh);
  if (shading == ShadingNormals::None) throw Error("tangents: the mesh has no normals");
  const std::size_t C = mesh.num_corners(), F = mesh.num_faces();
  const int dims = mesh.texcoord_dims;
  auto corner_normal = [&](std::size_t c, std::size_t f) {
    switch (shading) {
      case ShadingNormals::Corner: return get3(mesh.corner_normals, mesh.corner_normal_index[c]);
      case ShadingNormals::Vertex: return get3(mesh.vertex_normals, mesh.corner_vertex[c]);
      case ShadingNormals::Face:
      case ShadingNormals::None: break;
    }
    return get3(mesh.face_normals, f);
  };
  // Faces taken: 3+ corners, every one textured.
  std::vector<std::uint8_t> taken(F, 0);
  Corners in;
  in.positions.resize(mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const Vec3d p = mesh.position(v);
    in.positions[v] = {float(p.x), float(p.y), float(p.z)};
  }
  const std::vector<double>& normal_values = shading == ShadingNormals::Corner   ? mesh.corner_normals
                                             : shading == ShadingNormals::Vertex ? mesh.vertex_normals
                                                                                 : mesh.face_normals;
  in.normals.resize(normal_values.size() / 3);
  for (std::size_t k = 0; k < in.normals.size(); ++k)
    in.normals[k] = {float(normal_values[3 * k]), float(normal_values[3 * k + 1]), float(normal_values[3 * k + 2])};
  const std::size_t stride = std::size_t(std::max(dims, 1));
  in.texcoords.resize(dims >= 2 ? mesh.texcoords.size() / stride : 0);
  for (std::size_t k = 0; k < in.texcoords.size(); ++k)
    in.texcoords[k] = {float(mesh.texcoords[stride * k]), float(mesh.texcoords[stride * k + 1]), 1.0f};
  std::vector<std::uint32_t> corner_face;  // face normals: the normal index of a corner is its face
  if (shading == ShadingNormals::Face) {
    corner_face.resize(C);
    for (std::size_t f = 0; f < F; ++f)
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) corner_face[c] = std::uint32_t(f);
  }
  in.num_corners = C;
  in.vertex = mesh.corner_vertex.data();
  in.normal = shading == ShadingNormals::Corner   ? mesh.corner_normal_index.data()
              : shading == ShadingNormals::Vertex ? mesh.corner_vertex.data()
                                                  : corner_face.data();
  in.texcoord = mesh.corner_texcoord_index.data();
  bool taken_triangles = true;  // every face taken, every one a triangle
  bool every_face_taken = true;
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    bool ok = e - b >= 3 && dims >= 2;
    bool untextured = false;  // every corner read (no early exit: the loop is compares, not a branch each)
    if (ok)
      for (std::uint32_t c = b; c < e; ++c) untextured |= mesh.corner_texcoord_index[c] == kNoTexcoord;
    ok &= !untextured;
    taken[f] = ok;
    taken_triangles &= ok && mesh.face_size(f) == 3;
    every_face_taken &= ok;
  }
  // The welded vertex per corner: written straight into the triangles' index when triangle t is
  // face t (corners 3 t + k), else into a scratch array that make_triangles reads.
  Triangles tris;
  std::unique_ptr<std::uint32_t[]> welded_id;
  if (taken_triangles) tris.index.resize(C);
  else welded_id.reset(new std::uint32_t[C]);
  const std::vector<WeldedVertex> wv =
      weld(mesh, in, taken, every_face_taken, taken_triangles ? tris.index.data() : welded_id.get());
  make_triangles(mesh, in, taken, welded_id.get(), tris);
  TriInfos info(new TriInfo[tris.count]);  // TriInfo{}: zero derivatives
  degenerate_and_derivatives(mesh, wv, tris, info);
  std::vector<Group> groups;
  std::vector<std::uint32_t> members;
  CornerFrames frames;
  frames.frames.reserve(wv.size() + wv.size() / 4);  // about one per welded vertex
  frames.of.assign(C, ~0u);
  bool any = false;
  for (std::size_t t = 0; t < tris.good; ++t) any |= (tris.flag[t] & kGroupWithAny) != 0;
  if (any) {
    groups.reserve(wv.size() + wv.size() / 8);  // about one per welded vertex
    find_neighbours(tris, wv.size());
    build_groups(tris, groups, members);
  } else {
    frames_by_vertex(wv, tris, info, groups, members, frames);
  }
  group_frames(wv, tris, info, groups, members, frames);
  degenerate_frames(mesh, in, wv.size(), tris, frames.of);
  const TSpace none;  // the reference's default frame

  TangentFrames out;
  out.tangents.reserve(4 * C);  // filled in corner order below: no zeroing first; small pages (TriInfos)
  // Rows are staged in a small buffer and appended a block at a time: four push_backs per corner
  // keep the vector's end in memory, a chain of store-to-load forwards through the whole pass.
  constexpr std::size_t kBlock = 256;  // corners per append (8 KiB: stays in L1)
  double buffer[4 * kBlock];
  std::size_t staged = 0;
  auto row = [&](double x, double y, double z, double w) {
    double* r = buffer + 4 * staged;
    r[0] = x, r[1] = y, r[2] = z, r[3] = w;
    if (++staged == kBlock) out.tangents.insert(out.tangents.end(), buffer, buffer + 4 * kBlock), staged = 0;
  };
  for (std::size_t f = 0; f < F; ++f)
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      if (!taken[f]) {
        const Vec3d t = perpendicular_unit(corner_normal(c, f));
        row(t.x, t.y, t.z, 1.0);
        ++out.fallback_corners;
        continue;
      }
      const std::uint32_t k = frames.of[c];
      const TSpace& s = k != ~0u ? frames.frames[k] : none;
      if (!not_zero(s.os)) {
        // The reference's frame is zero here (its group's projected derivatives cancel or vanish,
        // e.g. texture coordinates constant over the vertex's faces): not a direction, and glTF
        // requires TANGENT of unit length. Any unit vector perpendicular to the normal, w as the
        // reference's (tangents.h, zero_corners).
        const Vec3d t = perpendicular_unit(corner_normal(c, f));
        row(t.x, t.y, t.z, s.orient ? 1.0 : -1.0);
        ++out.zero_corners;
        continue;
      }
      row(s.os.x, s.os.y, s.os.z, s.orient ? 1.0 : -1.0);
      if (k == ~0u) ++out.default_corners;
    }
  out.tangents.insert(out.tangents.end(), buffer, buffer + 4 * staged);
  return out;
}

std::string tangent_zero_corners_note(std::size_t zero_corners) {
  return "tangents: " + std::to_string(zero_corners) + (zero_corners == 1 ? " corner" : " corners") +
         " where MikkTSpace's frame is zero (texture coordinates that do not vary over the vertex's faces): a unit "
         "tangent perpendicular to the normal instead (a zero TANGENT is invalid glTF)";
}

}  // namespace shadetool
