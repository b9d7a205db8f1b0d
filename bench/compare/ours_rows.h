// ours_rows.h: shadetool's own kernels as rows of a comparison table, so that every anchor program
// times our kernels on the same mesh in the same process run as the anchor (ratios from one run).
//
// Threads: each row runs inside a tbb::task_arena of `threads` slots, so that the kernels see that
// concurrency (tbb::this_task_arena::max_concurrency(); tbb::global_control would cap the workers
// but leave a kernel believing it has all cores, and running its parallel code path on one).
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "harness.h"
#include "normals/face_normals.h"
#include "normals/vertex_normals.h"

namespace shadetool::bench {

inline std::string fmt_g(const char* format, double x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

inline const char* weighting_name(Weighting w) {
  switch (w) {
    case Weighting::Uniform: return "uniform";
    case Weighting::Area: return "area";
    case Weighting::Angle: return "angle";
    case Weighting::Max: return "max";
  }
  return "?";
}

// One row per (weighting, precision, threads): shadetool::vertex_normals. Returns the median of
// the first row (the reference for ratios).
inline double ours_vertex_rows(const std::string& program, const BenchMesh& b, int repeats,
                               const std::vector<Weighting>& weightings, const std::vector<Precision>& precisions,
                               const std::vector<int>& threads) {
  double first = 0;
  for (Weighting w : weightings) {
    std::vector<double> double_result;  // for the float rows: largest angle to the double result
    for (Precision p : precisions) {
      std::vector<double> first_result;
      for (int t : threads) {
        tbb::task_arena arena(t);
        VertexNormals result;
        const Timing time = time_median(repeats_for(b, repeats), [&] { result = VertexNormals{}; },
                                        [&] { arena.execute([&] { result = vertex_normals(b.am.mesh, w, p); }); });
        Row row{program, "shadetool vertex_normals", weighting_name(w), p == Precision::Double ? "double" : "float", "", t};
        if (first_result.empty()) first_result = result.normals;
        else if (first_result != result.normals) row.note = "differs from the 1-thread result";
        if (result.fallback_vertices) row.note += (row.note.empty() ? "" : "; ") + std::to_string(result.fallback_vertices) + " fallback vertices";
        if (p == Precision::Double && double_result.empty()) double_result = result.normals;
        if (p == Precision::Float && double_result.size() == result.normals.size() && t == threads.front()) {
          double worst = 0;
          for (std::size_t v = 0; 3 * v < result.normals.size(); ++v)
            if (!b.at_risk[v]) worst = std::max(worst, testing::angle_degrees(get3(result.normals, v), get3(double_result, v)));
          row.note += (row.note.empty() ? "" : "; ") + fmt_g("max angle to double result %.3g deg", worst);
        }
        print_row(b, row, time, angular_error(b, result.normals));
        if (first == 0) first = time.median_ms;
      }
    }
  }
  return first;
}

// shadetool::face_normals (no error against vertex truth: reported as timing only).
inline void ours_face_rows(const std::string& program, const BenchMesh& b, int repeats, const std::vector<int>& threads) {
  for (int t : threads) {
    tbb::task_arena arena(t);
    std::vector<double> fn;
    const Timing time = time_median(repeats_for(b, repeats), [&] { fn.clear(); fn.shrink_to_fit(); },
                                    [&] { arena.execute([&] { fn = face_normals(b.am.mesh, Precision::Double); }); });
    print_row(b, Row{program, "shadetool face_normals", "face", "double", "", t}, time, ErrorStats{});
  }
}

}  // namespace shadetool::bench
