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
  // Each face rotated to start at its smallest vertex m, bucketed by m (counts, offsets, data).
  // A triangle (m, n, p) is the back of (m, p, n): its key (n, p) packed in 64 bits, so a bucket
  // is searched by integer compares; larger faces compare corner by corner (reverse_of).
  auto smallest = [&](std::size_t f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    std::uint32_t at = b;
    for (std::uint32_t c = b + 1; c < e; ++c)
      if (mesh.corner_vertex[c] < mesh.corner_vertex[at]) at = c;
    return at;  // the corner holding the smallest vertex
  };
  std::vector<std::uint32_t> start(V + 2, 0);
  for (std::size_t f = 0; f < F; ++f) {
    if (mesh.face_start[f + 1] - mesh.face_start[f] < 3) continue;
    const std::uint32_t m = mesh.corner_vertex[smallest(f)];
    if (m < V) ++start[m + 2];
  }
  for (std::size_t v = 0; v < V; ++v) start[v + 2] += start[v + 1];
  // After placing, bucket v is [start[v], start[v + 1]) (each placement advances start[v + 1]).
  // Keys and faces in two arrays (12 bytes a face, not a padded 16-byte struct): this is the
  // peak of `normals` on a large mesh (bench/io/results.md, "Writing streams").
  constexpr std::uint64_t kNever = ~std::uint64_t(0) - 1;  // matches nothing
  std::vector<std::uint64_t> bucket_key(start[V + 1]);
  std::vector<std::uint32_t> bucket_face(start[V + 1]);
  for (std::size_t f = 0; f < F; ++f) {
    const std::uint32_t b = mesh.face_start[f], e = mesh.face_start[f + 1];
    if (e - b < 3) continue;
    const std::uint32_t at = smallest(f), m = mesh.corner_vertex[at];
    if (m >= V) continue;
    std::uint64_t key = ~std::uint64_t(0);  // polygons: compared by reverse_of
    if (e - b == 3) {
      const std::uint32_t n = mesh.corner_vertex[at + 1 < e ? at + 1 : b], p = mesh.corner_vertex[at > b ? at - 1 : e - 1];
      key = n == p || n == m || p == m ? kNever : std::uint64_t(n) << 32 | p;  // a repeated index: no winding
    }
    const std::uint32_t slot = start[m + 1]++;  // ascending face order within a bucket
    bucket_key[slot] = key;
    bucket_face[slot] = std::uint32_t(f);
  }
  std::vector<std::uint8_t> paired;  // faces already a front or a back; sized on the first pair
  for (std::size_t v = 0; v < V; ++v)
    for (std::uint32_t i = start[v] + 1; i < start[v + 1]; ++i) {
      const std::uint64_t g_key = bucket_key[i];
      const std::uint32_t g_face = bucket_face[i];
      if (g_key == kNever) continue;
      const std::uint64_t want = g_key == ~std::uint64_t(0) ? g_key : (g_key << 32 | g_key >> 32);
      for (std::uint32_t j = start[v]; j < i; ++j) {
        const std::uint32_t f_face = bucket_face[j];
        if (bucket_key[j] != want || (!paired.empty() && paired[f_face])) continue;
        if (want == ~std::uint64_t(0) && !reverse_of(mesh, f_face, g_face)) continue;
        if (paired.empty()) {
          paired.assign(F, 0);
          out.front_of.assign(F, TwoSidedFaces::kNotBack);
        }
        out.front_of[g_face] = f_face;
        paired[f_face] = paired[g_face] = 1;
        ++out.backs;
        break;
      }
    }
  if (out.front_of.empty()) {
    // The buckets go before front_of comes: not both at once (the peak, as above).
    std::vector<std::uint64_t>().swap(bucket_key);
    std::vector<std::uint32_t>().swap(bucket_face);
    std::vector<std::uint32_t>().swap(start);
    out.front_of.assign(F, TwoSidedFaces::kNotBack);
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
