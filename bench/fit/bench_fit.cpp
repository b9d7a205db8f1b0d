// bench_fit: `bake-lighting --fit point` against `--fit least-squares` at 1, 3 and 6 quadrature
// points per triangle (lighting/fit_vertex_lighting.h), on tori of about 10k, 100k (and 1M)
// triangles under data/scenes/studio.json and window.json.
//   time   the whole per-vertex bake: bake_lighting (the point colours), plus for least squares the
//          quadrature, f at its points, assembly and CG (8-bit: to kEightBitFitAccuracy, as
//          bake-lighting); wall and process CPU time, medians of REPEATS runs, the methods taken
//          round-robin
//   error  relative L2 distance of the interpolated colours (8-bit bounds: clamped to [0, 1], as
//          written) to the per-point colour render --shading phong computes (clamped likewise),
//          measured with the 12-point degree-6 rule: finer than any fit's own rule, so no fit is
//          scored by its own objective
// Usage: bench_fit table SRC_DIR [REPEATS] [MAX_TRIANGLES] [MIN_TRIANGLES] [studio|window|both] [RULES]
//                  (default 7, 200000, 0, both scenes, RULES 1,3,6: least squares at those points
//                  per triangle, beside the point bake)
//        bench_fit fresh SRC_DIR [REPEATS] [MAX_TRIANGLES] [MIN_TRIANGLES] [studio|window|both] [RULES]
//                  (table's rows, every bake in a fresh process of its own: `bench_fit once SRC_DIR
//                  U V SCENE SAMPLES`, the methods alternating process by process; run.sh's 1M rows)
//        bench_fit breakdown SRC_DIR [REPEATS] [MAX_TRIANGLES] [MIN_TRIANGLES] [studio|window]
//                  (the least-squares time per stage)
//        bench_fit errors SRC_DIR [MAX_TRIANGLES]   (error at several λ, with and without 8-bit bounds)
//        bench_fit variants SRC_DIR   (error of each objective and bound handling for 8-bit output)
//        bench_fit floor SRC_DIR [REPEATS] [MAX_TRIANGLES] [MIN_TRIANGLES] [studio|window]
//                  (default 11, 20000: the ratio's floor, the shading at the sites, and the rest)
// FIT_THREADS=N in the environment: at most N threads (1: no thread pool spin in the CPU times).
// FIT_MALLOC_KEEP=1: freed memory kept by the allocator (no page faults of first touch after the
// first repetition).
//        bench_fit solve SRC_DIR SAMPLES N [1m|99k]   (least_squares_fit alone; FIT_VECTORS=double: CG's
//                  vectors in double, as the HDR path stores them)
//        bench_fit bytes SRC_DIR SCENE SAMPLES   (1M torus, 8-bit: the bytes of the float-vector solve
//                  against the double one, and the exact solution's distance to the byte boundary
//                  where they differ)
//        bench_fit picture SRC_DIR OUT.png   (point Gouraud | least-squares Gouraud | Phong, coarse)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <malloc.h>
#include <unistd.h>

#include <tbb/global_control.h>

#include <shadetool/fit/least_squares_fit.h>
#include <shadetool/io/image_png.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include <shadetool/lighting/fit_vertex_lighting.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/render/render_mesh.h>

#include "../bench_timing.h"
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

std::vector<double> clamped(std::vector<double> v) {
  for (double& x : v) x = std::min(std::max(x, 0.0), 1.0);
  return v;
}

// One bake: the point colours (samples 0) or the least-squares fit at `samples` points per
// triangle, 8-bit bounds as bake-lighting writes them. Returns the colours.
std::vector<double> bake(const Mesh& mesh, const Scene& scene, int samples) {
  // least squares without --stats or --json: the normals only (VertexColors::None), as bake-lighting
  const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {},
                                         samples == 0 ? VertexColors::All : VertexColors::None);
  if (samples == 0) return clamped(point.rgb);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  fit.samples = samples;
  fit.solve.upper = 1;  // 8-bit, as bake-lighting writes it
  fit.solve.accuracy = kEightBitFitAccuracy;
  fit.measure_error = false;  // as bake-lighting without --stats or --json (the table's error is measured apart)
  return fit_vertex_lighting(mesh, scene, point, {}, {}, fit).rgb;
}

// One bake's process CPU and wall time, ms.
struct BakeTime {
  double cpu = 0, wall = 0;
};

// How `table` times method `m` on a mesh: in this process, or in a process of its own. False: the
// timing failed (the table stops, exit 1).
using TimeBake = std::function<bool(const Mesh& mesh, const Scene& scene, const int torus[2], const char* scene_name,
                                    int method, BakeTime& t)>;

// The four methods (point, least squares at 1, 3, 6 points) timed round-robin: each repetition runs
// every method once, so that the load of the machine falls on all of them alike. Wall and process
// CPU time, medians. The errors are measured first, and the reference's memory (12 points per
// triangle) freed before the timing.
int table(const std::string& src, int repeats, std::size_t max_triangles, std::size_t min_triangles,
          const std::string& only_scene, const std::vector<int>& methods, const TimeBake& time_bake) {
  std::printf("| mesh | scene | method | wall ms | CPU ms | x point (CPU) | relative L2 error | vs point |\n"
              "|---|---|---|---|---|---|---|---|\n");
  const int sizes[][2] = {{100, 50}, {316, 158}, {1000, 500}};
  const int M = int(methods.size());  // methods[0] is 0: the point bake, the ratios' denominator
  for (const auto& s : sizes) {
    const std::size_t triangles = std::size_t(2 * s[0] * s[1]);
    if (triangles > max_triangles || triangles < min_triangles) continue;
    const Mesh mesh = testing::torus(s[0], s[1], 1.0, 0.4).mesh;
    for (const char* name : {"studio", "window"}) {
      if (!only_scene.empty() && only_scene != name) continue;
      const Scene scene = read_scene(src + "/data/scenes/" + name + ".json");
      std::vector<double> error(M);
      {
        const BakeResult normals = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
        const std::vector<double> world = world_positions(mesh, scene);
        const FitQuadrature ref = fit_quadrature(fit_elements(mesh), world, 12);
        const std::vector<double> f = clamped(lighting_at_quadrature(mesh, scene, ref, world, normals.vertex_normals, {}, {}));
        for (int m = 0; m < M; ++m) error[m] = relative_l2_error(ref, f, bake(mesh, scene, methods[m]), 3);
      }
      std::vector<std::vector<double>> wall(M), cpu(M);
      for (int k = 0; k < repeats; ++k)
        for (int m = 0; m < M; ++m) {
          BakeTime t;
          if (!time_bake(mesh, scene, s, name, methods[m], t)) return 1;
          cpu[m].push_back(t.cpu);
          wall[m].push_back(t.wall);
        }
      for (int m = 0; m < M; ++m) {
        std::printf("| torus %zuk tri | %s | %s | %.1f | %.1f | %.2f | %.3g | %+.0f%% |\n", mesh.num_faces() / 1000, name,
                    m == 0 ? "point" : ("least squares, " + std::to_string(methods[m]) + " pt").c_str(), median(wall[m]),
                    median(cpu[m]), median(cpu[m]) / median(cpu[0]), error[m], 100 * (error[m] / error[0] - 1));
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

// table's timing in this process: bake after bake on the heap the previous ones left.
bool time_in_process(const Mesh& mesh, const Scene& scene, const int*, const char*, int method, BakeTime& t) {
  const double w0 = now_ms(), c0 = cpu_ms();
  bake(mesh, scene, method);
  t.cpu = cpu_ms() - c0;
  t.wall = now_ms() - w0;
  return true;
}

// table's timing with every bake in a fresh process of its own (`bench_fit once`), as a user's
// `bake-lighting` runs it: one bake per process, its memory fresh (page faults of first touch
// included, for every method alike), no row timed on the heap another row left. Process CPU time
// of the bake alone (the child's, from before the bake to after it; not the mesh's generation), the
// methods alternating process by process (repetition k runs point, 1, 3, ... in turn).
TimeBake time_in_fresh_process(const char* self, const std::string& src) {
  return [self, src](const Mesh&, const Scene&, const int torus[2], const char* scene_name, int method, BakeTime& t) {
    const std::string command = std::string(self) + " once '" + src + "' " + std::to_string(torus[0]) + " " +
                                std::to_string(torus[1]) + " " + scene_name + " " + std::to_string(method);
    FILE* child = popen(command.c_str(), "r");
    const bool read = child && std::fscanf(child, "%lf %lf", &t.cpu, &t.wall) == 2;
    if (!child || pclose(child) != 0 || !read) {
      std::fprintf(stderr, "bench_fit fresh: '%s' failed\n", command.c_str());
      return false;
    }
    return true;
  };
}

// Where the time of one least-squares bake goes, per stage, in process CPU time (every thread's:
// the work, not the wait), medians of `repeats` runs with the
// stages taken in turn within each run (round-robin): the point bake, the quadrature (elements and
// points), f at the quadrature points (lighting_at_quadrature: interpolation and shade_point),
// the normal equations' assembly (least_squares_fit stopped at once: tolerance 1, no CG step
// taken from the first guess), and the conjugate gradient (the full fit minus the assembly).
int breakdown(const std::string& src, int repeats, std::size_t max_triangles, std::size_t min_triangles,
              const std::string& only_scene) {
  std::printf("| mesh | scene | pt | point bake | normals only | quadrature | f at points | assembly | CG | CG iterations | total LS | f evals / vertex |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const int sizes[][2] = {{100, 50}, {316, 158}, {1000, 500}};
  for (const auto& s : sizes) {
    const std::size_t triangles = std::size_t(2 * s[0] * s[1]);
    if (triangles > max_triangles || triangles < min_triangles) continue;
    const Mesh mesh = testing::torus(s[0], s[1], 1.0, 0.4).mesh;
    for (const char* name : {"studio", "window"}) {
      if (!only_scene.empty() && only_scene != name) continue;
      const Scene scene = read_scene(src + "/data/scenes/" + name + ".json");
      for (int samples : {1, 3, 6}) {
        std::vector<double> t_point, t_normals, t_quad, t_f, t_asm, t_cg;
        int iterations = 0;
        std::size_t points = 0;
        for (int k = 0; k < repeats; ++k) {
          double t0 = cpu_ms();
          const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
          t_point.push_back(cpu_ms() - t0);
          t0 = cpu_ms();  // what least squares runs of the bake (bake-lighting without --stats or --json)
          bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {}, VertexColors::None);
          t_normals.push_back(cpu_ms() - t0);
          t0 = cpu_ms();
          const std::vector<double> world = world_positions(mesh, scene);
          const FitElements elements = fit_elements(mesh);
          const FitQuadrature q = fit_quadrature(elements, world, samples);
          t_quad.push_back(cpu_ms() - t0);
          points = q.size();
          t0 = cpu_ms();
          std::vector<double> f = clamped(lighting_at_quadrature(mesh, scene, q, world, point.vertex_normals, {}, {}));
          t_f.push_back(cpu_ms() - t0);
          LeastSquaresFitOptions o;
          o.upper = 1;
          o.tolerance = 1;
          t0 = cpu_ms();
          least_squares_fit(elements, world, q, f, point.rgb, 3, o);
          const double assembly = cpu_ms() - t0;
          t_asm.push_back(assembly);
          o.tolerance = LeastSquaresFitOptions{}.tolerance;
          o.accuracy = kEightBitFitAccuracy;  // as bake-lighting's 8-bit output
          t0 = cpu_ms();
          iterations = least_squares_fit(elements, world, q, f, point.rgb, 3, o).iterations;
          t_cg.push_back(std::max(0.0, cpu_ms() - t0 - assembly));
        }
        const double total = median(t_normals) + median(t_quad) + median(t_f) + median(t_asm) + median(t_cg);
        std::printf("| torus %zuk tri | %s | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %d | %.2f | %.1f |\n",
                    mesh.num_faces() / 1000, name, samples, median(t_point), median(t_normals), median(t_quad), median(t_f),
                    median(t_asm), median(t_cg), iterations, total, double(points) / double(mesh.num_vertices()));
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

// The floor of the least-squares bake's ratio to the point bake (issue 30's time goal at 3 points):
// per torus, scene and rule, process CPU medians of `repeats` runs, the rows round-robin in each:
//   point bake       bake_lighting, VertexColors::All (the normals and the shading at the vertices)
//   normals only     bake_lighting, VertexColors::None (what the least-squares bake runs of it)
//   f at the sites   lighting_at_sites on a quadrature built beforehand: the shading (and the
//                    interpolation of p and n) the fit cannot do without, at ~2 (1 pt) or ~3
//                    (3 pt, shared edge midpoints) sites per vertex against the point bake's 1
//   LS without f     fit_vertex_lighting's steps with f read from values computed beforehand:
//                    elements, quadrature, the clamp of f, least_squares_fit (8-bit accuracy)
//   LS               the whole bake, as the table's row
// floor = (normals only + f at the sites) / point bake: the ratio no change to the quadrature or
// the solve can go below; rest = (LS without f - normals only) / point bake: what they cost.
int floor_table(const std::string& src, int repeats, std::size_t max_triangles, std::size_t min_triangles,
                const std::string& only_scene) {
  std::printf("| mesh | scene | pt | point bake | normals only | f at the sites | LS without f | LS | sites / vertex | "
              "LS x point | floor x point | rest x point |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const int sizes[][2] = {{100, 50}, {316, 158}, {1000, 500}};
  for (const auto& sz : sizes) {
    const std::size_t triangles = std::size_t(2 * sz[0] * sz[1]);
    if (triangles > max_triangles || triangles < min_triangles) continue;
    const Mesh mesh = testing::torus(sz[0], sz[1], 1.0, 0.4).mesh;
    for (const char* name : {"studio", "window"}) {
      if (!only_scene.empty() && only_scene != name) continue;
      const Scene scene = read_scene(src + "/data/scenes/" + name + ".json");
      const std::vector<double> world = world_positions(mesh, scene);
      for (int samples : {1, 3}) {
        const BakeResult normals = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {}, VertexColors::None);
        const FitQuadrature q0 = fit_quadrature(fit_elements(mesh), world, samples);
        std::vector<double> f0 = lighting_at_sites(mesh, scene, q0, world, normals.vertex_normals, {}, {});
        VertexFitOptions fit;
        fit.method = VertexFit::LeastSquares;
        fit.samples = samples;
        fit.solve.upper = 1;
        fit.solve.accuracy = kEightBitFitAccuracy;
        fit.measure_error = false;
        std::vector<double> t[5];
        std::vector<double> without_f, with_f;
        for (int k = 0; k < repeats; ++k) {
          double c0 = cpu_ms();
          bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
          t[0].push_back(cpu_ms() - c0);
          c0 = cpu_ms();
          const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {}, VertexColors::None);
          t[1].push_back(cpu_ms() - c0);
          c0 = cpu_ms();
          lighting_at_sites(mesh, scene, q0, world, point.vertex_normals, {}, {});
          t[2].push_back(cpu_ms() - c0);
          c0 = cpu_ms();
          {  // fit_vertex_lighting's steps (the placement is the identity: the mesh's positions), f read
            const BakeResult none = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {}, VertexColors::None);
            const FitElements elements = fit_elements(mesh);
            const FitQuadrature q = fit_quadrature(elements, world, samples);
            std::vector<double>& f = f0;  // clamped in place: the same pass as the bake's, no copy
            for (double& v : f) v = std::min(std::max(v, fit.solve.lower), fit.solve.upper);
            without_f = least_squares_fit(
                            elements, world, q, f,
                            [&](const std::vector<std::uint32_t>& nodes) {
                              ShadeCounters counters;
                              return bake_vertex_colors(mesh, scene, none, nodes, {}, {}, counters);
                            },
                            3, fit.solve)
                            .values;
          }
          t[3].push_back(cpu_ms() - c0);
          c0 = cpu_ms();
          with_f = fit_vertex_lighting(mesh, scene, bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {},
                                                                  VertexColors::None),
                                       {}, {}, fit)
                       .rgb;
          t[4].push_back(cpu_ms() - c0);
        }
        if (without_f != with_f) {
          std::fprintf(stderr, "bench_fit floor: the bake without f differs from fit_vertex_lighting's\n");
          return 1;
        }
        const double point = median(t[0]);
        std::printf("| torus %zuk tri | %s | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f | %.2f | %.2f | %.2f |\n",
                    mesh.num_faces() / 1000, name, samples, point, median(t[1]), median(t[2]), median(t[3]),
                    median(t[4]), double(q0.sites()) / double(mesh.num_vertices()), median(t[4]) / point,
                    (median(t[1]) + median(t[2])) / point, (median(t[3]) - median(t[1])) / point);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

// Why a fit gains what it gains: the relative L2 error (the 12-point reference, as the table) of
// the point colours and of the 3-point least-squares fit at several regulariser weights λ (the
// default is 0), with the 8-bit bounds (f, the reference and the colours clamped to [0, 1]) and
// without them (HDR: nothing clamped), and the share of the surface where the clamped reference is
// saturated (some channel at 1).
int errors(const std::string& src, std::size_t max_triangles) {
  std::printf("| mesh | scene | bounds | point | LS λ=0 (default) | LS λ=1e-3 | LS λ=1e-2 | LS λ=1e-1 | gain at λ=0 | saturated area |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n");
  const int sizes[][2] = {{100, 50}, {316, 158}, {1000, 500}};
  for (const auto& s : sizes) {
    if (std::size_t(2 * s[0] * s[1]) > max_triangles) continue;
    const Mesh mesh = testing::torus(s[0], s[1], 1.0, 0.4).mesh;
    for (const char* name : {"studio", "window"}) {
      const Scene scene = read_scene(src + "/data/scenes/" + name + ".json");
      const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
      const std::vector<double> world = world_positions(mesh, scene);
      const FitQuadrature ref = fit_quadrature(fit_elements(mesh), world, 12);
      const std::vector<double> f_raw = lighting_at_quadrature(mesh, scene, ref, world, point.vertex_normals, {}, {});
      for (bool eight_bit : {true, false}) {
        const std::vector<double> f = eight_bit ? clamped(f_raw) : f_raw;
        double saturated = 0, area = 0;
        ref.for_each_point([&](std::size_t k, const std::uint32_t*, const std::uint32_t*, const double*, int, double w) {
          area += w;
          if (std::max({f[3 * k], f[3 * k + 1], f[3 * k + 2]}) >= 1) saturated += w;
        });
        const double e_point = relative_l2_error(ref, f, eight_bit ? clamped(point.rgb) : point.rgb, 3);
        std::printf("| torus %zuk tri | %s | %s | %.5f |", mesh.num_faces() / 1000, name, eight_bit ? "8-bit" : "HDR", e_point);
        double e0 = 0;
        for (double lambda : {0.0, 1e-3, 1e-2, 1e-1}) {
          VertexFitOptions fit;
          fit.method = VertexFit::LeastSquares;
          fit.samples = 3;
          fit.solve.regularization = lambda;
          if (eight_bit) {
            fit.solve.upper = 1;
            fit.solve.accuracy = kEightBitFitAccuracy;
          }
          const double e = relative_l2_error(ref, f, fit_vertex_lighting(mesh, scene, point, {}, {}, fit).rgb, 3);
          if (lambda == 0) e0 = e;
          std::printf(" %.5f |", e);
        }
        std::printf(" %+.0f%% | %.0f%% |\n", 100 * (e0 / e_point - 1), area > 0 ? 100 * saturated / area : 0.0);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

// The box-constrained minimum of the fit's objective  c^T M c - 2 b^T c  over 0 <= c <= 1 (an
// experiment, not the library's solve): Jacobi-scaled projected gradient,
// c <- clamp(c - (1/2) D^-1 (M c - b)) (the eigenvalues of D^-1 M lie in [1/2, 2] for triangles, so
// the step 1/2 = 1/L converges, linearly at rate 3/4), 400 steps from `start`. Triangles only
// (the torus). Also returns the largest violation of the KKT conditions (gradient of a free value;
// gradient pointing outward at a bound), relative to max |b|.
std::vector<double> box_fit(const FitElements& e, const FitQuadrature& q, const std::vector<double>& f,
                            std::vector<double> c, double& kkt) {
  const std::size_t N = e.nodes;
  std::vector<double> b(3 * N, 0.0), d(N, 0.0), g(3 * N);
  q.for_each_point([&](std::size_t s, const std::uint32_t* node, const std::uint32_t*, const double* phi, int corners,
                       double w) {
    for (int j = 0; j < corners; ++j)
      for (int k = 0; k < 3; ++k) b[3 * node[j] + k] += w * phi[j] * f[3 * s + k];
  });
  for (std::size_t t = 0; t < q.tri_area.size(); ++t)
    for (int i = 0; i < 3; ++i) d[q.triangle_nodes()[3 * t + i]] += q.tri_area[t] / 6;
  const auto gradient = [&]() {  // g = M c - b
    for (std::size_t i = 0; i < 3 * N; ++i) g[i] = -b[i];
    for (std::size_t t = 0; t < q.tri_area.size(); ++t) {
      const std::uint32_t* n = &q.triangle_nodes()[3 * t];
      const double a = q.tri_area[t] / 12;
      for (int k = 0; k < 3; ++k) {
        const double sum = c[3 * n[0] + k] + c[3 * n[1] + k] + c[3 * n[2] + k];
        for (int i = 0; i < 3; ++i) g[3 * n[i] + k] += a * (c[3 * n[i] + k] + sum);
      }
    }
  };
  for (int it = 0; it < 400; ++it) {
    gradient();
    for (std::size_t i = 0; i < 3 * N; ++i)
      if (d[i / 3] > 0) c[i] = std::min(1.0, std::max(0.0, c[i] - 0.5 * g[i] / d[i / 3]));
  }
  gradient();
  double worst = 0, bmax = 0;
  for (std::size_t i = 0; i < 3 * N; ++i) {
    bmax = std::max(bmax, std::fabs(b[i]));
    const double v = c[i] <= 0 ? std::max(0.0, -g[i]) : (c[i] >= 1 ? std::max(0.0, g[i]) : std::fabs(g[i]));
    worst = std::max(worst, v);
  }
  kkt = bmax > 0 ? worst / bmax : 0;
  return c;
}

// What objective and bounds give the least error for 8-bit output (issue 30's error goal): on the
// 10k torus, the relative L2 error against the clamped per-point colour (the 12-point reference, as
// the table) of the point colours and of least-squares fits that differ in the target (raw f or
// the clamped min(f, 1)), in how the bounds are met (clamped after the solve, or the
// box-constrained minimum), and in the rule (3: the default; 12: the reference's own rule, so the
// box-constrained fit of the clamped f is the least error any vertex colours in [0, 1] can have
// under this measure: the floor).
int variants(const std::string& src) {
  std::printf("| mesh | scene | rule | point | LS raw f, clamped after | LS min(f,1), clamped after (default) | box LS raw f | box LS min(f,1) | best vs point | clamped values (default) | at a bound (box) | KKT residual |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const Mesh mesh = testing::torus(100, 50, 1.0, 0.4).mesh;
  for (const char* name : {"studio", "window"}) {
    const Scene scene = read_scene(src + "/data/scenes/" + name + ".json");
    const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
    const std::vector<double> world = world_positions(mesh, scene);
    const FitElements elements = fit_elements(mesh);
    const FitQuadrature ref = fit_quadrature(elements, world, 12);
    const std::vector<double> f_ref = clamped(lighting_at_quadrature(mesh, scene, ref, world, point.vertex_normals, {}, {}));
    const double e_point = relative_l2_error(ref, f_ref, clamped(point.rgb), 3);
    for (int rule : {1, 3, 12}) {
      const FitQuadrature q = fit_quadrature(elements, world, rule);
      const std::vector<double> f_raw = lighting_at_quadrature(mesh, scene, q, world, point.vertex_normals, {}, {});
      const std::vector<double> f_clamped = clamped(f_raw);
      LeastSquaresFitOptions o;
      o.upper = 1;
      o.tolerance = 1e-12;
      const LeastSquaresFit raw = least_squares_fit(elements, world, q, f_raw, point.rgb, 3, o);
      const LeastSquaresFit def = least_squares_fit(elements, world, q, f_clamped, point.rgb, 3, o);
      double kkt_raw = 0, kkt = 0;
      const std::vector<double> box_raw = box_fit(elements, q, f_raw, def.values, kkt_raw);
      const std::vector<double> box = box_fit(elements, q, f_clamped, def.values, kkt);
      std::size_t at_bound = 0;
      for (double v : box) at_bound += v <= 0 || v >= 1;
      const double e[4] = {relative_l2_error(ref, f_ref, raw.values, 3), relative_l2_error(ref, f_ref, def.values, 3),
                           relative_l2_error(ref, f_ref, box_raw, 3), relative_l2_error(ref, f_ref, box, 3)};
      std::printf("| torus %zuk tri | %s | %d | %.5f | %.5f | %.5f | %.5f | %.5f | %+.1f%% | %zu | %zu | %.1e |\n",
                  mesh.num_faces() / 1000, name, rule, e_point, e[0], e[1], e[2], e[3],
                  100 * (*std::min_element(e, e + 4) / e_point - 1), def.clamped, at_bound, std::max(kkt, kkt_raw));
      std::fflush(stdout);
    }
  }
  return 0;
}

int picture(const std::string& src, const std::string& out) {
  const Mesh mesh = testing::icosphere(1).mesh;  // 80 triangles: highlights fall between vertices
  Scene scene = read_scene(src + "/data/scenes/studio.json");
  scene.lens.fov_y_degrees = 26;  // the sphere fills the frame
  const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  fit.samples = 6;
  fit.solve.upper = 1;
  const VertexLightingFit lsq = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
  std::printf("icosphere(1), studio: relative L2 error (its own 6-point rule) least squares %.4f, point %.4f\n",
              lsq.error_fit, lsq.error_point);
  RenderOptions o;
  o.width = o.height = 400;
  o.samples = 4;
  std::vector<ImageRGB> images;
  o.shading = RenderShading::Gouraud;
  images.push_back(render_mesh(mesh, scene, o).image);
  o.vertex_rgb = &lsq.rgb;
  images.push_back(render_mesh(mesh, scene, o).image);
  o.vertex_rgb = nullptr;
  o.shading = RenderShading::Phong;
  images.push_back(render_mesh(mesh, scene, o).image);
  const int W = 3 * o.width + 2 * 8, H = o.height;
  std::vector<std::uint8_t> srgb(std::size_t(3) * W * H, 255);
  for (int k = 0; k < 3; ++k)
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < o.width; ++x)
        for (int c = 0; c < 3; ++c)
          srgb[3 * (std::size_t(y) * W + std::size_t(k * (o.width + 8) + x)) + c] = encode_srgb_8bit(images[k].pixel(x, y)[c]);
  std::ofstream(out, std::ios::binary) << io::encode_png_srgb8(W, H, srgb, out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_fit table|breakdown SRC_DIR [REPEATS] [MAX_TRIANGLES] | picture SRC_DIR OUT.png\n");
    return 2;
  }
  const std::string mode = argv[1], src = argv[2];
  // FIT_THREADS=1: every stage on one thread. Process CPU time then holds no thread pool's spin
  // after a parallel stage (TBB's workers wait busily for more work, and that CPU time falls on
  // whatever stage or method runs next).
  // FIT_MALLOC_KEEP=1: glibc keeps freed memory (no trimming, no mmap per large block), so a
  // repetition reuses the pages of the one before: the CPU time without the page faults of first
  // touch (an experiment: a one-shot CLI run touches its memory first, as the default measures).
  if (const char* keep = std::getenv("FIT_MALLOC_KEEP"); keep && std::atoi(keep) > 0) {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
  }
  const char* threads = std::getenv("FIT_THREADS");
  tbb::global_control pool(tbb::global_control::max_allowed_parallelism,
                           threads && std::atoi(threads) > 0 ? std::size_t(std::atoi(threads))
                                                              : tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  if (mode == "picture" && argc > 3) return picture(src, argv[3]);
  if (mode == "variants") return variants(src);
  if (mode == "repeat" && argc > 4) {  // bench_fit repeat SRC SAMPLES N [1m]: N bakes of the 10k (1M) torus, studio (for perf)
    const bool million = argc > 5 && std::string(argv[5]) == "1m";
    const Mesh mesh = million ? testing::torus(1000, 500, 1.0, 0.4).mesh : testing::torus(100, 50, 1.0, 0.4).mesh;
    const Scene scene = read_scene(src + "/data/scenes/studio.json");
    for (int k = 0; k < std::atoi(argv[4]); ++k) bake(mesh, scene, std::atoi(argv[3]));
    std::vector<double> t_el, t_q;
    const std::vector<double> world = world_positions(mesh, scene);
    for (int k = 0; k < (million ? 5 : 200); ++k) {
      double t0 = cpu_ms();
      const FitElements e = fit_elements(mesh);
      t_el.push_back(cpu_ms() - t0);
      t0 = cpu_ms();
      const FitQuadrature q = fit_quadrature(e, world, std::atoi(argv[3]));
      t_q.push_back(cpu_ms() - t0);
    }
    std::printf("elements %.3f ms, quadrature %.3f ms\n", median(t_el), median(t_q));
    return 0;
  }
  if (mode == "solve" && argc > 4) {  // bench_fit solve SRC SAMPLES N [1m|99k]: least_squares_fit alone, N times (10k (1M, 99k) torus, studio)
    const std::string size = argc > 5 ? argv[5] : "";
    const Mesh mesh = size == "1m"    ? testing::torus(1000, 500, 1.0, 0.4).mesh
                      : size == "99k" ? testing::torus(316, 158, 1.0, 0.4).mesh
                                      : testing::torus(100, 50, 1.0, 0.4).mesh;
    const Scene scene = read_scene(src + "/data/scenes/studio.json");
    const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
    const std::vector<double> world = world_positions(mesh, scene);
    const FitElements e = fit_elements(mesh);
    const FitQuadrature q = fit_quadrature(e, world, std::atoi(argv[3]));
    const std::vector<double> f = clamped(lighting_at_sites(mesh, scene, q, world, point.vertex_normals, {}, {}));
    LeastSquaresFitOptions o;
    o.upper = 1;
    o.accuracy = kEightBitFitAccuracy;
    const char* vectors = std::getenv("FIT_VECTORS");  // "double": FitVectorStorage::Double (the HDR path's storage)
    if (vectors && std::string(vectors) == "double") o.vectors = FitVectorStorage::Double;
    std::vector<double> t;
    LeastSquaresFit last;
    for (int k = 0; k < std::atoi(argv[4]); ++k) {
      const double t0 = cpu_ms();
      last = least_squares_fit(e, world, q, f, point.rgb, 3, o);
      t.push_back(cpu_ms() - t0);
    }
    std::printf("least_squares_fit %.3f ms (median of %zu, process CPU), %d CG iterations, vectors %s%s, residual %.3g\n",
                median(t), t.size(), last.iterations, last.float_vectors ? "float" : "double",
                last.double_finish ? " (finished in double)" : "", last.residual);
    return 0;
  }
  if (mode == "bytes" && argc > 4) {  // bench_fit bytes SRC SCENE SAMPLES: the 8-bit bytes of float vs double vectors (1M torus)
    const Mesh mesh = testing::torus(1000, 500, 1.0, 0.4).mesh;
    const Scene scene = read_scene(src + "/data/scenes/" + argv[3] + ".json");
    const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex, {}, {}, VertexColors::None);
    VertexFitOptions fit;
    fit.method = VertexFit::LeastSquares;
    fit.samples = std::atoi(argv[4]);
    fit.solve.upper = 1;
    fit.solve.accuracy = kEightBitFitAccuracy;
    fit.measure_error = false;
    const VertexLightingFit in_float = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
    fit.solve.vectors = FitVectorStorage::Double;  // the solve before fit11 (the same bits)
    const VertexLightingFit in_double = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
    fit.solve.accuracy = 0;  // "exact": CG to a relative residual of 1e-14, double
    fit.solve.tolerance = 1e-14;
    const VertexLightingFit exact = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
    const auto byte = [](double c) { return int(quantize_8bit(srgb_encode(c))); };
    std::size_t differ = 0, values_differ = 0;
    double worst_float = 0, worst_double = 0, worst_gap = 0;  // |c - c*|, and |c* - boundary| where the bytes differ
    for (std::size_t i = 0; i < exact.rgb.size(); ++i) {
      worst_float = std::max(worst_float, std::fabs(in_float.rgb[i] - exact.rgb[i]));
      worst_double = std::max(worst_double, std::fabs(in_double.rgb[i] - exact.rgb[i]));
      values_differ += in_float.rgb[i] != in_double.rgb[i];
      const int a = byte(in_float.rgb[i]), b = byte(in_double.rgb[i]);
      if (a == b) continue;
      ++differ;
      // the rounding boundary between the two bytes, in linear units: bisect srgb_encode
      double lo = std::min(in_float.rgb[i], in_double.rgb[i]), hi = std::max(in_float.rgb[i], in_double.rgb[i]);
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (byte(mid) == byte(lo) ? lo : hi) = mid;
      }
      worst_gap = std::max(worst_gap, std::fabs(exact.rgb[i] - hi));
      std::printf("value %zu: float %.9f (byte %d), double %.9f (byte %d), exact %.9f, boundary %.9f\n", i,
                  in_float.rgb[i], a, in_double.rgb[i], b, exact.rgb[i], hi);
    }
    std::printf("%s %s pt: %zu of %zu bytes differ (%zu values differ); max |c - c*| float %.3g, double %.3g (bound %.3g); "
                "exact value within %.3g of the byte boundary where they differ; CG iterations float %d (float vectors %d, "
                "double finish %d, drift bounded %d), double %d\n",
                argv[3], argv[4], differ, exact.rgb.size(), values_differ, worst_float, worst_double, kEightBitFitAccuracy,
                worst_gap, in_float.solve.iterations, int(in_float.solve.float_vectors), int(in_float.solve.double_finish),
                int(in_float.solve.drift_bounded),
                in_double.solve.iterations);
    return 0;
  }
  if (mode == "once" && argc > 6) {  // bench_fit once SRC U V SCENE SAMPLES: one bake in this process (fresh)
    const Mesh mesh = testing::torus(std::atoi(argv[3]), std::atoi(argv[4]), 1.0, 0.4).mesh;
    const Scene scene = read_scene(src + "/data/scenes/" + argv[5] + ".json");
    BakeTime t;
    time_in_process(mesh, scene, nullptr, argv[5], std::atoi(argv[6]), t);
    std::printf("%.3f %.3f\n", t.cpu, t.wall);
    return 0;
  }
  if (mode == "errors") return errors(src, argc > 3 ? std::size_t(std::atoll(argv[3])) : 20000);
  if (mode == "floor")
    return floor_table(src, argc > 3 ? std::atoi(argv[3]) : 11, argc > 4 ? std::size_t(std::atoll(argv[4])) : 20000,
                       argc > 5 ? std::size_t(std::atoll(argv[5])) : 0, argc > 6 ? argv[6] : "");
  if (mode == "breakdown")
    return breakdown(src, argc > 3 ? std::atoi(argv[3]) : 7, argc > 4 ? std::size_t(std::atoll(argv[4])) : 20000,
                     argc > 5 ? std::size_t(std::atoll(argv[5])) : 0, argc > 6 ? argv[6] : "");
  std::vector<int> methods = {0, 1, 3, 6};  // point, least squares at 1, 3, 6 points
  if (argc > 7) {  // a comma-separated list of rules: the point bake and least squares at those
    methods = {0};
    for (const char* c = argv[7]; *c;) {
      char* after = nullptr;
      const long n = std::strtol(c, &after, 10);
      if (after == c || !triangle_quadrature_supported(int(n))) {
        std::fprintf(stderr, "bench_fit table: '%s' is not a list of rules (1, 3, 6, 12)\n", argv[7]);
        return 2;
      }
      methods.push_back(int(n));
      c = *after == ',' ? after + 1 : after;
    }
  }
  if (mode == "fresh") {
    char self[4096] = {};
    if (readlink("/proc/self/exe", self, sizeof self - 1) <= 0) return 1;  // this program, for its children
    return table(src, argc > 3 ? std::atoi(argv[3]) : 7, argc > 4 ? std::size_t(std::atoll(argv[4])) : 200000,
                 argc > 5 ? std::size_t(std::atoll(argv[5])) : 0, argc > 6 && std::string(argv[6]) != "both" ? argv[6] : "",
                 methods, time_in_fresh_process(self, src));
  }
  return table(src, argc > 3 ? std::atoi(argv[3]) : 7, argc > 4 ? std::size_t(std::atoll(argv[4])) : 200000,
               argc > 5 ? std::size_t(std::atoll(argv[5])) : 0, argc > 6 && std::string(argv[6]) != "both" ? argv[6] : "",
               methods, time_in_process);
}
