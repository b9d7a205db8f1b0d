// corner_normals.cpp: see corner_normals.h.
//
// Steps: (1) unit face normals (crease test, degenerate faces) and every corner's weighted
// contribution (corner_contributions.h); (2) vertex -> corners adjacency as flat arrays
// (offsets + corners, ascending corner order, two passes: count, fill); (3) in parallel over
// vertices: sort the vertex's edge ends by the far vertex, link the two corners across each
// smooth manifold edge (union-find), number groups by first corner, sum and normalise;
// (4) prefix sum of group counts gives each vertex's place in the pool; (5) write.
// Precision: contributions and sums in T (double or float, as vertex_normals); the crease test
// compares angles in double: atan2(|n1 x n2|, n1 . n2) > crease_angle.
#include "normals/corner_normals.h"

#include <algorithm>
#include <cmath>

#include "normals/corner_contributions.h"
#include "normals/face_normals.h"
#include "normals/parallel.h"
#include "normals/vertex_fallback.h"

namespace shadetool {
namespace {

using namespace normals_detail;

// Corner adjacency of each vertex: corners of v are corners[offset[v] .. offset[v+1]), ascending.
struct VertexCorners {
  std::vector<std::uint32_t> offset, corners;
};

VertexCorners vertex_corners(const Mesh& mesh) {
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

// Face of every corner, and the corners before and after it in its face.
struct CornerLinks {
  std::vector<std::uint32_t> face;
};

CornerLinks corner_faces(const Mesh& mesh) {
  CornerLinks l;
  l.face.resize(mesh.num_corners());
  parallel_ranges(mesh.num_faces(), [&](std::size_t b, std::size_t e) {
    for (std::size_t f = b; f < e; ++f)
      for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) l.face[c] = std::uint32_t(f);
  });
  return l;
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

template <class T, Weighting W>
CornerNormals compute(const Mesh& mesh, double crease_angle, Precision precision) {
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces(), C = mesh.num_corners();
  const std::vector<double> fn = face_normals(mesh, precision);
  auto face_valid = [&](std::size_t f) { return !(fn[3 * f] == 0.0 && fn[3 * f + 1] == 0.0 && fn[3 * f + 2] == 0.0); };

  // (1) per-corner contributions; corners of degenerate faces stay zero.
  std::vector<T> contrib(3 * C, T(0));
  const bool triangles = mesh.all_triangles();
  parallel_ranges(F, [&](std::size_t b, std::size_t e) {
    auto store = [&](std::size_t c, std::uint32_t, const Vec3<T>& n) {
      contrib[3 * c] = n.x; contrib[3 * c + 1] = n.y; contrib[3 * c + 2] = n.z;
    };
    if (triangles) triangle_contributions<T, W>(mesh, b, e, store);
    else polygon_contributions<T, W>(mesh, b, e, store);
  });
  const CornerLinks links = corner_faces(mesh);
  auto next_vertex = [&](std::uint32_t c) {
    const std::uint32_t f = links.face[c];
    return mesh.corner_vertex[c + 1 < mesh.face_start[f + 1] ? c + 1 : mesh.face_start[f]];
  };
  auto prev_vertex = [&](std::uint32_t c) {
    const std::uint32_t f = links.face[c];
    return mesh.corner_vertex[c > mesh.face_start[f] ? c - 1 : mesh.face_start[f + 1] - 1];
  };

  // (2) adjacency.
  const VertexCorners vc = vertex_corners(mesh);

  // (3) groups per vertex: group_of[c] = group number within its vertex (by first corner).
  std::vector<std::uint32_t> group_of(C), groups(V, 0);
  const double crease = crease_angle;
  parallel_ranges(V, [&](std::size_t v_begin, std::size_t v_end) {
    struct End { std::uint32_t far, local; bool out; };
    std::vector<End> ends;            // scratch, reused across the range's vertices
    std::vector<std::uint32_t> parent, number;
    for (std::size_t v = v_begin; v < v_end; ++v) {
      const std::uint32_t begin = vc.offset[v], end = vc.offset[v + 1], d = end - begin;
      if (d == 0) continue;
      ends.clear();
      parent.resize(d);
      for (std::uint32_t i = 0; i < d; ++i) {
        parent[i] = i;
        const std::uint32_t c = vc.corners[begin + i];
        if (!face_valid(links.face[c])) continue;  // edges of degenerate faces: creases
        const std::uint32_t n = next_vertex(c), p = prev_vertex(c);
        if (n != v) ends.push_back({n, i, true});
        if (p != v) ends.push_back({p, i, false});
      }
      std::sort(ends.begin(), ends.end(), [](const End& a, const End& b) {
        return a.far != b.far ? a.far < b.far : a.local < b.local;
      });
      for (std::size_t i = 0; i < ends.size();) {
        std::size_t j = i + 1;
        while (j < ends.size() && ends[j].far == ends[i].far) ++j;
        // Smooth only if exactly two faces meet at edge {v, far}, with opposite orientations
        // (one leaves v along it, the other arrives), and the dihedral angle is small enough.
        if (j - i == 2 && ends[i].out != ends[i + 1].out) {
          const std::uint32_t ca = vc.corners[begin + ends[i].local], cb = vc.corners[begin + ends[i + 1].local];
          const std::uint32_t fa = links.face[ca], fb = links.face[cb];
          if (fa != fb) {
            const Vec3d na = get3(fn, fa), nb = get3(fn, fb);
            const double angle = std::atan2(length(cross(na, nb)), dot(na, nb));
            if (angle <= crease) {
              const std::uint32_t ra = find_root(parent, ends[i].local), rb = find_root(parent, ends[i + 1].local);
              if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);  // root = smallest local index
            }
          }
        }
        i = j;
      }
      // Number groups by first corner; degenerate-face corners are numbered afterwards (below).
      number.assign(d, ~0u);
      std::uint32_t g = 0;
      bool any_degenerate = false;
      for (std::uint32_t i = 0; i < d; ++i) {
        const std::uint32_t c = vc.corners[begin + i];
        if (!face_valid(links.face[c])) { any_degenerate = true; continue; }
        const std::uint32_t r = find_root(parent, i);
        if (number[r] == ~0u) number[r] = g++;
        group_of[c] = number[r];
      }
      if (any_degenerate) {
        // Degenerate corners share the only group when there is one, else get their own.
        const std::uint32_t dg = g == 1 ? 0 : g++;
        for (std::uint32_t i = 0; i < d; ++i) {
          const std::uint32_t c = vc.corners[begin + i];
          if (!face_valid(links.face[c])) group_of[c] = dg;
        }
      }
      groups[v] = g;
    }
  });

  // (4) pool offsets.
  std::vector<std::uint32_t> base(V + 1, 0);
  for (std::size_t v = 0; v < V; ++v) base[v + 1] = base[v] + groups[v];
  CornerNormals out;
  out.normals.resize(3 * std::size_t(base[V]));
  out.corner_index.resize(C);

  // (5) sums and normals, in parallel over vertices (each writes only its own pool rows).
  std::vector<std::uint32_t> fallbacks(V, 0);
  parallel_ranges(V, [&](std::size_t v_begin, std::size_t v_end) {
    std::vector<Vec3<T>> sum;
    std::vector<std::uint32_t> first_face;
    for (std::size_t v = v_begin; v < v_end; ++v) {
      const std::uint32_t begin = vc.offset[v], end = vc.offset[v + 1], g = groups[v];
      if (g == 0) continue;
      sum.assign(g, Vec3<T>{});
      first_face.assign(g, ~0u);
      Vec3<T> smooth{};  // every valid contribution at v: the normal of degenerate corners
      bool has_degenerate = false;
      for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t c = vc.corners[i], f = links.face[c];
        const Vec3<T> n{contrib[3 * c], contrib[3 * c + 1], contrib[3 * c + 2]};
        if (!face_valid(f)) { has_degenerate = true; continue; }
        sum[group_of[c]] += n;
        smooth += n;
        if (first_face[group_of[c]] == ~0u) first_face[group_of[c]] = f;
      }
      // A group made only of degenerate corners (the vertex has 0 or 2+ regular groups) takes the
      // smooth normal; with exactly one regular group, that group's sum is the smooth sum.
      if (has_degenerate)
        for (std::uint32_t k = 0; k < g; ++k)
          if (first_face[k] == ~0u) sum[k] = smooth;
      for (std::uint32_t k = 0; k < g; ++k) {
        const T len = checked_length(sum[k]);
        double* o = &out.normals[3 * std::size_t(base[v] + k)];
        if (len > T(0)) {  // divisor checked
          o[0] = double(sum[k].x / len); o[1] = double(sum[k].y / len); o[2] = double(sum[k].z / len);
        } else {
          const bool has_face = first_face[k] != ~0u;
          for (int a = 0; a < 3; ++a) o[a] = has_face ? fn[3 * std::size_t(first_face[k]) + a] : kFallbackNormal[a];
          if (!has_face) {
            // Only degenerate corners and no valid face at all: as vertex_normals' fallback,
            // the first valid face of the vertex if any, else (0, 0, 1).
            for (std::uint32_t i = begin; i < end; ++i) {
              const std::uint32_t f = links.face[vc.corners[i]];
              if (face_valid(f)) { for (int a = 0; a < 3; ++a) o[a] = fn[3 * std::size_t(f) + a]; break; }
            }
          }
          for (std::uint32_t i = begin; i < end; ++i)
            if (group_of[vc.corners[i]] == k) ++fallbacks[v];
        }
      }
      for (std::uint32_t i = begin; i < end; ++i) out.corner_index[vc.corners[i]] = base[v] + group_of[vc.corners[i]];
    }
  });
  for (auto n : fallbacks) out.fallback_corners += n;
  for (std::size_t f = 0; f < F; ++f) out.degenerate_faces += !face_valid(f);
  return out;
}

}  // namespace

CornerNormals corner_normals(const Mesh& mesh, double crease_angle, Weighting weighting, Precision precision) {
  return dispatch(weighting, precision, [&](auto t, auto w) {
    using T = decltype(t);
    constexpr Weighting W = decltype(w)::value;
    return compute<T, W>(mesh, crease_angle, precision);
  });
}

}  // namespace shadetool
