// bench_tangents: MikkTSpace tangents (normals/tangents.h) against angle-weighted corner normals
// (corner_normals, crease 180 degrees) on the same mesh: a UV torus grid with texture coordinates
// (a seam at u = 1 and v = 1: split texture coordinates, as real files have). Median of N runs,
// one thread for both (the tangents are serial), the two timed round-robin in process CPU time. Writes the unindexed float inputs for the npm
// reference when --dump FILE is given (bench/normals/bench_tangents.js times it).
// usage: bench_tangents [--n GRID] [--runs N] [--dump FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <time.h>
#include <vector>

#include <tbb/global_control.h>

#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/tangents.h>
#include <shadetool/normals/vertex_normals.h>

#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

// The textured torus of tests/support/analytic_meshes.h (radii 1 and 0.35, (n + 1)^2 texture
// coordinates: the seam rows and columns repeat), with angle-weighted vertex normals.
Mesh torus_grid(int n) {
  Mesh m = shadetool::testing::textured_torus(n).mesh;
  m.vertex_normals = vertex_normals(m, Weighting::Angle, Precision::Double).normals;
  return m;
}

// Process CPU time in milliseconds (one thread: wall time minus what the other builds on the
// machine take from us).
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

template <class F>
double time_cpu_ms(F&& f) {
  const double a = cpu_ms();
  f();
  return cpu_ms() - a;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int n = 400, runs = 7;
  std::string dump;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--n")) n = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--runs")) runs = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--dump")) dump = argv[i + 1];
  }
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const Mesh m = torus_grid(n);
  const std::size_t C = m.num_corners();
  volatile double sink = 0;
  // Round-robin: each run times the normals, then the tangents, so that both see the same load.
  std::vector<double> normals_runs, tangents_runs, ratios;
  for (int k = 0; k < runs; ++k) {
    normals_runs.push_back(time_cpu_ms([&] { sink = sink + corner_normals(m, 3.141592653589793).normals[0]; }));
    tangents_runs.push_back(time_cpu_ms([&] { sink = sink + mikktspace_tangents(m).tangents[0]; }));
    ratios.push_back(tangents_runs.back() / normals_runs.back());
  }
  const double normals_ms = median(normals_runs), tangents_ms = median(tangents_runs);
  std::printf("mesh: torus grid %d x %d, %zu triangles, %zu corners; median of %d round-robin runs, 1 thread, process CPU time\n",
              n, n, m.num_faces(), C, runs);
  std::printf("| what | median CPU ms | corners per second |\n|---|---|---|\n");
  std::printf("| corner normals (angle, crease 180) | %.2f | %.3g |\n", normals_ms, C / (normals_ms / 1000));
  std::printf("| MikkTSpace tangents (ours) | %.2f | %.3g |\n", tangents_ms, C / (tangents_ms / 1000));
  std::printf("tangents / normals: %.2fx (median of the per-run ratios: %.2fx)\n", tangents_ms / normals_ms, median(ratios));
  if (!dump.empty()) {
    std::vector<float> d;
    for (std::size_t c = 0; c < C; ++c) {
      const Vec3d p = m.position(m.corner_vertex[c]), nn = get3(m.vertex_normals, m.corner_vertex[c]);
      const std::size_t t = 2 * std::size_t(m.corner_texcoord_index[c]);
      for (double x : {p.x, p.y, p.z, nn.x, nn.y, nn.z, m.texcoords[t], m.texcoords[t + 1]}) d.push_back(float(x));
    }
    std::ofstream(dump, std::ios::binary).write(reinterpret_cast<const char*>(d.data()), std::streamsize(d.size() * 4));
  }
  return 0;
}
