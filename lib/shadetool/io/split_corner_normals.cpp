// split_corner_normals.cpp
#include <shadetool/io/split_corner_normals.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <shadetool/core/fallback_normal.h>

namespace shadetool::io {

Mesh split_corner_normals(const Mesh& mesh, std::size_t& added) {
  added = 0;
  Mesh out = mesh;
  if (!mesh.has_corner_normals()) return out;
  const std::size_t nv = mesh.num_vertices();
  const std::size_t nc = mesh.num_corners();

  // Corners bucketed by vertex (CSR): start[v]..start[v+1] in `bucket`.
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (std::uint32_t v : mesh.corner_vertex) ++start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> bucket(nc), fill(start.begin(), start.end() - 1);
  for (std::uint32_t c = 0; c < nc; ++c) bucket[fill[mesh.corner_vertex[c]]++] = c;

  out.vertex_normals.assign(3 * nv, 0.0);
  if (mesh.has_vertex_normals()) out.vertex_normals = mesh.vertex_normals;
  // A vertex no corner uses gets no normal below: it keeps a valid one it had, else the fallback.
  for (std::size_t v = 0; v < nv; ++v) {
    if (start[v] != start[v + 1]) continue;
    double* n = &out.vertex_normals[3 * v];
    const bool valid = std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) && (n[0] != 0 || n[1] != 0 || n[2] != 0);
    if (!valid)
      for (int j = 0; j < 3; ++j) n[j] = kFallbackNormal[j];
  }
  // For each normal index, the vertex that last used it (owner) and the output vertex made for
  // that use (copy_of): a lookup is O(1), so a vertex shared by k corners with k distinct normals
  // costs O(k), not O(k^2) (a hostile OBJ can give one vertex millions of distinct normals).
  const std::size_t nn = mesh.corner_normals.size() / 3;
  std::vector<std::uint32_t> owner(nn, UINT32_MAX), copy_of(nn);
  for (std::size_t v = 0; v < nv; ++v) {
    bool first = true;  // no normal of v seen yet: its first normal stays on v itself
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      const std::uint32_t c = bucket[k];
      const std::uint32_t n = mesh.corner_normal_index[c];
      std::uint32_t target = owner[n] == v ? copy_of[n] : UINT32_MAX;
      if (target == UINT32_MAX) {
        if (first) {
          target = static_cast<std::uint32_t>(v);
        } else {
          target = static_cast<std::uint32_t>(out.num_vertices());
          out.positions.insert(out.positions.end(), &mesh.positions[3 * v], &mesh.positions[3 * v] + 3);
          // The copy takes v's values in every per-vertex array (Mesh::for_each_vertex_array; its
          // normal is set just below) that has one value per vertex so far.
          out.for_each_vertex_array([&](auto& a, std::size_t width) {
            if (a.size() != width * target) return;
            for (std::size_t j = 0; j < width; ++j) a.push_back(a[width * v + j]);
          });
          ++added;
        }
        for (int j = 0; j < 3; ++j) out.vertex_normals[3 * std::size_t(target) + std::size_t(j)] = mesh.corner_normals[3 * std::size_t(n) + std::size_t(j)];
        owner[n] = static_cast<std::uint32_t>(v);
        copy_of[n] = target;
        first = false;
      }
      out.corner_vertex[c] = target;
    }
  }
  out.corner_normals.clear();
  out.corner_normal_index.clear();
  return out;
}

const Mesh& with_corner_normals_split(const Mesh& input, Mesh& storage, std::size_t& added) {
  added = 0;
  if (!input.has_corner_normals()) return input;
  storage = split_corner_normals(input, added);
  return storage;
}

bool corner_normals_disagree(const Mesh& mesh) {
  if (!mesh.has_corner_normals()) return false;
  const std::size_t V = mesh.num_vertices();
  std::vector<std::uint32_t> first(V, std::numeric_limits<std::uint32_t>::max());  // a corner normal index per vertex
  for (std::size_t c = 0; c < mesh.num_corners(); ++c) {
    const std::uint32_t v = mesh.corner_vertex[c], k = mesh.corner_normal_index[c];
    if (v >= V || 3 * std::size_t(k) + 2 >= mesh.corner_normals.size()) return false;  // malformed: left to the caller
    if (first[v] == std::numeric_limits<std::uint32_t>::max()) {
      first[v] = k;
    } else if (first[v] != k && get3(mesh.corner_normals, first[v]) != get3(mesh.corner_normals, k)) {
      return true;
    }
  }
  return false;
}

const Mesh& with_creases_split(const Mesh& input, Mesh& storage, std::size_t& added) {
  added = 0;
  if (!corner_normals_disagree(input)) return input;
  storage = split_corner_normals(input, added);
  return storage;
}

}  // namespace shadetool::io
