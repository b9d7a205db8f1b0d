// two_sided_faces.cpp: see two_sided_faces.h.
#include <shadetool/normals/two_sided_faces.h>

#include <algorithm>

namespace shadetool {

namespace {

// True when g runs through f's vertices in the reverse cyclic order (same corner count).
bool reverse_of(const Mesh& mesh, std::uint32_t f, std::uint32_t g) {
  const std::uint32_t fb = mesh.face_start[f], gb = mesh.face_start[g];
  const std::uint32_t k = mesh.face_start[f + 1] - fb;
  if (mesh.face_start[g + 1] - gb != k) return false;
  const std::uint32_t a0 = mesh.corner_vertex[fb];
  for (std::uint32_t j = 0; j < k; ++j) {
    if (mesh.corner_vertex[gb + j] != a0) continue;
    bool all = true;  // f[i] == g[j - i mod k] for every i
    for (std::uint32_t i = 1; i < k && all; ++i) all = mesh.corner_vertex[fb + i] == mesh.corner_vertex[gb + (j + k - i) % k];
    if (all) return true;
  }
  return false;
}

}  // namespace

TwoSidedFaces two_sided_faces(const Mesh& mesh) {
  const std::size_t F = mesh.num_faces(), V = mesh.num_vertices();
  TwoSidedFaces out;
  out.front_of.assign(F, TwoSidedFaces::kNotBack);
  // Bucket by smallest vertex (CSR).
  std::vector<std::uint32_t> start(V + 1, 0), smallest(F, ~0u);
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    if (e - b < 3) continue;
    const std::uint32_t m = *std::min_element(mesh.corner_vertex.begin() + b, mesh.corner_vertex.begin() + e);
    if (m >= V) continue;
    smallest[f] = m;
    ++start[m + 1];
  }
  for (std::size_t v = 0; v < V; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> bucket(start[V]), fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < F; ++f)
    if (smallest[f] != ~0u) bucket[fill[smallest[f]]++] = std::uint32_t(f);  // ascending face order
  std::vector<std::uint8_t> has_back(F, 0);
  for (std::size_t v = 0; v < V; ++v)
    for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
      const std::uint32_t g = bucket[i];
      for (std::uint32_t j = start[v]; j < i; ++j) {
        const std::uint32_t f = bucket[j];
        if (has_back[f] || out.front_of[f] != TwoSidedFaces::kNotBack || !reverse_of(mesh, f, g)) continue;
        out.front_of[g] = f;
        has_back[f] = 1;
        ++out.backs;
        break;
      }
    }
  return out;
}

Mesh front_faces(const Mesh& mesh, const TwoSidedFaces& two_sided) {
  Mesh out;
  out.positions = mesh.positions;
  out.precision = mesh.precision;
  out.face_start.assign(1, 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (two_sided.front_of[f] != TwoSidedFaces::kNotBack) continue;
    out.corner_vertex.insert(out.corner_vertex.end(), mesh.corner_vertex.begin() + mesh.face_start[f],
                             mesh.corner_vertex.begin() + mesh.face_start[f + 1]);
    out.face_start.push_back(std::uint32_t(out.corner_vertex.size()));
  }
  return out;
}

}  // namespace shadetool
