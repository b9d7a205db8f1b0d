// bench_tangents: MikkTSpace tangents (normals/tangents.h) against angle-weighted corner normals
// (corner_normals, crease 180 degrees) on the same mesh: a UV torus grid with texture coordinates
// (a seam at u = 1 and v = 1: split texture coordinates, as real files have). Median of N runs,
// one thread for both (the tangents are serial), the two timed round-robin in process CPU time.
// Writes the unindexed float inputs for the npm reference when --dump FILE is given
// (bench/normals/bench_tangents.js times it).
//
// The allocator (--malloc): the two rows alternate in one process, and with glibc's defaults each
// row's frees give memory back (heap trim, dynamic mmap threshold) that the other row's next call
// faults in again: the tangents' 30.7 MB output got fresh pages on every timed call, or did not,
// depending on where the corner normals' blocks had landed (tangents_steps.md, "tangents6"). So the
// figure is taken with the allocator kept warm for both rows alike (`warm`, the default: mallopt
// M_TRIM_THRESHOLD INT_MAX, M_MMAP_THRESHOLD 32 MiB, M_TOP_PAD 64 MiB, set once before the mesh is
// built, and one untimed round): each row's steady cost, no page fault in a timed call (the median
// faults per call are printed). `glibc` keeps glibc's defaults (the protocol before tangents6).
// --fresh N adds what one `shadetool normals --tangents` pays: N processes of each row,
// interleaved, each timing one call on glibc's defaults, faults included (this binary re-run with
// --single ROW).
// usage: bench_tangents [--n GRID] [--runs N] [--malloc warm|glibc] [--fresh N] [--dump FILE]
//        bench_tangents --single normals|tangents [--n GRID]   (one call; prints its CPU ms)
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

#include <climits>
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

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

// Minor page faults of this process so far (fresh pages the kernel had to map and zero).
double minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_minflt);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One call of `row` in a fresh process (this binary with --single ROW, glibc's default allocator):
// its CPU ms, or -1 when the child failed.
double fresh_call_ms(const char* self, int n, const char* row) {
  const std::string cmd = std::string("'") + self + "' --single " + row + " --n " + std::to_string(n);
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  double ms = -1;
  if (std::fscanf(p, "%lf", &ms) != 1) ms = -1;
  return pclose(p) == 0 ? ms : -1;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 400, runs = 7, fresh = 0;
  std::string dump, single, malloc_mode = "warm";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--n")) n = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--runs")) runs = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--dump")) dump = argv[i + 1];
    else if (!std::strcmp(argv[i], "--malloc")) malloc_mode = argv[i + 1];
    else if (!std::strcmp(argv[i], "--fresh")) fresh = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--single")) single = argv[i + 1];
    else { std::fprintf(stderr, "bench_tangents: unknown option %s\n", argv[i]); return 2; }
  }
  if (malloc_mode != "warm" && malloc_mode != "glibc") {
    std::fprintf(stderr, "bench_tangents: --malloc takes warm or glibc, not %s\n", malloc_mode.c_str());
    return 2;
  }
  if (malloc_mode == "warm" && single.empty()) {
    // Keep freed memory in the heap (no trim, no mmap for blocks up to 32 MiB, grow by 64 MiB):
    // applied to both rows alike, before anything is allocated.
    mallopt(M_TRIM_THRESHOLD, INT_MAX);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TOP_PAD, 64 << 20);
  }
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const Mesh m = torus_grid(n);
  const std::size_t C = m.num_corners();
  volatile double sink = 0;
  if (!single.empty()) {
    double ms;
    if (single == "normals") ms = time_cpu_ms([&] { sink = sink + corner_normals(m, 3.141592653589793).normals[0]; });
    else if (single == "tangents") ms = time_cpu_ms([&] { sink = sink + mikktspace_tangents(m).tangents[0]; });
    else { std::fprintf(stderr, "bench_tangents: --single takes normals or tangents, not %s\n", single.c_str()); return 2; }
    std::printf("%.4f\n", ms);
    return 0;
  }
  // Round-robin: each run times the normals, then the tangents, so that both see the same load.
  // With the allocator warm, one untimed round first: the heap reaches its size there, and the
  // timed calls fault in no page (the faults per call are printed to show it).
  auto normals_call = [&] { sink = sink + corner_normals(m, 3.141592653589793).normals[0]; };
  auto tangents_call = [&] { sink = sink + mikktspace_tangents(m).tangents[0]; };
  if (malloc_mode == "warm") normals_call(), tangents_call();
  std::vector<double> normals_runs, tangents_runs, ratios, normals_faults, tangents_faults;
  for (int k = 0; k < runs; ++k) {
    double f0 = minor_faults();
    normals_runs.push_back(time_cpu_ms(normals_call));
    double f1 = minor_faults();
    tangents_runs.push_back(time_cpu_ms(tangents_call));
    tangents_faults.push_back(minor_faults() - f1), normals_faults.push_back(f1 - f0);
    ratios.push_back(tangents_runs.back() / normals_runs.back());
  }
  const double normals_ms = median(normals_runs), tangents_ms = median(tangents_runs);
  std::printf("mesh: torus grid %d x %d, %zu triangles, %zu corners; median of %d round-robin runs, 1 thread, process CPU time, allocator %s\n",
              n, n, m.num_faces(), C, runs, malloc_mode == "warm" ? "kept warm (mallopt: no trim, mmap above 32 MiB, top pad 64 MiB)" : "glibc's defaults");
  std::printf("| what | median CPU ms | corners per second |\n|---|---|---|\n");
  std::printf("| corner normals (angle, crease 180) | %.2f | %.3g |\n", normals_ms, C / (normals_ms / 1000));
  std::printf("| MikkTSpace tangents (ours) | %.2f | %.3g |\n", tangents_ms, C / (tangents_ms / 1000));
  std::printf("tangents / normals: %.2fx (median of the per-run ratios: %.2fx)\n", tangents_ms / normals_ms, median(ratios));
  std::printf("page faults per timed call (median): normals %.0f, tangents %.0f\n", median(normals_faults), median(tangents_faults));
  if (fresh > 0) {
    // Interleaved: a normals process, then a tangents process, N times.
    char self[4096];
    const ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
    if (len <= 0) { std::fprintf(stderr, "bench_tangents: cannot read /proc/self/exe\n"); return 1; }
    self[len] = 0;
    std::vector<double> fn, ft;
    for (int k = 0; k < fresh; ++k) {
      const double a = fresh_call_ms(self, n, "normals"), b = fresh_call_ms(self, n, "tangents");
      if (a <= 0 || b <= 0) { std::fprintf(stderr, "bench_tangents: a --single child failed\n"); return 1; }
      fn.push_back(a), ft.push_back(b);
    }
    std::printf("one call per fresh process (%d processes of each, interleaved, glibc's defaults, faults included): normals %.2f ms, tangents %.2f ms, ratio per fresh process: %.2fx\n",
                fresh, median(fn), median(ft), median(ft) / median(fn));
  }
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
