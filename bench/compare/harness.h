// harness.h: what every comparison program in bench/compare shares: which meshes to run on, how a
// kernel is timed, how its normals are scored against the analytic ones, and the CSV row format.
//
// Timing: one untimed warm-up run, then `repeats` timed runs (std::chrono::steady_clock); each run
// is preceded by an untimed `reset` (clears the previous output so that no library can reuse it).
// Reported: the median and the minimum wall time, and the median CPU time of the whole process
// (CLOCK_PROCESS_CPUTIME_ID, all threads), in milliseconds. On a shared, loaded machine the CPU
// time of a 1-thread row is the more stable figure (time-slicing does not add to it); wall time is
// what the targets use. IO is never inside the timed region. `warmup` = false skips the warm-up run
// (for anchors that take tens of seconds per call).
//
// Error: angle between computed and exact normal per vertex, atan2(|a x b|, a.b) in degrees
// (accurate for tiny angles). mean / p99 / max over the vertices that are not `at_risk` (degenerate
// or isolated, see bench_meshes.h) and whose normal is usable; `nan_or_zero` counts every vertex
// (at risk or not) whose normal is NaN/Inf or shorter than 1e-6; `missing` counts vertices a method
// gives no normal at all (an importer dropped them).
//
// CSV columns (header from csv_header()):
//   program,mesh,vertices,triangles,method,weighting,precision,threads,repeats,median_ms,min_ms,
//   median_cpu_ms,mean_deg,p99_deg,max_deg,nan_or_zero,missing,note
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_meshes.h"

namespace shadetool::bench {

struct Options {
  std::vector<std::string> meshes;  // "sphere_1M_irregular", ..., or "degenerate"
  int repeats = 7;
  std::vector<int> threads = {1, 2};
  bool header = true;
};

// --mesh NAME (repeatable; default sphere_1M_irregular and degenerate), --repeats N,
// --threads 1,2, --no-header.
inline Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--mesh") o.meshes.push_back(value());
    else if (a == "--repeats") o.repeats = std::max(1, std::stoi(value()));
    else if (a == "--threads") {
      o.threads.clear();
      const std::string list = value();
      for (std::size_t p = 0; p <= list.size();) {
        const std::size_t q = std::min(list.find(',', p), list.size());
        o.threads.push_back(std::max(1, std::stoi(list.substr(p, q - p))));
        p = q + 1;
      }
    } else if (a == "--no-header") o.header = false;
    else if (a == "-h" || a == "--help") {
      std::printf("usage: %s [--mesh SURFACE_SIZE_regular|irregular | --mesh degenerate]... [--repeats N] "
                  "[--threads 1,2] [--no-header]\n", argv[0]);
      std::exit(0);
    } else throw std::runtime_error("unknown argument '" + a + "'");
  }
  if (o.meshes.empty()) o.meshes = {"sphere_1M_irregular", "degenerate"};
  return o;
}

// "sphere_1M_irregular" -> make_bench_mesh(Sphere, S1M, true); "degenerate" -> make_degenerate_mesh().
inline BenchMesh load_bench_mesh(const std::string& name) {
  if (name == "degenerate") return make_degenerate_mesh();
  const std::size_t a = name.find('_'), b = name.rfind('_');
  if (a == std::string::npos || a == b) throw std::runtime_error("mesh name '" + name + "' is not SURFACE_SIZE_KIND");
  const std::string kind = name.substr(b + 1);
  if (kind != "regular" && kind != "irregular") throw std::runtime_error("mesh kind must be regular or irregular: " + name);
  return make_bench_mesh(parse_surface(name.substr(0, a)), parse_size(name.substr(a + 1, b - a - 1)), kind == "irregular");
}

struct Timing {
  double median_ms = 0, min_ms = 0, median_cpu_ms = 0;
  int repeats = 0;
};

inline double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

inline double median_of(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x.size() % 2 ? x[x.size() / 2] : 0.5 * (x[x.size() / 2 - 1] + x[x.size() / 2]);
}

template <class Reset, class Run>
Timing time_median(int repeats, Reset&& reset, Run&& run, bool warmup = true) {
  if (warmup) {
    reset();
    run();  // warm-up: page faults, caches, lazily built structures
  }
  std::vector<double> ms, cpu;
  for (int i = 0; i < repeats; ++i) {
    reset();
    const double c0 = process_cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    run();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(process_cpu_ms() - c0);
  }
  Timing t;
  t.repeats = repeats;
  t.min_ms = *std::min_element(ms.begin(), ms.end());
  t.median_ms = median_of(ms);
  t.median_cpu_ms = median_of(cpu);
  return t;
}

struct ErrorStats {
  double mean_deg = NAN, p99_deg = NAN, max_deg = NAN;
  std::size_t nan_or_zero = 0, missing = 0;
};

// normal_of(v, out) writes vertex v's normal into out and returns false if the method has none.
inline ErrorStats angular_error(const BenchMesh& b, const std::function<bool(std::size_t, Vec3d&)>& normal_of) {
  ErrorStats e;
  std::vector<double> err;
  err.reserve(b.am.exact_normals.size());
  for (std::size_t v = 0; v < b.am.exact_normals.size(); ++v) {
    Vec3d n{};
    if (!normal_of(v, n)) { ++e.missing; continue; }
    const double len = std::sqrt(dot(n, n));
    if (!std::isfinite(len) || len < 1e-6) { ++e.nan_or_zero; continue; }
    if (b.at_risk[v]) continue;
    err.push_back(testing::angle_degrees(n, b.am.exact_normals[v]));
  }
  if (err.empty()) return e;
  double sum = 0;
  for (double x : err) sum += x;
  e.mean_deg = sum / double(err.size());
  const std::size_t k = std::min(err.size() - 1, std::size_t(std::ceil(0.99 * double(err.size()))) - 1);
  std::nth_element(err.begin(), err.begin() + std::ptrdiff_t(k), err.end());
  e.p99_deg = err[k];
  e.max_deg = *std::max_element(err.begin() + std::ptrdiff_t(k), err.end());
  return e;
}

// Error of a flat #V by 3 array.
inline ErrorStats angular_error(const BenchMesh& b, const std::vector<double>& normals) {
  return angular_error(b, [&](std::size_t v, Vec3d& n) {
    if (3 * v + 2 >= normals.size()) return false;
    n = {normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]};
    return true;
  });
}

// True when triangle f names a vertex twice. Half-edge libraries cannot hold such a face (OpenMesh's
// add_face, as Debian builds it, aborts on an assertion), so the programs for OpenMesh and CGAL do
// not hand it to them and say how many they left out.
inline bool has_repeated_index(const Mesh& m, std::size_t f) {
  const std::uint32_t* c = &m.corner_vertex[3 * f];
  return c[0] == c[1] || c[1] == c[2] || c[2] == c[0];
}

inline const char* csv_header() {
  return "program,mesh,vertices,triangles,method,weighting,precision,threads,repeats,median_ms,min_ms,"
         "median_cpu_ms,mean_deg,p99_deg,max_deg,nan_or_zero,missing,note";
}

struct Row {
  std::string program, method, weighting, precision, note;
  int threads = 1;
};

inline void print_row(const BenchMesh& b, const Row& r, const Timing& t, const ErrorStats& e) {
  std::printf("%s,%s,%zu,%zu,%s,%s,%s,%d,%d,%.4f,%.4f,%.4f,%.6g,%.6g,%.6g,%zu,%zu,%s\n", r.program.c_str(), b.name.c_str(),
              b.am.mesh.num_vertices(), b.am.mesh.num_faces(), r.method.c_str(), r.weighting.c_str(),
              r.precision.c_str(), r.threads, t.repeats, t.median_ms, t.min_ms, t.median_cpu_ms, e.mean_deg, e.p99_deg, e.max_deg,
              e.nan_or_zero, e.missing, r.note.c_str());
  std::fflush(stdout);
}

// A timed case: one row of the table. Cases of one program are timed round-robin (run_cases), so
// that a change of machine load during the run hits every case alike and the ratios between rows
// stay meaningful on a shared machine.
struct Case {
  Row row;
  std::function<void()> reset = [] {}, run;
  std::function<ErrorStats()> error;  // after timing, from what the last run left; empty: no error
  std::function<std::string()> note;  // after timing, appended to row.note
  int max_repeats = 1 << 30;          // e.g. 1 for an anchor that takes tens of seconds per call
  bool warmup = true;
  std::vector<double> ms, cpu_ms;
};

// One untimed warm-up of every case (unless warmup = false), then `repeats` rounds, each running
// every case once in list order (reset untimed before each run). Prints one row per case.
inline void run_cases(const BenchMesh& b, std::vector<Case>& cases, int repeats) {
  for (Case& c : cases)
    if (c.warmup) { c.reset(); c.run(); }
  for (int r = 0; r < repeats; ++r)
    for (Case& c : cases) {
      if (r >= c.max_repeats) continue;
      c.reset();
      const double c0 = process_cpu_ms();
      const auto t0 = std::chrono::steady_clock::now();
      c.run();
      c.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      c.cpu_ms.push_back(process_cpu_ms() - c0);
    }
  for (Case& c : cases) {
    Timing t;
    t.repeats = int(c.ms.size());
    t.min_ms = *std::min_element(c.ms.begin(), c.ms.end());
    t.median_ms = median_of(c.ms);
    t.median_cpu_ms = median_of(c.cpu_ms);
    Row row = c.row;
    if (c.note) {
      const std::string extra = c.note();
      if (!extra.empty()) row.note += (row.note.empty() ? "" : "; ") + extra;
    }
    print_row(b, row, t, c.error ? c.error() : ErrorStats{});
  }
}

// Fewer repeats on large meshes keeps the full run within its time budget.
inline int repeats_for(const BenchMesh& b, int requested) {
  return b.am.mesh.num_faces() > 3000000 ? std::max(1, std::min(requested, 3)) : requested;
}

}  // namespace shadetool::bench
