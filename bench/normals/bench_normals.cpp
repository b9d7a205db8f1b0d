// bench_normals: vertex normals, ours against OpenMesh, on a generated irregular sphere.
//
// Usage: bench_normals [--quick] [--faces N] [--reps R] [--csv FILE] [--only SUBSTRING] [--mesh uv|ico]
// Mesh: irregular UV sphere (default) or icosphere (--mesh ico), jittered along the surface plus
// 30% random edge flips, about N triangles (default 1M), exact normals known. The UV sphere's
// poles are fans of slivers, where every weighting but Max has errors of tens of degrees: its max
// error column is the poles'; the icosphere shows the weightings without them. Kernels timed in one process, IO excluded,
// median of R repetitions (default 15), after one warm-up run. Threads: 1 and 2 (TBB arenas).
// Output: a Markdown table on stdout (time, ratio to OpenMesh update_normals, error against the
// analytic normals), and optionally CSV.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

// OpenMesh's PropertyT<T>::push_back (push_back(T()) of a default VectorT) trips GCC 12's
// -Wmaybe-uninitialized when inlined here; the warning is in OpenMesh's code, not ours.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <tbb/task_arena.h>
#include <type_traits>

#include "normals/corner_normals.h"
#include "normals/vertex_normals.h"
#include "support/analytic_meshes.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using OMd = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using OMf = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraits>;

struct Err { double mean = 0, p99 = 0, max = 0; std::size_t bad = 0; };

template <class Get>
Err error_of(std::size_t V, const std::vector<Vec3d>& exact, Get get) {
  Err e;
  std::vector<double> a;
  a.reserve(V);
  for (std::size_t v = 0; v < V; ++v) {
    const Vec3d n = get(v);
    if (!is_finite(n) || (n.x == 0 && n.y == 0 && n.z == 0)) { ++e.bad; continue; }
    a.push_back(angle_degrees(n, exact[v]));
  }
  std::sort(a.begin(), a.end());
  for (double x : a) e.mean += x;
  if (!a.empty()) {
    e.mean /= double(a.size());
    e.p99 = a[std::size_t(0.99 * double(a.size() - 1))];
    e.max = a.back();
  }
  return e;
}

// Error of corner normals: every corner against its vertex's exact normal (a smooth sphere has no
// crease above 30 degrees, so every corner should carry its vertex's normal).
Err corner_error(const Mesh& mesh, const CornerNormals& cn, const AnalyticMesh& am) {
  std::vector<Vec3d> exact(mesh.num_corners());
  for (std::size_t c = 0; c < mesh.num_corners(); ++c) exact[c] = am.exact_normals[mesh.corner_vertex[c]];
  return error_of(mesh.num_corners(), exact, [&](std::size_t c) { return get3(cn.normals, cn.corner_index[c]); });
}

template <class OM>
void build(OM& om, const Mesh& m) {
  std::vector<typename OM::VertexHandle> vh;
  vh.reserve(m.num_vertices());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3d p = m.position(v);
    vh.push_back(om.add_vertex(typename OM::Point(p.x, p.y, p.z)));
  }
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    om.add_face(vh[m.corner_vertex[3 * f]], vh[m.corner_vertex[3 * f + 1]], vh[m.corner_vertex[3 * f + 2]]);
  om.request_face_normals();
  om.request_vertex_normals();
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t faces = 1000000;
  int reps = 15;
  std::string csv, only, shape = "uv";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) { faces = 100000; reps = 5; }
    else if (!std::strcmp(argv[i], "--faces") && i + 1 < argc) faces = std::stoul(argv[++i]);
    else if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
    else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc) shape = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_normals [--quick] [--faces N] [--reps R] [--csv FILE] [--only SUBSTRING] [--mesh uv|ico]\n");
      return 2;
    }
  }
  // UV sphere with nu = 2 nv has 2 nu (nv - 1) triangles; icosphere level l has 20 4^l.
  // Jitter 0.15 of a grid cell (0.3 of an edge on the icosphere) keeps every triangle unfolded.
  AnalyticMesh am;
  if (shape == "ico") {
    int level = 1;
    while (20.0 * std::pow(4.0, level + 1) <= 1.5 * double(faces)) ++level;
    am = irregular(icosphere(level, 0.3, 11), 13);
  } else {
    const int nv = std::max(4, int(std::lround(std::sqrt(double(faces) / 4.0))));
    am = irregular(uv_sphere(2 * nv, nv, 0.15, 11), 13);
  }
  const Mesh& mesh = am.mesh;
  const std::size_t V = mesh.num_vertices();
  std::printf("mesh: irregular %s sphere (jitter + 30%% edge flips), %zu vertices, %zu triangles; median of %d interleaved runs\n\n",
              shape == "ico" ? "icosphere" : "UV", V, mesh.num_faces(), reps);

  struct Row { std::string method; int threads; double ms; Err err; };
  std::vector<Row> rows;

  // Every method is a closure run inside a TBB arena of its thread count. Repetitions are
  // interleaved (rep 1 of every method, then rep 2, ...) so that load from other processes on
  // this shared machine hits all methods alike; the table reports medians.
  struct Method { std::string name; int threads; std::function<void()> run; std::function<Err()> error; };
  std::vector<Method> methods;
  OMd omd;
  build(omd, mesh);
  OMf omf;
  build(omf, mesh);
  auto om_error = [&](auto& om) {
    return [&om, &am, V] {
      return error_of(V, am.exact_normals, [&](std::size_t v) {
        const auto n = om.normal(typename std::decay_t<decltype(om)>::VertexHandle(int(v)));
        return Vec3d{n[0], n[1], n[2]};
      });
    };
  };
  methods.push_back({"OpenMesh update_normals (double)", 1, [&] { omd.update_normals(); }, om_error(omd)});
  methods.push_back({"OpenMesh update_vertex_normals (double)", 1, [&] { omd.update_vertex_normals(); }, om_error(omd)});
  methods.push_back({"OpenMesh update_normals (float)", 1, [&] { omf.update_normals(); }, om_error(omf)});

  const std::pair<Weighting, const char*> weightings[] = {
      {Weighting::Area, "area"}, {Weighting::Angle, "angle"}, {Weighting::Max, "max"}, {Weighting::Uniform, "uniform"}};
  std::vector<VertexNormals> results(2 * 4 * 2);
  std::vector<CornerNormals> corner_results(2);
  int slot = 0;
  for (int threads : {1, 2}) {
    for (auto [w, name] : weightings)
      for (Precision p : {Precision::Double, Precision::Float}) {
        VertexNormals* r = &results[slot++];
        methods.push_back({std::string("shadetool vertex_normals ") + name + (p == Precision::Float ? " (float)" : " (double)"),
                           threads, [&mesh, r, w = w, p] { *r = vertex_normals(mesh, w, p); },
                           [r, &am, V] { return error_of(V, am.exact_normals, [&](std::size_t v) { return get3(r->normals, v); }); }});
      }
    CornerNormals* cn = &corner_results[threads - 1];
    methods.push_back({"shadetool corner_normals angle, crease 30 (double)", threads,
                       [&mesh, cn] { *cn = corner_normals(mesh, 30.0 * kPi / 180.0, Weighting::Angle); },
                       [&mesh, cn, &am] { return corner_error(mesh, *cn, am); }});
  }

  // --only: keep OpenMesh update_normals (the reference) and the methods whose name contains it.
  if (!only.empty()) {
    std::vector<Method> kept;
    for (auto& m : methods)
      if (m.name == "OpenMesh update_normals (double)" || m.name.find(only) != std::string::npos) kept.push_back(m);
    methods.swap(kept);
  }
  std::vector<std::vector<double>> times(methods.size());
  for (int rep = -1; rep < reps; ++rep)  // rep -1: warm-up
    for (std::size_t m = 0; m < methods.size(); ++m) {
      tbb::task_arena arena(methods[m].threads);
      arena.execute([&] {
        const auto t0 = std::chrono::steady_clock::now();
        methods[m].run();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (rep >= 0) times[m].push_back(ms);
      });
    }
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::sort(times[m].begin(), times[m].end());
    rows.push_back({methods[m].name, methods[m].threads, times[m][times[m].size() / 2], methods[m].error()});
  }

  const double reference = rows[0].ms;  // OpenMesh update_normals (double)
  auto find = [&](const std::string& m, int th) {
    for (auto& r : rows)
      if (r.method == m && r.threads == th) return r.ms;
    return 0.0;
  };
  std::printf("| method | threads | median ms | speed vs OpenMesh update_normals | mean err deg | p99 err deg | max err deg | NaN/zero |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (auto& r : rows)
    std::printf("| %s | %d | %.2f | %.1fx | %.3g | %.3g | %.3g | %zu |\n", r.method.c_str(), r.threads, r.ms,
                reference / r.ms, r.err.mean, r.err.p99, r.err.max, r.err.bad);
  const double area1 = find("shadetool vertex_normals area (double)", 1), area2 = find("shadetool vertex_normals area (double)", 2);
  std::printf("\nTargets (issue 8), double precision:\n");
  std::printf("  area, 1 thread, vs OpenMesh update_normals: %.1fx (target >= 5x)\n", reference / area1);
  std::printf("  angle / area, 1 thread: %.2f (target <= 2)\n", find("shadetool vertex_normals angle (double)", 1) / area1);
  std::printf("  max / area, 1 thread: %.2f (target <= 2)\n", find("shadetool vertex_normals max (double)", 1) / area1);
  for (auto [w, name] : weightings) {
    const std::string m = std::string("shadetool vertex_normals ") + name + " (double)";
    std::printf("  %s: 2 threads / 1 thread speed: %.2fx (target >= 1.7x)\n", name, find(m, 1) / find(m, 2));
  }
  std::printf("  area 2 threads vs OpenMesh update_normals: %.1fx\n", reference / area2);

  if (!csv.empty()) {
    FILE* f = std::fopen(csv.c_str(), "w");
    if (!f) { std::perror(csv.c_str()); return 1; }
    std::fprintf(f, "method,threads,median_ms,speedup_vs_openmesh_update_normals,mean_err_deg,p99_err_deg,max_err_deg,nan_or_zero\n");
    for (auto& r : rows)
      std::fprintf(f, "\"%s\",%d,%.4f,%.3f,%.6g,%.6g,%.6g,%zu\n", r.method.c_str(), r.threads, r.ms, reference / r.ms,
                   r.err.mean, r.err.p99, r.err.max, r.err.bad);
    std::fclose(f);
  }
  return 0;
}
