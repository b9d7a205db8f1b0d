// check_sphere_normals.cpp: bench_check_sphere_normals FILE..., the angular error of the vertex
// normals stored in mesh files whose vertices lie on the unit sphere centred at the origin (the
// end-to-end outputs of shadetool, assimp and MeshLab on sphere_*), where the exact normal at p
// is p / |p|. Works whether or not the writer joined vertices (assimp writes one per corner).
// Prints CSV: file,vertices,mean_deg,p99_deg,max_deg,nan_or_zero,no_normals.
// (Positions stored as float sit ~1e-7 off the sphere: ~1e-5 degrees of the error is theirs.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <shadetool/files/mesh_files.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

int main(int argc, char** argv) {
  std::puts("file,vertices,mean_deg,p99_deg,max_deg,nan_or_zero,no_normals");
  int rc = 0;
  for (int i = 1; i < argc; ++i) {
    try {
      const Mesh m = read_mesh(argv[i]);
      const std::size_t V = m.num_vertices();
      // Per-vertex normals, or per-corner ones (the first corner of each vertex) if that is what was read.
      std::vector<double> n(3 * V, NAN);
      std::size_t no_normals = 0;
      if (m.has_vertex_normals()) {
        n = m.vertex_normals;
      } else if (m.has_corner_normals()) {
        for (std::size_t c = 0; c < m.num_corners(); ++c) {
          double* o = &n[3 * std::size_t(m.corner_vertex[c])];
          if (std::isnan(o[0])) for (int k = 0; k < 3; ++k) o[k] = m.corner_normals[3 * std::size_t(m.corner_normal_index[c]) + k];
        }
      } else {
        no_normals = V;
      }
      std::vector<double> err;
      std::size_t bad = 0;
      for (std::size_t v = 0; v < V && !no_normals; ++v) {
        const Vec3d nv = get3(n, v), p = m.position(v);
        const double len = std::sqrt(dot(nv, nv));
        if (!std::isfinite(len) || len < 1e-6) { ++bad; continue; }
        err.push_back(testing::angle_degrees(nv, p));
      }
      double mean = NAN, p99 = NAN, mx = NAN;
      if (!err.empty()) {
        double s = 0;
        for (double e : err) s += e;
        mean = s / double(err.size());
        const std::size_t k = std::min(err.size() - 1, std::size_t(std::ceil(0.99 * double(err.size()))) - 1);
        std::nth_element(err.begin(), err.begin() + std::ptrdiff_t(k), err.end());
        p99 = err[k];
        mx = *std::max_element(err.begin() + std::ptrdiff_t(k), err.end());
      }
      std::printf("%s,%zu,%.6g,%.6g,%.6g,%zu,%zu\n", argv[i], V, mean, p99, mx, bad, no_normals);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_check_sphere_normals: %s\n", e.what());
      rc = 1;
    }
  }
  return rc;
}
