// corner_normals_reference.h: a frozen copy of corner_normals' grouping algorithm as it was at
// commit ae9cb5c (lib/shadetool/normals/corner_normals.cpp before issue 31's rewrite), kept as the
// reference that the rewritten corner_normals must match bit for bit (tests/normals/
// corner_normals_bitwise.cpp) and as the "before" row of bench/normals/bench_crease.cpp.
// Face normals: the old scalar loop, copied too (face_normals_reference).
// Per vertex: its edge ends sorted by far vertex, a crease test by interior_angle per end pair
// (each edge tested from both of its ends), union-find over the vertex's corners; then the sums by
// the library's deterministic scatter (the summation kernel is shared, not copied: the rewrite did
// not change it). Do not "fix" this file: its value is that it is the old code.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include <tbb/parallel_invoke.h>

#include <shadetool/core/engine/parallel.h>
#include <shadetool/geometry/interior_angle.h>
#include <shadetool/geometry/union_find.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/engine/accumulate_by_vertex.h>
#include <shadetool/normals/engine/corner_contributions.h>
#include <shadetool/normals/engine/mesh_scale.h>
#include <shadetool/normals/engine/normalise_sums.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/scaled_length.h>
#include <shadetool/normals/vertex_fallback.h>

namespace shadetool::testing::reference_crease {

using namespace shadetool::normals_detail;
using namespace shadetool::engine;

// face_normals as it was (one scalar loop for every face; since issue 31 the library sends
// all-triangle meshes through a vectorised pass that must give the same bits).
template <class T>
void face_normals_range_reference(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, double* out) {
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  const bool triangles = mesh.all_triangles();
  for (std::size_t f = f_begin; f < f_end; ++f) {
    Vec3d N;
    bool degenerate;
    if (triangles || mesh.face_size(f) == 3) {
      const std::size_t c = triangles ? 3 * f : mesh.face_begin(f);
      const TriangleAreaVector t = triangle_area_vector(P, cv[c], cv[c + 1], cv[c + 2]);
      N = t.N;
      degenerate = triangle_is_degenerate(t, P, cv[c], cv[c + 1], cv[c + 2]);
    } else {
      const std::uint32_t begin = mesh.face_begin(f), n = mesh.face_size(f);
      N = newell_area_vector(P, cv + begin, n);
      degenerate = face_area_kind(P, cv + begin, n) != DegenerateKind::None;
    }
    const double l = degenerate ? 0.0 : checked_length(N);
    double* o = out + 3 * f;
    if (l > 0.0) {  // divisor checked: non-zero and finite
      o[0] = double(T(N.x / l)); o[1] = double(T(N.y / l)); o[2] = double(T(N.z / l));
    } else {        // degenerate face: zero normal, never NaN
      o[0] = o[1] = o[2] = 0.0;
    }
  }
}

inline std::vector<double> face_normals_reference(const MeshView& mesh, Precision precision) {
  std::vector<double> storage;
  const MeshView in_range = in_kernel_range(mesh, storage);
  std::vector<double> out(3 * mesh.num_faces());
  if (precision == Precision::Float) face_normals_range_reference<float>(in_range, 0, mesh.num_faces(), out.data());
  else face_normals_range_reference<double>(in_range, 0, mesh.num_faces(), out.data());
  return out;
}

// Corners of each vertex: corners[offset[v] .. offset[v+1]), ascending.
struct VertexCorners {
  std::vector<std::uint32_t> offset, corners;
};

inline VertexCorners vertex_corners(const MeshView& mesh) {
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners();
  VertexCorners vc;
  vc.offset.assign(V + 1, 0);
  for (std::size_t c = 0; c < C; ++c) ++vc.offset[mesh.corner_vertex[c] + 1];
  for (std::size_t v = 0; v < V; ++v) vc.offset[v + 1] += vc.offset[v];
  vc.corners.resize(C);
  std::vector<std::uint32_t> fill(vc.offset.begin(), vc.offset.end() - 1);
  for (std::size_t c = 0; c < C; ++c) vc.corners[fill[mesh.corner_vertex[c]]++] = std::uint32_t(c);
  return vc;
}

// Face of each corner and its neighbours in the face; triangles by arithmetic (corner = 3 f + k),
// polygons through a corner -> face table.
struct CornerTopology {
  MeshView mesh;
  bool triangles;
  std::vector<std::uint32_t> face_of;  // polygons only

  explicit CornerTopology(const MeshView& m) : mesh(m), triangles(m.all_triangles()) {
    if (triangles) return;
    face_of.resize(m.num_corners());
    parallel_ranges(m.num_faces(), [&](std::size_t b, std::size_t e) {
      for (std::size_t f = b; f < e; ++f)
        for (std::uint32_t c = m.face_begin(f), end = m.face_end(f); c < end; ++c) face_of[c] = std::uint32_t(f);
    });
  }
  std::uint32_t face(std::uint32_t c) const { return triangles ? c / 3 : face_of[c]; }
  std::uint32_t next_vertex(std::uint32_t c) const {
    if (triangles) return mesh.corner_vertex[c % 3 == 2 ? c - 2 : c + 1];
    const std::uint32_t f = face_of[c];
    return mesh.corner_vertex[c + 1 < mesh.face_end(f) ? c + 1 : mesh.face_begin(f)];
  }
  std::uint32_t prev_vertex(std::uint32_t c) const {
    if (triangles) return mesh.corner_vertex[c % 3 == 0 ? c + 2 : c - 1];
    const std::uint32_t f = face_of[c];
    return mesh.corner_vertex[c > mesh.face_begin(f) ? c - 1 : mesh.face_end(f) - 1];
  }
};

// Sums of the corners' contributions into rows: row target[c] < rows for every corner, added in
// ascending corner order by the deterministic parallel scatter (accumulate_by_vertex.h). The sums
// are in `normals` (3 rows values) for T = double, else in float_sum. The chunk plan is made
// beside the (serial) zeroing of the arrays. Returns the number of degenerate faces.
template <class T, Weighting W>
inline std::size_t sum_rows(const MeshView& mesh, const std::uint32_t* target, std::size_t rows, std::vector<double>& normals,
                     std::vector<float>& float_sum) {
  ChunkPlan plan;
  tbb::parallel_invoke(
      [&] {
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
CornerNormals compute(const MeshView& mesh, double crease_angle, Precision precision, const std::uint32_t* face_group) {
  const std::size_t V = mesh.num_vertices(), C = mesh.num_corners();
  // (1) face normals: zero for degenerate faces.
  const std::vector<double> fn = face_normals_reference(mesh, precision);
  std::vector<std::uint8_t> valid(mesh.num_faces());
  parallel_ranges(mesh.num_faces(), [&](std::size_t b, std::size_t e) {
    for (std::size_t f = b; f < e; ++f) valid[f] = !(fn[3 * f] == 0.0 && fn[3 * f + 1] == 0.0 && fn[3 * f + 2] == 0.0);
  });
  auto face_valid = [&](std::size_t f) { return valid[f] != 0; };
  const CornerTopology topo(mesh);
  // (2) adjacency.
  const VertexCorners vc = vertex_corners(mesh);

  // (3) groups per vertex; the group number of each corner is stored in corner_index for now.
  CornerNormals out;
  out.corner_index.resize(C);
  std::vector<std::uint32_t> groups(V, 0);
  std::vector<std::uint8_t> has_degenerate_group(V, 0);
  parallel_ranges(V, [&](std::size_t v_begin, std::size_t v_end) {
    // Edge ends as one 64-bit key: far vertex (high 32 bits), local corner index, and whether
    // the edge leaves v (bit 0); sorting the keys sorts by far vertex, then corner.
    std::vector<std::uint64_t> ends;  // scratch, reused across the range's vertices
    std::vector<std::uint32_t> parent, number;
    auto end_key = [](std::uint32_t far, std::uint32_t local, bool out) {
      return (std::uint64_t(far) << 32) | (std::uint64_t(local) << 1) | std::uint64_t(out);
    };
    for (std::size_t v = v_begin; v < v_end; ++v) {
      const std::uint32_t begin = vc.offset[v], d = vc.offset[v + 1] - begin;
      if (d == 0) continue;
      ends.clear();
      parent.resize(d);
      for (std::uint32_t i = 0; i < d; ++i) {
        parent[i] = i;
        const std::uint32_t c = vc.corners[begin + i];
        if (!face_valid(topo.face(c))) continue;  // edges of degenerate faces: creases
        const std::uint32_t n = topo.next_vertex(c), p = topo.prev_vertex(c);
        if (n != v) ends.push_back(end_key(n, i, true));
        if (p != v) ends.push_back(end_key(p, i, false));
      }
      std::sort(ends.begin(), ends.end());
      for (std::size_t i = 0; i < ends.size();) {
        std::size_t j = i + 1;
        while (j < ends.size() && (ends[j] >> 32) == (ends[i] >> 32)) ++j;
        // Smooth only if exactly two faces meet at edge {v, far}, with opposite orientations
        // (one leaves v along it, the other arrives), and the dihedral angle is small enough.
        if (j - i == 2 && (ends[i] & 1) != (ends[i + 1] & 1)) {
          const auto la = std::uint32_t(ends[i] & 0xffffffffu) >> 1, lb = std::uint32_t(ends[i + 1] & 0xffffffffu) >> 1;
          const std::uint32_t fa = topo.face(vc.corners[begin + la]), fb = topo.face(vc.corners[begin + lb]);
          // Faces of different smoothing groups, or of none (0: flat), never join.
          if (fa != fb && (!face_group || (face_group[fa] == face_group[fb] && face_group[fa] != 0))) {
            const Vec3d na = get3(fn, fa), nb = get3(fn, fb), x = cross(na, nb);
            // unit vectors: |na x nb| <= 1, no scaling needed before squaring
            if (interior_angle(std::sqrt(dot(x, x)), dot(na, nb)) <= crease_angle) {
              union_find_unite(parent.data(), la, lb);  // root = smallest local index
            }
          }
        }
        i = j;
      }
      // Number groups by first corner; degenerate-face corners share the vertex's only group
      // when it has one, else get a group of their own (numbered last).
      number.assign(d, ~0u);
      std::uint32_t g = 0;
      bool any_degenerate = false;
      for (std::uint32_t i = 0; i < d; ++i) {
        const std::uint32_t c = vc.corners[begin + i];
        if (!face_valid(topo.face(c))) { any_degenerate = true; continue; }
        const std::uint32_t r = union_find_root(parent.data(), i);
        if (number[r] == ~0u) number[r] = g++;
        out.corner_index[c] = number[r];
      }
      if (any_degenerate) {
        std::uint32_t dg = 0;
        if (g != 1) { dg = g++; has_degenerate_group[v] = 1; }
        for (std::uint32_t i = 0; i < d; ++i) {
          const std::uint32_t c = vc.corners[begin + i];
          if (!face_valid(topo.face(c))) out.corner_index[c] = dg;
        }
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
  std::vector<std::size_t> fallback_corners(V, 0);
  parallel_ranges(V, [&](std::size_t v_begin, std::size_t v_end) {
    for (std::size_t v = v_begin; v < v_end; ++v) {
      for (std::uint32_t r = base[v]; r < base[v + 1]; ++r) {
        double* o = &out.normals[3 * std::size_t(r)];
        if (normalise_sum(double(sum[3 * std::size_t(r)]), double(sum[3 * std::size_t(r) + 1]),
                          double(sum[3 * std::size_t(r) + 2]), o))
          continue;
        std::uint32_t in_group = ~0u, any = ~0u;
        std::size_t corners_in_row = 0;
        for (std::uint32_t i = vc.offset[v]; i < vc.offset[v + 1]; ++i) {
          const std::uint32_t c = vc.corners[i], f = topo.face(c);
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
  for (auto n : fallback_corners) out.fallback_corners += n;
  return out;
}


// The old public entry points: corner_normals(mesh, crease_angle, weighting, precision[, face_group]).
inline CornerNormals corner_normals_reference(const MeshView& mesh, double crease_angle, Weighting weighting = Weighting::Angle,
                                              Precision precision = Precision::Double,
                                              const std::uint32_t* face_group = nullptr) {
  std::vector<double> storage;
  const MeshView in_range = in_kernel_range(mesh, storage);
  return dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    return compute<T, W>(in_range, crease_angle, precision, face_group);
  });
}

}  // namespace shadetool::testing::reference_crease
