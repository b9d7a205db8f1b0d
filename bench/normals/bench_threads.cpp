// bench_threads: the parallel sum of vertex_normals alone, 1 thread against 2, with warm caches.
//
// Usage: bench_threads [--reps R] [--weighting area|angle|max|uniform]
// Mesh: the irregular UV sphere of bench_normals (1M triangles). Unlike bench_normals, which
// interleaves our kernels with OpenMesh's (so every run starts with cold caches and the two
// threads share the memory bus), this program runs only our kernels, round-robin, with one
// VertexNormalsPlan per thread count made before timing and the arenas kept. Rows: 1 thread with
// the 1-thread plan (the serial loop); 1 thread with the 2-thread plan (the chunked path's cost on
// one core); 2 threads with the 2-thread plan; the plain call on 2 threads (serial). A trivially
// parallel control loop (sqrt) runs in the same rounds: its speed-up says whether the second core
// was free. Medians of wall and process CPU time; the load average before and after.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "load_average.h"
#include "parallel_control.h"
#include <shadetool/normals/vertex_normals.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 31;
  Weighting w = Weighting::Area;
  std::string wname = "area";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--weighting") && i + 1 < argc) {
      wname = argv[++i];
      if (wname == "area") w = Weighting::Area;
      else if (wname == "angle") w = Weighting::Angle;
      else if (wname == "max") w = Weighting::Max;
      else if (wname == "uniform") w = Weighting::Uniform;
      else { std::fprintf(stderr, "bench_threads: unknown weighting '%s'\n", wname.c_str()); return 2; }
    } else {
      std::fprintf(stderr, "usage: bench_threads [--reps R] [--weighting area|angle|max|uniform]\n");
      return 2;
    }
  }
  const std::string load_start = load_average();
  const testing::AnalyticMesh am = testing::irregular(testing::uv_sphere(1000, 500, 0.15, 11), 13);
  const Mesh& m = am.mesh;
  tbb::task_arena a1(1), a2(2);
  VertexNormalsPlan p1, p2;
  a1.execute([&] { p1 = VertexNormalsPlan(m); });
  const double t0 = wall_ms();
  a2.execute([&] { p2 = VertexNormalsPlan(m); });
  const double plan_ms = wall_ms() - t0;
  VertexNormals r1, r2, r3, r4;
  double sink = 0;
  auto control = [&](tbb::task_arena& a) {
    a.execute([&] { sink += parallel_sqrt_control(); });
  };
  struct Case { const char* name; std::function<void()> run; std::vector<double> wall, cpu; };
  std::vector<Case> cases = {
      {"1 thread, 1-thread plan (serial loop)", [&] { a1.execute([&] { vertex_normals(m, p1, w, Precision::Double, r1); }); }, {}, {}},
      {"1 thread, 2-thread plan (chunked path on one core)", [&] { a1.execute([&] { vertex_normals(m, p2, w, Precision::Double, r2); }); }, {}, {}},
      {"2 threads, 2-thread plan", [&] { a2.execute([&] { vertex_normals(m, p2, w, Precision::Double, r3); }); }, {}, {}},
      {"2 threads, plain call (serial)", [&] { a2.execute([&] { vertex_normals(m, w, Precision::Double, r4); }); }, {}, {}},
      {"control: parallel sqrt loop, 1 thread", [&] { control(a1); }, {}, {}},
      {"control: parallel sqrt loop, 2 threads", [&] { control(a2); }, {}, {}},
  };
  for (int rep = -1; rep < reps; ++rep)
    for (Case& c : cases) {
      const double c0 = cpu_ms(), w0 = wall_ms();
      c.run();
      if (rep >= 0) { c.wall.push_back(wall_ms() - w0); c.cpu.push_back(cpu_ms() - c0); }
    }
  auto median = [](std::vector<double> x) { std::sort(x.begin(), x.end()); return x[x.size() / 2]; };
  std::printf("mesh: irregular UV sphere, %zu vertices, %zu triangles; %s weighting, double; median of %d rounds\n",
              m.num_vertices(), m.num_faces(), wname.c_str(), reps);
  std::printf("plan for 2 threads built in %.2f ms (once; not in the rows)\n\n", plan_ms);
  std::printf("| case | median ms | median CPU ms |\n|---|---:|---:|\n");
  for (Case& c : cases) std::printf("| %s | %.2f | %.2f |\n", c.name, median(c.wall), median(c.cpu));
  const double s1 = median(cases[0].wall), s2 = median(cases[2].wall);
  const double c1 = median(cases[4].wall), c2 = median(cases[5].wall);
  std::printf("\n2 threads / 1 thread (plan): %.2fx; control: %.2fx; bitwise equal: %s\n", s1 / s2, c1 / c2,
              (r1.normals == r2.normals && r1.normals == r3.normals && r1.normals == r4.normals) ? "yes" : "NO");
  std::printf("load average (1, 5, 15 min) at start: %s, at end: %s\n", load_start.c_str(), load_average().c_str());
  return sink == 12345.0;  // keeps the control's work
}
